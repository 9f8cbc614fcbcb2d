//! Replays, under stable `cargo test`, the inputs kept from fuzzing the
//! record readers (`fuzz/`, target `records`): each file is the fuzz input,
//! its first byte picking the format as the fuzz target does. Every reader
//! must refuse or accept without panicking, and an accepted record must hold
//! finite values at strictly increasing times. New crashing inputs go to
//! `tests/data/fuzz/records/`.

use rocking::{AccelerationUnit, CsvOptions, Record, RecordFormat};
use std::path::Path;

/// What the `records` fuzz target does with one input.
fn replay(data: &[u8]) {
    let Some((&selector, rest)) = data.split_first() else { return };
    let Ok(text) = std::str::from_utf8(rest) else { return };
    let format = match selector % 5 {
        0 => Some(RecordFormat::At2),
        1 => Some(RecordFormat::Esm),
        2 | 3 => Some(RecordFormat::Csv),
        _ => None,
    };
    let csv = CsvOptions {
        units: AccelerationUnit::G,
        dt: (selector % 5 == 3).then_some(0.01),
    };
    if let Ok(record) = Record::parse(text, format, &csv, 9.81) {
        assert!(record.values().iter().all(|v| v.is_finite()));
        assert!(record.times().windows(2).all(|w| w[1] > w[0]));
    }
}

#[test]
fn kept_fuzz_inputs_never_panic() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/fuzz/records");
    let mut count = 0;
    for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
        let path = entry.unwrap_or_else(|e| panic!("{e}")).path();
        let data = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        replay(&data);
        count += 1;
    }
    assert!(count > 0, "no input in {}", dir.display());
}
