//! A scenario as a JSON object (what a Python binding passes from a dict),
//! turned into the TOML table the parser reads.

use crate::error::{ErrorKind, Fault};
use serde_json::Value as Json;
use toml::{Table, Value};

/// The table of a JSON object; `null` members are dropped (an absent key).
pub(crate) fn to_table(value: Json) -> Result<Table, Fault> {
    match value {
        Json::Object(map) => object(map, ""),
        other => Err(Fault {
            key: None,
            kind: ErrorKind::WrongType {
                expected: "a JSON object",
                got: json_article(&other),
            },
        }),
    }
}

fn object(map: serde_json::Map<String, Json>, prefix: &str) -> Result<Table, Fault> {
    let mut table = Table::new();
    for (key, value) in map {
        let dotted = if prefix.is_empty() { key.clone() } else { format!("{prefix}.{key}") };
        if let Some(v) = convert(value, &dotted)? {
            table.insert(key, v);
        }
    }
    Ok(table)
}

fn convert(value: Json, key: &str) -> Result<Option<Value>, Fault> {
    Ok(Some(match value {
        Json::Null => return Ok(None),
        Json::Bool(b) => Value::Boolean(b),
        Json::Number(n) => match n.as_i64() {
            Some(i) => Value::Integer(i),
            None => Value::Float(n.as_f64().unwrap_or(f64::NAN)),
        },
        Json::String(s) => Value::String(s),
        Json::Array(items) => {
            let mut out = Vec::with_capacity(items.len());
            for (i, item) in items.into_iter().enumerate() {
                let item_key = format!("{key}[{i}]");
                match convert(item, &item_key)? {
                    Some(v) => out.push(v),
                    None => return Err(Fault::invalid(item_key, "null is not allowed in a list")),
                }
            }
            Value::Array(out)
        }
        Json::Object(map) => Value::Table(object(map, key)?),
    }))
}

fn json_article(value: &Json) -> &'static str {
    match value {
        Json::Null => "null",
        Json::Bool(_) => "a boolean",
        Json::Number(_) => "a number",
        Json::String(_) => "a string",
        Json::Array(_) => "an array",
        Json::Object(_) => "an object",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn converts_nested_objects_and_drops_nulls() {
        let t = to_table(json!({"tower": {"width": 4, "height": 12.5, "points": [[0, 12]], "depth": null}, "name": "x"}));
        let t = t.unwrap_or_else(|e| panic!("{e}"));
        let tower = t.get("tower").and_then(Value::as_table).cloned().unwrap_or_default();
        assert_eq!(tower.get("width"), Some(&Value::Integer(4)));
        assert_eq!(tower.get("height"), Some(&Value::Float(12.5)));
        assert_eq!(tower.get("depth"), None);
        assert_eq!(t.get("name"), Some(&Value::String("x".into())));
    }

    #[test]
    fn rejects_non_objects_and_nulls_in_lists() {
        let e = to_table(json!([1, 2])).err().map(|e| e.to_string());
        assert_eq!(e.as_deref(), Some("expected a JSON object, got an array"));
        let e = to_table(json!({"tower": {"points": [null]}})).err().map(|e| e.to_string());
        assert_eq!(e.as_deref(), Some("tower.points[0]: null is not allowed in a list"));
    }
}
