//! A stack on a building without friction (μs = μk = 0) never ended: at rest
//! with no ground motion, or under a harmonic that starts from zero, the
//! friction the stuck building needs is zero at t = 0, and so is μs N. The
//! stack's search took a slip condition on zero that does not leave it as a
//! slip at once, on the side of the demand's sign (+x for a demand of
//! exactly 0); the slip stopped at the same instant, the building stuck, and
//! the run went round slip and stick at t = 0 without end (found by the `run`
//! fuzz target). A condition that stays on zero has not grown, and a slip
//! that starts on a zero demand starts against the demand's growth, as the
//! tower's does.
//!
//! Without friction the foundation carries no horizontal force: the building
//! stays still in absolute terms whatever the ground does, the blocks on it
//! feel no acceleration and never lift, and its slip relative to the ground
//! is minus the ground's displacement from rest.

use rocking::stack::Block;
use rocking::{
    simulate, Building, Event, Flow, GroundMotion, Halt, Harmonic, Initial, MassInput, Model, NormalForce, Observer, Section, Settings, Summary, Tower,
    TowerGeometry,
};

/// Stops a run past 1000 events: the runs here have at most a few, and a
/// run that goes round its regimes at one instant ends with an error rather
/// than never.
struct Bounded(usize);

impl Observer for Bounded {
    fn on_event(&mut self, _event: &Event) -> Flow {
        self.0 += 1;
        if self.0 > 1000 {
            return Flow::Break(Halt::Stop);
        }
        Flow::Continue(())
    }
}

const G: f64 = 9.81;

/// The shaft and belfry of examples/belfry-on-church.toml (as solid blocks)
/// on a church of 2,000 t without friction, run for 1 s.
fn run(ground: &GroundMotion) -> Summary {
    let shaft = Tower::from_geometry(&TowerGeometry {
        width: 4.0,
        height: 12.0,
        depth: None,
        section: Section::Solid,
        mass: MassInput::Mass(1.5e5),
        inertia_pivot: None,
        restitution: None,
    })
    .expect("a valid shaft");
    let belfry = Block::solid(2, 3.2, 4.5, 3.0e4).expect("a valid belfry");
    let church = Building::new(2.0e6, 0.0, 0.0, NormalForce::Constant).expect("a valid building");
    let model = Model::new(Some(shaft), Some(church), G)
        .and_then(|m| m.with_blocks(&[belfry]))
        .expect("a valid model");
    let settings = Settings {
        duration: 1.0,
        ..Settings::default()
    };
    let summary = simulate(&model, ground, Initial::default(), &settings, &mut Bounded(0)).unwrap_or_else(|e| panic!("{e}"));
    assert!((summary.end_time - 1.0).abs() < 1e-12, "ended at {}", summary.end_time);
    summary
}

#[test]
fn a_stack_at_rest_on_a_building_without_friction_stays_at_rest() {
    let summary = run(&GroundMotion::None);
    // Nothing drives it: no event, no slip, no rotation (exact zeros).
    assert_eq!(summary.events, 0);
    assert_eq!(summary.first_slip_time, None);
    assert!(summary.max_abs_slip == 0.0 && summary.max_abs_theta() == 0.0, "{summary:?}");
}

#[test]
fn a_building_without_friction_slips_back_by_the_grounds_displacement() {
    // a_g = A sin(ω t) from t = 0: the demand starts from zero, growing
    // towards +x, so the slip starts at once towards −x.
    let (amplitude, frequency) = (0.3 * G, 2.0);
    let summary = run(&GroundMotion::Harmonic(Harmonic::new(amplitude, frequency, 1.0, 0.0).expect("a valid input")));
    assert_eq!(summary.first_slip_time, Some(0.0));
    // The ground's displacement from rest, A (t/ω − sin(ω t)/ω²), at t = 1 s
    // (ω t = 4π: sin = 0 to rounding): the slip is minus it, −0.234196 m. The
    // integrator's tolerance (rtol 1e-8 per step, some 100 steps) leaves
    // about 1e-9 of it; 1e-8 relative bounds that with a margin.
    let omega = std::f64::consts::TAU * frequency;
    let expected = -amplitude * (1.0 / omega - (omega * 1.0).sin() / (omega * omega));
    assert!(
        (summary.final_slip - expected).abs() <= 1e-8 * expected.abs(),
        "{} vs {expected}",
        summary.final_slip
    );
    // The building carries no horizontal force: the tower and the belfry never lift.
    assert_eq!(summary.first_uplift_time, None);
    let stack = summary.stack.expect("a stacked run");
    assert!(
        stack.blocks()[0].first_uplift_time.is_none() && stack.blocks()[0].max_abs_theta == 0.0,
        "{stack:?}"
    );
}
