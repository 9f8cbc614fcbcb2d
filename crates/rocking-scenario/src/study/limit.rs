//! Limit states of a study (`[[study.limit_state]]`) and the tally of their
//! exceedances per level as the rows of `stripes.csv` stream by: memory in
//! the number of limit states × levels, not cases.

use super::fit::{fit_until, Fit, Stripe};
use crate::error::{ErrorKind, Fault};
use crate::read::{as_number, with_article};
use crate::{Cell, Row};
use std::sync::atomic::AtomicBool;
use toml::Value;

/// The columns of `fragility.csv`.
pub const FRAGILITY_HEADER: [&str; 6] = ["limit_state", "median", "beta", "cases", "exceeded", "method"];
/// The columns of `fractions.csv`.
pub const FRACTIONS_HEADER: [&str; 4] = ["limit_state", "level", "cases", "exceeded"];

/// When a case exceeds a limit state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Threshold {
    /// A numeric field exceeds when it is greater than this (an empty field does not).
    Above(f64),
    /// A boolean field exceeds when true.
    True,
}

/// One limit state: a name, a scalar field of `summary.json` and its threshold.
#[derive(Debug, Clone, PartialEq)]
pub struct LimitState {
    /// The name (unique in the study).
    pub name: String,
    /// The field of `summary.json` (a dotted name for a nested one: `time_in_regime_s.rocking`).
    pub field: String,
    /// When it is exceeded.
    pub threshold: Threshold,
}

impl LimitState {
    /// Whether `cell` (the field's value in a case that ran) exceeds the limit state.
    pub fn exceeded_by(&self, cell: &Cell) -> bool {
        match (self.threshold, cell) {
            (Threshold::True, Cell::Bool(b)) => *b,
            (Threshold::Above(limit), cell) => cell.as_f64().is_some_and(|x| x > limit),
            _ => false,
        }
    }
}

const KEYS: &[&str] = &["name", "field", "above"];

/// The fields of `summary.json` that only a tower has (empty, or always
/// false, in a run without one).
pub const TOWER_FIELDS: [&str; 19] = [
    "alpha_rad",
    "R_m",
    "p_rad_s",
    "restitution",
    "uplift_acceleration_g",
    "max_abs_theta_rad",
    "max_theta_over_alpha",
    "impacts",
    "overturned",
    "overturn_time_s",
    "first_uplift_time_s",
    "max_top_displacement_m",
    "max_top_abs_acceleration_m_s2",
    "max_pivot_friction_demand",
    "tower_uplift_detected",
    "time_in_regime_s.rocking",
    "time_in_regime_s.rocking_sliding",
    "min_theta_rad",
    "max_theta_rad",
];

/// The fields of `summary.json` that only a building that can slide has.
pub const BUILDING_FIELDS: [&str; 6] = [
    "slip_acceleration_g",
    "max_abs_slip_m",
    "final_slip_m",
    "first_slip_time_s",
    "time_in_regime_s.sliding",
    "time_in_regime_s.rocking_sliding",
];

/// Refuses a limit state on a field the study's scenario cannot have (a
/// tower's field without `[tower]`, a slip without `[building]`): every case
/// would count as not exceeded, and the study would report "0 exceeded".
pub(crate) fn check_fields(states: &[LimitState], tower: bool, building: bool) -> Result<(), Fault> {
    for (i, state) in states.iter().enumerate() {
        let missing = if !tower && TOWER_FIELDS.contains(&state.field.as_str()) {
            Some("a field of the tower, and the scenario has no [tower]")
        } else if !building && BUILDING_FIELDS.contains(&state.field.as_str()) {
            Some("a field of the building's slip, and the scenario has no [building]")
        } else {
            None
        };
        if let Some(why) = missing {
            return Err(Fault::new(
                format!("study.limit_state[{i}].field"),
                ErrorKind::NotApplicable(format!("\"{}\" is {why}: no case could exceed it", state.field)),
            ));
        }
    }
    Ok(())
}

/// Reads `[[study.limit_state]]` against the summary's fields (`template`: their names and kinds).
pub(crate) fn parse(value: Option<&Value>, template: &[(String, Cell)]) -> Result<Vec<LimitState>, Fault> {
    let items = match value {
        None => return Ok(Vec::new()),
        Some(Value::Array(items)) => items,
        Some(other) => {
            return Err(Fault::new(
                "study.limit_state",
                ErrorKind::WrongType {
                    expected: "an array of tables ([[study.limit_state]])",
                    got: with_article(other),
                },
            ))
        }
    };
    let fields: Vec<&str> = template.iter().filter(|(_, c)| !matches!(c, Cell::Text(_))).map(|(k, _)| k.as_str()).collect();
    let mut states: Vec<LimitState> = Vec::with_capacity(items.len());
    for (i, item) in items.iter().enumerate() {
        let at = |k: &str| format!("study.limit_state[{i}].{k}");
        let Value::Table(t) = item else {
            return Err(Fault::new(
                format!("study.limit_state[{i}]"),
                ErrorKind::WrongType {
                    expected: "a table",
                    got: with_article(item),
                },
            ));
        };
        if let Some(k) = t.keys().find(|k| !KEYS.contains(&k.as_str())) {
            return Err(Fault::new(at(k), ErrorKind::unknown_key(k, KEYS)));
        }
        let string = |k: &str| match t.get(k) {
            Some(Value::String(s)) if !s.is_empty() => Ok(s.clone()),
            Some(Value::String(_)) => Err(Fault::invalid(at(k), "must not be empty")),
            Some(other) => Err(Fault::new(
                at(k),
                ErrorKind::WrongType {
                    expected: "a string",
                    got: with_article(other),
                },
            )),
            None => Err(Fault::new(at(k), ErrorKind::Missing("required".into()))),
        };
        let name = string("name")?;
        if states.iter().any(|s| s.name == name) {
            return Err(Fault::invalid(at("name"), format!("\"{name}\" names two limit states")));
        }
        let field = string("field")?;
        let Some((_, kind)) = template.iter().find(|(k, _)| *k == field) else {
            return Err(Fault::invalid(
                at("field"),
                format!("\"{field}\" is not a numeric or boolean field of summary.json; valid: {}", fields.join(", ")),
            ));
        };
        let threshold = match (kind, t.get("above")) {
            (Cell::Text(_), _) => return Err(Fault::invalid(at("field"), format!("\"{field}\" is text, not a numeric or boolean field"))),
            (Cell::Bool(_), None) => Threshold::True,
            (Cell::Bool(_), Some(_)) => {
                return Err(Fault::new(
                    at("above"),
                    ErrorKind::NotApplicable(format!("\"{field}\" is a boolean: it is exceeded when true, without a threshold")),
                ))
            }
            (_, None) => {
                return Err(Fault::new(
                    at("above"),
                    ErrorKind::Missing(format!("required: \"{field}\" is numeric, give the value it must exceed")),
                ))
            }
            (_, Some(v)) => match as_number(v) {
                Some(x) if x.is_finite() => Threshold::Above(x),
                Some(x) => return Err(Fault::invalid(at("above"), format!("must be a finite number, got {x}"))),
                None => {
                    return Err(Fault::new(
                        at("above"),
                        ErrorKind::WrongType {
                            expected: "a number",
                            got: with_article(v),
                        },
                    ))
                }
            },
        };
        states.push(LimitState { name, field, threshold });
    }
    Ok(states)
}

/// Exceedances of each limit state at each level, counted from rows in any order.
#[derive(Debug, Clone)]
pub struct Tally {
    states: Vec<LimitState>,
    /// The column of each limit state's field in a row.
    columns: Vec<usize>,
    levels: Vec<f64>,
    /// `counts[state][level] = (cases, exceeded)`.
    counts: Vec<Vec<(u64, u64)>>,
}

impl Tally {
    /// An empty tally; `header` gives the columns of the rows it will see.
    pub fn new(states: &[LimitState], levels: &[f64], header: &[String]) -> Self {
        let columns = states.iter().map(|s| header.iter().position(|h| *h == s.field).unwrap_or(usize::MAX)).collect();
        Self {
            states: states.to_vec(),
            columns,
            levels: levels.to_vec(),
            counts: vec![vec![(0, 0); levels.len()]; states.len()],
        }
    }

    /// Counts row `row` (case `index` is at level `index % levels`); a failed case is not counted.
    pub fn add(&mut self, row: &Row) {
        if row.error().is_some() || self.levels.is_empty() {
            return;
        }
        let level = row.index % self.levels.len();
        for ((state, &column), counts) in self.states.iter().zip(&self.columns).zip(&mut self.counts) {
            let exceeded = row.cells.get(column).is_some_and(|c| state.exceeded_by(c));
            counts[level].0 += 1;
            counts[level].1 += u64::from(exceeded);
        }
    }

    /// The stripes of limit state `state`, one per level in order.
    pub fn stripes(&self, state: usize) -> Vec<Stripe> {
        self.levels
            .iter()
            .zip(&self.counts[state])
            .map(|(&level, &(cases, exceeded))| Stripe { level, cases, exceeded })
            .collect()
    }

    /// The limit states.
    pub fn limit_states(&self) -> &[LimitState] {
        &self.states
    }

    /// The fitted fragility of every limit state, in order.
    pub fn fits(&self) -> Vec<Fit> {
        self.fits_until(&AtomicBool::new(false))
    }

    /// The fits as [`Tally::fits`] makes them, given up once `cancel` is set
    /// (Ctrl-C: see [`fit_until`]).
    pub fn fits_until(&self, cancel: &AtomicBool) -> Vec<Fit> {
        (0..self.states.len()).map(|i| fit_until(&self.stripes(i), cancel)).collect()
    }

    /// `fragility.csv`: header and one line per limit state, with its fit in `fits` ([`Tally::fits`]).
    pub fn fragility_csv(&self, fits: &[Fit]) -> String {
        let mut out = crate::csv_line(FRAGILITY_HEADER) + "\n";
        for (state, f) in self.states.iter().zip(fits) {
            let cells = [
                Cell::Text(state.name.clone()),
                f.median.map_or(Cell::Empty, Cell::Float),
                f.beta.map_or(Cell::Empty, Cell::Float),
                Cell::Int(i64::try_from(f.cases).unwrap_or(i64::MAX)),
                Cell::Int(i64::try_from(f.exceeded).unwrap_or(i64::MAX)),
                Cell::Text(f.method.clone()),
            ];
            out.push_str(
                &Row {
                    index: 0,
                    cells: cells.to_vec(),
                }
                .to_csv_line(),
            );
            out.push('\n');
        }
        out
    }

    /// `fractions.csv`: header and one line per limit state and level.
    pub fn fractions_csv(&self) -> String {
        let mut out = crate::csv_line(FRACTIONS_HEADER) + "\n";
        for (i, state) in self.states.iter().enumerate() {
            for s in self.stripes(i) {
                let cells = vec![
                    Cell::Text(state.name.clone()),
                    Cell::Float(s.level),
                    Cell::Int(i64::try_from(s.cases).unwrap_or(i64::MAX)),
                    Cell::Int(i64::try_from(s.exceeded).unwrap_or(i64::MAX)),
                ];
                out.push_str(&Row { index: 0, cells }.to_csv_line());
                out.push('\n');
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn header() -> Vec<String> {
        ["record", "level", "scale", "max_theta_over_alpha", "overturned", "error"]
            .map(String::from)
            .to_vec()
    }

    fn row(index: usize, theta: Cell, overturned: Cell, error: Cell) -> Row {
        let cells = vec![Cell::Text("r".into()), Cell::Float(0.0), Cell::Float(1.0), theta, overturned, error];
        Row { index, cells }
    }

    /// Counted by hand: a numeric state exceeds strictly above its threshold
    /// (an empty cell never does), a boolean one when true, and a failed case
    /// counts in neither `cases` nor `exceeded`.
    #[test]
    fn tally_counts_by_hand() {
        let states = [
            LimitState {
                name: "half".into(),
                field: "max_theta_over_alpha".into(),
                threshold: Threshold::Above(0.5),
            },
            LimitState {
                name: "collapse".into(),
                field: "overturned".into(),
                threshold: Threshold::True,
            },
        ];
        let mut tally = Tally::new(&states, &[0.1, 0.2], &header());
        // Level 0.1 (even indices): 0.5 (not above), 0.7 with overturned, empty, failed.
        // Level 0.2 (odd indices): 0.51, 3.0 with overturned.
        let rows = [
            row(0, Cell::Float(0.5), Cell::Bool(false), Cell::Empty),
            row(1, Cell::Float(0.51), Cell::Bool(false), Cell::Empty),
            row(2, Cell::Float(0.7), Cell::Bool(true), Cell::Empty),
            row(3, Cell::Float(3.0), Cell::Bool(true), Cell::Empty),
            row(4, Cell::Empty, Cell::Bool(false), Cell::Empty),
            row(6, Cell::Empty, Cell::Empty, Cell::Text("boom".into())),
        ];
        for r in &rows {
            tally.add(r);
        }
        let counts = |i: usize| tally.stripes(i).iter().map(|s| (s.cases, s.exceeded)).collect::<Vec<_>>();
        assert_eq!(counts(0), [(3, 1), (2, 2)]);
        assert_eq!(counts(1), [(3, 1), (2, 1)]);
        assert_eq!(
            tally.fractions_csv(),
            "limit_state,level,cases,exceeded\nhalf,0.1,3,1\nhalf,0.2,2,2\ncollapse,0.1,3,1\ncollapse,0.2,2,1\n"
        );
    }
}
