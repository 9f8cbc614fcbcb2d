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
    for (i, part) in path.iter().enumerate() {
        let entry = current.entry(part.to_string()).or_insert_with(|| Value::Table(Table::new()));
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
