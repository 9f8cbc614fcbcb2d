//! Every record reader on arbitrary text: the first byte picks the format
//! (AT2, ESM, CSV with or without `dt`, or guessed), the rest is the file.
//! A reader may refuse the text, never panic; a record it accepts holds
//! finite values at strictly increasing times.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rocking::{AccelerationUnit, CsvOptions, Record, RecordFormat};

fuzz_target!(|data: &[u8]| {
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
});
