//! The rows of a sweep: one [`Row`] of [`Cell`]s per case, in the order of
//! [`crate::Sweep::header`], and their CSV form.
//!
//! Numbers are written in their shortest form that reads back to the same
//! `f64` (as `summary.json` writes them), so a row holds exactly the numbers
//! of `rocking run` on the same case. Text is quoted as RFC 4180 says (an
//! error message may hold commas).

use std::fmt::Write as _;

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

    /// Appends the CSV field of this cell to `out`.
    pub fn write_csv(&self, out: &mut String) {
        match self {
            Cell::Empty => {}
            Cell::Bool(b) => out.push_str(if *b { "true" } else { "false" }),
            // Writing to a String cannot fail.
            Cell::Int(i) => {
                let _ = write!(out, "{i}");
            }
            Cell::Float(x) if x.is_finite() => out.push_str(ryu::Buffer::new().format_finite(*x)),
            Cell::Float(x) => {
                let _ = write!(out, "{x}");
            }
            Cell::Text(s) => push_text(out, s),
        }
    }
}

/// Appends `text` as one CSV field, quoted when it holds a comma, a quote or a line break.
fn push_text(out: &mut String, text: &str) {
    if text.contains([',', '"', '\n', '\r']) {
        out.push('"');
        out.push_str(&text.replace('"', "\"\""));
        out.push('"');
    } else {
        out.push_str(text);
    }
}

/// One line of CSV (without its line break) of `fields`.
pub fn csv_line<'a>(fields: impl IntoIterator<Item = &'a str>) -> String {
    let mut out = String::new();
    for (i, field) in fields.into_iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        push_text(&mut out, field);
    }
    out
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
        let mut out = String::with_capacity(16 * self.cells.len());
        for (i, cell) in self.cells.iter().enumerate() {
            if i > 0 {
                out.push(',');
            }
            cell.write_csv(&mut out);
        }
        out
    }
}
