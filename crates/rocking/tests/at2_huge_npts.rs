//! Found by fuzzing (`fuzz/`, target `records`): an AT2 header claiming
//! `NPTS = 8888888200` made the reader reserve room for that many values
//! (71 GB) before reading one, and the process died out of memory. The count
//! now sizes the vector only up to a bound, and the mismatch is reported.

use rocking::{AccelerationUnit, CsvOptions, Record, RecordError, RecordFormat};

#[test]
fn a_header_count_far_above_the_data_is_a_clean_error() {
    let text = "TITLE\nsource\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=   8888888200, DT=   .0100 SEC,\n  0.1  0.2  0.3\n";
    let csv = CsvOptions {
        units: AccelerationUnit::G,
        dt: None,
    };
    let e = Record::parse(text, Some(RecordFormat::At2), &csv, 9.81);
    assert_eq!(e, Err(RecordError::Invalid("header says NPTS = 8888888200 but the file has 3 values".into())));
}
