//! Vertical ground acceleration (docs/src/model.md, "Vertical ground acceleration"):
//! the closed forms a vertical input must reproduce. `a_v` enters only as the
//! effective gravity `g + a_v`, so a constant `a_v = c` is a run under gravity
//! `g + c`; `a_v` alone moves nothing; the thresholds follow `g + a_v(t)`; and
//! `g + a_v <= 0` stops the run at the located instant.

#![allow(clippy::unwrap_used)]

mod common;

use approx::assert_relative_eq;
use common::*;
use rocking::{reference, simulate_with_vertical, Building, Error, GroundMotion, Harmonic, Initial, Model, NormalForce, Pulse, Settings, Summary};
use std::f64::consts::{PI, TAU};

fn run_v(model: &Model, ground: &GroundMotion, vertical: &GroundMotion, settings: &Settings) -> Result<Summary, Error> {
    simulate_with_vertical(model, ground, Some(vertical), Initial::default(), settings, &mut ())
}

/// A constant vertical acceleration `c` for the whole run: a rectangular
/// pulse that lasts beyond it.
fn constant(c: f64) -> GroundMotion {
    GroundMotion::Pulse(Pulse::rectangular(c, 1000.0).unwrap())
}

/// The models of the comparisons: fixed base, and on a church with both
/// normal-force laws, under gravity `g`.
fn models(g: f64) -> Vec<(&'static str, Model)> {
    let building = |normal| Some(Building::new(2.0e3, 0.3, 0.25, normal).unwrap());
    vec![
        ("fixed", Model::new(Some(block()), None, g).unwrap()),
        ("constant N", Model::new(Some(block()), building(NormalForce::Constant), g).unwrap()),
        ("dynamic N", Model::new(Some(block()), building(NormalForce::Dynamic), g).unwrap()),
        ("church alone", Model::new(None, building(NormalForce::Constant), g).unwrap()),
    ]
}

/// `a_v = c` (up and down) against gravity `g + c`, with the same horizontal
/// input in m/s² (rocking, impacts and slips). The two runs take the same
/// steps and differ only in where `g + c` is rounded, so agreement to 1e-9
/// relative (of the largest value) is a test of every `g` being the
/// effective one; a `g` left behind in any equation shows at 1e-2 or more.
#[test]
fn constant_vertical_acceleration_is_a_change_of_gravity() {
    let ground = GroundMotion::Harmonic(Harmonic::new(0.45 * G, 1.5, 3.0, 0.0).unwrap());
    let settings = tight(5.0);
    for c in [0.3 * G, -0.25 * G] {
        for ((name, with_g), (_, with_gc)) in models(G).into_iter().zip(models(G + c)) {
            let a = run_v(&with_g, &ground, &constant(c), &settings).unwrap();
            let b = run(&with_gc, &ground, Initial::default(), &settings);
            let scale = a.theta_range.0.abs().max(a.theta_range.1).max(1e-12);
            assert!(
                (a.theta_range.0 - b.theta_range.0).abs() <= 1e-9 * scale,
                "{name}, c = {c}: {:?} vs {:?}",
                a.theta_range,
                b.theta_range
            );
            assert!((a.theta_range.1 - b.theta_range.1).abs() <= 1e-9 * scale, "{name}, c = {c}");
            let slip = a.max_abs_slip.max(1e-12);
            assert!(
                (a.final_slip - b.final_slip).abs() <= 1e-9 * slip,
                "{name}, c = {c}: {} vs {}",
                a.final_slip,
                b.final_slip
            );
            assert_eq!(a.impacts, b.impacts, "{name}, c = {c}");
            assert_eq!(a.first_uplift_time.is_some(), b.first_uplift_time.is_some(), "{name}, c = {c}");
            if let (Some(ta), Some(tb)) = (a.first_uplift_time, b.first_uplift_time) {
                assert!((ta - tb).abs() <= 1e-9, "{name}, c = {c}: uplift {ta} vs {tb}");
            }
            if let (Some(ta), Some(tb)) = (a.first_slip_time, b.first_slip_time) {
                assert!((ta - tb).abs() <= 1e-9, "{name}, c = {c}: slip {ta} vs {tb}");
            }
            assert_relative_eq!(a.max_top_abs_acceleration, b.max_top_abs_acceleration, max_relative = 1e-9);
            assert_relative_eq!(a.max_pivot_friction_demand, b.max_pivot_friction_demand, max_relative = 1e-9);
            // The least g + a_v is g + c exactly (one rounding).
            assert_eq!(a.min_effective_gravity, Some(G + c));
            assert_eq!(b.min_effective_gravity, None);
        }
        // The runs above must be non-trivial for the comparison to mean anything.
        let fixed = run(&models(G + c).remove(0).1, &ground, Initial::default(), &settings);
        assert!(fixed.impacts > 0, "c = {c}: the tower must rock");
    }
}

/// With no horizontal motion, a vertical one (below free fall) moves nothing:
/// every condition to leave rest compares a zero horizontal force with a
/// positive threshold. Exactly zero, for every body combination.
#[test]
fn vertical_acceleration_alone_moves_nothing() {
    let vertical = GroundMotion::Harmonic(Harmonic::new(0.9 * G, 3.0, 4.0, 0.3).unwrap());
    for (name, model) in models(G) {
        let s = run_v(&model, &GroundMotion::None, &vertical, &tight(5.0)).unwrap();
        assert_eq!(s.theta_range, (0.0, 0.0), "{name}");
        assert!(s.final_slip.abs() < f64::MIN_POSITIVE, "{name}: exactly zero");
        assert_eq!((s.impacts, s.events), (0, 0), "{name}");
        assert_eq!(s.first_uplift_time, None, "{name}");
        assert_eq!(s.first_slip_time, None, "{name}");
        // The least g + a_v of 0.9 g sin(6π t + 0.3) is g − 0.9 g, reached at a
        // segment end (an extremum), where sin is 1 to rounding.
        assert_relative_eq!(s.min_effective_gravity.unwrap(), 0.1 * G, max_relative = 1e-12);
    }
}

/// A block alone on its foundation under a rectangular pulse `a0 > μs (g + c)`
/// with a constant `a_v = c`: the closed form of docs/src/model.md with `g + c` for `g`.
/// The accelerations are piecewise constant, integrated exactly; 1e-12
/// relative is rounding only.
#[test]
fn sliding_block_under_rectangular_pulse_with_constant_vertical() {
    let (mu_s, mu_k) = (0.5, 0.4);
    let model = Model::new(None, Some(Building::new(1.0e5, mu_s, mu_k, NormalForce::Constant).unwrap()), G).unwrap();
    for (c, a0, td) in [(0.4 * G, 0.9 * G, 0.3), (-0.3 * G, 0.4 * G, 0.2)] {
        assert!(a0 > mu_s * (G + c));
        let ground = GroundMotion::Pulse(Pulse::rectangular(a0, td).unwrap());
        let s = run_v(
            &model,
            &ground,
            &constant(c),
            &Settings {
                duration: 3.0,
                ..Settings::default()
            },
        )
        .unwrap();
        let exact = reference::sliding_block_rectangular_pulse(a0, td, mu_k, G + c);
        assert_relative_eq!(s.final_slip, exact, max_relative = 1e-12);
        // Without the vertical input the answer is different: the test can fail.
        let without = reference::sliding_block_rectangular_pulse(a0, td, mu_k, G);
        assert!((exact - without).abs() > 0.05 * exact.abs());
    }
}

/// Mirror symmetry with a vertical input: `a_g → −a_g` with the same `a_v`
/// gives `θ → −θ`, `u → −u`. The equations are odd in (`a_g`, `θ`, `u`) and
/// even in `a_v`; the mirrored run takes the mirrored steps, so only rounding
/// separates the two: 1e-9 relative.
#[test]
fn mirror_symmetry_with_vertical_input() {
    let vertical = GroundMotion::Harmonic(Harmonic::new(0.35 * G, 2.3, 3.0, 0.7).unwrap());
    for (name, model) in models(G) {
        let plus = GroundMotion::Harmonic(Harmonic::new(0.45 * G, 1.5, 3.0, 0.0).unwrap());
        let minus = GroundMotion::Harmonic(Harmonic::new(-0.45 * G, 1.5, 3.0, 0.0).unwrap());
        let a = run_v(&model, &plus, &vertical, &tight(5.0)).unwrap();
        let b = run_v(&model, &minus, &vertical, &tight(5.0)).unwrap();
        let scale = a.theta_range.0.abs().max(a.theta_range.1).max(1e-12);
        assert!(
            (a.theta_range.0 + b.theta_range.1).abs() <= 1e-9 * scale,
            "{name}: {:?} vs {:?}",
            a.theta_range,
            b.theta_range
        );
        assert!((a.theta_range.1 + b.theta_range.0).abs() <= 1e-9 * scale, "{name}");
        assert!((a.final_slip + b.final_slip).abs() <= 1e-9 * a.max_abs_slip.max(1e-12), "{name}");
        assert_eq!(a.impacts, b.impacts, "{name}");
        assert!(a.impacts > 0 || name == "church alone", "{name}: the tower must rock");
    }
}

/// The first root of `f` on `[0, t_max]`: a scan on a grid of `dt` for the
/// first sign change, then bisection to rounding.
fn first_root(f: impl Fn(f64) -> f64, t_max: f64, dt: f64) -> f64 {
    let mut a = 0.0;
    assert!(f(a) < 0.0);
    while a < t_max {
        let b = a + dt;
        if f(b) >= 0.0 {
            let (mut lo, mut hi) = (a, b);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if f(mid) >= 0.0 {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            return hi;
        }
        a = b;
    }
    panic!("no root");
}

/// Uplift from rest when `a_h(t) = (g + a_v(t)) tan α`: under a constant
/// horizontal push below `g tan α` that a falling `a_v` brings above the
/// threshold, and under two harmonics whose difference is not monotone
/// between the inputs' own extrema. The root is found here by bisection on
/// the closed form; the run locates it by root finding too: 1e-9 s.
#[test]
fn uplift_instant_follows_the_effective_gravity() {
    let model = fixed(block());
    let tan_alpha = 0.25; // the 0.5 m × 2 m block
    let cases = [
        // 0.2 g < g tan α; g − 0.5 g sin(2π t) brings the threshold below it.
        (
            GroundMotion::Pulse(Pulse::rectangular(0.2 * G, 100.0).unwrap()),
            GroundMotion::Harmonic(Harmonic::new(0.5 * G, 1.0, 10.0, PI).unwrap()),
        ),
        (
            GroundMotion::Harmonic(Harmonic::new(0.3 * G, 2.0, 10.0, 0.0).unwrap()),
            GroundMotion::Harmonic(Harmonic::new(0.4 * G, 0.7, 10.0, 2.0).unwrap()),
        ),
    ];
    for (horizontal, vertical) in &cases {
        // a positive a_g lifts the tower on its −x corner: uplift when a_g > (g + a_v) tan α
        // or −a_g > (g + a_v) tan α.
        let margin = |t: f64| horizontal.acceleration(t).abs() - (G + vertical.acceleration(t)) * tan_alpha;
        let exact = first_root(margin, 5.0, 1e-4);
        let s = run_v(&model, horizontal, vertical, &tight(exact + 0.5)).unwrap();
        let t = s.first_uplift_time.expect("the tower must lift");
        assert!((t - exact).abs() < 1e-9, "uplift at {t}, root at {exact}");
        // Under g alone the first case would never lift.
    }
    let s = run(&model, &cases[0].0, Initial::default(), &tight(2.0));
    assert_eq!(s.first_uplift_time, None);
}

/// `g + a_v <= 0` stops the run with the instant located: the first root of
/// `g − 1.2 g sin(2π f t)` is `asin(1/1.2) / (2π f)`, for a tower at rest, a
/// rocking one, and one rocking on a sliding church; a constant `−1.2 g`
/// stops it at once. The crossing is located by root finding: 1e-12 s.
#[test]
fn free_fall_stops_the_run_at_the_located_instant() {
    let f = 1.3;
    let vertical = GroundMotion::Harmonic(Harmonic::new(1.2 * G, f, 10.0, PI).unwrap());
    let exact = (1.0 / 1.2f64).asin() / (TAU * f);
    let rocking = GroundMotion::Harmonic(Harmonic::new(0.6 * G, 4.0, 10.0, 0.0).unwrap());
    for (name, model) in models(G) {
        for horizontal in [GroundMotion::None, rocking.clone()] {
            let err = run_v(&model, &horizontal, &vertical, &tight(2.0)).unwrap_err();
            let Error::FreeFall { time } = err else { panic!("{name}: {err}") };
            assert!((time - exact).abs() < 1e-12, "{name}: {time} vs {exact}");
            assert!(err.to_string().contains(&format!("t = {time} s")), "{err}");
        }
        let err = run_v(&model, &rocking, &constant(-1.2 * G), &tight(2.0)).unwrap_err();
        assert_eq!(err, Error::FreeFall { time: 0.0 }, "{name}");
    }
}
