//! Responses to recorded accelerograms: the integrator steps onto the sample
//! instants (the kinks of the input), so a record resampled onto its own
//! instants, scaled exactly, or mirrored gives the expected response. Uses the
//! 1940 El Centro N-S record of the repository (`data/records/`).

#![allow(clippy::unwrap_used)]

mod common;

use common::*;
use rocking::{CsvOptions, GroundMotion, Initial, NormalForce, Record, RecordFormat, Settings, Summary};

/// The El Centro 1940 N-S record of the repository (`data/records/`); a
/// missing file fails the test rather than skipping it.
fn el_centro() -> Record {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/records/elcentro_1940_ns.AT2");
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("cannot read {path}: {e}"));
    Record::parse(&text, Some(RecordFormat::At2), &CsvOptions::default(), G).unwrap()
}

fn respond(record: Record) -> Summary {
    // tan α = 0.2 < μk = 0.25 < μs = 0.3 < 0.32 g, the peak: the block rocks, the building slides.
    let model = on_building(rocking::reference::solid_block(0.4, 2.0), 5.0e3, 0.3, 0.25, NormalForce::Constant);
    run(
        &model,
        &GroundMotion::Record(record),
        Initial::default(),
        &Settings {
            duration: 35.0,
            ..Settings::default()
        },
    )
}

/// Sampling the interpolated record at its own instants gives the same record,
/// and so, bit for bit, the same summary; the run both rocks and slides.
#[test]
fn resampled_onto_its_own_instants_gives_the_same_summary() {
    let record = el_centro();
    let ground = GroundMotion::Record(record.clone());
    let values = record.times().iter().map(|&t| ground.acceleration(t)).collect();
    let resampled = Record::from_samples(record.times().to_vec(), values).unwrap();
    let (a, b) = (respond(record), respond(resampled));
    assert_eq!(format!("{a:?}"), format!("{b:?}"));
    assert!(a.impacts > 0 && a.first_slip_time.is_some(), "{a:?}");
}

/// `scaled(2)` equals the record with doubled values (doubling is exact in
/// floating point), so the summaries are identical; and a mirrored record
/// mirrors the response (θ → −θ, u → −u) to rounding.
#[test]
fn scaling_and_mirroring() {
    let record = el_centro();
    let doubled = Record::from_samples(record.times().to_vec(), record.values().iter().map(|v| 2.0 * v).collect()).unwrap();
    assert_eq!(format!("{:?}", respond(record.scaled(2.0))), format!("{:?}", respond(doubled)));
    let (a, b) = (respond(record.clone()), respond(record.scaled(-1.0)));
    assert!((a.theta_range.0 + b.theta_range.1).abs() < 1e-12 && (a.theta_range.1 + b.theta_range.0).abs() < 1e-12);
    assert!((a.final_slip + b.final_slip).abs() < 1e-12);
    assert_eq!(a.impacts, b.impacts);
}

/// After the last sample the ground is still: a record that ends while the
/// building slides lets it stop, and the time in each regime adds up to the run.
#[test]
fn time_in_regimes_adds_up_and_motion_dies_out() {
    let record = el_centro();
    let s = respond(record);
    let total: f64 = s.time_in_motion.iter().sum();
    assert!((total - 35.0).abs() < 1e-9, "{total}: {s:?}");
    assert!(s.time_in(rocking::Motion::Rest) > 1.0);
}
