//! PEER NGA `.AT2` records: three free-text header lines, a fourth with the
//! number of points and the time step, then the values in g, several per line.
//!
//! The fourth line comes in three forms:
//! `NPTS=   5437, DT=   .0050 SEC,` and `NPTS=  1559, DT=   .0200 SEC`
//! (NGA-West2), and `4164    0.0100    NPTS, DT` (NGA-West1).

use super::scan::{parse_number, values};
use super::{Record, RecordError};

/// The line that holds the number of points and the time step.
const COUNT_LINE: usize = 4;

/// True if the fourth line gives NPTS and DT in one of the known forms.
pub(super) fn looks_like(text: &str) -> bool {
    raw_lines(text).nth(COUNT_LINE - 1).and_then(count_fields).is_some()
}

/// Reads an AT2 record; `g` (m/s²) converts its values.
pub(super) fn parse(text: &str, g: f64) -> Result<Record, RecordError> {
    let Some(line) = raw_lines(text).nth(COUNT_LINE - 1) else {
        return Err(RecordError::Invalid(format!(
            "an AT2 file has {COUNT_LINE} header lines, this one has {}",
            raw_lines(text).count()
        )));
    };
    let (npts, dt) = counts(line)?;
    let data = raw_lines(text).enumerate().skip(COUNT_LINE).map(|(k, line)| (k + 1, line.trim()));
    let values = values(data, npts, "NPTS")?;
    Record::uniform(dt, values.into_iter().map(|a| a * g).collect())
}

/// Every line, blank ones too (the header lines are counted by position).
fn raw_lines(text: &str) -> std::str::Lines<'_> {
    text.strip_prefix('\u{feff}').unwrap_or(text).lines()
}

/// NPTS and DT from the fourth line, checked: NPTS a whole number, DT a number > 0.
fn counts(line: &str) -> Result<(usize, f64), RecordError> {
    let error = |reason: String| RecordError::Line { line: COUNT_LINE, reason };
    let (npts, dt) = count_fields(line).ok_or_else(|| error(format!("expected `NPTS= n, DT= dt SEC` or `n dt NPTS, DT`, found \"{}\"", line.trim())))?;
    let npts = npts
        .parse::<usize>()
        .map_err(|_| error(format!("NPTS must be a whole number, got \"{npts}\"")))?;
    let dt = parse_number(dt).ok_or_else(|| error(format!("DT \"{dt}\" is not a number")))?;
    if dt <= 0.0 {
        return Err(error(format!("DT must be > 0, got {dt}")));
    }
    Ok((npts, dt))
}

/// The texts of NPTS and DT on the fourth line, in either form.
fn count_fields(line: &str) -> Option<(&str, &str)> {
    keyed_fields(line).or_else(|| west1_fields(line))
}

/// `NPTS=   5437, DT=   .0050 SEC` (a trailing comma or not).
fn keyed_fields(line: &str) -> Option<(&str, &str)> {
    let (npts, rest) = value_after(line, "NPTS")?;
    let (dt, _) = value_after(rest, "DT")?;
    Some((npts, dt))
}

/// `4164    0.0100    NPTS, DT`.
fn west1_fields(line: &str) -> Option<(&str, &str)> {
    let words: Vec<&str> = line.split(|c: char| c.is_whitespace() || c == ',').filter(|w| !w.is_empty()).collect();
    match words.as_slice() {
        [npts, dt, a, b, ..] if a.eq_ignore_ascii_case("NPTS") && b.eq_ignore_ascii_case("DT") => Some((npts, dt)),
        _ => None,
    }
}

/// The text after `key` (any case), optional spaces and `=`, up to a comma or
/// white space; with the rest of the line.
fn value_after<'a>(line: &'a str, key: &str) -> Option<(&'a str, &'a str)> {
    // ASCII upper-casing keeps byte offsets.
    let at = line.to_ascii_uppercase().find(key)?;
    let rest = line[at + key.len()..].trim_start().strip_prefix('=')?.trim_start();
    let end = rest.find(|c: char| c == ',' || c.is_whitespace()).unwrap_or(rest.len());
    (end > 0).then(|| (&rest[..end], &rest[end..]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    const G: f64 = 9.81;
    const HEAD: &str = "title\nevent\nACCELERATION TIME SERIES IN UNITS OF G\n";

    fn line_error(result: Result<Record, RecordError>) -> (usize, String) {
        match result {
            Err(RecordError::Line { line, reason }) => (line, reason),
            other => panic!("expected a line error, got {other:?}"),
        }
    }

    #[test]
    fn the_three_forms_of_the_count_line() {
        let forms = [
            ("NPTS=   5437, DT=   .0050 SEC,", 5437, 0.005),
            ("NPTS=  1559, DT=   .0200 SEC", 1559, 0.02),
            ("  4164    0.0100    NPTS, DT", 4164, 0.01),
        ];
        for (line, npts, dt) in forms {
            let (n, step) = counts(line).expect(line);
            assert_eq!(n, npts, "{line}");
            assert_relative_eq!(step, dt, max_relative = 1e-15);
            assert!(looks_like(&format!("{HEAD}{line}\n")), "{line}");
        }
        let (n, step) = counts("npts=3,dt=1.0D-02 sec").expect("lower case, no spaces, D exponent");
        assert_eq!(n, 3);
        assert_relative_eq!(step, 0.01, max_relative = 1e-15);
    }

    #[test]
    fn reads_e15_7_values_five_per_line() {
        let text = format!("{HEAD}NPTS=     7, DT=   .0100 SEC,\n  6.3000000E-03  3.6400000E-03  9.9000000E-04  4.2800000E-03 -7.5800000E-03\n  1.0870000E-02 -3.1882000E-01\n");
        let record = parse(&text, G).expect("valid");
        assert_eq!(record.len(), 7);
        assert_relative_eq!(record.time_step().expect("uniform"), 0.01, max_relative = 1e-12);
        // 6.3e-3 g = 0.061803 m/s²; -0.31882 g = -3.1276242 m/s² at t = 6 × 0.01 s.
        assert_relative_eq!(record.values()[0], 0.061803, max_relative = 1e-14);
        assert_relative_eq!(record.values()[6], -3.1276242, max_relative = 1e-14);
        let (peak, t) = record.peak();
        assert_relative_eq!(peak, 3.1276242, max_relative = 1e-14);
        assert_relative_eq!(t, 0.06, max_relative = 1e-14);
    }

    #[test]
    fn running_together_values_f10_5_and_west1_header() {
        let text = format!("{HEAD}  5    0.0200    NPTS, DT\n  -0.12345-0.23456   0.34567-10.00000\n-0.123E-02\n");
        let record = parse(&text, 10.0).expect("valid");
        let expected = [-1.2345, -2.3456, 3.4567, -100.0, -0.0123];
        for (v, e) in record.values().iter().zip(expected) {
            assert_relative_eq!(*v, e, max_relative = 1e-14);
        }
        assert_relative_eq!(record.times()[4], 0.08, max_relative = 1e-14);
    }

    #[test]
    fn running_together_e_format_values() {
        let text = format!("{HEAD}NPTS=     4, DT=   .0050 SEC,\n-0.1234567E-01-0.2345678E-01 0.3456789E+00\n-0.4567890E-01\n");
        let record = parse(&text, 1.0).expect("valid");
        for (v, e) in record.values().iter().zip([-0.01234567, -0.02345678, 0.3456789, -0.0456789]) {
            assert_relative_eq!(*v, e, max_relative = 1e-15);
        }
        assert_relative_eq!(record.duration(), 0.015, max_relative = 1e-14);
    }

    #[test]
    fn d_exponents_crlf_and_trailing_blank_line() {
        let text = "a\r\nb\r\nc\r\nNPTS=  3, DT=   .0100 SEC\r\n  0.1000000D+00 -2.5000000D-01  1.0000000D-03\r\n\r\n";
        assert!(looks_like(text));
        let record = parse(text, G).expect("valid");
        // 0.1 g = 0.981, -0.25 g = -2.4525, 1e-3 g = 0.00981 m/s².
        for (v, e) in record.values().iter().zip([0.981, -2.4525, 0.00981]) {
            assert_relative_eq!(*v, e, max_relative = 1e-15);
        }
    }

    #[test]
    fn blank_header_lines_count() {
        let text = "\n\n\nNPTS=  2, DT=   .0100 SEC\n1.0 2.0\n";
        assert_eq!(parse(text, 1.0).expect("valid").len(), 2);
    }

    #[test]
    fn count_mismatches() {
        let short = parse(&format!("{HEAD}NPTS=  4, DT= .01 SEC\n1.0 2.0 3.0\n"), G);
        assert_eq!(short, Err(RecordError::Invalid("header says NPTS = 4 but the file has 3 values".into())));
        let (line, reason) = line_error(parse(&format!("{HEAD}NPTS=  2, DT= .01 SEC\n1.0 2.0\n\n3.0\n"), G));
        assert_eq!(
            (line, reason.as_str()),
            (7, "header says NPTS = 2 but the file has 3 values (value 3 is on this line)")
        );
    }

    #[test]
    fn bad_values_and_counts_name_their_line() {
        let (line, reason) = line_error(parse(&format!("{HEAD}NPTS=  3, DT= .01 SEC\n1.0 2.0\n0.12x\n"), G));
        assert_eq!((line, reason.as_str()), (6, "\"0.12x\" is not a number"));
        let (line, reason) = line_error(parse(&format!("{HEAD}NPTS=  3, DT= .0000 SEC\n1.0 2.0 3.0\n"), G));
        assert_eq!((line, reason.as_str()), (4, "DT must be > 0, got 0"));
        let (line, reason) = line_error(parse(&format!("{HEAD}NPTS=  3, DT= -.01 SEC\n1.0 2.0 3.0\n"), G));
        assert_eq!((line, reason.as_str()), (4, "DT must be > 0, got -0.01"));
        let (line, reason) = line_error(parse(&format!("{HEAD}NPTS=  3.5, DT= .01 SEC\n"), G));
        assert_eq!((line, reason.as_str()), (4, "NPTS must be a whole number, got \"3.5\""));
        let (line, reason) = line_error(parse(&format!("{HEAD}NPTS=  3, DT= .0x SEC\n"), G));
        assert_eq!((line, reason.as_str()), (4, "DT \".0x\" is not a number"));
        let (line, _) = line_error(parse(&format!("{HEAD}3 values at 0.01 s\n"), G));
        assert_eq!(line, 4);
    }

    #[test]
    fn too_short_a_header() {
        let result = parse("a\nb\nc\n", G);
        assert_eq!(result, Err(RecordError::Invalid("an AT2 file has 4 header lines, this one has 3".into())));
    }

    #[test]
    fn recognises_the_count_line_only() {
        assert!(!looks_like("time,acc\n0.0,0.1\n0.1,0.2\n0.2,0.3\n"));
        assert!(!looks_like("a\nb\nc\n"));
        assert!(!looks_like("a\nb\nNPTS= 3, DT= .01\nd\n"));
    }
}
