//! Responses to ground motion with closed-form or symmetry checks: the uplift
//! threshold, a rectangular pulse that overturns or not, mirror symmetry, and
//! independence from output spacing.

mod common;

use approx::assert_relative_eq;
use common::*;
use proptest::prelude::*;
use rocking::{reference, EventKind, GroundMotion, Harmonic, History, Initial, NormalForce, Pulse, PulseShape, Settings};
use std::f64::consts::PI;

/// A harmonic of amplitude 1% above g tan α lifts the block at the instant
/// `sin(ω t) = tan α / A`; 1% below, it never does.
#[test]
fn uplift_starts_at_g_tan_alpha_and_not_below() {
    let tower = block();
    let threshold = tower.alpha().tan();
    let f = 2.0;
    let below = GroundMotion::Harmonic(Harmonic::new(0.99 * threshold * G, f, 5.0, 0.0).unwrap());
    let s = run(&fixed(tower), &below, Initial::default(), &tight(5.0));
    assert_eq!(s.first_uplift_time, None);
    assert_eq!(s.impacts, 0);
    assert!(s.max_abs_theta().abs() < 1e-300);

    let above = GroundMotion::Harmonic(Harmonic::new(1.01 * threshold * G, f, 5.0, 0.0).unwrap());
    let (s, log) = run_logged(&fixed(tower), &above, Initial::default(), &tight(5.0));
    let expected = (1.0 / 1.01f64).asin() / (2.0 * PI * f);
    // Located by root finding on sin: to a few ulp of t.
    assert_relative_eq!(s.first_uplift_time.unwrap(), expected, max_relative = 1e-13);
    // a_g > 0 pushes the block towards −x: it pivots on its −x corner.
    let uplift = log.events.iter().find(|e| e.kind == EventKind::Uplift).unwrap();
    assert_eq!(uplift.regime.tower, rocking::TowerRegime::Rocking(rocking::Pivot::Negative));
    assert!(s.theta_range.0 < 0.0);
}

/// A rectangular pulse of `a0 = 3 g tan α` overturns the block if it lasts 0.1%
/// longer than the critical duration (energy argument + quadrature, see
/// `reference`), and does not if it lasts 0.1% less; just below, the block
/// tips nearly to its corner (`θ = α` is the top of the potential).
#[test]
fn rectangular_pulse_overturns_above_the_critical_duration_only() {
    let tower = block();
    let ratio = 3.0 * tower.alpha().tan();
    let critical = reference::rectangular_pulse_overturning_duration(tower.frequency_parameter(G), tower.alpha(), ratio);
    for (factor, overturns) in [(1.001, true), (0.999, false)] {
        let ground = GroundMotion::Pulse(Pulse::rectangular(ratio * G, factor * critical).unwrap());
        let s = run(&fixed(tower), &ground, Initial::default(), &tight(10.0));
        assert_eq!(s.overturned(), overturns, "pulse of {factor} × critical duration {critical}");
        if overturns {
            assert_relative_eq!(s.max_abs_theta(), PI / 2.0, max_relative = 1e-12);
        } else {
            assert!(
                s.max_abs_theta() > 0.9 * tower.alpha() && s.max_abs_theta() < tower.alpha(),
                "{} vs α = {}",
                s.max_abs_theta(),
                tower.alpha()
            );
        }
    }
}

/// The jump of a cosine pulse at t = 0 above the threshold uplifts at once: a
/// condition that holds when a regime is entered switches without waiting.
#[test]
fn a_jump_above_the_threshold_uplifts_at_once() {
    let tower = block();
    let ground = GroundMotion::Pulse(Pulse::cycle(PulseShape::Cosine, 2.0 * tower.alpha().tan() * G, 2.0).unwrap());
    let s = run(&fixed(tower), &ground, Initial::default(), &tight(3.0));
    assert_eq!(s.first_uplift_time, Some(0.0));
}

/// Output spacing only reads the dense output: the summary is bit-for-bit the
/// same with history every 1 ms, every 50 ms, and none at all.
#[test]
fn summary_does_not_depend_on_output_spacing() {
    let model = on_building(block(), 5.0e3, 0.3, 0.25, NormalForce::Dynamic);
    let ground = GroundMotion::Harmonic(Harmonic::new(0.6 * G, 3.0, 4.0, 0.3).unwrap());
    let settings = Settings {
        duration: 6.0,
        ..Settings::default()
    };
    let bare = run(&model, &ground, Initial::default(), &settings);
    for dt in [0.001, 0.05] {
        let mut h = History::new(dt, vec![(0.1, 1.0)]);
        let s = rocking::simulate(&model, &ground, Initial::default(), &settings, &mut h).unwrap();
        assert_eq!(format!("{s:?}"), format!("{bare:?}"));
        assert_eq!(h.samples.len(), (6.0 / dt).round() as usize + 1);
    }
    assert!(bare.first_slip_time.is_some() && bare.impacts > 0, "the case exercises both bodies");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// a_g → −a_g gives θ → −θ and u → −u (docs/src/validation.md), for
    /// random harmonic inputs on a sliding building with either normal force.
    #[test]
    fn mirror_symmetry(amp in 0.2f64..1.5, f in 1.0f64..6.0, phase in 0.0f64..std::f64::consts::TAU, mu in 0.2f64..1.0, dynamic in proptest::bool::ANY) {
        let normal = if dynamic { NormalForce::Dynamic } else { NormalForce::Constant };
        let model = on_building(block(), 4.0e3, mu, 0.8 * mu, normal);
        let settings = Settings { duration: 4.0, ..Settings::default() };
        let plus = GroundMotion::Harmonic(Harmonic::new(amp * G, f, 3.0, phase).unwrap());
        let minus = GroundMotion::Harmonic(Harmonic::new(-amp * G, f, 3.0, phase).unwrap());
        let a = run(&model, &plus, Initial::default(), &settings);
        let b = run(&model, &minus, Initial::default(), &settings);
        // The equations are odd in (a_g, θ, u): the runs mirror each other to rounding.
        let tol = 1e-9;
        prop_assert!((a.theta_range.0 + b.theta_range.1).abs() <= tol && (a.theta_range.1 + b.theta_range.0).abs() <= tol);
        prop_assert!((a.final_slip + b.final_slip).abs() <= tol * (1.0 + a.final_slip.abs()));
        prop_assert_eq!(a.impacts, b.impacts);
        prop_assert_eq!(a.overturned(), b.overturned());
    }

    /// Impacts never add energy: with no ground motion, the tower's energy at
    /// each impact is below that at the previous one, by the factor r² on the
    /// kinetic part.
    #[test]
    fn restitution_ratio_and_energy_loss_at_every_impact(fraction in 0.05f64..0.99, aspect in 2.0f64..8.0) {
        let tower = rocking::reference::solid_block(1.0, aspect);
        let (_, log) = run_logged(&fixed(tower), &GroundMotion::None, Initial { theta: fraction * tower.alpha(), theta_dot: 0.0 }, &Settings { duration: 10.0, ..Settings::default() });
        let mut last = f64::INFINITY;
        for e in log.events.iter().filter(|e| e.kind == EventKind::Impact) {
            prop_assert!((e.after.theta_dot - tower.restitution() * e.before.theta_dot).abs() <= 1e-15 * e.before.theta_dot.abs());
            let kinetic = e.before.theta_dot.powi(2);
            prop_assert!(kinetic < last);
            last = kinetic;
        }
    }
}
