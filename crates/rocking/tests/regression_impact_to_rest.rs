//! An impact whose law gives a `θ̇⁺` of the sign opposite to `θ̇⁻` ends at rest
//! (docs/src/model.md, "Impact on a building that can slide"): `θ̇⁺ = 0`, the
//! normal impulse `N_imp = −s m2 b θ̇⁻`, and the friction decision made again
//! with the horizontal momentum of both bodies.
//!
//! Before, such an impact turned the tower back about its new corner: `θ`
//! crossed zero again at once and the run repeated impacts at one instant
//! without end (the tower on its church with `restitution = 0` never finished,
//! its memory growing by the gigabyte).
#![allow(clippy::unwrap_used)]

mod common;
use common::{block, tight, G};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;
use rocking::{
    simulate, Building, BuildingRegime, Event, EventKind, EventLog, Flow, GroundMotion, Halt, Harmonic, Initial, MassInput, Model, NormalForce, Observer,
    Section, Settings, Summary, Tower, TowerGeometry, TowerRegime,
};

/// The test block (0.5 m × 2 m, 1000 kg) with restitution `r`.
fn block_with_restitution(r: f64) -> Tower {
    let b = block();
    Tower::from_properties(b.mass(), b.inertia_pivot(), b.radius(), b.alpha(), Some(r)).unwrap()
}

/// An event log that fails the run beyond `limit` events: a run that
/// repeats impacts at one instant fails the test instead of hanging it.
struct Bounded {
    log: EventLog,
    limit: usize,
}

impl Observer for Bounded {
    fn on_event(&mut self, event: &Event) -> Flow {
        if self.log.events.len() >= self.limit {
            return Flow::Break(Halt::Fail(format!("more than {} events (the last at t = {} s)", self.limit, event.time)));
        }
        self.log.on_event(event)
    }
}

fn run_bounded(model: &Model, ground: &GroundMotion, initial: Initial, settings: &Settings, limit: usize) -> (Summary, Vec<Event>) {
    let mut obs = Bounded {
        log: EventLog::default(),
        limit,
    };
    let summary = simulate(model, ground, initial, settings, &mut obs).unwrap();
    (summary, obs.log.events)
}

/// A frictionless building (`μs = μk = 0`, so `P = 0`) under a block released
/// from `θ0` with no ground motion. The law's ratio
/// `θ̇⁺/θ̇⁻ = (r I_O − m2² h²/M) / (I_O − m2² h²/M)` is negative for
/// `r < m2² h² / (M I_O)` (0.353 here, M = 2 m2): the impact ends at rest,
/// `u̇⁺ = u̇⁻ + m2 h θ̇⁻ / M`. The horizontal momentum `M u̇ + m2 R cos φ θ̇`
/// is zero from the start, so `u̇⁺ = 0`: everything stops at the first
/// impact. The centre of mass of the two bodies has not moved, which puts the
/// building at `u = (m2/M) s (b − R sin(α − s θ0))`; and energy gives
/// `θ̇⁻² (I_O − m2² h²/M) = 2 m2 g R (cos(α − θ0) − cos α)`.
#[test]
fn frictionless_building_stops_with_the_tower() {
    let r = 0.2;
    let tower = block_with_restitution(r);
    let (m2, inertia, radius, alpha) = (tower.mass(), tower.inertia_pivot(), tower.radius(), tower.alpha());
    let (b, h) = (radius * alpha.sin(), radius * alpha.cos());
    let total = 2.0 * m2;
    assert!(r * inertia - m2 * m2 * h * h / total < 0.0, "the law's ratio must be negative here");
    let model = Model::new(Some(tower), Some(Building::new(m2, 0.0, 0.0, NormalForce::Constant).unwrap()), G).unwrap();
    for theta0 in [0.6 * alpha, -0.3 * alpha] {
        let (summary, events) = run_bounded(&model, &GroundMotion::None, Initial { theta: theta0, theta_dot: 0.0 }, &tight(3.0), 100);
        assert_eq!(summary.impacts, 1, "θ0 = {theta0}: {events:?}");
        let impact = events.iter().find(|e| e.kind == EventKind::Impact).unwrap();
        let s = theta0.signum();
        let approach = -s * (2.0 * m2 * G * radius * ((alpha - theta0.abs()).cos() - alpha.cos()) / (inertia - m2 * m2 * h * h / total)).sqrt();
        // The run is integrated to rtol 1e-11: θ̇⁻ to 1e-9 of itself is
        // a hundred times the integrator's tolerance.
        assert!(
            (impact.before.theta_dot - approach).abs() <= 1e-9 * approach.abs(),
            "θ̇⁻ {} against {approach}",
            impact.before.theta_dot
        );
        // The momentum balance before it, to the same relative accuracy.
        assert!((total * impact.before.slip_vel + m2 * h * impact.before.theta_dot).abs() <= 1e-9 * m2 * h * approach.abs());
        assert_eq!(impact.after.theta_dot.to_bits(), 0.0f64.to_bits());
        assert_eq!(impact.after.slip_vel.to_bits(), 0.0f64.to_bits());
        let slip = m2 / total * s * (b - radius * (alpha - theta0.abs()).sin());
        // Slip of millimetres from an integration to rtol 1e-11: 1e-9 relative.
        assert!(
            (summary.final_slip - slip).abs() <= 1e-9 * slip.abs(),
            "final slip {} against {slip}",
            summary.final_slip
        );
        assert!((impact.before.slip - slip).abs() <= 1e-9 * slip.abs());
        let last = events.last().unwrap();
        assert_eq!(last.kind, EventKind::Rest);
        assert_eq!(last.regime.tower, TowerRegime::Rest);
    }
}

/// A rough building at rest under the same block (`r = 0.1`, `μs = μk = 0.2`,
/// `M = 4 m2`; the finite stick demand of the rocking block stays below a
/// quarter of `μs M g`, so the building is stuck until the impact). Sticking
/// through the impact would need `μs >= (1 − r) / ((1 + r) tan α)` = 3.3;
/// sliding, the law gives `θ̇⁺/θ̇⁻ = (r I_O M − m2² h (h − μk b)) / det`,
/// negative here. So the impact ends at rest: with `u̇⁻ = 0` the impulse that
/// sticking needs is `P = −m2 h θ̇⁻`, beyond `μs N_imp = μs m2 b |θ̇⁻|`
/// (`h/b = 4 > μs`), and the building slides with `P = −μk σ N_imp`:
/// `u̇⁺ = m2 (h − μk b) θ̇⁻ / M`, `σ = sgn θ̇⁻`. The tower stands (a building
/// sliding at `μk g < g tan α` cannot lift it) and the complex slides as one
/// body, `ü = −μk σ g`, until it stops: a final slip of `u̇⁺ |u̇⁺| / (2 μk g)`.
#[test]
fn rough_building_slides_off_the_impact_and_stops() {
    let r = 0.1;
    let tower = block_with_restitution(r);
    let (m2, inertia, radius, alpha) = (tower.mass(), tower.inertia_pivot(), tower.radius(), tower.alpha());
    let (b, h) = (radius * alpha.sin(), radius * alpha.cos());
    let (mu, total) = (0.2, 4.0 * m2);
    assert!(mu < (1.0 - r) / ((1.0 + r) * alpha.tan()) && mu < alpha.tan());
    assert!(
        r * inertia * total - m2 * m2 * h * (h - mu * b) < 0.0,
        "the sliding law's θ̇⁺ must change sign here"
    );
    for normal in [NormalForce::Constant, NormalForce::Dynamic] {
        let model = Model::new(Some(tower), Some(Building::new(total - m2, mu, mu, normal).unwrap()), G).unwrap();
        let (summary, events) = run_bounded(
            &model,
            &GroundMotion::None,
            Initial {
                theta: 0.6 * alpha,
                theta_dot: 0.0,
            },
            &tight(4.0),
            100,
        );
        let kinds: Vec<EventKind> = events.iter().map(|e| e.kind).collect();
        assert_eq!(kinds, [EventKind::Impact, EventKind::Slip, EventKind::Rest, EventKind::Stick], "{normal:?}");
        let impact = events[0];
        assert_eq!(impact.before.slip_vel.to_bits(), 0.0f64.to_bits());
        assert_eq!(impact.after.theta_dot.to_bits(), 0.0f64.to_bits());
        let slip_vel = m2 * (h - mu * b) * impact.before.theta_dot / total;
        // Three products and a quotient of the event's own θ̇⁻: a few ulps.
        assert!(
            (impact.after.slip_vel - slip_vel).abs() <= 1e-14 * slip_vel.abs(),
            "{normal:?}: u̇⁺ {} against {slip_vel}",
            impact.after.slip_vel
        );
        assert_eq!(impact.regime.building, BuildingRegime::Slip(rocking::SlipDirection::Negative));
        assert!(impact.before.theta_dot < 0.0);
        // The slide is integrated to rtol 1e-11 (and its stop located on the
        // dense output): 1e-9 of the slip.
        let slide = slip_vel * slip_vel.abs() / (2.0 * mu * G);
        assert!(
            (summary.final_slip - slide).abs() <= 1e-9 * slide.abs(),
            "{normal:?}: final slip {} against {slide}",
            summary.final_slip
        );
        assert_eq!(summary.impacts, 1);
    }
}

/// The tower on its church (4 m × 12 m, 150 t, on 2,000 t with μs = 1.25,
/// μk = 1) with `restitution = 0` under 1.5 g at 5 Hz for 10 s: every impact
/// ends at rest, and on a sliding church decelerating at `μk g > g tan α` the
/// tower lifts again at once. The run ends, no two impacts share an instant,
/// and no impact leaves the tower turning back (`θ̇⁺ θ̇⁻ >= 0`).
#[test]
fn tower_on_church_without_restitution_finishes() {
    let tower = Tower::from_geometry(&TowerGeometry {
        width: 4.0,
        height: 12.0,
        depth: None,
        section: Section::Solid,
        mass: MassInput::Mass(1.5e5),
        inertia_pivot: None,
        restitution: Some(0.0),
    })
    .unwrap();
    let model = Model::new(Some(tower), Some(Building::new(2.0e6, 1.25, 1.0, NormalForce::Constant).unwrap()), G).unwrap();
    let ground = GroundMotion::Harmonic(Harmonic::new(1.5 * G, 5.0, 10.0, 0.0).unwrap());
    let settings = Settings {
        duration: 15.0,
        ..Settings::default()
    };
    let (summary, events) = run_bounded(&model, &ground, Initial::default(), &settings, 100_000);
    assert_eq!(summary.end_time.to_bits(), 15.0f64.to_bits());
    let impacts: Vec<&Event> = events.iter().filter(|e| e.kind == EventKind::Impact).collect();
    assert!(impacts.len() > 10, "{} impacts", impacts.len());
    for pair in impacts.windows(2) {
        assert!(pair[1].time > pair[0].time, "two impacts at t = {}", pair[0].time);
    }
    for e in &impacts {
        assert!(e.after.theta_dot * e.before.theta_dot >= 0.0, "t = {}: {e:?}", e.time);
    }
}

/// `½ M u̇² + m2 h θ̇ u̇ + ½ I_O θ̇²`, the kinetic energy of both bodies at `θ = 0`.
fn kinetic(tower: &Tower, total: f64, state: rocking::State) -> f64 {
    let m2h = tower.mass() * tower.radius() * tower.alpha().cos();
    0.5 * total * state.slip_vel.powi(2) + m2h * state.theta_dot * state.slip_vel + 0.5 * tower.inertia_pivot() * state.theta_dot.powi(2)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, rng_seed: RngSeed::Fixed(0x7e57), ..ProptestConfig::default() })]

    /// Low restitutions on buildings of any friction and mass under a
    /// harmonic that rocks the tower and may slide the building: every run
    /// ends, no two impacts share an instant, no impact turns the tower back,
    /// and none adds kinetic energy (to the rounding of the sums, 1e-12).
    #[test]
    fn low_restitution_runs_end_without_repeated_impacts(
        r in 0.0f64..0.5,
        ratio in 1.0f64..20.0,
        mu_s in 0.0f64..1.5,
        kinetic_fraction in 0.0f64..=1.0,
        amplitude in 0.3f64..1.5,
        frequency in 1.0f64..5.0,
    ) {
        let tower = block_with_restitution(r);
        let total = (1.0 + ratio) * tower.mass();
        let building = Building::new(ratio * tower.mass(), mu_s, kinetic_fraction * mu_s, NormalForce::Constant).unwrap();
        let model = Model::new(Some(tower), Some(building), G).unwrap();
        let ground = GroundMotion::Harmonic(Harmonic::new(amplitude * G, frequency, 2.0, 0.0).unwrap());
        let settings = Settings { duration: 4.0, ..Settings::default() };
        let (_, events) = run_bounded(&model, &ground, Initial::default(), &settings, 100_000);
        let impacts: Vec<&Event> = events.iter().filter(|e| e.kind == EventKind::Impact).collect();
        for pair in impacts.windows(2) {
            prop_assert!(pair[1].time > pair[0].time, "two impacts at t = {}", pair[0].time);
        }
        for e in impacts {
            prop_assert!(e.after.theta_dot * e.before.theta_dot >= 0.0, "t = {}: {:?}", e.time, e);
            let (before, after) = (kinetic(&tower, total, e.before), kinetic(&tower, total, e.after));
            prop_assert!(after <= before * (1.0 + 1e-12), "t = {}: {} > {}", e.time, after, before);
        }
    }
}
