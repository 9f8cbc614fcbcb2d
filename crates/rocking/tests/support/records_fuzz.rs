// What the `records` fuzz target does with one input, shared by the target
// (`fuzz/fuzz_targets/records.rs`, through `include!`) and the stable replay
// of the kept inputs (`tests/record_fuzz_corpus.rs`): the first byte picks the
// format (AT2, ESM, CSV with or without `dt`, or guessed), the rest is the
// file. A reader may refuse the text, never panic; a record it accepts holds
// finite values at strictly increasing times.

/// Reads one fuzz input with the reader its first byte picks, and checks what it accepts.
pub fn replay(data: &[u8]) {
    use rocking::{AccelerationUnit, CsvOptions, Record, RecordFormat};
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
