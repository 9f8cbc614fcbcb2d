//! The rows of a sweep: one [`Row`] of [`Cell`]s per case, in the order of
//! [`crate::Sweep::header`], and their CSV form.
//!
//! Numbers are written in their shortest form that reads back to the same
//! `f64` (as `summary.json` writes them), so a row holds exactly the numbers
//! of `rocking run` on the same case. Lines are written by the `csv` crate,
//! the writer of every CSV file of the project: text is quoted as RFC 4180
//! says (an error message may hold commas).

use std::borrow::Cow;

/// One value of a row.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// No value: a quantity that does not exist (`null` in `summary.json`:
    /// the slip without a building), or any result of a failed case.
    Empty,
    /// A boolean (`overturned`).
    Bool(bool),
    /// An integer (`impacts`, an integer axis value).
    Int(i64),
    /// A number.
    Float(f64),
    /// Text (`name`, `end_reason`, a string axis value, the error message).
    Text(String),
}

impl Cell {
    /// The number in this cell (an integer as a float); `None` for anything else.
    pub fn as_f64(&self) -> Option<f64> {
        match self {
            Cell::Float(x) => Some(*x),
            Cell::Int(i) => Some(*i as f64),
            _ => None,
        }
    }

    /// The text in this cell, if it holds text.
    pub fn as_str(&self) -> Option<&str> {
        match self {
            Cell::Text(s) => Some(s),
            _ => None,
        }
    }

    /// Whether the cell is empty.
    pub fn is_empty(&self) -> bool {
        matches!(self, Cell::Empty)
    }

    /// The cell of a TOML value (an axis value).
    pub fn from_toml(value: &toml::Value) -> Self {
        match value {
            toml::Value::Float(x) => Cell::Float(*x),
            toml::Value::Integer(i) => Cell::Int(*i),
            toml::Value::Boolean(b) => Cell::Bool(*b),
            toml::Value::String(s) => Cell::Text(s.clone()),
            other => Cell::Text(other.to_string()),
        }
    }

    /// The cell of a JSON scalar (a field of `summary.json`).
    pub fn from_json(value: &serde_json::Value) -> Self {
        match value {
            serde_json::Value::Null => Cell::Empty,
            serde_json::Value::Bool(b) => Cell::Bool(*b),
            serde_json::Value::Number(n) => match n.as_i64() {
                Some(i) => Cell::Int(i),
                None => n.as_f64().map_or(Cell::Empty, Cell::Float),
            },
            serde_json::Value::String(s) => Cell::Text(s.clone()),
            other => Cell::Text(other.to_string()),
        }
    }

    /// The cell of a CSV field's text as [`Cell::text`] writes it: empty,
    /// `true`/`false`, an integer, a number, else text (a row read back).
    pub fn from_text(text: &str) -> Self {
        match text {
            "" => Cell::Empty,
            "true" => Cell::Bool(true),
            "false" => Cell::Bool(false),
            _ => text
                .parse::<i64>()
                .map(Cell::Int)
                .or_else(|_| text.parse::<f64>().map(Cell::Float))
                .unwrap_or_else(|_| Cell::Text(text.to_string())),
        }
    }

    /// The text of this cell's CSV field, before quoting.
    pub fn text(&self) -> Cow<'_, str> {
        match self {
            Cell::Empty => Cow::Borrowed(""),
            Cell::Bool(b) => Cow::Borrowed(if *b { "true" } else { "false" }),
            Cell::Int(i) => Cow::Owned(i.to_string()),
            Cell::Float(x) if x.is_finite() => Cow::Owned(ryu::Buffer::new().format_finite(*x).to_owned()),
            Cell::Float(x) => Cow::Owned(x.to_string()),
            Cell::Text(s) => Cow::Borrowed(s),
        }
    }
}

/// The first characters that make a spreadsheet read a cell as a formula
/// (`=HYPERLINK(...)`, `+cmd`, `-2+3`, `@SUM(...)`) or strip them (TAB, CR).
const FORMULA_STARTS: [u8; 6] = [b'=', b'+', b'-', b'@', b'\t', b'\r'];

/// Whether the CSV field `field` needs a leading `'` to be shown as text: it
/// begins with one of [`FORMULA_STARTS`] and is not a number (`-2`, `+1e-3`,
/// `-inf` are left as they are: a spreadsheet reads them as numbers).
fn reads_as_a_formula(field: &[u8]) -> bool {
    field.first().is_some_and(|b| FORMULA_STARTS.contains(b)) && std::str::from_utf8(field).map_or(true, |t| t.parse::<f64>().is_err())
}

/// `text` as a CSV cell that a spreadsheet shows as text: a text beginning
/// with `=`, `+`, `-`, `@`, a TAB or a CR gets a leading `'` (OWASP's rule
/// against CSV injection); a number and any other text are left as they are.
/// Every CSV the tool writes passes its text cells through this (or [`csv_line`]).
pub fn spreadsheet_text(text: &str) -> Cow<'_, str> {
    if reads_as_a_formula(text.as_bytes()) {
        Cow::Owned(format!("'{text}"))
    } else {
        Cow::Borrowed(text)
    }
}

/// One line of CSV (without its line break) of `fields`, quoted where needed,
/// a text that a spreadsheet would read as a formula written as text ([`spreadsheet_text`]).
pub fn csv_line<I>(fields: I) -> String
where
    I: IntoIterator,
    I::Item: AsRef<[u8]>,
{
    // A line's buffer, not the writer's default 8 KiB (zeroed at every line):
    // a longer line is only flushed more often into the vector.
    let mut writer = csv::WriterBuilder::new()
        .terminator(csv::Terminator::Any(b'\n'))
        .buffer_capacity(1024)
        .from_writer(Vec::with_capacity(1024));
    // Writing to memory cannot fail.
    for field in fields {
        let field = field.as_ref();
        let _ = if reads_as_a_formula(field) {
            writer.write_field([b"'".as_slice(), field].concat())
        } else {
            writer.write_field(field)
        };
    }
    let _ = writer.write_record(None::<&[u8]>);
    let mut bytes = writer.into_inner().unwrap_or_default();
    bytes.pop();
    // The fields were text, and quoting adds only ASCII.
    String::from_utf8(bytes).unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned())
}

/// The result of one case: its cells in the order of [`crate::Sweep::header`]
/// (the axis values, the summary's scalar fields, then `error`).
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// The case's place in the sweep (0-based; the first axis varies slowest).
    pub index: usize,
    /// One cell per column of the header.
    pub cells: Vec<Cell>,
}

impl Row {
    /// The error message of a failed case (the last cell), `None` for a case that ran.
    pub fn error(&self) -> Option<&str> {
        self.cells.last().and_then(Cell::as_str)
    }

    /// The row as one line of CSV, without its line break.
    pub fn to_csv_line(&self) -> String {
        csv_line(self.cells.iter().map(|cell| cell.text().into_owned()))
    }
}
