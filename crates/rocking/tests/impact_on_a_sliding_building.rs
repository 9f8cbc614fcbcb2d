//! The impact law on a building that can slide (docs/src/model.md, "Impact on a
//! building that can slide"), against its closed forms.
//!
//! Before it, an impact kept `u̇` continuous and `θ̇⁺ = r θ̇⁻`, which creates
//! horizontal momentum whenever the building is free to move. Now the tower's
//! angular momentum about the new corner and the horizontal momentum of both
//! bodies balance the foundation's friction impulse, bounded by Coulomb's law
//! with the normal impulse `N_imp = −s m2 b (θ̇⁺ + θ̇⁻)`.
#![allow(clippy::unwrap_used)]

mod common;
use common::{block, on_building, run_logged, tight, G};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;
use rocking::{EventKind, GroundMotion, Initial, NormalForce};

/// Free rocking from 0.6 α on a building 100 times heavier than the tower
/// (its finite stick demand stays below 0.01 μs-units before the first impact,
/// far from the impact's threshold of 0.18): the events at the first impact.
fn first_impact(mu_s: f64, normal: NormalForce) -> Vec<(EventKind, rocking::Event)> {
    let tower = block();
    let model = on_building(tower, 100.0 * tower.mass(), mu_s, mu_s, normal);
    let initial = Initial {
        theta: 0.6 * tower.alpha(),
        theta_dot: 0.0,
    };
    let (_, log) = run_logged(&model, &GroundMotion::None, initial, &tight(1.5));
    let impact = log.events.iter().find(|e| e.kind == EventKind::Impact).unwrap();
    log.events
        .iter()
        .filter(|e| e.time.to_bits() == impact.time.to_bits())
        .map(|e| (e.kind, *e))
        .collect()
}

/// A building at rest stays stuck through the impact if and only if
/// `μs ≥ (1 − r) / ((1 + r) tan α)`: 0.1% above, Housner's `θ̇⁺ = r θ̇⁻` with
/// `u̇⁺ = 0`; 0.1% below, it slides from the impact on (a slip event at the
/// same instant), for both normal-force laws (the law bounds impulses, not
/// forces, so it is the same for both).
#[test]
fn stick_through_the_impact_exactly_above_the_threshold() {
    let tower = block();
    let r = tower.restitution();
    let threshold = (1.0 - r) / ((1.0 + r) * tower.alpha().tan());
    for normal in [NormalForce::Constant, NormalForce::Dynamic] {
        let above = first_impact(threshold * 1.001, normal);
        assert_eq!(above.len(), 1, "{normal:?}: {above:?}");
        let e = above[0].1;
        assert!((e.after.theta_dot - r * e.before.theta_dot).abs() <= 1e-15 * e.before.theta_dot.abs());
        assert_eq!(e.after.slip_vel.to_bits(), 0.0f64.to_bits());

        let below = first_impact(threshold * 0.999, normal);
        let kinds: Vec<EventKind> = below.iter().map(|(k, _)| *k).collect();
        assert_eq!(kinds, [EventKind::Impact, EventKind::Slip], "{normal:?}");
        let e = below[0].1;
        assert!(e.after.slip_vel.abs() > 0.0);
        // Sliding, the impulse is μk N_imp: the tower keeps less than Housner's r.
        assert!(e.after.theta_dot.abs() < r * e.before.theta_dot.abs());
    }
}

/// The kinetic energy of the two bodies at `θ = 0`:
/// `½ M u̇² + m2 h θ̇ u̇ + ½ I_O θ̇²` (h = R cos α).
fn kinetic(state: rocking::State, total: f64) -> f64 {
    let tower = block();
    let m2h = tower.mass() * tower.radius() * tower.alpha().cos();
    0.5 * total * state.slip_vel.powi(2) + m2h * state.theta_dot * state.slip_vel + 0.5 * tower.inertia_pivot() * state.theta_dot.powi(2)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, rng_seed: RngSeed::Fixed(0x1a7ac7), ..ProptestConfig::default() })]

    /// Energy never increases at an impact, whatever the friction and the
    /// building's mass, under a harmonic that rocks the tower (μs > tan α =
    /// 0.25, so the tower lifts before the building slips) and may slide the
    /// building (amplitude up to 1 g, above μs).
    #[test]
    fn impacts_never_add_energy(ratio in 1.0f64..20.0, mu_s in 0.3f64..0.9, kinetic_fraction in 0.5f64..1.0, amplitude in 0.3f64..1.0, frequency in 1.0f64..4.0) {
        let tower = block();
        let total = (1.0 + ratio) * tower.mass();
        let model = on_building(tower, ratio * tower.mass(), mu_s, kinetic_fraction * mu_s, NormalForce::Constant);
        let ground = GroundMotion::Harmonic(rocking::Harmonic::new(amplitude * G, frequency, 3.0, 0.0).unwrap());
        let (summary, log) = run_logged(&model, &ground, Initial::default(), &rocking::Settings { duration: 4.0, ..rocking::Settings::default() });
        let impacts: Vec<_> = log.events.iter().filter(|e| e.kind == EventKind::Impact).collect();
        // (A tower that overturns on its first swing has no impact to check.)
        prop_assert!(!impacts.is_empty() || summary.overturned());
        for e in impacts {
            let (before, after) = (kinetic(e.before, total), kinetic(e.after, total));
            // Rounding of the two sums: 1e-12 of the energy.
            prop_assert!(after <= before * (1.0 + 1e-12), "t = {}: {after} > {before}", e.time);
        }
    }
}
