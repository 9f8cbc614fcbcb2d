//! Regression: a stick condition exceeded only inside one integrator step was
//! missed while the tower rocked.
//!
//! The engine examined a condition only through its signs at the two ends of
//! a step, so a friction demand that rose above `μs N` for a few milliseconds
//! around a peak of the shaking, while the tower rocked, gave no slip at all.
//!
//! The case is built so that the answer follows from first principles: a
//! 1 kg tower on a 10⁶ kg building. The stick demand of (B) with `ü = 0` is
//! `F_req = M a_g + m2 R (cos φ θ̈ + s sin φ θ̇²)`, and the tower's part is
//! below `m2 R (|θ̈| + θ̇²) ≈ 30 N` against `M a_g ≈ 5·10⁶ N`: the building
//! slips exactly when `|a_g| > μs g` to within 6e-6 relative. Under
//! `a_g = A sin ωt` with `A = μs g (1 + ε)`, that holds only for
//! `|ωt − π/2| < δ`, `cos δ = 1/(1 + ε)`: with `ε = 1e-4` and 2 Hz, a window of
//! 2.3 ms, while the tower (tan α = 0.25 < μs) has been rocking since
//! `a_g` passed `g tan α`.

#![allow(clippy::unwrap_used)]

mod common;
use common::{block, on_building, G};
use rocking::{simulate, GroundMotion, Harmonic, Initial, NormalForce, Settings, Tower};
use std::f64::consts::FRAC_PI_2;

const MU_S: f64 = 0.5;
const F: f64 = 2.0;

fn light_tower() -> Tower {
    let b = block();
    Tower::from_properties(1.0, b.inertia_pivot() / b.mass(), b.radius(), b.alpha(), None).unwrap()
}

fn first_slip(epsilon: f64, settings: &Settings) -> Option<f64> {
    let model = on_building(light_tower(), 1.0e6, MU_S, 0.4, NormalForce::Constant);
    let ground = GroundMotion::Harmonic(Harmonic::new(MU_S * G * (1.0 + epsilon), F, 1.0, 0.0).unwrap());
    simulate(&model, &ground, Initial::default(), settings, &mut ()).unwrap().first_slip_time
}

#[test]
fn a_demand_above_the_threshold_for_two_milliseconds_slips_at_its_start() {
    let epsilon: f64 = 1e-4;
    let omega = 2.0 * std::f64::consts::PI * F;
    let delta = (1.0 / (1.0 + epsilon)).acos();
    let start = (FRAC_PI_2 - delta) / omega;
    assert!(2.0 * delta / omega < 2.5e-3, "the window is short");
    for rtol in [1e-6, 1e-8, 1e-11] {
        let settings = Settings {
            duration: 0.5,
            rtol,
            atol: rtol * 1e-2,
        };
        let t = first_slip(epsilon, &settings).unwrap_or_else(|| panic!("rtol {rtol}: no slip"));
        // The tower's share of the demand (≤ 6e-6 of it) moves the crossing by
        // at most 6e-6 μs g / ȧ_g(start) = 3.4e-5 s, with ȧ_g = A ω sin δ.
        let shift = 6e-6 * MU_S * G / (MU_S * G * (1.0 + epsilon) * omega * delta.sin());
        assert!((t - start).abs() <= shift, "rtol {rtol}: slip at {t}, expected {start} ± {shift:e}");
    }
}

#[test]
fn a_demand_just_below_the_threshold_never_slips() {
    // 1e-4 below μs g: the demand never reaches μs N (the tower's share is 6e-6).
    assert_eq!(
        first_slip(
            -1e-4,
            &Settings {
                duration: 0.5,
                ..Settings::default()
            }
        ),
        None
    );
}
