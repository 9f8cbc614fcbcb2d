//! The end of an impact cascade in closed form (`cascade.rs`): once no ground
//! motion is left, small free flights are jumped by energy conservation and
//! the free-rocking quadrature instead of being integrated. Checked against
//! integration of the same motion at a tolerance 1e5 times tighter, which a
//! never-ending input of 1e-300 m/s² forces: it changes no bit of any
//! right-hand side (it is 1e-290 times the smallest acceleration in play), but
//! the input is never over, so the closed form never applies.

#![allow(clippy::unwrap_used)]

mod common;

use common::*;
use proptest::prelude::*;
use proptest::test_runner::RngSeed;
use rocking::{reference::solid_block, simulate, EventKind, EventLog, GroundMotion, Harmonic, Initial, Model, NormalForce, Ricker, Settings, Summary};

/// An input that never ends and moves nothing.
fn never_over(duration: f64) -> GroundMotion {
    GroundMotion::Harmonic(Harmonic::new(1e-300, 1.0, 2.0 * duration, 0.0).unwrap())
}

fn settings(duration: f64, rtol: f64) -> Settings {
    Settings {
        duration,
        rtol,
        atol: 1e-2 * rtol,
    }
}

fn logged(model: &Model, ground: &GroundMotion, initial: Initial, settings: &Settings) -> (Summary, EventLog) {
    let mut log = EventLog::default();
    let s = simulate(model, ground, initial, settings, &mut log).unwrap();
    (s, log)
}

fn rest_time(log: &EventLog) -> f64 {
    log.events.iter().find(|e| e.kind == EventKind::Rest).map(|e| e.time).expect("comes to rest")
}

/// The two runs took the same path: every event and the summary the same to the bit.
fn same_bits(a: &(Summary, EventLog), b: &(Summary, EventLog)) -> bool {
    a.1.events == b.1.events && a.0.evaluations == b.0.evaluations && a.0.impacts == b.0.impacts
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, rng_seed: RngSeed::Fixed(0x0ca5_cade), ..ProptestConfig::default() })]

    /// Random solid blocks released from random angles: the closed-form
    /// cascade gives the reference's impact count and peaks (to 10 rtol), and
    /// its time of rest as closely as integrating the cascade at the same
    /// tolerance does (within twice that error, or 10 rtol of the run's
    /// length). The flights before the closed form applies are integrated and
    /// keep their error: it grows as the speeds shrink towards atol (1.6e-6
    /// relative for a block of slenderness 7 at rtol 1e-8, where the closed
    /// form halves it). The count is exact because the last speeds would have
    /// to fall within that error of the rest threshold to change it.
    #[test]
    fn closed_form_cascade_matches_integration(
        width in 0.2f64..2.0,
        slenderness in 2.5f64..8.0,
        fraction in 0.05f64..0.9,
    ) {
        let tower = solid_block(width, slenderness * width);
        let model = fixed(tower);
        let initial = Initial { theta: fraction * tower.alpha(), theta_dot: 0.0 };
        // Long enough for every block drawn to come to rest (`rest_time` fails
        // otherwise): a 1.3 m × 9.9 m block released at 0.6 α still rocks at 60 s.
        let duration = 120.0;
        let rtol = 1e-8;
        let (reference, reference_log) = logged(&model, &never_over(duration), initial, &settings(duration, 1e-13));
        let (fast, fast_log) = logged(&model, &GroundMotion::None, initial, &settings(duration, rtol));
        let (integrated, integrated_log) = logged(&model, &never_over(duration), initial, &settings(duration, rtol));
        // The closed form was used: the cascade costs no evaluations.
        prop_assert!(fast.evaluations < integrated.evaluations, "{} against {}", fast.evaluations, integrated.evaluations);
        prop_assert_eq!(fast.impacts, reference.impacts);
        let (t_fast, t_reference) = (rest_time(&fast_log), rest_time(&reference_log));
        let integration_error = (rest_time(&integrated_log) - t_reference).abs();
        prop_assert!(
            (t_fast - t_reference).abs() <= (2.0 * integration_error).max(10.0 * rtol * t_reference),
            "rest at {t_fast} s against {t_reference} s (integration: {integration_error:e} s off)"
        );
        for (got, exact) in [
            (fast.max_abs_theta(), reference.max_abs_theta()),
            (fast.max_top_abs_acceleration, reference.max_top_abs_acceleration),
            (fast.max_pivot_friction_demand, reference.max_pivot_friction_demand),
        ] {
            prop_assert!((got - exact).abs() <= 10.0 * rtol * exact, "{got} against {exact}");
        }
        // Every impact of the cascade: θ̇ leaves as r times what arrived, to rounding.
        for e in fast_log.events.iter().filter(|e| e.kind == EventKind::Impact) {
            prop_assert!((e.after.theta_dot - tower.restitution() * e.before.theta_dot).abs() <= 1e-15 * e.before.theta_dot.abs());
        }
    }
}

/// Started inside the cascade (θ = 0, θ̇ = 1e-3 rad/s: every flight is
/// jumped), against the reference integrated at rtol 1e-13:
/// - the largest rotation is the first flight's apex, from Newton on the
///   energy: equal to a few ulps (1.7e-15 relative measured; bound 1e-14);
/// - the top acceleration and the pivot demand, read at the impacts and the
///   apexes, equal to the reference's (identical bits measured; bound 1e-14);
/// - the time of rest, the sum of about a hundred flight times, to 1e-10 s
///   (3.7e-12 s measured: the reference's own error over those flights).
#[test]
fn peaks_of_a_cascade_in_closed_form() {
    let tower = block();
    let initial = Initial { theta: 0.0, theta_dot: 1e-3 };
    let duration = 5.0;
    let (fast, fast_log) = logged(&fixed(tower), &GroundMotion::None, initial, &settings(duration, 1e-8));
    let (reference, reference_log) = logged(&fixed(tower), &never_over(duration), initial, &settings(duration, 1e-13));
    assert!(fast.evaluations < 20, "jumped whole: {} evaluations", fast.evaluations);
    assert_eq!(fast.impacts, reference.impacts);
    for (name, got, exact) in [
        ("max |θ|", fast.max_abs_theta(), reference.max_abs_theta()),
        ("top acceleration", fast.max_top_abs_acceleration, reference.max_top_abs_acceleration),
        ("pivot demand", fast.max_pivot_friction_demand, reference.max_pivot_friction_demand),
    ] {
        assert!((got / exact - 1.0).abs() < 1e-14, "{name}: {got} against {exact}");
    }
    let (t_fast, t_reference) = (rest_time(&fast_log), rest_time(&reference_log));
    assert!((t_fast - t_reference).abs() < 1e-10, "rest at {t_fast} s against {t_reference} s");
}

/// The block of the benchmark released from half its slenderness, 40 s (it
/// rests after 7.94 s), at the default rtol: (tower, initial state, duration, rtol).
fn benchmark_block_released() -> (rocking::Tower, Initial, f64, f64) {
    let tower = block();
    let initial = Initial {
        theta: 0.5 * tower.alpha(),
        theta_dot: 0.0,
    };
    (tower, initial, 40.0, 1e-8)
}

/// On a building that stays stuck (μs = 0.8, heavy) the flights are jumped too,
/// with both normal-force laws, and the cascade ends as on a fixed base: the
/// same impacts and the same time of rest to 10 rtol of the run's length.
#[test]
fn jumped_on_a_stuck_building() {
    let (tower, initial, duration, rtol) = benchmark_block_released();
    let (reference, reference_log) = logged(&fixed(tower), &never_over(duration), initial, &settings(duration, 1e-13));
    for normal in [NormalForce::Constant, NormalForce::Dynamic] {
        let model = on_building(tower, 20.0 * tower.mass(), 0.8, 0.7, normal);
        let (fast, fast_log) = logged(&model, &GroundMotion::None, initial, &settings(duration, rtol));
        let (integrated, _) = logged(&model, &never_over(duration), initial, &settings(duration, rtol));
        assert!(
            fast.evaluations < integrated.evaluations,
            "{normal:?}: {} against {}",
            fast.evaluations,
            integrated.evaluations
        );
        assert!(fast.max_abs_slip == 0.0, "{normal:?}: the building never slips");
        assert_eq!(fast.impacts, reference.impacts, "{normal:?}");
        let (t_fast, t_reference) = (rest_time(&fast_log), rest_time(&reference_log));
        assert!(
            (t_fast - t_reference).abs() <= 10.0 * rtol * t_reference,
            "{normal:?}: rest at {t_fast} s against {t_reference} s"
        );
    }
}

/// Where it does not apply, the run is integrated: bit-identical to the run
/// whose input never ends.
#[test]
fn not_used_where_it_does_not_apply() {
    let (tower, initial, duration, rtol) = benchmark_block_released();
    let both = |model: &Model, duration: f64| {
        (
            logged(model, &GroundMotion::None, initial, &settings(duration, rtol)),
            logged(model, &never_over(duration), initial, &settings(duration, rtol)),
        )
    };
    // Control: on a fixed base it applies, and the paths differ.
    let (fast, integrated) = both(&fixed(tower), duration);
    assert!(!same_bits(&fast, &integrated));
    // A building that slides while the tower rocks (as light as the tower, μ = 0.05).
    let (fast, integrated) = both(&on_building(tower, tower.mass(), 0.05, 0.05, NormalForce::Dynamic), duration);
    assert!(fast.0.max_abs_slip > 0.0);
    assert!(same_bits(&fast, &integrated));
    // The run ends inside the cascade (at rest from 7.94 s for this release;
    // 7.9 s cuts a flight): the flights before the cut are jumped, the one
    // that the end cuts is integrated, and the impacts are those of the
    // reference cut at the same instant.
    let (fast, _) = logged(&fixed(tower), &GroundMotion::None, initial, &settings(7.9, rtol));
    let (reference, _) = logged(&fixed(tower), &never_over(7.9), initial, &settings(7.9, 1e-13));
    assert_eq!(fast.impacts, reference.impacts);
    assert_eq!(fast.end_time.to_bits(), 7.9f64.to_bits());
    // A ground motion still to come (a Ricker pulse at 30 s): nothing is jumped
    // before it. Its values underflow to zero until about 22 s, so the events up
    // to the rest agree to the bit with the never-ending input's.
    let ricker = GroundMotion::Ricker(Ricker::new(0.3 * G, 1.0, Some(30.0)).unwrap());
    let (_, later) = logged(&fixed(tower), &ricker, initial, &settings(duration, rtol));
    let rest = |log: &EventLog| log.events.iter().position(|e| e.kind == EventKind::Rest).expect("rest");
    let (_, integrated_log) = logged(&fixed(tower), &never_over(duration), initial, &settings(duration, rtol));
    assert_eq!(later.events[..=rest(&later)], integrated_log.events[..=rest(&integrated_log)]);
}
