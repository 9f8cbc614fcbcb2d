//! ESM / ITACA ASCII records: `KEY: value` header lines (64 in DYNA 1.2, fewer
//! in older layouts), then the values, one per line.

use super::scan::{lines, parse_number, values};
use super::{Record, RecordError};

/// The header keys a record needs.
const REQUIRED: [&str; 4] = ["DATA_TYPE", "SAMPLING_INTERVAL_S", "NDATA", "UNITS"];

/// True if the first line is `KEY: value` and the text has a `SAMPLING_INTERVAL_S`.
pub(super) fn looks_like(text: &str) -> bool {
    lines(text).next().is_some_and(|(_, line)| key_value(line).is_some()) && text.contains("SAMPLING_INTERVAL_S")
}

/// Reads an ESM record; `g` (m/s²) converts values given in g.
pub(super) fn parse(text: &str, g: f64) -> Result<Record, RecordError> {
    let mut rows = lines(text).peekable();
    let mut header = Vec::new();
    while let Some((line, (key, value))) = rows.peek().and_then(|&(line, text)| Some((line, key_value(text)?))) {
        header.push(Entry { line, key, value });
        rows.next();
    }
    let (dt, count, scale) = settings(&header, g)?;
    let values = values(rows, count, "NDATA")?;
    Record::uniform(dt, values.into_iter().map(|a| a * scale).collect())
}

/// The time step, the number of values and the factor to m/s², from the header.
fn settings(header: &[Entry], g: f64) -> Result<(f64, usize, f64), RecordError> {
    let missing: Vec<&str> = REQUIRED.into_iter().filter(|key| find(header, key).is_none()).collect();
    if missing.len() > 1 {
        return Err(RecordError::Invalid(format!("missing header keys {}", missing.join(", "))));
    }
    let entry = |key: &str| find(header, key).ok_or_else(|| RecordError::Invalid(format!("missing header key {key}")));
    let data_type = entry("DATA_TYPE")?;
    if !data_type.value.eq_ignore_ascii_case("ACCELERATION") {
        return Err(data_type.error(format!("DATA_TYPE is \"{}\", only ACCELERATION can be read", data_type.value)));
    }
    let dt = entry("SAMPLING_INTERVAL_S")?;
    let dt_value = parse_number(dt.value).ok_or_else(|| dt.error(format!("SAMPLING_INTERVAL_S \"{}\" is not a number", dt.value)))?;
    if dt_value <= 0.0 {
        return Err(dt.error(format!("SAMPLING_INTERVAL_S must be > 0, got {dt_value}")));
    }
    let ndata = entry("NDATA")?;
    let count = ndata
        .value
        .parse::<usize>()
        .map_err(|_| ndata.error(format!("NDATA must be a whole number, got \"{}\"", ndata.value)))?;
    let units = entry("UNITS")?;
    let scale = unit_factor(units.value, g).ok_or_else(|| units.error(format!("UNITS \"{}\" is not one of cm/s^2, m/s^2, g", units.value)))?;
    Ok((dt_value, count, scale))
}

/// One header line.
#[derive(Clone, Copy)]
struct Entry<'a> {
    line: usize,
    key: &'a str,
    value: &'a str,
}

impl Entry<'_> {
    /// An error on this line.
    fn error(&self, reason: String) -> RecordError {
        RecordError::Line { line: self.line, reason }
    }
}

/// The first header line with `key`.
fn find<'a>(header: &[Entry<'a>], key: &str) -> Option<Entry<'a>> {
    header.iter().find(|entry| entry.key == key).copied()
}

/// `KEY: value`, the key in capitals without spaces (`VS30_M/S`, `PGA_CM/S^2`), the value maybe empty.
fn key_value(line: &str) -> Option<(&str, &str)> {
    let (key, value) = line.split_once(':')?;
    let key = key.trim_end();
    let capitals = key.chars().any(|c| c.is_ascii_uppercase()) && !key.chars().any(|c| c.is_whitespace() || c.is_lowercase());
    capitals.then(|| (key, value.trim()))
}

/// The factor from the file's units to m/s².
fn unit_factor(units: &str, g: f64) -> Option<f64> {
    match units.to_ascii_lowercase().as_str() {
        "cm/s^2" | "cm/s2" => Some(0.01),
        "m/s^2" | "m/s2" => Some(1.0),
        "g" => Some(g),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    const G: f64 = 9.81;

    fn file(header: &[(&str, &str)], data: &str) -> String {
        let mut text: String = header.iter().map(|(k, v)| format!("{k}: {v}\n")).collect();
        text.push_str(data);
        text
    }

    fn standard(units: &str) -> Vec<(&'static str, String)> {
        vec![
            ("EVENT_NAME", "TEST".into()),
            ("VS30_M/S", "213".into()),
            ("SAMPLING_INTERVAL_S", "0.010000".into()),
            ("NDATA", "3".into()),
            ("UNITS", units.into()),
            ("HYPOCENTER_REFERENCE", String::new()),
            ("DATA_TYPE", "ACCELERATION".into()),
        ]
    }

    fn text(header: &[(&'static str, String)], data: &str) -> String {
        file(&header.iter().map(|(k, v)| (*k, v.as_str())).collect::<Vec<_>>(), data)
    }

    fn line_error(result: Result<Record, RecordError>) -> (usize, String) {
        match result {
            Err(RecordError::Line { line, reason }) => (line, reason),
            other => panic!("expected a line error, got {other:?}"),
        }
    }

    #[test]
    fn reads_cm_s2_values() {
        let record = parse(&text(&standard("cm/s^2"), "6.180300E+00\n-3.127624E+02\n0.000000E+00\n"), G).expect("valid");
        assert_eq!(record.len(), 3);
        assert_relative_eq!(record.times()[2], 0.02, max_relative = 1e-15);
        // 6.1803 cm/s² = 0.061803 m/s²; -312.7624 cm/s² = -3.127624 m/s².
        assert_relative_eq!(record.values()[0], 0.061803, max_relative = 1e-15);
        assert_relative_eq!(record.values()[1], -3.127624, max_relative = 1e-15);
    }

    #[test]
    fn every_unit_spelling() {
        for (units, factor) in [("cm/s^2", 0.01), ("CM/S2", 0.01), ("m/s^2", 1.0), ("M/S2", 1.0), ("g", G), ("G", G)] {
            let record = parse(&text(&standard(units), "1.0\n2.0\n-4.0\n"), G).expect(units);
            assert_relative_eq!(record.values()[2], -4.0 * factor, max_relative = 1e-15);
        }
        let (line, reason) = line_error(parse(&text(&standard("gal"), "1.0\n2.0\n-4.0\n"), G));
        assert_eq!((line, reason.as_str()), (5, "UNITS \"gal\" is not one of cm/s^2, m/s^2, g"));
    }

    #[test]
    fn several_values_per_line_crlf_d_exponents_and_trailing_blank_line() {
        let data = text(&standard("m/s^2"), "1.0D+00 -2.5d-01\n\n5.0E-01\n\n").replace('\n', "\r\n");
        assert!(looks_like(&data));
        let record = parse(&data, G).expect("valid");
        for (v, e) in record.values().iter().zip([1.0, -0.25, 0.5]) {
            assert_relative_eq!(*v, e, max_relative = 1e-15);
        }
    }

    #[test]
    fn header_of_any_length() {
        // An older (DYNA 1.0) layout: fewer keys, in another order.
        let short = file(
            &[("SAMPLING_INTERVAL_S", "0.5"), ("DATA_TYPE", "acceleration"), ("NDATA", "2"), ("UNITS", "g")],
            "0.1\n0.2\n",
        );
        let record = parse(&short, G).expect("valid");
        assert_relative_eq!(record.times()[1], 0.5);
        assert_relative_eq!(record.values()[1], 0.2 * G, max_relative = 1e-15);
    }

    #[test]
    fn missing_keys_are_named() {
        let mut header = standard("cm/s^2");
        header.retain(|(k, _)| *k != "NDATA");
        assert_eq!(parse(&text(&header, "1.0\n"), G), Err(RecordError::Invalid("missing header key NDATA".into())));
        header.retain(|(k, _)| *k != "UNITS");
        assert_eq!(
            parse(&text(&header, "1.0\n"), G),
            Err(RecordError::Invalid("missing header keys NDATA, UNITS".into()))
        );
    }

    #[test]
    fn bad_header_values_name_their_line() {
        let mut header = standard("cm/s");
        header[6].1 = "VELOCITY".into();
        let (line, reason) = line_error(parse(&text(&header, "1.0\n2.0\n3.0\n"), G));
        assert_eq!((line, reason.as_str()), (7, "DATA_TYPE is \"VELOCITY\", only ACCELERATION can be read"));
        let mut header = standard("cm/s^2");
        header[2].1 = "0.0".into();
        let (line, reason) = line_error(parse(&text(&header, "1.0\n2.0\n3.0\n"), G));
        assert_eq!((line, reason.as_str()), (3, "SAMPLING_INTERVAL_S must be > 0, got 0"));
        header[2].1 = "fast".into();
        let (line, reason) = line_error(parse(&text(&header, "1.0\n2.0\n3.0\n"), G));
        assert_eq!((line, reason.as_str()), (3, "SAMPLING_INTERVAL_S \"fast\" is not a number"));
        let mut header = standard("cm/s^2");
        header[3].1 = "three".into();
        let (line, reason) = line_error(parse(&text(&header, "1.0\n2.0\n3.0\n"), G));
        assert_eq!((line, reason.as_str()), (4, "NDATA must be a whole number, got \"three\""));
    }

    #[test]
    fn bad_values_and_counts() {
        let header = standard("cm/s^2");
        let (line, reason) = line_error(parse(&text(&header, "1.0\n0.12x\n3.0\n"), G));
        assert_eq!((line, reason.as_str()), (9, "\"0.12x\" is not a number"));
        let short = parse(&text(&header, "1.0\n2.0\n"), G);
        assert_eq!(short, Err(RecordError::Invalid("header says NDATA = 3 but the file has 2 values".into())));
        let (line, reason) = line_error(parse(&text(&header, "1.0\n2.0\n3.0\n4.0\n"), G));
        assert_eq!(
            (line, reason.as_str()),
            (11, "header says NDATA = 3 but the file has 4 values (value 4 is on this line)")
        );
    }

    #[test]
    fn recognises_esm_headers_only() {
        assert!(looks_like(&text(&standard("g"), "1.0\n")));
        assert!(!looks_like("EVENT_NAME: X\nNDATA: 3\n1.0\n"));
        assert!(!looks_like("Note: SAMPLING_INTERVAL_S\n"));
        assert!(!looks_like("title\nSAMPLING_INTERVAL_S: 0.01\n"));
        assert!(!looks_like("0.0,0.1\n"));
    }
}
