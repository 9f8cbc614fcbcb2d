//! Free rocking on a fixed base (docs/src/validation.md): time to the first
//! impact, restitution at every impact, energy between impacts, and rest in
//! finite time.

mod common;

use approx::assert_relative_eq;
use common::*;
use rocking::{reference, EventKind, GroundMotion, Initial, Motion};

/// Released from rest at θ0, the block reaches θ = 0 after the quadrature time.
/// rtol 1e-11 keeps the integration error near 1e-10; the root is located to a
/// few ulp, so 1e-7 relative (the figure) holds with margin.
#[test]
fn time_to_first_impact_matches_quadrature() {
    let tower = block();
    let p = tower.frequency_parameter(G);
    for fraction in [0.05, 0.5, 0.95] {
        let theta0 = fraction * tower.alpha();
        let (_, log) = run_logged(&fixed(tower), &GroundMotion::None, Initial { theta: theta0, theta_dot: 0.0 }, &tight(3.0));
        let first = log.events.iter().find(|e| e.kind == EventKind::Impact).expect("an impact");
        let exact = reference::free_rocking_time_to_impact(p, tower.alpha(), theta0);
        assert_relative_eq!(first.time, exact, max_relative = 1e-7);
        // And well inside that: the method's own accuracy.
        assert_relative_eq!(first.time, exact, max_relative = 1e-9);
    }
}

/// θ̇⁺ = r θ̇⁻ at every impact, to rounding; and the cascade ends at rest.
#[test]
fn restitution_at_every_impact_and_rest_in_finite_time() {
    let tower = block();
    let (summary, log) = run_logged(
        &fixed(tower),
        &GroundMotion::None,
        Initial {
            theta: 0.8 * tower.alpha(),
            theta_dot: 0.0,
        },
        &tight(60.0),
    );
    let impacts: Vec<_> = log.events.iter().filter(|e| e.kind == EventKind::Impact).collect();
    assert!(impacts.len() > 20);
    for e in &impacts {
        assert_relative_eq!(e.after.theta_dot, tower.restitution() * e.before.theta_dot, max_relative = 1e-15);
        assert!(e.before.theta.abs() < 1e-14);
    }
    // Consecutive impacts alternate sides.
    for w in impacts.windows(2) {
        assert!(w[0].before.theta_dot * w[1].before.theta_dot < 0.0);
    }
    let rest = log.events.iter().find(|e| e.kind == EventKind::Rest).expect("comes to rest");
    assert!(rest.after.theta_dot.abs() < 1e-300 && rest.time < 60.0);
    assert_eq!(summary.impacts as usize, impacts.len());
    assert!(summary.time_in(Motion::Rest) > 0.0);
    // Rest comes once |θ̇| falls below the threshold: the last impact's outgoing velocity.
    let last = impacts[impacts.len() - 1];
    assert!(last.after.theta_dot.abs() < rocking::REST_ANGULAR_VELOCITY);
    assert!(impacts[impacts.len() - 2].after.theta_dot.abs() >= rocking::REST_ANGULAR_VELOCITY);
}

/// `½ I_O θ̇² + m g R cos(α − |θ|)` is constant between impacts (to the
/// integration tolerance) and drops by the factor r² of the kinetic energy at each.
#[test]
fn energy_is_constant_between_impacts() {
    let tower = block();
    let (_, history, log) = run_history(
        &fixed(tower),
        &GroundMotion::None,
        Initial {
            theta: 0.9 * tower.alpha(),
            theta_dot: 0.0,
        },
        &tight(4.0),
        0.001,
    );
    let energy = |theta: f64, theta_dot: f64| {
        0.5 * tower.inertia_pivot() * theta_dot * theta_dot + tower.mass() * G * tower.radius() * (tower.alpha() - theta.abs()).cos()
    };
    let impacts: Vec<f64> = log.events.iter().filter(|e| e.kind == EventKind::Impact).map(|e| e.time).collect();
    assert!(impacts.len() >= 3);
    let scale = tower.mass() * G * tower.radius();
    for w in impacts.windows(2) {
        let inside: Vec<f64> = history
            .samples
            .iter()
            .filter(|s| s.t > w[0] && s.t < w[1])
            .map(|s| energy(s.state.theta, s.state.theta_dot))
            .collect();
        let (lo, hi) = inside.iter().fold((f64::MAX, f64::MIN), |(lo, hi), &e| (lo.min(e), hi.max(e)));
        // rtol 1e-11 over a few hundred steps: drift well below 1e-9 of m g R.
        assert!((hi - lo) / scale < 1e-9, "energy drifts by {:e}", (hi - lo) / scale);
    }
}

/// Peaks of θ are the true extremes located where θ̇ = 0: no sample of a fine
/// history exceeds them, and the finest sample comes within the quadratic error
/// of sampling (½ |θ̈| δt² with δt = 1e-4 s).
#[test]
fn peaks_are_true_extremes() {
    let tower = block();
    let ground = GroundMotion::Harmonic(rocking::Harmonic::new(0.5 * G, 2.0, 3.0, 0.0).unwrap());
    let (summary, history, _) = run_history(&fixed(tower), &ground, Initial::default(), &tight(4.0), 1e-4);
    let sampled = history.samples.iter().map(|s| s.state.theta.abs()).fold(0.0, f64::max);
    assert!(sampled <= summary.max_abs_theta() * (1.0 + 1e-12));
    let p2 = tower.frequency_parameter(G).powi(2);
    assert!(
        summary.max_abs_theta() - sampled <= 0.5 * p2 * 2.0 * 1e-8,
        "{} vs {}",
        summary.max_abs_theta(),
        sampled
    );
    assert!(summary.max_abs_theta() > 0.1 * tower.alpha());
}

/// Housner's cascade, the impacts of a block released from rest, in closed
/// form: the `n`-th impact meets the ground at `rⁿ⁻¹ ω1`, `ω1` from energy
/// (`ω1² = 2p² (cos(α − θ0) − cos α)`), and leaves it at `rⁿ ω1`; between
/// them the flight rises to the apex energy gives and takes twice the time
/// from that apex to `θ = 0` (the reference quadrature). The impact times
/// are the partial sums of that series of flight times, and the block comes
/// to rest at the finite sum where `rⁿ ω1` falls below the rest threshold.
/// The run integrates the large flights (rtol 1e-11) and jumps the small
/// ones in closed form (`cascade.rs`); both are checked here.
#[test]
fn the_cascade_is_housners_geometric_series() {
    let tower = block();
    let (p, alpha, r) = (tower.frequency_parameter(G), tower.alpha(), tower.restitution());
    let theta0 = 0.3 * alpha;
    let (_, log) = run_logged(&fixed(tower), &GroundMotion::None, Initial { theta: theta0, theta_dot: 0.0 }, &tight(10.0));
    let impacts: Vec<_> = log.events.iter().filter(|e| e.kind == EventKind::Impact).collect();
    // The apex of a flight leaving θ = 0 at ω: 2 sin(α − ψ/2) sin(ψ/2) = ω² / (2p²)
    // (energy, as cos(α − ψ) − cos α without the cancellation), by bisection.
    let apex = |omega: f64| {
        let c = omega * omega / (2.0 * p * p);
        let (mut lo, mut hi) = (0.0, alpha);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if 2.0 * (alpha - 0.5 * mid).sin() * (0.5 * mid).sin() < c {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    };
    // A flight's duration: twice the reference quadrature's time from its
    // apex; below an apex of 1e-6 rad, where that quadrature's difference of
    // cosines loses digits, the linearised equation's closed form
    // `(2/λ) artanh(ω / (λ tan α))`, `λ = p √(cos α)`, off by a relative ψm².
    let lambda = p * alpha.cos().sqrt();
    let flight = |omega: f64| match apex(omega) {
        psi if psi > 1e-6 => 2.0 * reference::free_rocking_time_to_impact(p, alpha, psi),
        _ => 2.0 / lambda * (omega / (lambda * alpha.tan())).atanh(),
    };
    let omega1 = (2.0 * p * p * ((alpha - theta0).cos() - alpha.cos())).sqrt();
    let mut t = reference::free_rocking_time_to_impact(p, alpha, theta0);
    let mut omega = omega1;
    for (n, e) in impacts.iter().enumerate() {
        // The last integrated flights rise some 1e-5 rad, where atol 1e-13
        // is a relative 1e-8 of θ: the speeds they hand on err by up to
        // 1.2e-8 (the flights jumped in closed form after them add none).
        // The times, sums of flights, err by up to 1e-9 s. Both bounds are
        // 3 times what is seen.
        assert!((e.time - t).abs() <= 3e-9, "impact {}: at {} s against {t} s", n + 1, e.time);
        let speed = e.before.theta_dot.abs() / omega - 1.0;
        assert!(speed.abs() <= 3.5e-8, "impact {}: θ̇⁻ {} against {omega}", n + 1, e.before.theta_dot);
        omega *= r;
        if omega >= rocking::REST_ANGULAR_VELOCITY {
            t += flight(omega);
        }
    }
    // The block stood at the last impact, where rⁿ ω1 fell below the threshold.
    assert_eq!(impacts.len(), ((rocking::REST_ANGULAR_VELOCITY / omega1).ln() / r.ln()).ceil() as usize);
    let rest = log.events.iter().find(|e| e.kind == EventKind::Rest).expect("comes to rest");
    assert!((rest.time - t).abs() <= 3e-9, "rest at {} s against {t} s", rest.time);
    // In finite time: below the whole series. A flight that leaves at ω and
    // rises to ψm is decelerated by at least p² sin(α − ψm), so it lasts at
    // most 2ω / (p² sin(α − ψm)); with the largest apex, the first flight's,
    // in every term, the sum is geometric.
    let slowest = p * p * (alpha - apex(r * omega1)).sin();
    let bound = reference::free_rocking_time_to_impact(p, alpha, theta0) + 2.0 * omega1 * r / (slowest * (1.0 - r));
    assert!(rest.time < bound, "{} against {bound}", rest.time);
}
