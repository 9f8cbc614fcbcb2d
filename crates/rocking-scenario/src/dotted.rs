//! Dotted keys (`"ground.frequency"`) into a scenario table: how a parametric
//! sweep sets one value of a case before the table is parsed.

use crate::read::with_article;
use toml::{Table, Value};

/// A dotted key that cannot be set.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum DottedKeyError {
    /// An empty key or an empty part (`"ground..frequency"`).
    #[error("`{0}` is not a dotted key (parts separated by single dots)")]
    Malformed(String),
    /// A part on the way is a value, not a table.
    #[error("cannot set `{key}`: `{prefix}` is {found}, not a table")]
    NotATable {
        /// The whole key.
        key: String,
        /// The part that is not a table.
        prefix: String,
        /// What it is ("a float").
        found: &'static str,
    },
}

/// Sets `key` (dotted, `"ground.frequency"`) to `value` in `table`, creating
/// the tables on the way; returns the value it replaced.
pub fn set_dotted(table: &mut Table, key: &str, value: Value) -> Result<Option<Value>, DottedKeyError> {
    let parts: Vec<&str> = key.split('.').collect();
    if parts.iter().any(|p| p.is_empty()) {
        return Err(DottedKeyError::Malformed(key.to_string()));
    }
    let (last, path) = parts.split_last().ok_or_else(|| DottedKeyError::Malformed(key.to_string()))?;
    let mut current = table;
    let mut parts_left = path.iter().enumerate().peekable();
    while let Some((i, part)) = parts_left.next() {
        let entry = current.entry(part.to_string()).or_insert_with(|| Value::Table(Table::new()));
        // An array of tables ([[support.mode]]) is entered by the next part,
        // a 1-based position: `support.mode.2.period`.
        let entry = match entry {
            Value::Array(items) => {
                let position = parts_left
                    .peek()
                    .and_then(|(_, p)| p.parse::<usize>().ok())
                    .filter(|k| (1..=items.len()).contains(k));
                match position {
                    Some(k) => {
                        parts_left.next();
                        &mut items[k - 1]
                    }
                    None => {
                        return Err(DottedKeyError::NotATable {
                            key: key.to_string(),
                            prefix: parts[..=i].join("."),
                            found: "an array (name an item by its position from 1)",
                        })
                    }
                }
            }
            other => other,
        };
        current = match entry {
            Value::Table(t) => t,
            other => {
                return Err(DottedKeyError::NotATable {
                    key: key.to_string(),
                    prefix: parts[..=i].join("."),
                    found: with_article(other),
                })
            }
        };
    }
    Ok(current.insert(last.to_string(), value))
}

/// The value at `key` (dotted) in `table`, if there is one.
pub fn get_dotted<'a>(table: &'a Table, key: &str) -> Option<&'a Value> {
    let mut parts = key.split('.');
    let mut value = table.get(parts.next()?)?;
    for part in parts {
        value = value.as_table()?.get(part)?;
    }
    Some(value)
}

/// Removes `key` (dotted) from `table`; returns the value it held.
pub fn remove_dotted(table: &mut Table, key: &str) -> Option<Value> {
    match key.rsplit_once('.') {
        None => table.remove(key),
        Some((parent, last)) => {
            let mut current = table;
            for part in parent.split('.') {
                current = current.get_mut(part)?.as_table_mut()?;
            }
            current.remove(last)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn base() -> Table {
        "[ground]\ntype = \"harmonic\"\nfrequency = 2.0\n".parse().unwrap_or_default()
    }

    #[test]
    fn replaces_and_creates() {
        let mut t = base();
        let old = set_dotted(&mut t, "ground.frequency", Value::Float(5.0));
        assert_eq!(old, Ok(Some(Value::Float(2.0))));
        assert_eq!(get_dotted(&t, "ground.frequency"), Some(&Value::Float(5.0)));
        assert_eq!(set_dotted(&mut t, "building.mu_static", Value::Float(1.25)), Ok(None));
        assert_eq!(get_dotted(&t, "building.mu_static"), Some(&Value::Float(1.25)));
        assert_eq!(set_dotted(&mut t, "name", Value::String("x".into())), Ok(None));
        assert_eq!(remove_dotted(&mut t, "ground.frequency"), Some(Value::Float(5.0)));
        assert_eq!(get_dotted(&t, "ground.frequency"), None);
    }

    #[test]
    fn enters_an_array_of_tables_by_position() {
        let mut t: Table = "[[support.mode]]\nperiod = 0.3\n[[support.mode]]\nperiod = 0.1\n".parse().unwrap_or_default();
        assert_eq!(set_dotted(&mut t, "support.mode.2.period", Value::Float(0.05)), Ok(Some(Value::Float(0.1))));
        let second = t["support"]["mode"].as_array().map(|m| m[1]["period"].clone());
        assert_eq!(second, Some(Value::Float(0.05)));
        let e = set_dotted(&mut t, "support.mode.3.period", Value::Float(0.05)).map_err(|e| e.to_string());
        assert_eq!(
            e,
            Err("cannot set `support.mode.3.period`: `support.mode` is an array (name an item by its position from 1), not a table".to_string())
        );
    }

    #[test]
    fn refuses_to_go_through_a_value() {
        let mut t = base();
        let e = set_dotted(&mut t, "ground.frequency.hz", Value::Float(1.0));
        assert_eq!(
            e.map_err(|e| e.to_string()),
            Err("cannot set `ground.frequency.hz`: `ground.frequency` is a float, not a table".to_string())
        );
        assert!(matches!(set_dotted(&mut t, "ground..x", Value::Float(1.0)), Err(DottedKeyError::Malformed(_))));
        assert!(matches!(set_dotted(&mut t, "", Value::Float(1.0)), Err(DottedKeyError::Malformed(_))));
    }
}
