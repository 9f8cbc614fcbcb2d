//! Invariants over random scenarios: every run finishes (or reports Painlevé's
//! singularity of the dynamic normal force), the time spent in the four
//! motions adds up to the run, and the summary holds no NaN and respects its
//! own bounds.

#![allow(clippy::unwrap_used)]

mod common;

use common::*;
use proptest::prelude::*;
use rocking::{simulate, Error, GroundMotion, Harmonic, Initial, NormalForce, Pulse, PulseShape, Settings};
use std::f64::consts::FRAC_PI_2;

fn ground_strategy() -> impl Strategy<Value = GroundMotion> {
    prop_oneof![
        (0.0f64..2.0, 0.3f64..8.0, 0.0f64..6.0).prop_map(|(a, f, phase)| GroundMotion::Harmonic(Harmonic::new(a * G, f, 3.0, phase).unwrap())),
        (-2.0f64..2.0, 0.3f64..8.0).prop_map(|(a, f)| GroundMotion::Pulse(Pulse::cycle(PulseShape::Cosine, a * G, f).unwrap())),
        (-2.0f64..2.0, 0.05f64..1.0).prop_map(|(a, td)| GroundMotion::Pulse(Pulse::rectangular(a * G, td).unwrap())),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn runs_finish_and_account_for_their_time(
        aspect in 1.5f64..10.0,
        building in proptest::option::of((100.0f64..1e5, 0.0f64..1.5, 0.0f64..1.0, proptest::bool::ANY)),
        ground in ground_strategy(),
        tilt in -0.5f64..0.5,
    ) {
        let tower = rocking::reference::solid_block(1.0, aspect);
        let model = match building {
            Some((m1, mu_s, fraction, dynamic)) => on_building(tower, m1, mu_s, fraction * mu_s, if dynamic { NormalForce::Dynamic } else { NormalForce::Constant }),
            None => fixed(tower),
        };
        let initial = Initial { theta: tilt * tower.alpha(), theta_dot: 0.0 };
        match simulate(&model, &ground, initial, &Settings { duration: 4.0, ..Settings::default() }, &mut ()) {
            Ok(s) => {
                let total: f64 = s.time_in_motion.iter().sum();
                prop_assert!((total - s.end_time).abs() <= 1e-9 * s.end_time.max(1.0), "{total} vs {}", s.end_time);
                prop_assert!(s.max_abs_theta() <= FRAC_PI_2 * (1.0 + 1e-12));
                prop_assert_eq!(s.overturned(), s.overturn_time.is_some());
                if s.overturned() {
                    prop_assert!((s.max_abs_theta() - FRAC_PI_2).abs() < 1e-9);
                } else {
                    prop_assert!((s.end_time - 4.0).abs() < 1e-12);
                }
                let numbers = [s.max_abs_theta(), s.max_abs_slip, s.final_slip, s.max_top_displacement, s.max_top_abs_acceleration];
                prop_assert!(numbers.iter().all(|x| x.is_finite()), "{s:?}");
                // The pivot demand |f_x| / f_y is unbounded exactly when f_y reached zero.
                prop_assert_eq!(s.max_pivot_friction_demand.is_finite(), !s.tower_uplift_detected, "{:?}", s);
                prop_assert!(s.max_abs_slip >= s.final_slip.abs());
            }
            Err(Error::Singular { .. }) => prop_assert!(matches!(building, Some((_, _, _, true)))),
            Err(e) => prop_assert!(false, "{e}"),
        }
    }
}
