//! Lines and numbers as record files write them, shared by the readers.
//!
//! The number scanner is hand-written on purpose: Fortran fixed-width fields
//! run together when a value fills its field (`-0.1234567E-01-0.2345678E-01`,
//! `  -0.12345-0.23456`), so a line is not CSV nor white-space separated, and
//! no crate reads such fields; a dozen lines of scanning do.

use super::RecordError;

/// The numbered lines (1-based) of a file that are not blank, trimmed; a
/// leading byte-order mark and `\r\n` line endings are accepted.
pub(super) fn lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    text.lines()
        .enumerate()
        .map(|(k, line)| (k + 1, line.trim()))
        .filter(|(_, line)| !line.is_empty())
}

/// Parses one number: `1`, `-.25`, `6.3E-03`, Fortran's `1.0D-03`. Anything
/// else (including `inf`, `nan`, overflow) is `None`.
pub(super) fn parse_number(text: &str) -> Option<f64> {
    let allowed = |b: u8| b.is_ascii_digit() || matches!(b, b'.' | b'+' | b'-' | b'e' | b'E' | b'd' | b'D');
    if text.is_empty() || !text.bytes().all(allowed) {
        return None;
    }
    let value: f64 = text.replace(['d', 'D'], "e").parse().ok()?;
    value.is_finite().then_some(value)
}

/// Splits a line into the texts of its numbers: at white space, and before a
/// sign that does not follow an exponent letter (fields that run together).
pub(super) fn fields(line: &str) -> Vec<&str> {
    let mut out = Vec::new();
    for chunk in line.split_whitespace() {
        let bytes = chunk.as_bytes();
        let mut start = 0;
        for k in 1..bytes.len() {
            if matches!(bytes[k], b'+' | b'-') && !matches!(bytes[k - 1], b'e' | b'E' | b'd' | b'D') {
                // A sign is ASCII, so `k` is a character boundary.
                out.push(&chunk[start..k]);
                start = k;
            }
        }
        out.push(&chunk[start..]);
    }
    out
}

/// The error for a text that is not a number, on a given line.
pub(super) fn not_a_number(line: usize, text: &str) -> RecordError {
    RecordError::Line {
        line,
        reason: format!("\"{text}\" is not a number"),
    }
}

/// Values reserved up front from a header's count; beyond, the vector grows as values come.
const PREALLOCATED_VALUES: usize = 1 << 16;

/// Reads the data block of a file: every number on the given lines, exactly
/// `expected` of them as the header's `key` says.
pub(super) fn values<'a>(lines: impl Iterator<Item = (usize, &'a str)>, expected: usize, key: &str) -> Result<Vec<f64>, RecordError> {
    // The header's count sizes the vector only up to a bound: a header
    // claiming 8,888,888,200 samples asked for 71 GB before a value was read.
    let mut values = Vec::with_capacity(expected.min(PREALLOCATED_VALUES));
    let mut first_extra_line = None;
    let mut found = 0usize;
    for (line, text) in lines {
        for field in fields(text) {
            let value = parse_number(field).ok_or_else(|| not_a_number(line, field))?;
            found += 1;
            if found <= expected {
                values.push(value);
            } else if first_extra_line.is_none() {
                first_extra_line = Some(line);
            }
        }
    }
    let reason = format!("header says {key} = {expected} but the file has {found} values");
    match first_extra_line {
        Some(line) => Err(RecordError::Line {
            line,
            reason: format!("{reason} (value {} is on this line)", expected + 1),
        }),
        None if found < expected => Err(RecordError::Invalid(reason)),
        None => Ok(values),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn numbers_in_every_written_form() {
        let cases = [
            ("1", 1.0),
            ("-.25", -0.25),
            ("+2.", 2.0),
            ("6.3E-03", 0.0063),
            ("1.0D-03", 0.001),
            ("-2.5d+02", -250.0),
            ("0.1234567e1", 1.234567),
        ];
        for (text, expected) in cases {
            let value = parse_number(text).expect(text);
            assert_relative_eq!(value, expected, max_relative = 1e-15);
        }
    }

    #[test]
    fn non_numbers_are_rejected() {
        for text in ["", "0.12x", "inf", "NaN", "1e400", "1.2.3", "E5", "--1", "1,5", "0x10"] {
            assert!(parse_number(text).is_none(), "{text:?} was read as a number");
        }
    }

    #[test]
    fn fields_split_at_white_space_and_at_signs_that_start_a_number() {
        assert_eq!(fields("  6.3000000E-03  3.6400000E-03"), ["6.3000000E-03", "3.6400000E-03"]);
        assert_eq!(fields("-0.123E-02-0.456E-02"), ["-0.123E-02", "-0.456E-02"]);
        assert_eq!(fields("  -0.12345-0.23456   0.34567"), ["-0.12345", "-0.23456", "0.34567"]);
        assert_eq!(fields("1.0D-03+2.0d+01"), ["1.0D-03", "+2.0d+01"]);
        assert_eq!(fields("0.12x-3"), ["0.12x", "-3"]);
        assert!(fields("   ").is_empty());
    }

    #[test]
    fn lines_are_numbered_from_one_without_blank_lines_or_line_endings() {
        let text = "\u{feff}a\r\n\r\n  b  \r\nc\r\n\r\n";
        let got: Vec<_> = lines(text).collect();
        assert_eq!(got, [(1, "a"), (3, "b"), (4, "c")]);
    }

    #[test]
    fn values_checks_the_count_and_names_lines() {
        let data = [(5, "1.0 2.0"), (6, "3.0")];
        let got = values(data.into_iter(), 3, "NPTS").expect("three values");
        assert_eq!(got.len(), 3);
        assert_relative_eq!(got[2], 3.0);
        let short = values(data.into_iter(), 4, "NPTS");
        assert_eq!(short, Err(RecordError::Invalid("header says NPTS = 4 but the file has 3 values".into())));
        let long = values(data.into_iter(), 1, "NDATA");
        let reason = "header says NDATA = 1 but the file has 3 values (value 2 is on this line)".to_string();
        assert_eq!(long, Err(RecordError::Line { line: 5, reason }));
        let bad = values([(5, "1.0"), (6, "2.0 0.12x")].into_iter(), 3, "NPTS");
        assert_eq!(
            bad,
            Err(RecordError::Line {
                line: 6,
                reason: "\"0.12x\" is not a number".into()
            })
        );
    }
}
