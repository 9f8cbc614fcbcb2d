//! One axis of a sweep: a scalar scenario key and its values, given as a list
//! or as an evenly spaced range (docs/src/reference/keys.md, "[sweep]"); the rules are on [`AxisSpec`].

use crate::block::BlockNames;
use crate::error::{ErrorKind, Fault};
use crate::keys::KeyKind;
use crate::read::{as_number, with_article};
use std::sync::LazyLock;
use toml::Value;

/// At most this many values on one axis (a `step` far too small for its range
/// is an error, not an allocation of gigabytes).
pub const MAX_AXIS_VALUES: usize = 1_000_000;

/// The scalar keys of a scenario that a sweep can vary, as dotted keys, in
/// the order of the key reference: read from [`crate::SCENARIO_KEYS`] (every
/// key but a list or a table, and the keys of `[ground]` again as
/// `ground.vertical.KEY`).
pub static SWEEPABLE_KEYS: LazyLock<Vec<&'static str>> = LazyLock::new(crate::keys::sweepable_keys);

/// Keys that are alternatives of each other: an axis on one removes the other
/// from the base scenario (a scenario giving `amplitude` can be swept over
/// `amplitude_ratio`), and two axes on the same pair are an error.
pub(crate) const ALTERNATIVES: &[(&str, &str)] = &[
    ("ground.amplitude", "ground.amplitude_ratio"),
    ("ground.frequency", "ground.frequency_ratio"),
    ("ground.vertical.amplitude", "ground.vertical.amplitude_ratio"),
    ("ground.vertical.frequency", "ground.vertical.frequency_ratio"),
    ("initial.theta", "initial.theta_over_alpha"),
    ("tower.mass", "tower.density"),
];

/// The alternative of `key` (`ground.amplitude` ↔ `ground.amplitude_ratio`), if it has one.
pub(crate) fn alternative(key: &str) -> Option<&'static str> {
    ALTERNATIVES.iter().find_map(|&(a, b)| match key {
        k if k == a => Some(b),
        k if k == b => Some(a),
        _ => None,
    })
}

/// What a key takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum KeyType {
    Number,
    Text,
}

/// How the values of one axis are given (docs/src/reference/keys.md, "[sweep]"):
///
/// - `[v1, v2, …]`: those values, in that order (numbers for a numeric key,
///   strings for a string key such as `building.normal_force`).
/// - `{ from, to, steps }`: `steps` values (an integer >= 1) evenly spaced from
///   `from` to `to`, both included, like NumPy's `linspace`: value `i` is
///   `(from·(steps−1−i) + to·i) / (steps−1)`. `steps = 1` needs `from = to`.
/// - `{ from, to, step }`: `from, from ± step, …, to` (`step > 0`; the values
///   descend when `to < from`). The step must divide `to − from` to within 1e-9
///   of a step; one that does not is an error naming the key, rather than a
///   range that silently stops short of `to`. The values are those of
///   `steps = |to − from| / step + 1`.
///
/// Every range value is then rounded to the shortest decimal of at most 12
/// significant digits that lies within `4 ε max(|from|, |to|)` of it (a few
/// roundings of the arithmetic above), if there is one: `{ from = 3, to = 7,
/// steps = 41 }` gives 3.1, not 3.1000000000000001, and the value in
/// `sweep.csv` is the one a scenario file with `frequency = 3.1` would give.
/// `from` and `to` are kept exactly.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum AxisSpec {
    /// These values, in this order (TOML numbers or strings).
    List(Vec<Value>),
    /// `steps` values evenly spaced from `from` to `to`, both included.
    Steps {
        /// First value.
        from: f64,
        /// Last value.
        to: f64,
        /// Number of values (>= 1; 1 needs `from = to`).
        steps: i64,
    },
    /// `from, from ± step, …, to`; `step` (> 0) must divide `to − from`.
    Step {
        /// First value.
        from: f64,
        /// Last value.
        to: f64,
        /// Spacing (> 0).
        step: f64,
    },
}

/// One axis, expanded: the dotted key and its values in order.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    key: String,
    values: Vec<Value>,
}

impl Axis {
    /// The dotted scenario key (`ground.frequency`).
    pub fn key(&self) -> &str {
        &self.key
    }
    /// The values, in sweep order (floats or integers for a numeric key, strings for a string key).
    pub fn values(&self) -> &[Value] {
        &self.values
    }
    /// The number of values (>= 1).
    pub fn len(&self) -> usize {
        self.values.len()
    }
    /// Never true: an axis has at least one value.
    pub fn is_empty(&self) -> bool {
        self.values.is_empty()
    }
}

/// How an axis key is written in an error: `sweep."ground.frequency"`.
pub(crate) fn axis_name(key: &str) -> String {
    format!("sweep.\"{key}\"")
}

/// Checks that `key` is a scalar scenario key and says what it takes.
#[cfg(test)]
pub(crate) fn check_key(key: &str) -> Result<KeyType, Fault> {
    check_key_with(key, &BlockNames::default())
}

/// As [`check_key`], taking also the keys of the blocks named in `blocks`
/// (`belfry.width`), but not their names.
pub(crate) fn check_key_with(key: &str, blocks: &BlockNames) -> Result<KeyType, Fault> {
    // `block.width` would be every block's width and none: a block's key is its name's.
    if key.split_once('.').is_some_and(|(s, _)| s == crate::block::BLOCK) {
        return Err(unknown_key(key, blocks));
    }
    let described = crate::keys::block_axis_key(key, blocks);
    if described.as_deref() == Some("block.name") {
        return Err(Fault::invalid(axis_name(key), "a block's name cannot be swept (its outputs are named by it)"));
    }
    match crate::keys::describe_key(described.as_deref().unwrap_or(key)).map(|k| k.doc.kind) {
        Some(KeyKind::Number) => return Ok(KeyType::Number),
        Some(KeyKind::Text) => return Ok(KeyType::Text),
        _ => {}
    }
    let name = axis_name(key);
    if key == "tower.points" {
        return Err(Fault::new(
            name,
            ErrorKind::Invalid("is a list of points, not a scalar key: it cannot be swept".into()),
        ));
    }
    if crate::scenario::SECTIONS.contains(&key) {
        return Err(Fault::new(
            name,
            ErrorKind::Invalid(format!("is a section, not a scalar key: sweep one of its keys (\"{key}.…\")")),
        ));
    }
    Err(unknown_key(key, blocks))
}

/// `key` is no key a sweep can vary on a tower carrying `blocks`: the keys of
/// the section or the block it names, else every key (the blocks' after the
/// tower's, as the key reference orders them), with the closest suggested.
fn unknown_key(key: &str, blocks: &BlockNames) -> Fault {
    let of_blocks = || blocks.iter().flat_map(crate::keys::named_block_keys);
    let valid: Vec<String> = match key.split_once('.').map(|(s, _)| s) {
        Some(crate::block::BLOCK) if !blocks.is_empty() => of_blocks().collect(),
        Some(s) if s != crate::block::BLOCK && crate::scenario::SECTIONS.contains(&s) => SWEEPABLE_KEYS
            .iter()
            .filter(|k| k.split_once('.').is_some_and(|(p, _)| p == s))
            .map(|k| k.to_string())
            .collect(),
        Some(s) if blocks.position(s).is_some() => crate::keys::named_block_keys(s),
        _ => {
            let (tower, others): (Vec<&str>, Vec<&str>) = SWEEPABLE_KEYS.iter().partition(|k| **k == "name" || k.starts_with("tower."));
            tower
                .into_iter()
                .map(String::from)
                .chain(of_blocks())
                .chain(others.into_iter().map(String::from))
                .collect()
        }
    };
    Fault::new(axis_name(key), ErrorKind::unknown_key(key, &valid))
}

impl AxisSpec {
    /// Reads the value of `key` in `[sweep]`: a list, or a table
    /// `{ from, to, steps }` / `{ from, to, step }`. Errors name
    /// `sweep."key"` (and the range field or list item); the values themselves
    /// are checked by [`crate::Sweep::from_parts`].
    pub fn from_toml(key: &str, value: &Value) -> Result<Self, Fault> {
        let name = axis_name(key);
        match value {
            Value::Array(items) => Ok(Self::List(items.clone())),
            Value::Table(t) => {
                const FIELDS: &[&str] = &["from", "to", "steps", "step"];
                if let Some(k) = t.keys().find(|k| !FIELDS.contains(&k.as_str())) {
                    return Err(Fault::new(format!("{name}.{k}"), ErrorKind::unknown_key(k, FIELDS)));
                }
                let number = |field: &str| -> Result<f64, Fault> {
                    let fkey = format!("{name}.{field}");
                    let v = t.get(field).ok_or_else(|| {
                        Fault::new(
                            &fkey,
                            ErrorKind::Missing(format!(
                                "required: a range is {{ from, to, steps }} or {{ from, to, step }}, and it has no {field}"
                            )),
                        )
                    })?;
                    let x = as_number(v).ok_or_else(|| {
                        Fault::new(
                            &fkey,
                            ErrorKind::WrongType {
                                expected: "a number",
                                got: with_article(v),
                            },
                        )
                    })?;
                    if x.is_finite() {
                        Ok(x)
                    } else {
                        Err(Fault::invalid(fkey, format!("must be a finite number, got {x}")))
                    }
                };
                let (from, to) = (number("from")?, number("to")?);
                match (t.get("steps"), t.get("step")) {
                    (Some(_), Some(_)) => Err(Fault::new(
                        format!("{name}.step"),
                        ErrorKind::NotApplicable("give either steps (the number of values) or step (their spacing), not both".into()),
                    )),
                    (None, None) => Err(Fault::new(
                        format!("{name}.steps"),
                        ErrorKind::Missing("required: steps (the number of values) or step (their spacing)".into()),
                    )),
                    (Some(v), None) => match v {
                        Value::Integer(steps) => Ok(Self::Steps { from, to, steps: *steps }),
                        other => Err(Fault::new(
                            format!("{name}.steps"),
                            ErrorKind::WrongType {
                                expected: "an integer (the number of values, >= 1)",
                                got: with_article(other),
                            },
                        )),
                    },
                    (None, Some(_)) => Ok(Self::Step {
                        from,
                        to,
                        step: number("step")?,
                    }),
                }
            }
            other => Err(Fault::new(
                name,
                ErrorKind::WrongType {
                    expected: "a list of values or a range { from, to, steps } / { from, to, step }",
                    got: with_article(other),
                },
            )),
        }
    }

    /// The values of this axis for `key`, checked against what the key takes.
    pub(crate) fn expand(&self, key: &str) -> Result<Axis, Fault> {
        self.expand_with(key, &BlockNames::default())
    }

    /// As [`AxisSpec::expand`], taking also the keys of the blocks named in `blocks`.
    pub(crate) fn expand_with(&self, key: &str, blocks: &BlockNames) -> Result<Axis, Fault> {
        let kind = check_key_with(key, blocks)?;
        let name = axis_name(key);
        let values = match self {
            Self::List(items) => {
                if items.is_empty() {
                    return Err(Fault::invalid(name, "the list of values is empty: give at least one"));
                }
                if items.len() > MAX_AXIS_VALUES {
                    return Err(Fault::invalid(name, format!("{} values, more than {MAX_AXIS_VALUES}", items.len())));
                }
                for (i, item) in items.iter().enumerate() {
                    check_item(&format!("{name}[{i}]"), kind, item)?;
                }
                items.clone()
            }
            Self::Steps { from, to, steps } => {
                range_key(&name, kind)?;
                let n = match usize::try_from(*steps) {
                    Ok(n) if n >= 1 => n,
                    _ => {
                        return Err(Fault::invalid(
                            format!("{name}.steps"),
                            format!("must be an integer >= 1 (the number of values), got {steps}"),
                        ))
                    }
                };
                if n > MAX_AXIS_VALUES {
                    return Err(Fault::invalid(format!("{name}.steps"), format!("{n} values, more than {MAX_AXIS_VALUES}")));
                }
                if n == 1 && !within_rounding(*from, *to) {
                    return Err(Fault::invalid(
                        format!("{name}.steps"),
                        format!("steps = 1 gives the single value from = {from}, but to = {to}: give steps >= 2, or a list"),
                    ));
                }
                linspace(*from, *to, n).map(Value::Float).collect()
            }
            Self::Step { from, to, step } => {
                range_key(&name, kind)?;
                if !(step.is_finite() && *step > 0.0) {
                    return Err(Fault::invalid(format!("{name}.step"), format!("must be a finite number > 0, got {step}")));
                }
                let count = (to - from).abs() / step;
                let k = count.round();
                if !k.is_finite() || k >= MAX_AXIS_VALUES as f64 {
                    return Err(Fault::invalid(
                        format!("{name}.step"),
                        format!("{step} over {from}..{to} gives {count:.3e} values, more than {MAX_AXIS_VALUES}"),
                    ));
                }
                if (count - k).abs() > 1e-9 * k.max(1.0) {
                    return Err(Fault::invalid(
                        format!("{name}.step"),
                        format!(
                            "{step} does not divide to − from = {} ({count:.6} steps): choose a step that does, or give steps (the number of values)",
                            to - from
                        ),
                    ));
                }
                // k is a whole number below MAX_AXIS_VALUES: the cast is exact.
                linspace(*from, *to, k as usize + 1).map(Value::Float).collect()
            }
        };
        Ok(Axis { key: key.to_string(), values })
    }
}

fn range_key(name: &str, kind: KeyType) -> Result<(), Fault> {
    match kind {
        KeyType::Number => Ok(()),
        KeyType::Text => Err(Fault::new(
            name,
            ErrorKind::WrongType {
                expected: "a list of strings (the key takes a string, so a numeric range does not apply)",
                got: "a range",
            },
        )),
    }
}

fn check_item(name: &str, kind: KeyType, item: &Value) -> Result<(), Fault> {
    let wrong = |expected| {
        Err(Fault::new(
            name,
            ErrorKind::WrongType {
                expected,
                got: with_article(item),
            },
        ))
    };
    match (kind, item) {
        (KeyType::Number, Value::Integer(_)) => Ok(()),
        (KeyType::Number, Value::Float(x)) if x.is_finite() => Ok(()),
        (KeyType::Number, Value::Float(x)) => Err(Fault::invalid(name, format!("must be a finite number, got {x}"))),
        (KeyType::Number, _) => wrong("a number"),
        (KeyType::Text, Value::String(_)) => Ok(()),
        (KeyType::Text, _) => wrong("a string"),
    }
}

/// Whether `a` and `b` are equal to within a few roundings.
fn within_rounding(a: f64, b: f64) -> bool {
    (a - b).abs() <= 4.0 * f64::EPSILON * a.abs().max(b.abs())
}

/// `n` values evenly spaced from `from` to `to`, both kept exactly, the
/// others rounded to a short decimal when one is within rounding (module docs).
fn linspace(from: f64, to: f64, n: usize) -> impl Iterator<Item = f64> {
    let tolerance = 4.0 * f64::EPSILON * from.abs().max(to.abs());
    let last = n.saturating_sub(1);
    (0..n).map(move |i| match i {
        0 => from,
        i if i == last => to,
        i => {
            // One rounding per product, one for the sum, one for the quotient.
            let x = (from * (last - i) as f64 + to * i as f64) / last as f64;
            shortest_nearby(x, tolerance)
        }
    })
}

/// The shortest decimal (at most 12 significant digits) within `tolerance` of `x`, or `x`.
pub(crate) fn shortest_nearby(x: f64, tolerance: f64) -> f64 {
    if x.abs() <= tolerance {
        return 0.0;
    }
    for digits in 0..12 {
        if let Ok(candidate) = format!("{x:.digits$e}").parse::<f64>() {
            if (candidate - x).abs() <= tolerance {
                return candidate;
            }
        }
    }
    x
}
