//! The synthetic records of `tests/data/records/` (see its README): every valid
//! file gives the same samples and peak, every malformed one its error.

use approx::assert_relative_eq;
use rocking::{AccelerationUnit, CsvOptions, Record, RecordError, RecordFormat};

const G: f64 = 9.81;
const SAMPLES: usize = 200;
const DT: f64 = 0.01;
/// The peak, 0.3 sin(4π t) exp(−t) g at t = 0.12 s, to 7 significant digits.
const PEAK_G: f64 = 0.2655511;
const PEAK_T: f64 = 0.12;
/// F10.5 keeps 5 decimals: its values differ by up to 5e-6 g (plus the last bits of the decimal).
const F10_TOLERANCE_G: f64 = 5.000_001e-6;

fn text(name: &str) -> String {
    let path = format!("{}/tests/data/records/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("cannot read {path}: {e}"))
}

/// Reads a file with its format given and guessed; both must agree.
fn read(name: &str, format: RecordFormat, csv: CsvOptions) -> Result<Record, RecordError> {
    let text = text(name);
    assert_eq!(Record::guess_format(&text), Ok(format), "{name}: guessed format");
    let given = Record::parse(&text, Some(format), &csv, G);
    assert_eq!(Record::parse(&text, None, &csv, G), given, "{name}: format given and guessed");
    given
}

fn csv_options(dt: Option<f64>) -> CsvOptions {
    CsvOptions {
        units: AccelerationUnit::G,
        dt,
    }
}

/// Every valid file with its format, CSV options and tolerance (in g) against `synthetic.AT2`.
fn valid_files() -> Vec<(&'static str, RecordFormat, CsvOptions, f64)> {
    let csv = csv_options(None);
    vec![
        ("synthetic.AT2", RecordFormat::At2, csv, 0.0),
        ("synthetic_crlf.AT2", RecordFormat::At2, csv, 0.0),
        ("synthetic_runtogether.AT2", RecordFormat::At2, csv, 0.0),
        ("synthetic_f10.AT2", RecordFormat::At2, csv, F10_TOLERANCE_G),
        ("synthetic.csv", RecordFormat::Csv, csv, 0.0),
        ("synthetic_dexp.csv", RecordFormat::Csv, csv, 0.0),
        ("synthetic_dt.csv", RecordFormat::Csv, csv_options(Some(DT)), 0.0),
        ("synthetic.ASC", RecordFormat::Esm, csv, 0.0),
        ("synthetic_dyna10.ASC", RecordFormat::Esm, csv, 0.0),
    ]
}

#[test]
fn the_reference_holds_the_stated_signal() {
    let record = read("synthetic.AT2", RecordFormat::At2, csv_options(None)).expect("valid");
    assert_eq!(record.len(), SAMPLES);
    assert_relative_eq!(record.time_step().expect("uniform"), DT, max_relative = 1e-12);
    for (t, a) in record.times().iter().zip(record.values()) {
        // 0.3 sin(4π t) exp(−t) g rounded to 7 significant digits (exact zeros written as 0).
        let exact = 0.3 * (4.0 * std::f64::consts::PI * t).sin() * (-t).exp();
        assert!((a / G - exact).abs() <= 5e-7 * exact.abs() + 1e-15, "t = {t}: {} g against {exact} g", a / G);
    }
}

#[test]
fn every_valid_file_gives_the_same_samples_and_peak() {
    let reference = read("synthetic.AT2", RecordFormat::At2, csv_options(None)).expect("valid");
    for (name, format, csv, tolerance_g) in valid_files() {
        let record = read(name, format, csv).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(record.len(), SAMPLES, "{name}");
        for (k, (t, t_ref)) in record.times().iter().zip(reference.times()).enumerate() {
            assert_relative_eq!(*t, *t_ref, max_relative = 1e-12);
            let (a, a_ref) = (record.values()[k] / G, reference.values()[k] / G);
            if tolerance_g > 0.0 {
                assert!((a - a_ref).abs() <= tolerance_g, "{name}, sample {k}: {a} g against {a_ref} g");
            } else {
                assert!((a - a_ref).abs() <= 1e-12 * a_ref.abs(), "{name}, sample {k}: {a} g against {a_ref} g");
            }
        }
        let (peak, t) = record.peak();
        let peak_tolerance = if tolerance_g > 0.0 { tolerance_g / PEAK_G } else { 1e-12 };
        assert_relative_eq!(peak / G, PEAK_G, max_relative = peak_tolerance);
        assert_relative_eq!(t, PEAK_T, max_relative = 1e-12);
    }
}

#[test]
fn a_single_column_needs_dt() {
    let result = read("synthetic_dt.csv", RecordFormat::Csv, csv_options(None));
    assert!(matches!(&result, Err(RecordError::Invalid(m)) if m.contains("`dt`")), "{result:?}");
}

#[test]
fn every_malformed_file_gives_its_error() {
    let cases = [
        (
            "short.AT2",
            RecordFormat::At2,
            RecordError::Invalid("header says NPTS = 200 but the file has 199 values".into()),
        ),
        (
            "long.AT2",
            RecordFormat::At2,
            RecordError::Line {
                line: 45,
                reason: "header says NPTS = 200 but the file has 201 values (value 201 is on this line)".into(),
            },
        ),
        (
            "nonnumeric.AT2",
            RecordFormat::At2,
            RecordError::Line {
                line: 10,
                reason: "\"-2.8991520E-O2\" is not a number".into(),
            },
        ),
        (
            "zero_dt.AT2",
            RecordFormat::At2,
            RecordError::Line {
                line: 4,
                reason: "DT must be > 0, got 0".into(),
            },
        ),
        ("missing_ndata.ASC", RecordFormat::Esm, RecordError::Invalid("missing header key NDATA".into())),
        (
            "velocity.ASC",
            RecordFormat::Esm,
            RecordError::Line {
                line: 50,
                reason: "DATA_TYPE is \"VELOCITY\", only ACCELERATION can be read".into(),
            },
        ),
    ];
    for (name, format, expected) in cases {
        let error = read(name, format, csv_options(None)).expect_err(name);
        assert_eq!(error, expected, "{name}");
        assert!(!error.to_string().contains('\n'), "{name}: one line");
    }
}
