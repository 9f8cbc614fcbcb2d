//! How a stack's run ends: a belfry that overturns while its shaft stands,
//! at the instant the energy balance gives, and a free stack whose impacts
//! accumulate coming to rest in finite time.

use rocking::stack::run::{run, RunSettings, StackEventKind};
use rocking::stack::{Block, Interface, Stack, StackRegime, StackState};
use rocking::GroundMotion;

const G: f64 = 9.81;

/// A slender belfry 1 m × 6 m (α = atan(1/6)) released at θ_2 = 0.2 > α on a
/// squat shaft 8 m × 4 m that cannot lift: it falls as a block on a fixed
/// base, reaching π/2 after
///
/// ```text
/// t = ∫_{θ0}^{π/2} dθ / sqrt(2 p² (cos(α − θ0) − cos(α − θ))),  p² = m g R / I_O = 3 g / (4 R)
/// ```
///
/// (energy `½ I_O θ̇² + m g R cos(α − θ)` conserved), integrated here by
/// Simpson's rule after `θ = θ0 + v²`, which removes the square-root
/// singularity at the start.
#[test]
fn belfry_overturns_at_the_time_of_the_energy_balance() {
    let shaft = Block::solid(1, 8.0, 4.0, 5.0e5).expect("a valid shaft");
    let belfry = Block::solid(2, 1.0, 6.0, 5.0e3).expect("a valid belfry");
    let stack = Stack::new(&[shaft, belfry], None, G).expect("a valid stack");
    let theta0 = 0.2;
    let mut initial = StackState::default();
    initial.theta[1] = theta0;
    let settings = RunSettings {
        duration: 10.0,
        rtol: 1e-12,
        atol: 1e-14,
        sample_interval: 0.01,
    };
    let out = run(&stack, &GroundMotion::None, &initial, &settings).expect("the run");
    assert_eq!(out.overturned, Some(1));
    let last = out.events.last().expect("events");
    assert_eq!(last.kind, StackEventKind::Overturn(1));
    assert!(out.events.iter().all(|e| !matches!(e.kind, StackEventKind::Uplift(0))), "the shaft lifted");

    let (alpha, radius) = ((0.5f64 / 3.0).atan(), 0.5f64.hypot(3.0));
    let p2 = 3.0 * G / (4.0 * radius);
    let integrand = |v: f64| {
        if v == 0.0 {
            // The limit: 2v / sqrt(2 p² sin(θ0 − α) v²).
            2.0 / (2.0 * p2 * (theta0 - alpha).sin()).sqrt()
        } else {
            let theta = theta0 + v * v;
            2.0 * v / (2.0 * p2 * ((alpha - theta0).cos() - (alpha - theta).cos())).sqrt()
        }
    };
    let (n, end) = (20_000, (std::f64::consts::FRAC_PI_2 - theta0).sqrt());
    let h = end / n as f64;
    let simpson: f64 = (0..=n)
        .map(|i| {
            integrand(i as f64 * h)
                * if i == 0 || i == n {
                    1.0
                } else if i % 2 == 1 {
                    4.0
                } else {
                    2.0
                }
        })
        .sum::<f64>()
        * h
        / 3.0;
    // Simpson's error with 2e4 parts of a smooth integrand is ~1e-15; the run's
    // rtol 1e-12 over ~1 s keeps the time to ~1e-10 s.
    assert!((last.time - simpson).abs() < 1e-8, "{} vs {simpson}", last.time);
}

/// Shaft and belfry released leaning on a fixed base with no input: each
/// impact keeps less than all the energy, the impacts accumulate, and both
/// interfaces come to rest (seated, θ = θ̇ = 0) in finite time, long before
/// the end of the run; after that nothing happens.
#[test]
fn a_free_stack_comes_to_rest_in_finite_time() {
    let shaft = Block::solid(1, 4.0, 20.0, 3.2e5).expect("a valid shaft");
    let belfry = Block::solid(2, 3.0, 6.0, 4.0e4).expect("a valid belfry");
    let stack = Stack::new(&[shaft, belfry], None, G).expect("a valid stack");
    let mut initial = StackState::default();
    initial.theta[..2].copy_from_slice(&[0.03, -0.05]);
    let out = run(
        &stack,
        &GroundMotion::None,
        &initial,
        &RunSettings {
            duration: 60.0,
            ..RunSettings::default()
        },
    )
    .expect("the run");
    let end = out.samples.last().expect("samples");
    assert_eq!(end.regime, StackRegime::REST, "{:?}", out.events.last());
    assert!(end.state.theta[..2].iter().chain(&end.state.theta_dot[..2]).all(|&x| x == 0.0), "{end:?}");
    let last = out.events.last().expect("events");
    assert!(matches!(last.kind, StackEventKind::Rest(_)), "{last:?}");
    assert!(last.time < 40.0, "rest at {} s", last.time);
    for k in 0..2 {
        assert!(out.events.iter().any(|e| e.kind == StackEventKind::Rest(k)), "interface {} never seated", k + 1);
    }
    assert!(out
        .events
        .iter()
        .all(|e| e.regime.interfaces.iter().all(|i| *i == Interface::Stuck || e.time < last.time + 1e-12)));
}

/// The summary's peak: a belfry 3 m × 6 m kicked at θ̇_2 = 0.3 rad/s from
/// upright on a squat shaft that stays put swings to the angle where its
/// kinetic energy is spent (`½ I_O θ̇² + m g R cos(α − θ)` is conserved):
///
/// ```text
/// cos(α − θ_max) = cos α + I_O θ̇0² / (2 m g R),  I_O = (4/3) m R²
/// ```
///
/// and the run reports it as the belfry's largest `|θ|`; the shaft's stays 0.
#[test]
fn peak_of_a_kicked_belfry_by_the_energy_balance() {
    let shaft = Block::solid(1, 8.0, 4.0, 5.0e5).expect("a valid shaft");
    let belfry = Block::solid(2, 3.0, 6.0, 4.0e4).expect("a valid belfry");
    let stack = Stack::new(&[shaft, belfry], None, G).expect("a valid stack");
    let w0 = 0.3;
    let mut initial = StackState::default();
    initial.theta_dot[1] = w0;
    let settings = RunSettings {
        duration: 0.5,
        rtol: 1e-12,
        atol: 1e-14,
        sample_interval: 0.01,
    };
    let out = run(&stack, &GroundMotion::None, &initial, &settings).expect("the run");
    let radius = 1.5f64.hypot(3.0);
    let alpha = (1.5f64 / 3.0).atan();
    let theta_max = alpha - (alpha.cos() + 4.0 / 3.0 * radius * w0 * w0 / (2.0 * G)).acos();
    // The peak sits where θ̇ = 0, found to a few ulps of time, and θ is flat
    // there: its error is the integration's, ~1e-12 here.
    assert!(
        (out.blocks[1].max_abs_theta - theta_max).abs() < 1e-9,
        "{} vs {theta_max}",
        out.blocks[1].max_abs_theta
    );
    assert!(out.blocks[0].max_abs_theta == 0.0 && out.blocks[0].impacts == 0);
    // No event before the peak (at about 0.16 s): it was found inside a step.
    assert!(out.events.iter().all(|e| e.time > 0.1), "{:?}", out.events.first());
}

/// A standing shaft and belfry under `a_g = A sin(2π f t)` lift first at the
/// interface with the lower threshold (the shaft's, `g (B_1/2) Σ m / Σ m y`,
/// checked by hand in `stack_core.rs`), when `A sin(2π f t)` first reaches it:
/// `t = asin(threshold / A) / (2π f)`.
#[test]
fn first_uplift_at_the_threshold() {
    let shaft = Block::solid(1, 4.0, 20.0, 3.2e5).expect("a valid shaft");
    let belfry = Block::solid(2, 3.0, 6.0, 4.0e4).expect("a valid belfry");
    let stack = Stack::new(&[shaft, belfry], None, G).expect("a valid stack");
    let threshold = G * 2.0 * 3.6e5 / (3.2e5 * 10.0 + 4.0e4 * 23.0);
    let (amplitude, frequency) = (0.4 * G, 1.5);
    let input = GroundMotion::Harmonic(rocking::Harmonic::new(amplitude, frequency, 2.0, 0.0).expect("a valid input"));
    let out = run(
        &stack,
        &input,
        &StackState::default(),
        &RunSettings {
            duration: 2.0,
            ..RunSettings::default()
        },
    )
    .expect("the run");
    let expected = (threshold / amplitude).asin() / (2.0 * std::f64::consts::PI * frequency);
    let first = out.blocks[0].first_uplift_time.expect("the shaft lifts");
    // Located by root finding to a few ulps of time on a margin that is exact
    // at rest (everything moves with the ground): 1e-12 s.
    assert!((first - expected).abs() < 1e-12, "{first} vs {expected}");
    let uplift = out.events.iter().find(|e| matches!(e.kind, StackEventKind::Uplift(_))).expect("an uplift");
    assert_eq!(uplift.kind, StackEventKind::Uplift(0));
    // A positive ground acceleration throws the shaft towards −x.
    assert_eq!(uplift.regime.interfaces[0], Interface::Rocking(rocking::Pivot::Negative));
    assert!(
        out.blocks[0].impacts > 0
            && out.blocks[0].impacts
                == out
                    .events
                    .iter()
                    .filter(|e| matches!(e.kind, StackEventKind::Impact(0) | StackEventKind::Rest(0)))
                    .count()
    );
}
