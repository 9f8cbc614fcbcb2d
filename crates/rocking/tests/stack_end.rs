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
