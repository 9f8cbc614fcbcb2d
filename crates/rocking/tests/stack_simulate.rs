//! A stacked model through the library's entry points ([`simulate`] with
//! [`Model::with_blocks`]): the samples, events and summary it reports against
//! the engine's run of an equivalent single tower, and against what the run
//! itself must satisfy (counts read off the events, the samples of the history).

use rocking::stack::Block;
use rocking::{
    simulate, Building, EventKind, EventLog, GroundMotion, Harmonic, History, Initial, Model, NormalForce, Parameter, Section, Settings, Tower, TowerGeometry,
};

const G: f64 = 9.81;

/// The shaft of the stack tests, 4 m × 20 m, 3.2e5 kg, solid, with `restitution` if given.
fn shaft_with(restitution: Option<f64>) -> Tower {
    Tower::from_geometry(&TowerGeometry {
        width: 4.0,
        height: 20.0,
        depth: None,
        section: Section::Solid,
        mass: rocking::MassInput::Mass(3.2e5),
        inertia_pivot: None,
        restitution,
    })
    .expect("a valid shaft")
}

fn shaft() -> Tower {
    shaft_with(None)
}

/// The displacement of the shaft's top centre `(0, 20)` (m) when the tower
/// leans by `theta` on its corner `(2 sgn θ, 0)`: `s b (1 − cos θ) + y sin θ`.
fn shaft_top(theta: f64) -> f64 {
    2.0 * theta.signum() * (1.0 - theta.cos()) + 20.0 * theta.sin()
}

fn settings(duration: f64) -> Settings {
    Settings {
        duration,
        rtol: 1e-11,
        atol: 1e-13,
    }
}

/// A cap 4 m wide and 1 m high on the 4 m × 20 m shaft cannot rock on it
/// under 0.3 g (its uplift needs far more), so the stack moves as one block
/// of the combined shape, computed by hand:
///
/// ```text
/// m = 3.2e5 + 4e4 = 3.6e5 kg,  y_G = (3.2e5 · 10 + 4e4 · 20.5) / m
/// I_O = 3.2e5 (16 + 400)/12 + 3.2e5 (4 + 100) + 4e4 (16 + 1)/12 + 4e4 (4 + 420.25)
/// R = sqrt(2² + y_G²),  α = atan(2 / y_G)
/// ```
///
/// Through `simulate`, the stacked model's history (θ, slip) and its impacts
/// equal the engine's for that tower, on a fixed base and on a sliding
/// building, and its top is the shaft's, 20 m up, moved by that θ; the cap
/// has no event of its own.
#[test]
fn a_cap_that_cannot_rock_runs_as_one_block_through_simulate() {
    let cap = Block::solid(2, 4.0, 1.0, 4.0e4).expect("a valid cap");
    let m = 3.6e5;
    let y_g = (3.2e5 * 10.0 + 4.0e4 * 20.5) / m;
    let inertia = 3.2e5 * 416.0 / 12.0 + 3.2e5 * 104.0 + 4.0e4 * 17.0 / 12.0 + 4.0e4 * 424.25;
    let combined = Tower::from_properties(m, inertia, 2.0f64.hypot(y_g), (2.0 / y_g).atan(), None).expect("a valid tower");
    let input = GroundMotion::Harmonic(Harmonic::new(0.3 * G, 1.0, 3.0, 0.0).expect("a valid input"));
    for building in [None, Some(Building::new(8.0e5, 0.35, 0.3, NormalForce::Constant).expect("a valid building"))] {
        let stacked = Model::new(Some(shaft()), building, G)
            .and_then(|m| m.with_blocks(&[cap]))
            .expect("a valid stack");
        let single = Model::new(Some(combined), building, G).expect("a valid model");
        let go = |model: &Model| {
            let mut observer = (History::new(0.01, vec![]), EventLog::default());
            let summary = simulate(model, &input, Initial::default(), &settings(5.0), &mut observer).expect("the run");
            (summary, observer.0, observer.1)
        };
        let (s_stack, h_stack, e_stack) = go(&stacked);
        let (s_one, h_one, _) = go(&single);
        assert!(s_one.impacts >= 2, "{} impacts", s_one.impacts);
        assert_eq!(s_stack.impacts, s_one.impacts);
        assert!(e_stack.events.iter().all(|e| e.block == 0), "the cap had an event");
        let blocks = s_stack.stack.expect("a stack's summary");
        assert_eq!(blocks.blocks().len(), 1);
        assert!(blocks.blocks()[0].first_uplift_time.is_none());
        assert_eq!(h_stack.samples.len(), h_one.samples.len());
        for (a, b) in h_stack.samples.iter().zip(&h_one.samples) {
            // Two integrations to rtol 1e-11 with events located to ~1e-15 s
            // agree to 1e-7 rad after a few impacts (the angles are 1e-2); the
            // top's displacement is H θ to first order, 20 m × 1e-7.
            assert!(
                (a.state.theta - b.state.theta).abs() < 1e-7,
                "t = {}: {} vs {}",
                a.t,
                a.state.theta,
                b.state.theta
            );
            assert!(
                (a.state.slip - b.state.slip).abs() < 1e-7,
                "t = {}: u {} vs {}",
                a.t,
                a.state.slip,
                b.state.slip
            );
            let top = shaft_top(b.state.theta);
            assert!((a.top_dx - top).abs() < 2e-6, "t = {}: top {} vs {top}", a.t, a.top_dx);
            let stack = a.stack.expect("every interface's state");
            assert_eq!(stack.theta[0].to_bits(), a.state.theta.to_bits());
            assert_eq!(stack.theta[1].to_bits(), 0.0f64.to_bits(), "the cap rocked");
            assert!(b.stack.is_none());
        }
        // The peaks are located on different integrations of the same motion
        // (the engine's and the stack's steps), θ's both by root finding: to
        // the 1e-7 rad of the histories.
        assert!((s_stack.max_abs_theta() - s_one.max_abs_theta()).abs() < 1e-7);
        let top = shaft_top(s_one.theta_range.0).abs().max(shaft_top(s_one.theta_range.1).abs());
        assert!((s_stack.max_top_displacement - top).abs() < 2e-6);
    }
}

/// A belfry that rocks on a rocking shaft: the summary's counts are those of
/// the events (each event once, the tower's impacts and the belfry's apart),
/// the first uplifts are the first uplift events of each, and the history's
/// belfry angle never exceeds the peak the summary located.
#[test]
fn a_rocking_belfry_reports_its_own_events_and_peaks() {
    let belfry = Block::solid(2, 3.0, 6.0, 4.0e4).expect("a valid belfry");
    let model = Model::new(Some(shaft()), None, G)
        .and_then(|m| m.with_blocks(&[belfry]))
        .expect("a valid stack");
    let input = GroundMotion::Harmonic(Harmonic::new(0.45 * G, 1.5, 3.0, 0.0).expect("a valid input"));
    let mut observer = (History::new(0.005, vec![]), EventLog::default());
    let summary = simulate(&model, &input, Initial::default(), &settings(6.0), &mut observer).expect("the run");
    let (history, log) = observer;
    let blocks = summary.stack.expect("a stack's summary");
    let count = |block: usize, kind: EventKind| log.events.iter().filter(|e| e.block == block && e.kind == kind).count() as u64;
    let first = |block: usize| log.events.iter().find(|e| e.block == block && e.kind == EventKind::Uplift).map(|e| e.time);
    assert_eq!(summary.events, log.events.len() as u64);
    assert_eq!(summary.impacts, count(0, EventKind::Impact));
    assert!(count(1, EventKind::Impact) > 0, "the belfry did not rock");
    assert_eq!(blocks.blocks()[0].impacts as u64, count(1, EventKind::Impact));
    assert_eq!(summary.first_uplift_time, first(0));
    assert_eq!(blocks.blocks()[0].first_uplift_time, first(1));
    let sampled = history.samples.iter().map(|s| s.stack.expect("the stack").theta[1].abs()).fold(0.0, f64::max);
    assert!(
        sampled > 0.0 && sampled <= blocks.blocks()[0].max_abs_theta,
        "{sampled} > {}",
        blocks.blocks()[0].max_abs_theta
    );
    let tower_sampled = history.samples.iter().map(|s| s.state.theta.abs()).fold(0.0, f64::max);
    assert!(tower_sampled <= summary.max_abs_theta());
    // An event of the belfry holds the belfry's angle: 0 at its impacts.
    for e in log.events.iter().filter(|e| e.block == 1 && e.kind == EventKind::Impact) {
        assert_eq!(e.after.theta.to_bits(), 0.0f64.to_bits());
    }
    assert!(blocks.max_seat_impulse_ratio.is_finite());
}

/// The model's own errors: a block wider than the one below, a restitution
/// given to a tower that carries blocks.
#[test]
fn a_stack_the_model_refuses() {
    let wide = Block::solid(2, 4.5, 6.0, 4.0e4).expect("a valid block");
    let err = Model::new(Some(shaft()), None, G)
        .and_then(|m| m.with_blocks(&[wide]))
        .expect_err("wider than the tower");
    assert!(
        matches!(&err, rocking::Error::InvalidParameter { parameter: Parameter::Blocks, reason } if reason.contains("wider than the 4 m of the tower")),
        "{err}"
    );
    let given = shaft_with(Some(0.8));
    let narrow = Block::solid(2, 3.0, 6.0, 4.0e4).expect("a valid block");
    let err = Model::new(Some(given), None, G)
        .and_then(|m| m.with_blocks(&[narrow]))
        .expect_err("a restitution with blocks");
    assert!(
        matches!(
            err,
            rocking::Error::InvalidParameter {
                parameter: Parameter::TowerRestitution,
                ..
            }
        ),
        "{err}"
    );
}
