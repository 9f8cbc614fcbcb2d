//! Property tests of the record readers on arbitrary input: random bytes
//! (read as text where they are UTF-8), and structure-aware text built from
//! the tokens the readers look for (header words, numbers in every notation,
//! separators, line ends). Each reader must return a record or an error,
//! never panic, and an accepted record must hold finite values at strictly
//! increasing times (what the integrator relies on).

use proptest::prelude::*;
use rocking::{AccelerationUnit, CsvOptions, Record, RecordFormat};

fn check_all_readers(text: &str) {
    for format in [None, Some(RecordFormat::At2), Some(RecordFormat::Esm), Some(RecordFormat::Csv)] {
        for dt in [None, Some(0.01)] {
            let csv = CsvOptions {
                units: AccelerationUnit::G,
                dt,
            };
            if let Ok(record) = Record::parse(text, format, &csv, 9.81) {
                assert!(record.values().iter().all(|v| v.is_finite()), "{format:?}: non-finite value from {text:?}");
                assert!(record.times().windows(2).all(|w| w[1] > w[0]), "{format:?}: times not increasing from {text:?}");
            }
        }
    }
}

/// Pieces of AT2, ESM and CSV files, numbers included.
fn token() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("NPTS=".to_string()),
        Just("DT=".to_string()),
        Just("SEC".to_string()),
        Just("NPTS".to_string()),
        Just("ACCELERATION TIME SERIES IN UNITS OF G".to_string()),
        Just("SAMPLING_INTERVAL_S:".to_string()),
        Just("NDATA:".to_string()),
        Just("UNITS:".to_string()),
        Just("cm/s^2".to_string()),
        Just("time,acceleration".to_string()),
        Just("#".to_string()),
        Just(",".to_string()),
        Just(" ".to_string()),
        Just("\n".to_string()),
        Just("\r\n".to_string()),
        Just("1.0D+300".to_string()),
        Just("-0".to_string()),
        Just("1e-320".to_string()),
        any::<f64>().prop_map(|x| format!("{x:e}")),
        any::<i32>().prop_map(|x| x.to_string()),
        (0.0f64..1.0).prop_map(|x| format!("{x:.4}")),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_bytes(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        check_all_readers(&String::from_utf8_lossy(&bytes));
    }

    #[test]
    fn structured_text(tokens in proptest::collection::vec(token(), 0..80)) {
        check_all_readers(&tokens.concat());
    }
}
