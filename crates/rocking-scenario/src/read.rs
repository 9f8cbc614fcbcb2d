//! Typed, checked access to the keys of one section of a scenario.
//!
//! Every getter names the dotted key in its error; integers are accepted where
//! a number is expected (`width = 4`).

use crate::error::{ErrorKind, Fault};
use toml::{Table, Value};

/// One table of the scenario (`[tower]`), read key by key.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Section<'a> {
    name: &'static str,
    table: &'a Table,
}

/// "a string", "an integer", … for error messages.
pub(crate) fn with_article(value: &Value) -> &'static str {
    match value {
        Value::String(_) => "a string",
        Value::Integer(_) => "an integer",
        Value::Float(_) => "a float",
        Value::Boolean(_) => "a boolean",
        Value::Datetime(_) => "a date-time",
        Value::Array(_) => "an array",
        Value::Table(_) => "a table",
    }
}

/// A number (float or integer) or `None` for another type.
pub(crate) fn as_number(value: &Value) -> Option<f64> {
    match value {
        Value::Float(x) => Some(*x),
        // i64 → f64 rounds beyond 2^53; such values are far outside every physical range here.
        Value::Integer(i) => Some(*i as f64),
        _ => None,
    }
}

impl<'a> Section<'a> {
    /// The section `name` of the scenario, which must be a table.
    pub(crate) fn new(name: &'static str, value: &'a Value) -> Result<Self, Fault> {
        match value {
            Value::Table(table) => Ok(Self { name, table }),
            other => Err(Fault::new(
                name,
                ErrorKind::WrongType {
                    expected: "a table (a [section])",
                    got: with_article(other),
                },
            )),
        }
    }

    /// The dotted name of `key` in this section.
    pub(crate) fn key(&self, key: &str) -> String {
        format!("{}.{key}", self.name)
    }

    /// Rejects every key not in `valid`, naming it and listing the valid ones.
    pub(crate) fn only(&self, valid: &[&'static str]) -> Result<(), Fault> {
        match self.table.keys().find(|k| !valid.contains(&k.as_str())) {
            Some(k) => Err(Fault::new(self.key(k), ErrorKind::unknown_key(k, valid))),
            None => Ok(()),
        }
    }

    /// Rejects every key that is not a scenario key of this section; the list
    /// of valid keys is built only for the error.
    pub(crate) fn only_scenario_keys(&self) -> Result<(), Fault> {
        if self.table.keys().all(|k| crate::keys::is_section_key(self.name, k)) {
            return Ok(());
        }
        self.only(&crate::keys::section_keys(self.name))
    }

    /// The section's dotted name (`ground`, `ground.vertical`).
    pub(crate) fn name(&self) -> &'static str {
        self.name
    }

    /// The value of `key`, if given.
    pub(crate) fn get(&self, key: &str) -> Option<&'a Value> {
        self.table.get(key)
    }

    /// Whether `key` is given.
    pub(crate) fn has(&self, key: &str) -> bool {
        self.table.contains_key(key)
    }

    /// The keys given, in file order.
    pub(crate) fn keys(&self) -> impl Iterator<Item = &'a str> {
        self.table.keys().map(String::as_str)
    }

    fn wrong_type(&self, key: &str, expected: &'static str, got: &Value) -> Fault {
        Fault::new(
            self.key(key),
            ErrorKind::WrongType {
                expected,
                got: with_article(got),
            },
        )
    }

    /// An optional number (not yet range-checked).
    pub(crate) fn number(&self, key: &str) -> Result<Option<f64>, Fault> {
        match self.table.get(key) {
            None => Ok(None),
            Some(v) => as_number(v).map(Some).ok_or_else(|| self.wrong_type(key, "a number", v)),
        }
    }

    /// A number that must be given: its absence is an error saying `required: {what}`.
    pub(crate) fn required_number(&self, key: &str, what: &str) -> Result<f64, Fault> {
        self.number(key)?
            .ok_or_else(|| Fault::new(self.key(key), ErrorKind::Missing(format!("required: {what}"))))
    }

    /// An optional boolean (`true` or `false`).
    pub(crate) fn boolean(&self, key: &str) -> Result<Option<bool>, Fault> {
        match self.table.get(key) {
            None => Ok(None),
            Some(Value::Boolean(b)) => Ok(Some(*b)),
            Some(v) => Err(self.wrong_type(key, "true or false", v)),
        }
    }

    /// An optional string.
    pub(crate) fn string(&self, key: &str) -> Result<Option<&'a str>, Fault> {
        match self.table.get(key) {
            None => Ok(None),
            Some(Value::String(s)) => Ok(Some(s.as_str())),
            Some(v) => Err(self.wrong_type(key, "a string", v)),
        }
    }

    /// An optional string that must be one of `choices` (`name`, value).
    pub(crate) fn choice<T: Copy>(&self, key: &str, choices: &[(&'static str, T)]) -> Result<Option<T>, Fault> {
        let Some(s) = self.string(key)? else { return Ok(None) };
        match choices.iter().find(|(name, _)| *name == s) {
            Some(&(_, value)) => Ok(Some(value)),
            None => {
                let names: Vec<String> = choices.iter().map(|(n, _)| format!("\"{n}\"")).collect();
                Err(Fault::invalid(self.key(key), format!("\"{s}\" is not one of {}", names.join(", "))))
            }
        }
    }

    /// An optional list of `[x, y]` pairs of numbers.
    pub(crate) fn pairs(&self, key: &str) -> Result<Option<Vec<(f64, f64)>>, Fault> {
        let Some(v) = self.table.get(key) else { return Ok(None) };
        let Value::Array(items) = v else {
            return Err(self.wrong_type(key, "an array of [x, y] pairs", v));
        };
        let mut out = Vec::with_capacity(items.len());
        for (i, item) in items.iter().enumerate() {
            let item_key = format!("{}[{i}]", self.key(key));
            let pair = match item {
                Value::Array(xy) if xy.len() == 2 => xy.iter().map(as_number).collect::<Option<Vec<f64>>>(),
                _ => None,
            };
            match pair.as_deref() {
                Some(&[x, y]) if x.is_finite() && y.is_finite() => out.push((x, y)),
                Some(_) => return Err(Fault::invalid(item_key, "coordinates must be finite numbers")),
                None => {
                    return Err(Fault::new(
                        item_key,
                        ErrorKind::WrongType {
                            expected: "a pair [x, y] of numbers",
                            got: with_article(item),
                        },
                    ))
                }
            }
        }
        Ok(Some(out))
    }

    /// Fails if both `a` and `b` are given.
    pub(crate) fn exclusive(&self, a: &str, b: &str) -> Result<(), Fault> {
        if self.has(a) && self.has(b) {
            return Err(Fault::new(self.key(b), ErrorKind::NotApplicable(format!("give either {a} or {b}, not both"))));
        }
        Ok(())
    }
}

/// Checks that `value` (of `key`) is finite and > 0.
pub(crate) fn positive(key: &str, value: f64) -> Result<f64, Fault> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Fault::invalid(key, format!("must be a finite number > 0, got {value}")))
    }
}

/// Checks that `value` (of `key`) is finite and >= 0.
pub(crate) fn non_negative(key: &str, value: f64) -> Result<f64, Fault> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(Fault::invalid(key, format!("must be a finite number >= 0, got {value}")))
    }
}

/// Checks that `value` (of `key`) is finite.
pub(crate) fn finite(key: &str, value: f64) -> Result<f64, Fault> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Fault::invalid(key, format!("must be a finite number, got {value}")))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(text: &str) -> Value {
        Value::Table(text.parse::<Table>().unwrap_or_default())
    }

    #[test]
    fn integers_are_numbers_and_strings_are_not() {
        let v = table("a = 4\nb = 2.5\nc = \"x\"");
        let s = Section::new("tower", &v).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(s.number("a").ok().flatten(), Some(4.0));
        assert_eq!(s.number("b").ok().flatten(), Some(2.5));
        assert_eq!(s.number("z").ok().flatten(), None);
        let e = s.number("c").err().map(|e| e.to_string());
        assert_eq!(e.as_deref(), Some("tower.c: expected a number, got a string"));
    }

    #[test]
    fn pairs_name_the_bad_item() {
        let v = table("points = [[0.0, 12], [1.0]]");
        let s = Section::new("tower", &v).unwrap_or_else(|e| panic!("{e}"));
        let e = s.pairs("points").err().map(|e| e.to_string()).unwrap_or_default();
        assert!(e.starts_with("tower.points[1]: expected a pair [x, y] of numbers"), "{e}");
        let v = table("points = [[0.0, 12], [1.0, -2]]");
        let s = Section::new("tower", &v).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(s.pairs("points").ok().flatten(), Some(vec![(0.0, 12.0), (1.0, -2.0)]));
    }

    #[test]
    fn choice_lists_the_options() {
        let v = table("section = \"round\"");
        let s = Section::new("tower", &v).unwrap_or_else(|e| panic!("{e}"));
        let e = s.choice("section", &[("solid", 0), ("hollow", 1)]).err().map(|e| e.to_string());
        assert_eq!(e.as_deref(), Some("tower.section: \"round\" is not one of \"solid\", \"hollow\""));
    }

    #[test]
    fn a_section_must_be_a_table() {
        let e = Section::new("tower", &Value::Integer(3)).err().map(|e| e.to_string());
        assert_eq!(e.as_deref(), Some("tower: expected a table (a [section]), got an integer"));
    }
}
