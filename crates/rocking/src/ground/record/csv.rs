//! Comma-separated records: `time,acceleration` columns, or one acceleration
//! column sampled every `dt`; an optional header line first, comment lines
//! starting with `#` anywhere.

use super::scan::{lines, not_a_number, parse_number};
use super::{CsvOptions, Record, RecordError};

/// The data lines: comment lines (starting with `#`, as in the records
/// shipped with pySLAMMER) are skipped wherever they are.
fn data_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    lines(text).filter(|(_, line)| !line.starts_with('#'))
}

/// True if the first line (after an optional header) holds 1 or 2 comma-separated numbers.
pub(super) fn looks_like(text: &str) -> bool {
    let mut rows = data_lines(text).map(|(_, line)| line).peekable();
    rows.next_if(|line| is_header(line));
    rows.next().is_some_and(|row| {
        let cells: Vec<&str> = cells(row).collect();
        cells.len() <= 2 && cells.iter().all(|cell| parse_number(cell).is_some())
    })
}

/// Reads a CSV record; values in `options.units`, `g` (m/s²) for values in g.
///
/// Streams the lines into the two columns (no vector per row: a one-column
/// file of 1e7 samples took 1.39 GB that way), checking times as they come.
pub(super) fn parse(text: &str, options: &CsvOptions, g: f64) -> Result<Record, RecordError> {
    let scale = options.units.to_si(g);
    // Column count and line of the first data row.
    let mut first: Option<(usize, usize)> = None;
    let mut previous = (0usize, 0.0f64);
    let (mut times, mut values) = (Vec::new(), Vec::new());
    for (k, (line, text)) in data_lines(text).enumerate() {
        if k == 0 && is_header(text) {
            continue;
        }
        let (count, row) = row(line, text)?;
        let (first_line, columns) = *first.get_or_insert((line, count));
        if count != columns || columns > 2 {
            let expected = if line == first_line {
                "1 column (acceleration) or 2 (time,acceleration)".to_string()
            } else {
                format!("{columns} columns as on line {first_line}")
            };
            return Err(RecordError::Line {
                line,
                reason: format!("expected {expected}, found {count}"),
            });
        }
        if columns == 2 {
            let t = row[0];
            if line == first_line && t < 0.0 {
                return Err(RecordError::Line {
                    line,
                    reason: format!("the first time must be >= 0, got {t}"),
                });
            }
            if line != first_line && t <= previous.1 {
                return Err(RecordError::Line {
                    line,
                    reason: format!("time {t} does not come after {} (line {})", previous.1, previous.0),
                });
            }
            previous = (line, t);
            times.push(t);
            values.push(row[1] * scale);
        } else {
            values.push(row[0] * scale);
        }
    }
    let Some((_, columns)) = first else {
        return Err(RecordError::Invalid("the CSV file has no data lines".into()));
    };
    if columns == 1 {
        let dt = options
            .dt
            .ok_or_else(|| RecordError::Invalid("a CSV file with one column (acceleration) needs `dt`, the time step in s".into()))?;
        if !(dt.is_finite() && dt > 0.0) {
            return Err(RecordError::Invalid(format!("dt must be > 0, got {dt}")));
        }
        Record::uniform(dt, values)
    } else {
        Record::from_samples(times, values)
    }
}

/// The trimmed cells of a line.
fn cells(line: &str) -> impl Iterator<Item = &str> {
    line.split(',').map(str::trim)
}

/// A header line: not one of its cells is a number.
fn is_header(line: &str) -> bool {
    cells(line).all(|cell| parse_number(cell).is_none())
}

/// The number of cells of one line and the first two as numbers (a third
/// cell is counted, not read: the row is refused for its count).
fn row(line: usize, text: &str) -> Result<(usize, [f64; 2]), RecordError> {
    let mut values = [0.0; 2];
    let mut count = 0;
    for (k, cell) in cells(text).enumerate() {
        count += 1;
        if k >= 2 {
            continue;
        }
        values[k] = match (cell.is_empty(), parse_number(cell)) {
            (_, Some(value)) => value,
            (true, None) => {
                return Err(RecordError::Line {
                    line,
                    reason: format!("column {} is empty", k + 1),
                })
            }
            (false, None) => return Err(not_a_number(line, cell)),
        };
    }
    Ok((count, values))
}

#[cfg(test)]
mod tests {
    use super::super::AccelerationUnit;
    use super::*;
    use approx::assert_relative_eq;

    const G: f64 = 9.81;

    fn options(units: AccelerationUnit, dt: Option<f64>) -> CsvOptions {
        CsvOptions { units, dt }
    }

    fn line_error(result: Result<Record, RecordError>) -> (usize, String) {
        match result {
            Err(RecordError::Line { line, reason }) => (line, reason),
            other => panic!("expected a line error, got {other:?}"),
        }
    }

    #[test]
    fn two_columns_with_header_in_g() {
        let text = "time,acceleration\n0.0,0.1\n0.02,-0.25\n0.04,0.5\n";
        let record = parse(text, &CsvOptions::default(), G).expect("valid");
        assert_eq!(record.len(), 3);
        assert_relative_eq!(record.times()[2], 0.04);
        // -0.25 g = -2.4525 m/s².
        assert_relative_eq!(record.values()[1], -2.4525, max_relative = 1e-15);
        assert_relative_eq!(record.time_step().expect("uniform"), 0.02, max_relative = 1e-12);
    }

    #[test]
    fn two_columns_ignore_dt_and_take_units() {
        let text = "0.0, 10.0\n0.5, -20.0\n";
        let record = parse(text, &options(AccelerationUnit::CentimetersPerSecond2, Some(0.01)), G).expect("valid");
        assert_relative_eq!(record.times()[1], 0.5);
        assert_relative_eq!(record.values()[0], 0.1, max_relative = 1e-15);
        assert_relative_eq!(record.values()[1], -0.2, max_relative = 1e-15);
    }

    #[test]
    fn one_column_needs_dt() {
        let text = "acc\n1.5\n-3.0\n2.0\n";
        let record = parse(text, &options(AccelerationUnit::MetersPerSecond2, Some(0.01)), G).expect("valid");
        assert_eq!(record.len(), 3);
        assert_relative_eq!(record.times()[2], 0.02);
        assert_relative_eq!(record.values()[1], -3.0);
        let missing = parse(text, &options(AccelerationUnit::MetersPerSecond2, None), G);
        assert!(matches!(missing, Err(RecordError::Invalid(ref m)) if m.contains("`dt`")), "{missing:?}");
        let zero = parse(text, &options(AccelerationUnit::G, Some(0.0)), G);
        assert!(matches!(zero, Err(RecordError::Invalid(ref m)) if m.contains("dt must be > 0")), "{zero:?}");
    }

    #[test]
    fn crlf_spaces_trailing_blank_line_and_d_exponents() {
        let text = "  time , acc  \r\n 0.0 , 1.0D-01 \r\n 1.0D-02 , -2.5d-01\r\n\r\n";
        let record = parse(text, &CsvOptions::default(), G).expect("valid");
        assert_eq!(record.len(), 2);
        assert_relative_eq!(record.times()[1], 0.01);
        // 0.1 g = 0.981 m/s², -0.25 g = -2.4525 m/s².
        assert_relative_eq!(record.values()[0], 0.981, max_relative = 1e-15);
        assert_relative_eq!(record.values()[1], -2.4525, max_relative = 1e-15);
    }

    #[test]
    fn bad_values_name_their_line() {
        let (line, reason) = line_error(parse("t,a\n0.0,0.1\n0.1,0.12x\n", &CsvOptions::default(), G));
        assert_eq!((line, reason.as_str()), (3, "\"0.12x\" is not a number"));
        // A header is only skipped on the first line.
        let (line, reason) = line_error(parse("0.0,0.1\ntime,acc\n", &CsvOptions::default(), G));
        assert_eq!((line, reason.as_str()), (2, "\"time\" is not a number"));
        let (line, reason) = line_error(parse("0.0,0.1\n0.1,\n", &CsvOptions::default(), G));
        assert_eq!((line, reason.as_str()), (2, "column 2 is empty"));
    }

    #[test]
    fn wrong_column_counts_name_their_line() {
        let (line, reason) = line_error(parse("t,a\n0.0,0.1\n0.1\n", &CsvOptions::default(), G));
        assert_eq!((line, reason.as_str()), (3, "expected 2 columns as on line 2, found 1"));
        let (line, reason) = line_error(parse("0.0,0.1,0.2\n", &CsvOptions::default(), G));
        assert_eq!(
            (line, reason.as_str()),
            (1, "expected 1 column (acceleration) or 2 (time,acceleration), found 3")
        );
    }

    #[test]
    fn times_must_increase() {
        let (line, reason) = line_error(parse("0.0,0.1\n0.1,0.2\n0.1,0.3\n", &CsvOptions::default(), G));
        assert_eq!((line, reason.as_str()), (3, "time 0.1 does not come after 0.1 (line 2)"));
        let (line, _) = line_error(parse("-0.1,0.1\n0.1,0.2\n", &CsvOptions::default(), G));
        assert_eq!(line, 1);
    }

    #[test]
    fn empty_files_are_invalid() {
        assert!(matches!(parse("time,acc\n\n", &CsvOptions::default(), G), Err(RecordError::Invalid(_))));
    }

    #[test]
    fn recognises_numeric_csv_only() {
        assert!(looks_like("time,acc\n0.0,0.1\n"));
        assert!(looks_like("\r\n0.1\r\n0.2\r\n"));
        assert!(looks_like("1.0D-03, 2\n"));
        assert!(!looks_like("0.0,0.1,0.2\n"));
        assert!(!looks_like("EVENT_NAME: X\nSAMPLING_INTERVAL_S: 0.01\n"));
        assert!(!looks_like("title\nmore text\n"));
        assert!(!looks_like(""));
    }
}
