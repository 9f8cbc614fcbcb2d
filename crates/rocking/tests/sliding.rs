//! The sliding building: a block alone under a rectangular pulse (closed form),
//! a frictionless building (momentum and energy), and a very rough one (the
//! fixed-base answer).

mod common;

use approx::assert_relative_eq;
use common::*;
use rocking::{reference, Building, EventKind, GroundMotion, Harmonic, Initial, Model, NormalForce, Pulse, Settings};

/// A block alone, pulse `a0 > μs g` lasting `td`: final slip
/// `−[(a0 − μk g) td²/2 + ((a0 − μk g) td)² / (2 μk g)]`. Piecewise-constant
/// accelerations are integrated exactly by the Runge–Kutta pair; the stop is a
/// root of a linear function. 1e-12 relative is rounding only.
#[test]
fn sliding_block_under_rectangular_pulse() {
    let (mu_s, mu_k) = (0.5, 0.4);
    let model = Model::new(None, Some(Building::new(1.0e5, mu_s, mu_k, NormalForce::Constant).unwrap()), G).unwrap();
    for (a0, td) in [(0.6 * G, 0.3), (2.0 * G, 0.05)] {
        let ground = GroundMotion::Pulse(Pulse::rectangular(a0, td).unwrap());
        let (s, log) = run_logged(
            &model,
            &ground,
            Initial::default(),
            &Settings {
                duration: 3.0,
                ..Settings::default()
            },
        );
        let exact = reference::sliding_block_rectangular_pulse(a0, td, mu_k, G);
        assert_relative_eq!(s.final_slip, exact, max_relative = 1e-12);
        assert_relative_eq!(s.max_abs_slip, exact.abs(), max_relative = 1e-12);
        // It slips at once (the pulse jumps above μs g at t = 0) and sticks when u̇ = 0.
        assert_eq!(s.first_slip_time, Some(0.0));
        let stick = log.events.iter().find(|e| e.kind == EventKind::Stick).unwrap();
        let t_stop = td + (a0 - mu_k * G) * td / (mu_k * G);
        assert_relative_eq!(stick.time, t_stop, max_relative = 1e-12);
    }
    // Below μs g nothing moves.
    let weak = GroundMotion::Pulse(Pulse::rectangular(0.49 * G, 0.3).unwrap());
    let s = run(
        &model,
        &weak,
        Initial::default(),
        &Settings {
            duration: 1.0,
            ..Settings::default()
        },
    );
    assert_eq!(s.first_slip_time, None);
    assert!(s.final_slip.abs() < 1e-300);
}

/// Frictionless building, no ground motion, tower released tilted: between
/// impacts, horizontal momentum `M u̇ + m2 R cos φ θ̇` and energy
/// `½ M u̇² + m2 R cos φ θ̇ u̇ + ½ I_O θ̇² + m2 g R cos φ` are constant (to the
/// integration tolerance), for both normal-force laws. Momentum starts at zero
/// and the impact law keeps it (docs/src/model.md, "Impact on a building that can
/// slide"), with `θ̇⁺/θ̇⁻ = (r I_O − m2² h²/M) / (I_O − m2² h²/M)`; energy only
/// falls at an impact.
#[test]
fn frictionless_building_conserves_momentum_and_energy() {
    let tower = block();
    for normal in [NormalForce::Constant, NormalForce::Dynamic] {
        let m1 = 2000.0;
        let model = on_building(tower, m1, 0.0, 0.0, normal);
        let total = m1 + tower.mass();
        let (_, history, log) = run_history(
            &model,
            &GroundMotion::None,
            Initial {
                theta: 0.7 * tower.alpha(),
                theta_dot: 0.0,
            },
            &tight(3.0),
            0.002,
        );
        let mr = tower.mass() * tower.radius();
        let impacts: Vec<_> = log.events.iter().filter(|e| e.kind == EventKind::Impact).collect();
        assert!(impacts.len() >= 2, "{normal:?}");
        let momentum_energy = |x: rocking::State| {
            let phi = tower.alpha() - x.theta.abs();
            let momentum = total * x.slip_vel + mr * phi.cos() * x.theta_dot;
            let energy = 0.5 * total * x.slip_vel.powi(2)
                + mr * phi.cos() * x.theta_dot * x.slip_vel
                + 0.5 * tower.inertia_pivot() * x.theta_dot.powi(2)
                + mr * G * phi.cos();
            (momentum, energy)
        };
        // The impact law keeps the horizontal momentum M u̇ + m2 h θ̇ (h = R cos α
        // at θ = 0): zero for all time, impacts included. m2 R θ̇ is of the order
        // of 100 kg·m/s here; rtol 1e-11, so 1e-7 m2 R is far above rounding.
        let mut start = 0.0;
        let mut last_energy = f64::INFINITY;
        for (k, end) in impacts.iter().map(|e| e.time).chain([3.0]).enumerate() {
            let inside: Vec<(f64, f64)> = history
                .samples
                .iter()
                .filter(|s| s.t > start && s.t < end)
                .map(|s| momentum_energy(s.state))
                .collect();
            assert!(inside.len() > 10);
            for (p, _) in &inside {
                assert!(p.abs() < 1e-7 * mr, "{normal:?}: momentum {p:e}");
            }
            let (lo, hi) = inside.iter().fold((f64::MAX, f64::MIN), |(lo, hi), &(_, e)| (lo.min(e), hi.max(e)));
            assert!(hi - lo < 1e-8 * mr * G, "{normal:?}: energy spread {:e}", hi - lo);
            assert!(hi < last_energy, "{normal:?}: energy grew at an impact");
            last_energy = lo;
            if let Some(e) = impacts.get(k) {
                let (before, after) = (momentum_energy(e.before).0, momentum_energy(e.after).0);
                assert!((after - before).abs() <= 1e-10 * mr, "{normal:?}: momentum jumped by {:e}", after - before);
                // docs/src/model.md: θ̇⁺/θ̇⁻ = (r I_O − m2² h²/M) / (I_O − m2² h²/M), h = H/2.
                let h = 0.5 * 2.0;
                let coupling = (tower.mass() * h).powi(2) / total;
                let ratio = (tower.restitution() * tower.inertia_pivot() - coupling) / (tower.inertia_pivot() - coupling);
                assert!((e.after.theta_dot - ratio * e.before.theta_dot).abs() <= 1e-12 * e.before.theta_dot.abs());
            }
            start = end;
        }
        // The building moves opposite to the tower's lean.
        assert!(history.samples.iter().any(|s| s.state.slip.abs() > 1e-4));
    }
}

/// A very rough foundation (μs = μk = 50) never slips: the response equals the
/// fixed-base one. The equations are the same; the building's run integrates
/// four components instead of two, so its steps differ and the two agree to
/// the integration tolerance (rtol 1e-8), not to rounding.
#[test]
fn very_rough_foundation_gives_the_fixed_base_answer() {
    let tower = block();
    let ground = GroundMotion::Harmonic(Harmonic::new(0.5 * G, 2.0, 6.0, 0.0).unwrap());
    let settings = Settings {
        duration: 8.0,
        ..Settings::default()
    };
    let fixed_base = run(&fixed(tower), &ground, Initial::default(), &settings);
    for normal in [NormalForce::Constant, NormalForce::Dynamic] {
        let rough = run(&on_building(tower, 1.0e4, 50.0, 50.0, normal), &ground, Initial::default(), &settings);
        assert_eq!(rough.first_slip_time, None);
        assert_relative_eq!(rough.max_abs_theta(), fixed_base.max_abs_theta(), max_relative = 1e-7);
        assert_eq!(rough.impacts, fixed_base.impacts);
    }
}

/// With the tower standing and the complex sliding, the pivot line decelerates
/// at μk g: a tower with tan α < μk lifts at the instant the slip starts.
#[test]
fn sliding_complex_lifts_a_slender_tower() {
    let tower = block(); // tan α = 0.25
    let model = on_building(tower, 1.0e4, 0.35, 0.3, NormalForce::Constant);
    let ground = GroundMotion::Pulse(Pulse::rectangular(0.5 * G, 0.2).unwrap());
    let (s, log) = run_logged(
        &model,
        &ground,
        Initial::default(),
        &Settings {
            duration: 2.0,
            ..Settings::default()
        },
    );
    assert_eq!(s.first_slip_time, Some(0.0));
    assert_eq!(s.first_uplift_time, Some(0.0));
    assert!(log.events.iter().any(|e| e.kind == EventKind::Stick));
}
