//! A CSV record with samples at 0.09 s and 0.090000000000001 s failed with
//! "step size too small": the integrator must land on every sample (each is a
//! kink of the linearly interpolated input), and it refused any step shorter
//! than ten units in the last place of the run's end time (2.2e-15 s for a
//! run of 1 s), even one that only lands on such a kink. A step that lands on
//! a kink is now taken however short.
//!
//! The answer must not depend on how close the two samples are once they are
//! close: the input of a record whose samples are `ε` apart differs from that
//! of one whose samples are 1e-11 s apart by a velocity of at most
//! `0.5 · 1.1 g · 1e-11 s` = 5e-11 m/s, far below the integrator's tolerance.
#![allow(clippy::unwrap_used)]

mod common;
use common::{fixed, on_building, G};
use rocking::{simulate, AccelerationUnit, CsvOptions, GroundMotion, Initial, Model, NormalForce, Record, RecordFormat, Settings, Summary};

/// The CSV text of a record rising to 0.5 g at 0.09 s, then to 1.6 g
/// `gap` seconds later (an all but vertical jump), back to 0 at 0.2 s and 0.6 s.
fn record_text(gap: f64) -> String {
    format!("time,acceleration\n0,0\n0.09,0.5\n{:?},1.6\n0.2,0.4\n0.6,0\n", 0.09 + gap)
}

fn run(model: &Model, gap: f64) -> Summary {
    let options = CsvOptions {
        units: AccelerationUnit::G,
        dt: None,
    };
    let record = Record::parse(&record_text(gap), Some(RecordFormat::Csv), &options, G).unwrap();
    assert!(record.times()[2] > record.times()[1], "gap {gap}: the samples must stay distinct");
    let settings = Settings {
        duration: 4.0,
        ..Settings::default()
    };
    simulate(model, &GroundMotion::Record(record), Initial::default(), &settings, &mut ()).unwrap_or_else(|e| panic!("gap {gap:e}: {e}"))
}

/// A 4 m × 12 m block (the tower of the tower-on-church example, tan α = 1/3)
/// on a fixed base and on a building 10 times heavier (μs = 1.25, μk = 1: it
/// slides under the 1.6 g): gaps of 1e-15 s (the reported one), 1e-16 s and
/// one unit in the last place of 0.09 (1.4e-17 s) against 1e-11 s, over 4 s
/// (5 and 6 impacts). Measured, θ's peaks agree to 3e-12 of their range and
/// the peak slip (9.5 mm) to 7e-11 of itself, what the input's difference
/// makes; the bound, 1e-8, is the integrator's relative tolerance: a jump
/// handled differently would miss it by far more.
#[test]
fn samples_a_few_ulps_apart_are_a_jump() {
    let tower = rocking::reference::solid_block(4.0, 12.0);
    let models = [fixed(tower), on_building(tower, 10.0 * tower.mass(), 1.25, 1.0, NormalForce::Constant)];
    for model in &models {
        let reference = run(model, 1e-11);
        assert!(reference.impacts > 0, "the tower must rock");
        for gap in [1e-15, 1e-16, 0.09f64.next_up() - 0.09] {
            let s = run(model, gap);
            let theta_scale = reference.theta_range.1 - reference.theta_range.0;
            assert!(
                (s.theta_range.0 - reference.theta_range.0).abs() <= 1e-8 * theta_scale,
                "gap {gap:e}: {s:?}\nagainst {reference:?}"
            );
            assert!(
                (s.theta_range.1 - reference.theta_range.1).abs() <= 1e-8 * theta_scale,
                "gap {gap:e}: {s:?}\nagainst {reference:?}"
            );
            assert!((s.max_abs_slip - reference.max_abs_slip).abs() <= 1e-8 * reference.max_abs_slip, "gap {gap:e}");
            assert_eq!(s.impacts, reference.impacts, "gap {gap:e}");
        }
    }
    assert!(run(&models[1], 1e-15).max_abs_slip > 0.0, "the building must slide");
}
