//! One descriptor per output column and summary field: its name, unit,
//! meaning, when it is present and how it is read from a run. Every writer
//! takes its columns from here (the command's `history.csv`, `events.csv`,
//! `summary.json` and `sweep.csv`, the Python arrays and dicts, the figures),
//! and so does the outputs reference ([`outputs_markdown`]); a column added to
//! one of these lists appears in all of them.
//!
//! An optional column is one entry with a presence condition on the run's
//! [`Layout`] (a vertical ground motion, when it comes, adds `ground_acc_v`).

use crate::block::BlockNames;
use crate::run::Outcome;
use crate::sweep::Cell;
use rocking::{EndReason, Event, Motion, Sample};
use std::borrow::Cow;

/// What a run's outputs hold beyond the fixed columns: the presence
/// conditions read it. Known before the run (from the scenario).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Layout {
    /// Extra tower points (`tower.points`): `pK_dx`, `pK_abs_acc` for K = 1..=points.
    pub points: usize,
    /// A vertical ground motion (`[ground.vertical]`): `ground_acc_v` and
    /// `min_effective_gravity_m_s2`.
    pub vertical: bool,
    /// The blocks on the tower (`[[block]]`): each adds the columns of
    /// [`HISTORY_BLOCKS`] and the fields of [`SUMMARY_BLOCKS`] prefixed by its
    /// name, and the run the fields of [`SUMMARY`] present with [`stacked`].
    pub blocks: BlockNames,
}

/// The run has blocks on its tower.
pub fn stacked(layout: &Layout) -> bool {
    !layout.blocks.is_empty()
}

/// The run has a vertical ground motion.
pub fn vertical(layout: &Layout) -> bool {
    layout.vertical
}

/// How a column is read from a record of type `T`.
#[derive(Clone, Copy)]
pub enum Read<T> {
    /// A number, written in its shortest round-trip form.
    Number(fn(&T) -> f64),
    /// A name (`rocking`, `impact`).
    Text(fn(&T) -> &'static str),
}

/// A column of a CSV file (and of the matching Python arrays or dicts).
#[derive(Clone, Copy)]
pub struct Column<T> {
    /// Header name.
    pub name: &'static str,
    /// SI unit, empty for a name or a pure number.
    pub unit: &'static str,
    /// What it is, for the reference.
    pub meaning: &'static str,
    /// Whether a run of this layout has the column.
    pub present: fn(&Layout) -> bool,
    /// How it is read.
    pub read: Read<T>,
}

impl<T> std::fmt::Debug for Column<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Column").field("name", &self.name).finish_non_exhaustive()
    }
}

/// Every run has the column.
pub fn always(_: &Layout) -> bool {
    true
}

/// One row of `history.csv`: a sample and the `(dx, abs_acc)` of each extra point.
#[derive(Debug, Clone, Copy)]
pub struct HistoryRow<'a> {
    /// The response at the row's time.
    pub sample: &'a Sample,
    /// `(dx, abs_acc)` of each extra point, in the order of `tower.points`.
    pub points: &'a [(f64, f64)],
}

/// The columns of `history.csv` before the extra points, in order.
pub const HISTORY: &[Column<Sample>] = &[
    Column {
        name: "t",
        unit: "s",
        meaning: "time",
        present: always,
        read: Read::Number(|s| s.t),
    },
    Column {
        name: "ground_acc",
        unit: "m/s²",
        meaning: "horizontal ground acceleration",
        present: always,
        read: Read::Number(|s| s.ground_acc),
    },
    Column {
        name: "theta",
        unit: "rad",
        meaning: "rotation of the tower",
        present: always,
        read: Read::Number(|s| s.state.theta),
    },
    Column {
        name: "theta_dot",
        unit: "rad/s",
        meaning: "angular velocity of the tower",
        present: always,
        read: Read::Number(|s| s.state.theta_dot),
    },
    Column {
        name: "slip",
        unit: "m",
        meaning: "slip of the building on its foundation",
        present: always,
        read: Read::Number(|s| s.state.slip),
    },
    Column {
        name: "slip_vel",
        unit: "m/s",
        meaning: "slip velocity of the building",
        present: always,
        read: Read::Number(|s| s.state.slip_vel),
    },
    Column {
        name: "top_dx",
        unit: "m",
        meaning: "horizontal displacement of the top centre relative to the building",
        present: always,
        read: Read::Number(|s| s.top_dx),
    },
    Column {
        name: "top_abs_acc",
        unit: "m/s²",
        meaning: "absolute horizontal acceleration of the top centre",
        present: always,
        read: Read::Number(|s| s.top_abs_acc),
    },
    Column {
        name: "regime",
        unit: "",
        meaning: "combined motion: `rest`, `rocking`, `sliding` or `rocking_sliding`",
        present: always,
        read: Read::Text(|s| s.motion.as_str()),
    },
    Column {
        name: "ground_acc_v",
        unit: "m/s²",
        meaning: "vertical ground acceleration `a_v`, positive upwards (only with `[ground.vertical]`)",
        present: vertical,
        read: Read::Number(|s| s.ground_acc_v),
    },
];

/// A column repeated for each extra point K: named `p{K}_{suffix}`.
#[derive(Debug, Clone, Copy)]
pub struct PointColumn {
    /// The part of the name after `pK_`.
    pub suffix: &'static str,
    /// SI unit.
    pub unit: &'static str,
    /// What it is, for the reference.
    pub meaning: &'static str,
    /// How it is read from the point's `(dx, abs_acc)`.
    pub read: fn(&(f64, f64)) -> f64,
}

/// The columns of each extra point, after the fixed ones.
pub const HISTORY_POINTS: &[PointColumn] = &[
    PointColumn {
        suffix: "dx",
        unit: "m",
        meaning: "horizontal displacement of point K relative to the building",
        read: |p| p.0,
    },
    PointColumn {
        suffix: "abs_acc",
        unit: "m/s²",
        meaning: "absolute horizontal acceleration of point K",
        read: |p| p.1,
    },
];

/// A column repeated for each block on the tower: named `{name}_{suffix}`,
/// after the extra points.
#[derive(Debug, Clone, Copy)]
pub struct BlockColumn {
    /// The part of the name after `{name}_`.
    pub suffix: &'static str,
    /// SI unit.
    pub unit: &'static str,
    /// What it is, for the reference.
    pub meaning: &'static str,
    /// How it is read from a sample for the `k`-th block above the tower (from 1).
    pub read: fn(&Sample, usize) -> f64,
}

/// The columns of each block on the tower.
pub const HISTORY_BLOCKS: &[BlockColumn] = &[
    BlockColumn {
        suffix: "theta",
        unit: "rad",
        meaning: "rotation of the block relative to the block below",
        read: |s, k| s.stack.map_or(0.0, |st| st.theta[k]),
    },
    BlockColumn {
        suffix: "theta_dot",
        unit: "rad/s",
        meaning: "its angular velocity relative to the block below",
        read: |s, k| s.stack.map_or(0.0, |st| st.theta_dot[k]),
    },
];

/// The name of the `kind` column of `events.csv`, whose text is [`event_kind`].
pub const KIND: &str = "kind";

/// The `kind` of an event in `events.csv`: the event's own (`impact`) for the
/// tower and the building, prefixed by the block's name for a block's
/// (`belfry_impact`).
pub fn event_kind(layout: &Layout, event: &Event) -> Cow<'static, str> {
    match event.block {
        0 => Cow::Borrowed(event.kind.as_str()),
        k => Cow::Owned(format!("{}_{}", layout.blocks.name(k), event.kind.as_str())),
    }
}

/// The columns of `events.csv`, in order (`theta`, `slip_vel`, `slip` and `regime` after the event).
pub const EVENTS: &[Column<Event>] = &[
    Column {
        name: "t",
        unit: "s",
        meaning: "time of the event",
        present: always,
        read: Read::Number(|e| e.time),
    },
    Column {
        name: KIND,
        unit: "",
        meaning: "`uplift`, `impact`, `rest`, `slip`, `stick`, `reverse` or `overturn`; a block's `<name>_uplift`, `<name>_impact`, `<name>_rest` or `<name>_overturn`, whose θ columns then hold that block's θ ([`event_kind`])",
        present: always,
        read: Read::Text(|e| e.kind.as_str()),
    },
    Column {
        name: "theta",
        unit: "rad",
        meaning: "rotation after the event",
        present: always,
        read: Read::Number(|e| e.after.theta),
    },
    Column {
        name: "theta_dot_before",
        unit: "rad/s",
        meaning: "angular velocity before the event",
        present: always,
        read: Read::Number(|e| e.before.theta_dot),
    },
    Column {
        name: "theta_dot_after",
        unit: "rad/s",
        meaning: "angular velocity after the event",
        present: always,
        read: Read::Number(|e| e.after.theta_dot),
    },
    Column {
        name: "slip_vel",
        unit: "m/s",
        meaning: "slip velocity after the event",
        present: always,
        read: Read::Number(|e| e.after.slip_vel),
    },
    Column {
        name: "slip",
        unit: "m",
        meaning: "slip after the event",
        present: always,
        read: Read::Number(|e| e.after.slip),
    },
    Column {
        name: "regime",
        unit: "",
        meaning: "combined motion after the event",
        present: always,
        read: Read::Text(|e| e.regime.motion().as_str()),
    },
    Column {
        name: "slip_vel_before",
        unit: "m/s",
        meaning: "slip velocity before the event (an impact on a building that can slide changes it)",
        present: always,
        read: Read::Number(|e| e.before.slip_vel),
    },
];

/// What a summary field holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A number (or `null`).
    Number,
    /// `true` or `false`.
    Flag,
    /// A name.
    Text,
}

/// A field of `summary.json` (a dotted name is nested: `time_in_regime_s.rest`)
/// and a column of `sweep.csv`.
#[derive(Clone, Copy)]
pub struct Field {
    /// Key, dotted when nested.
    pub name: &'static str,
    /// What the values are (the type of a Python column when every case failed).
    pub kind: Kind,
    /// SI unit, empty for a count, a ratio, a flag or a name.
    pub unit: &'static str,
    /// What it is, for the reference.
    pub meaning: &'static str,
    /// Whether a run of this layout has the field.
    pub present: fn(&Layout) -> bool,
    /// How it is read; [`Cell::Empty`] (`null`) where the quantity does not exist.
    pub read: fn(&Outcome) -> Cell,
}

impl std::fmt::Debug for Field {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Field").field("name", &self.name).finish_non_exhaustive()
    }
}

fn float(v: Option<f64>) -> Cell {
    v.filter(|v| v.is_finite()).map_or(Cell::Empty, Cell::Float)
}
fn tower(o: &Outcome, v: f64) -> Cell {
    float(o.derived.alpha.is_some().then_some(v))
}
fn building(o: &Outcome, v: f64) -> Cell {
    float(o.derived.slip_acceleration_g.is_some().then_some(v))
}
fn count(n: u64) -> Cell {
    i64::try_from(n).map_or(Cell::Float(n as f64), Cell::Int)
}
fn time_in(o: &Outcome, m: Motion) -> Cell {
    float(Some(o.summary.time_in(m)))
}

/// A quantity the summary reports of the tower and again of each block on
/// it, written once: the tower's field (`impacts`, in [`SUMMARY`], through
/// `tower_field!`) and each block's, named `{name}_{suffix}`
/// (`belfry_impacts`), after the fields of [`SUMMARY`], in the order of
/// [`SUMMARY_BLOCKS`].
#[derive(Clone, Copy)]
pub struct BodyField {
    /// The tower's field.
    pub tower: &'static str,
    /// The part of a block's field name after `{name}_`.
    pub suffix: &'static str,
    /// What the values are.
    pub kind: Kind,
    /// SI unit, empty for a count, a ratio or a flag.
    pub unit: &'static str,
    /// What the tower's is, for the reference.
    pub tower_meaning: &'static str,
    /// What a block's is, for the reference.
    pub meaning: &'static str,
    /// How it is read for body `k`: the tower for 0, else the `k`-th block above it.
    pub read: fn(&Outcome, usize) -> Cell,
}

impl std::fmt::Debug for BodyField {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("BodyField").field("suffix", &self.suffix).finish_non_exhaustive()
    }
}

/// What the run found of one body: the tower or a block on it.
struct Body {
    /// Its largest |θ| (a block's relative to the block below).
    max_abs_theta: f64,
    /// Its slenderness α.
    alpha: f64,
    /// Its impacts (a block's on the block below).
    impacts: u64,
    /// When it first lifted.
    first_uplift_time: Option<f64>,
    /// Its largest friction demand: the tower's at its pivot, a block's on the block below.
    max_friction_demand: f64,
}

/// Body `k` of `o`: the tower for 0 (`None` without one), else the `k`-th block above it.
fn body(o: &Outcome, k: usize) -> Option<Body> {
    if k == 0 {
        let s = &o.summary;
        return o.derived.alpha.map(|alpha| Body {
            max_abs_theta: s.max_abs_theta(),
            alpha,
            impacts: s.impacts,
            first_uplift_time: s.first_uplift_time,
            max_friction_demand: s.max_pivot_friction_demand,
        });
    }
    let b = o.summary.stack.as_ref()?.blocks().get(k - 1)?;
    Some(Body {
        max_abs_theta: b.max_abs_theta,
        alpha: o.blocks.get(k - 1)?.alpha(),
        impacts: b.impacts as u64,
        first_uplift_time: b.first_uplift_time,
        max_friction_demand: b.max_friction_demand,
    })
}

/// The largest |θ| of each body.
const MAX_ABS_THETA: BodyField = BodyField {
    tower: "max_abs_theta_rad",
    suffix: "max_abs_theta_rad",
    kind: Kind::Number,
    unit: "rad",
    tower_meaning: "largest rotation in absolute value",
    meaning: "largest rotation in absolute value of the block relative to the block below",
    read: |o, k| float(body(o, k).map(|b| b.max_abs_theta)),
};

/// That peak over the body's own α.
const MAX_THETA_OVER_ALPHA: BodyField = BodyField {
    tower: "max_theta_over_alpha",
    suffix: "max_theta_over_alpha",
    kind: Kind::Number,
    unit: "",
    tower_meaning: "largest rotation over α",
    meaning: "that peak over the block's own slenderness α = atan(B/H)",
    read: |o, k| float(body(o, k).map(|b| b.max_abs_theta / b.alpha)),
};

/// The impacts of each body.
const IMPACTS: BodyField = BodyField {
    tower: "impacts",
    suffix: "impacts",
    kind: Kind::Number,
    unit: "",
    tower_meaning: "number of impacts",
    meaning: "impacts of the block on the block below",
    read: |o, k| body(o, k).map_or(Cell::Empty, |b| count(b.impacts)),
};

/// Whether it overturned: the tower's field says whether any body did (it
/// is there without a tower too).
const OVERTURNED: BodyField = BodyField {
    tower: "overturned",
    suffix: "overturned",
    kind: Kind::Flag,
    unit: "",
    tower_meaning: "whether the tower overturned",
    meaning: "whether the block overturned (its rotation reached π/2; the run stops there)",
    read: |o, k| match k {
        0 => Cell::Bool(o.summary.overturned()),
        k => Cell::Bool(o.summary.stack.is_some_and(|s| s.overturned_block == Some(k))),
    },
};

/// When each body first lifted.
const FIRST_UPLIFT_TIME: BodyField = BodyField {
    tower: "first_uplift_time_s",
    suffix: "first_uplift_time_s",
    kind: Kind::Number,
    unit: "s",
    tower_meaning: "time of the first uplift",
    meaning: "first time the block lifted off the block below",
    read: |o, k| float(body(o, k).and_then(|b| b.first_uplift_time)),
};

/// The largest friction demand under each body.
const FRICTION_DEMAND: BodyField = BodyField {
    tower: "max_pivot_friction_demand",
    suffix: "max_friction_demand",
    kind: Kind::Number,
    unit: "",
    tower_meaning: "largest ratio |f_x| / f_y of friction force to normal force at the pivot (Shenton); null once f_y reached zero (tower_uplift_detected), where it grows without bound",
    meaning: "largest ratio of the tangential to the normal force between the block and the block below (the friction the joint needs; the model lets it never slide); empty once the block above lost contact",
    read: |o, k| float(body(o, k).map(|b| b.max_friction_demand)),
};

/// The tower's field of a quantity of every body ([`BodyField`]): an entry of [`SUMMARY`].
macro_rules! tower_field {
    ($body:ident) => {
        Field {
            name: $body.tower,
            kind: $body.kind,
            unit: $body.unit,
            meaning: $body.tower_meaning,
            present: always,
            read: |o| ($body.read)(o, 0),
        }
    };
}

/// The fields of each block on the tower, in order: the quantities of every
/// body, read for the block.
pub const SUMMARY_BLOCKS: &[BodyField] = &[MAX_ABS_THETA, MAX_THETA_OVER_ALPHA, IMPACTS, FIRST_UPLIFT_TIME, OVERTURNED, FRICTION_DEMAND];

// The quantities derived from a scenario that the summary holds too: each
// an entry of `DERIVED`, and a field of `SUMMARY` through `derived_field!`,
// which reads it from the run's own derived quantities.

/// α, in [`DERIVED`] and the summary.
const ALPHA: DerivedQuantity = DerivedQuantity {
    name: "alpha_rad",
    unit: "rad",
    meaning: "slenderness angle α of the tower",
    value: |m| m.derived().alpha,
};

/// R, in [`DERIVED`] and the summary.
const RADIUS: DerivedQuantity = DerivedQuantity {
    name: "R_m",
    unit: "m",
    meaning: "distance R from a base corner to the centre of mass",
    value: |m| m.derived().radius,
};

/// p, in [`DERIVED`] and the summary.
const FREQUENCY_PARAMETER: DerivedQuantity = DerivedQuantity {
    name: "p_rad_s",
    unit: "rad/s",
    meaning: "frequency parameter p of the tower",
    value: |m| m.derived().p,
};

/// r, in [`DERIVED`] and the summary.
const RESTITUTION: DerivedQuantity = DerivedQuantity {
    name: "restitution",
    unit: "",
    meaning: "coefficient of restitution r of an impact",
    value: |m| m.derived().restitution,
};

/// The uplift threshold, in [`DERIVED`] and the summary.
const UPLIFT_ACCELERATION: DerivedQuantity = DerivedQuantity {
    name: "uplift_acceleration_g",
    unit: "g",
    meaning: "ground acceleration that lifts the tower from rest",
    value: |m| m.derived().uplift_acceleration_g,
};

/// The slip threshold, in [`DERIVED`] and the summary.
const SLIP_ACCELERATION: DerivedQuantity = DerivedQuantity {
    name: "slip_acceleration_g",
    unit: "g",
    meaning: "ground acceleration that makes the building slip from rest",
    value: |m| m.derived().slip_acceleration_g,
};

/// The summary's field of a derived quantity `$q`: its name, unit and
/// meaning, read from the run's `derived.$of`.
macro_rules! derived_field {
    ($q:ident, $of:ident) => {
        Field {
            name: $q.name,
            kind: Kind::Number,
            unit: $q.unit,
            meaning: $q.meaning,
            present: always,
            read: |o| float(o.derived.$of),
        }
    };
}

/// The fields of `summary.json` but `wall_time_s` (last, not a result of the
/// model), in order: also the result columns of `sweep.csv`.
pub const SUMMARY: &[Field] = &[
    Field {
        name: "name",
        kind: Kind::Text,
        unit: "",
        meaning: "the scenario's name",
        present: always,
        read: |o| Cell::Text(o.name.clone()),
    },
    derived_field!(ALPHA, alpha),
    derived_field!(RADIUS, radius),
    derived_field!(FREQUENCY_PARAMETER, p),
    derived_field!(RESTITUTION, restitution),
    derived_field!(UPLIFT_ACCELERATION, uplift_acceleration_g),
    derived_field!(SLIP_ACCELERATION, slip_acceleration_g),
    tower_field!(MAX_ABS_THETA),
    tower_field!(MAX_THETA_OVER_ALPHA),
    Field {
        name: "max_abs_slip_m",
        kind: Kind::Number,
        unit: "m",
        meaning: "largest slip in absolute value",
        present: always,
        read: |o| building(o, o.summary.max_abs_slip),
    },
    Field {
        name: "final_slip_m",
        kind: Kind::Number,
        unit: "m",
        meaning: "slip at the end of the run",
        present: always,
        read: |o| building(o, o.summary.final_slip),
    },
    tower_field!(IMPACTS),
    tower_field!(OVERTURNED),
    Field {
        name: "overturn_time_s",
        kind: Kind::Number,
        unit: "s",
        meaning: "time of overturning",
        present: always,
        read: |o| float(o.summary.overturn_time),
    },
    tower_field!(FIRST_UPLIFT_TIME),
    Field {
        name: "first_slip_time_s",
        kind: Kind::Number,
        unit: "s",
        meaning: "time the building first slipped",
        present: always,
        read: |o| float(o.summary.first_slip_time),
    },
    Field {
        name: "max_top_displacement_m",
        kind: Kind::Number,
        unit: "m",
        meaning: "largest horizontal displacement of the top relative to the building",
        present: always,
        read: |o| tower(o, o.summary.max_top_displacement),
    },
    Field {
        name: "max_top_abs_acceleration_m_s2",
        kind: Kind::Number,
        unit: "m/s²",
        meaning: "largest absolute horizontal acceleration of the top",
        present: always,
        read: |o| tower(o, o.summary.max_top_abs_acceleration),
    },
    tower_field!(FRICTION_DEMAND),
    Field {
        name: "tower_uplift_detected",
        kind: Kind::Flag,
        unit: "",
        meaning: "whether the vertical pivot reaction f_y reached zero (the tower would fly: outside the model)",
        present: always,
        read: |o| Cell::Bool(o.summary.tower_uplift_detected),
    },
    Field {
        name: "time_in_regime_s.rest",
        kind: Kind::Number,
        unit: "s",
        meaning: "time at rest",
        present: always,
        read: |o| time_in(o, Motion::Rest),
    },
    Field {
        name: "time_in_regime_s.rocking",
        kind: Kind::Number,
        unit: "s",
        meaning: "time rocking on a fixed base",
        present: always,
        read: |o| time_in(o, Motion::Rocking),
    },
    Field {
        name: "time_in_regime_s.sliding",
        kind: Kind::Number,
        unit: "s",
        meaning: "time sliding with the tower at rest",
        present: always,
        read: |o| time_in(o, Motion::Sliding),
    },
    Field {
        name: "time_in_regime_s.rocking_sliding",
        kind: Kind::Number,
        unit: "s",
        meaning: "time rocking and sliding",
        present: always,
        read: |o| time_in(o, Motion::RockingSliding),
    },
    Field {
        name: "end_time_s",
        kind: Kind::Number,
        unit: "s",
        meaning: "time the run ended",
        present: always,
        read: |o| float(Some(o.summary.end_time)),
    },
    Field {
        name: "end_reason",
        kind: Kind::Text,
        unit: "",
        meaning: "`end_of_duration` or `overturned`",
        present: always,
        read: |o| {
            Cell::Text(
                match o.summary.end_reason {
                    EndReason::EndOfDuration => "end_of_duration",
                    EndReason::Overturned => "overturned",
                }
                .to_string(),
            )
        },
    },
    Field {
        name: "end_state",
        kind: Kind::Text,
        unit: "",
        meaning: "the tower at the end: `rest`, `rocking` (within its stability limit), `beyond_stability_limit` (θ past ±α: its centre of mass beyond the pivot) or `overturned`",
        present: always,
        read: |o| match o.derived.alpha {
            Some(_) => Cell::Text(o.summary.end_state.as_str().to_string()),
            None => Cell::Empty,
        },
    },
    Field {
        name: "will_overturn",
        kind: Kind::Flag,
        unit: "",
        meaning: "whether the tower's free motion from the end overturns it (closed form: its energy against the barrier at θ = ±α, its direction, the next impact's restitution); empty while ground motion remains after the end, the building slides, or blocks stand on the tower (the closed form is of one block)",
        present: always,
        read: |o| o.summary.will_overturn.map_or(Cell::Empty, Cell::Bool),
    },
    Field {
        name: "min_theta_rad",
        kind: Kind::Number,
        unit: "rad",
        meaning: "least rotation",
        present: always,
        read: |o| tower(o, o.summary.theta_range.0),
    },
    Field {
        name: "max_theta_rad",
        kind: Kind::Number,
        unit: "rad",
        meaning: "largest rotation",
        present: always,
        read: |o| tower(o, o.summary.theta_range.1),
    },
    Field {
        name: "min_effective_gravity_m_s2",
        kind: Kind::Number,
        unit: "m/s²",
        meaning: "least effective gravity `g + a_v` over the run (only with `[ground.vertical]`)",
        present: vertical,
        read: |o| float(o.summary.min_effective_gravity),
    },
    Field {
        name: "events",
        kind: Kind::Number,
        unit: "",
        meaning: "number of events (rows of events.csv)",
        present: always,
        read: |o| count(o.summary.events),
    },
    Field {
        name: "rhs_evaluations",
        kind: Kind::Number,
        unit: "",
        meaning: "evaluations of the equations of motion",
        present: always,
        read: |o| count(o.summary.evaluations),
    },
    Field {
        name: "max_seat_impulse_ratio",
        kind: Kind::Number,
        unit: "",
        meaning: "(with `[[block]]`) the largest ratio of the impulsive moment a seated interface carried through an impact elsewhere to the most its base can carry, V_imp B/2: the model keeps it seated, and above 1 that assumption is violated (the block would tip); empty where a seat would have had to pull the blocks above it down (V_imp ≤ 0: they would have been thrown off it, an infinite ratio)",
        present: stacked,
        read: |o| float(o.summary.stack.map(|s| s.max_seat_impulse_ratio)),
    },
    Field {
        name: "overturned_block",
        kind: Kind::Text,
        unit: "",
        meaning: "(with `[[block]]`) the block that overturned: `tower` or a block's name; empty when none did (`overturned` is true when any did)",
        present: stacked,
        read: |o| match o.summary.stack.and_then(|s| s.overturned_block) {
            Some(k) => Cell::Text(o.layout.blocks.name(k).to_string()),
            None => Cell::Empty,
        },
    },
];

/// The last field of `summary.json` (and column of `sweep.csv` before `error`): the run's wall-clock time.
pub const WALL_TIME: Field = Field {
    name: "wall_time_s",
    kind: Kind::Number,
    unit: "s",
    meaning: "wall-clock time of the run (the only field that differs between two runs of the same case)",
    present: always,
    read: |_| Cell::Empty,
};

/// A quantity derived from a scenario without running it: what `rocking
/// check` prints, what `rocking.derived` returns in Python and the page shows
/// beside the summary. Those the summary also holds have its name, unit and
/// meaning (a test checks it).
#[derive(Clone, Copy)]
pub struct DerivedQuantity {
    /// Key, named as in `summary.json` where the summary has it.
    pub name: &'static str,
    /// SI unit (`g` for an acceleration in units of gravity), empty for a ratio.
    pub unit: &'static str,
    /// What it is.
    pub meaning: &'static str,
    /// Its value for a model; `None` for a quantity of an absent body.
    pub value: fn(&rocking::Model) -> Option<f64>,
}

impl std::fmt::Debug for DerivedQuantity {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("DerivedQuantity").field("name", &self.name).finish_non_exhaustive()
    }
}

/// The quantities derived from a scenario without running it, in order.
pub const DERIVED: &[DerivedQuantity] = &[
    DerivedQuantity {
        name: "g_m_s2",
        unit: "m/s²",
        meaning: "gravity g",
        value: |m| Some(m.gravity()),
    },
    ALPHA,
    DerivedQuantity {
        name: "alpha_deg",
        unit: "°",
        meaning: "slenderness angle α of the tower, in degrees",
        value: |m| m.derived().alpha.map(f64::to_degrees),
    },
    RADIUS,
    FREQUENCY_PARAMETER,
    RESTITUTION,
    DerivedQuantity {
        name: "inertia_pivot_kg_m2",
        unit: "kg·m²",
        meaning: "moment of inertia I_O of the tower about a base corner",
        value: |m| m.derived().inertia_pivot,
    },
    DerivedQuantity {
        name: "tower_mass_kg",
        unit: "kg",
        meaning: "mass m2 of the tower",
        value: |m| m.derived().tower_mass,
    },
    DerivedQuantity {
        name: "sliding_mass_kg",
        unit: "kg",
        meaning: "mass M that slides on the foundation: the building and the tower it carries",
        value: |m| m.derived().sliding_mass,
    },
    UPLIFT_ACCELERATION,
    SLIP_ACCELERATION,
];

/// The derived quantities' descriptions as JSON, in order: `[{ name, unit, meaning }, …]`
/// (the page's labels, the Python package's `rocking.DERIVED`).
pub fn derived_json() -> serde_json::Value {
    DERIVED
        .iter()
        .map(|q| serde_json::json!({ "name": q.name, "unit": q.unit, "meaning": q.meaning }))
        .collect()
}

/// The header of `history.csv` for `layout`, from `columns` and `points`.
pub fn history_header(columns: &[Column<Sample>], points: &[PointColumn], layout: &Layout) -> Vec<String> {
    let mut header: Vec<String> = columns.iter().filter(|c| (c.present)(layout)).map(|c| c.name.to_string()).collect();
    for k in 1..=layout.points {
        header.extend(points.iter().map(|p| format!("p{k}_{}", p.suffix)));
    }
    for name in layout.blocks.iter() {
        header.extend(HISTORY_BLOCKS.iter().map(|c| format!("{name}_{}", c.suffix)));
    }
    header
}

/// Hands `cell` every value of a history row, in header order.
pub fn history_values<'a>(columns: &[Column<Sample>], points: &[PointColumn], layout: &Layout, row: HistoryRow<'a>, mut cell: impl FnMut(Value)) {
    for c in columns.iter().filter(|c| (c.present)(layout)) {
        cell(c.read.value(row.sample));
    }
    for p in row.points {
        for c in points {
            cell(Value::Number((c.read)(p)));
        }
    }
    for k in 1..=layout.blocks.len() {
        for c in HISTORY_BLOCKS {
            cell(Value::Number((c.read)(row.sample, k)));
        }
    }
}

/// One value of a CSV row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value {
    /// A number.
    Number(f64),
    /// A name.
    Text(&'static str),
}

impl<T> Read<T> {
    /// The value of `record`.
    pub fn value(&self, record: &T) -> Value {
        match self {
            Read::Number(f) => Value::Number(f(record)),
            Read::Text(f) => Value::Text(f(record)),
        }
    }
}

/// The summary fields of `outcome` present in `layout`, in order, as `(name, cell)`.
pub fn fields_of(fields: &[Field], layout: &Layout, outcome: &Outcome) -> Vec<(String, Cell)> {
    fields
        .iter()
        .filter(|f| (f.present)(layout))
        .map(|f| (f.name.to_string(), (f.read)(outcome)))
        .collect()
}

/// The names of the summary fields of a run of `layout`, in order: those of
/// [`SUMMARY`] present, then each block's ([`SUMMARY_BLOCKS`]).
pub fn summary_names(layout: &Layout) -> Vec<String> {
    let mut names: Vec<String> = SUMMARY.iter().filter(|f| (f.present)(layout)).map(|f| f.name.to_string()).collect();
    for name in layout.blocks.iter() {
        names.extend(SUMMARY_BLOCKS.iter().map(|f| format!("{name}_{}", f.suffix)));
    }
    names
}

/// Each block's summary fields of `outcome`, in the order of [`summary_names`].
pub fn block_fields_of(outcome: &Outcome) -> Vec<(String, Cell)> {
    let mut out = Vec::new();
    for (i, name) in outcome.layout.blocks.iter().enumerate() {
        out.extend(SUMMARY_BLOCKS.iter().map(|f| (format!("{name}_{}", f.suffix), (f.read)(outcome, i + 1))));
    }
    out
}

/// The outputs reference (Markdown): every column and field with its unit and
/// meaning, generated from the lists of this module.
pub fn outputs_markdown() -> String {
    outputs_markdown_of(HISTORY, HISTORY_POINTS, EVENTS, SUMMARY)
}

/// The reference of the given lists (see [`outputs_markdown`]).
pub fn outputs_markdown_of(history: &[Column<Sample>], points: &[PointColumn], events: &[Column<Event>], summary: &[Field]) -> String {
    let mut out = String::from(
        "<!-- generated -->\n<!-- from crates/rocking-scenario/src/columns.rs: do not edit; UPDATE_OUTPUTS_MD=1 cargo test -p rocking-scenario --test outputs_reference rewrites it -->\n\n# Outputs\n\n\
         Every number is in SI units and written with every digit (the shortest form that reads back to the same value). \
         In every CSV the tool writes, a text cell (a name, an id, a record's file name, an error) that begins with `=`, `+`, `-`, `@`, a TAB or a CR \
         is written with a leading `'`, so that a spreadsheet shows it as text instead of running it as a formula (OWASP's rule against CSV injection); \
         numbers, negative ones included, are written as they are.\n\n",
    );
    let unit = |u: &str| if u.is_empty() { "–".to_string() } else { u.to_string() };
    // A `|` in a meaning (|f_x|) would end its table cell: written escaped.
    let cell = |m: &str| m.replace('|', "\\|");
    out.push_str("## `history.csv`\n\nOne row every `simulation.output_dt` seconds.\n\n| column | unit | meaning |\n|---|---|---|\n");
    for c in history {
        out.push_str(&format!("| `{}` | {} | {} |\n", c.name, unit(c.unit), cell(c.meaning)));
    }
    for p in points {
        out.push_str(&format!(
            "| `pK_{}` | {} | {} (one pair per entry K = 1, 2, … of `tower.points`) |\n",
            p.suffix,
            unit(p.unit),
            cell(p.meaning)
        ));
    }
    for c in HISTORY_BLOCKS {
        out.push_str(&format!(
            "| `<name>_{}` | {} | {} (one pair per `[[block]]`, after the points, named by the block's `name`) |\n",
            c.suffix,
            unit(c.unit),
            cell(c.meaning)
        ));
    }
    out.push_str("\n## `events.csv`\n\nOne row per event (a change of regime), in time order.\n\n| column | unit | meaning |\n|---|---|---|\n");
    for c in events {
        out.push_str(&format!("| `{}` | {} | {} |\n", c.name, unit(c.unit), cell(c.meaning)));
    }
    out.push_str(
        "\n## `summary.json` and `sweep.csv`\n\n`summary.json` holds these fields in this order (a dotted name is a nested object); \
         `null` where a quantity does not exist (the tower's without a tower, the slip's without a building). \
         `sweep.csv` has one column per swept key, then these fields, then `error` (empty, or why the case failed).\n\n\
         | field | unit | meaning |\n|---|---|---|\n",
    );
    for f in summary {
        out.push_str(&format!("| `{}` | {} | {} |\n", f.name, unit(f.unit), cell(f.meaning)));
    }
    for f in SUMMARY_BLOCKS {
        out.push_str(&format!(
            "| `<name>_{}` | {} | {} (one per `[[block]]`, named by the block's `name`) |\n",
            f.suffix,
            unit(f.unit),
            cell(f.meaning)
        ));
    }
    out.push_str(&format!("| `{}` | {} | {} |\n", WALL_TIME.name, unit(WALL_TIME.unit), cell(WALL_TIME.meaning)));
    out.push_str(
        "\nWith `[[block]]` the tower's fields are those of the tower (block 1) in the stack, and `overturned` is true when any block overturned. \
         The derived quantities (`alpha_rad` … `uplift_acceleration_g`) are the tower's alone; `rocking check` prints the ground acceleration \
         that lifts each interface of the stack. The peaks of θ are located by root finding; the top's acceleration and the friction \
         demands at the ends of every step and at their extrema inside it, located on their exact time derivatives (an event's instant \
         in the regime that holds after it: a regime that another event ends at the same instant, as an impact that at once sets the \
         building sliding, is not read); the slip's peak at the ends of every step and at every event.\n",
    );
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{RunOptions, Scenario};
    use std::path::Path;

    /// A column added to the list, optional (present only with extra points,
    /// standing in for a vertical motion's `ground_acc_v`): twice the ground
    /// acceleration, so its value is checked against another column.
    const EXTRA: Column<Sample> = Column {
        name: "twice_ground_acc",
        unit: "m/s²",
        meaning: "a column added for the test",
        present: |l| l.points > 0,
        read: Read::Number(|s| 2.0 * s.ground_acc),
    };

    fn outcome(points: &str) -> Outcome {
        outcome_of(&format!("[tower]\nwidth = 4\nheight = 12.0\nmass = 1.5e5\n{points}\n{GROUND}"))
    }

    /// The ground motion and simulation of every test outcome.
    const GROUND: &str = "[ground]\ntype = \"sine-pulse\"\namplitude = 0.6\nfrequency = 1.0\n[simulation]\nduration = 0.5\noutput_dt = 0.05\n";

    fn outcome_of(text: &str) -> Outcome {
        let case = Scenario::from_toml_str(text, Path::new("t.toml"))
            .and_then(|s| s.build())
            .unwrap_or_else(|e| panic!("{e}"));
        case.run(RunOptions::ALL).unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn a_column_added_to_the_list_appears_in_the_header_the_rows_and_the_reference() {
        let mut columns = HISTORY.to_vec();
        columns.push(EXTRA); // after the last column, before the points
        let with = outcome("points = [[0.0, 6.0]]");
        // The columns of this run before the new one (no vertical motion here).
        let before = HISTORY.iter().filter(|c| (c.present)(&with.layout)).count();
        let header = history_header(&columns, HISTORY_POINTS, &with.layout);
        assert_eq!(header[before], "twice_ground_acc");
        assert_eq!(&header[before + 1..], ["p1_dx", "p1_abs_acc"]);
        let Some(history) = &with.history else { panic!("no history") };
        for (sample, points) in history.samples.iter().zip(&history.point_values) {
            let mut values = Vec::new();
            history_values(&columns, HISTORY_POINTS, &with.layout, HistoryRow { sample, points }, |v| values.push(v));
            assert_eq!(values.len(), header.len());
            // Doubling is exact in binary floating point.
            assert_eq!(values[before], Value::Number(2.0 * sample.ground_acc));
        }
        // Absent where its condition does not hold: the header is today's.
        let without = outcome("");
        let names: Vec<&str> = HISTORY.iter().filter(|c| (c.present)(&without.layout)).map(|c| c.name).collect();
        assert_eq!(history_header(&columns, HISTORY_POINTS, &without.layout), names);
        let reference = outputs_markdown_of(&columns, HISTORY_POINTS, EVENTS, SUMMARY);
        assert!(reference.contains("| `twice_ground_acc` | m/s² | a column added for the test |"), "{reference}");
    }

    #[test]
    fn a_field_added_to_the_list_appears_in_the_summary_and_the_reference() {
        let mut fields = SUMMARY.to_vec();
        fields.push(Field {
            name: "impacts_plus_one",
            kind: Kind::Number,
            unit: "",
            meaning: "a field added for the test",
            present: always,
            read: |o| Cell::Int(o.summary.impacts as i64 + 1),
        });
        let o = outcome("");
        let cells = fields_of(&fields, &o.layout, &o);
        assert_eq!(cells.len(), SUMMARY.iter().filter(|f| (f.present)(&o.layout)).count() + 1);
        assert_eq!(cells.last().map(|(k, _)| k.as_str()), Some("impacts_plus_one"));
        assert_eq!(cells.last().map(|(_, c)| c.clone()), Some(Cell::Int(o.summary.impacts as i64 + 1)));
        assert!(outputs_markdown_of(HISTORY, HISTORY_POINTS, EVENTS, &fields).contains("`impacts_plus_one`"));
    }

    #[test]
    fn every_row_of_the_reference_has_its_three_cells() {
        // A `|` left unescaped in a meaning (|f_x|) splits its cell: a row of
        // the three-column tables then has more than the four separators of
        // `| name | unit | meaning |`. The pipes are counted by hand here.
        let reference = outputs_markdown();
        let rows: Vec<&str> = reference.lines().filter(|l| l.starts_with("| `")).collect();
        assert!(rows.len() > 40, "{} rows", rows.len());
        assert!(reference.contains(r"ratio \|f_x\| / f_y"));
        for row in rows {
            let separators = row.char_indices().filter(|&(i, c)| c == '|' && !row[..i].ends_with('\\')).count();
            assert_eq!(separators, 4, "{row}");
        }
    }

    #[test]
    fn each_field_kind_is_that_of_its_cells() {
        // A tower without a building (null slip quantities), with extra points,
        // a building without a tower (null tower quantities), and a vertical motion.
        let building = format!("[building]\nmass = 2.0e6\nmu_static = 0.3\n{GROUND}");
        let vertical =
            format!("[tower]\nwidth = 4\nheight = 12.0\nmass = 1.5e5\n{GROUND}[ground.vertical]\ntype = \"harmonic\"\namplitude = 0.1\nfrequency = 5.0\n");
        let outcomes = [outcome(""), outcome("points = [[0.0, 6.0]]"), outcome_of(&building), outcome_of(&vertical)];
        assert!(outcomes[2].derived.alpha.is_none() && outcomes[3].layout.vertical);
        for o in outcomes {
            for f in SUMMARY {
                let cell = (f.read)(&o);
                // Text and flags of the tower are empty without one (end_state,
                // will_overturn), and will_overturn while the end is undecided.
                let ok = match f.kind {
                    Kind::Text => matches!(cell, Cell::Text(_)) || (matches!(cell, Cell::Empty) && ["end_state", "overturned_block"].contains(&f.name)),
                    Kind::Flag => matches!(cell, Cell::Bool(_)) || (matches!(cell, Cell::Empty) && f.name == "will_overturn"),
                    Kind::Number => matches!(cell, Cell::Float(_) | Cell::Int(_) | Cell::Empty),
                };
                assert!(ok, "{}: {:?} is not a {:?}", f.name, cell, f.kind);
            }
        }
    }

    /// A derived quantity the summary also holds (its field made from it)
    /// has the summary's value bit for bit, the one from the model and the
    /// other from the run; each is checked by hand on the tower on its
    /// church (4 m × 12 m, 1.5e5 kg, solid: I_O = (m2/3)(B² + H²), R the
    /// half-diagonal, tan α = 1/3; the church 2.0e6 kg, μs = 0.3).
    #[test]
    fn the_derived_quantities_agree_with_the_summary() {
        let text = format!("[tower]\nwidth = 4\nheight = 12.0\nmass = 1.5e5\n[building]\nmass = 2.0e6\nmu_static = 0.3\n{GROUND}");
        let case = Scenario::from_toml_str(&text, Path::new("t.toml"))
            .and_then(|s| s.build())
            .unwrap_or_else(|e| panic!("{e}"));
        let o = case.run(RunOptions::ALL).unwrap_or_else(|e| panic!("{e}"));
        let mut shared = 0;
        for q in DERIVED {
            let value = (q.value)(&case.model);
            if let Some(f) = SUMMARY.iter().find(|f| f.name == q.name) {
                shared += 1;
                let Cell::Float(x) = (f.read)(&o) else { panic!("{}", q.name) };
                assert_eq!(value.map(f64::to_bits), Some(x.to_bits()), "{}", q.name);
            }
        }
        assert_eq!(shared, 6);
        let of = |name: &str| DERIVED.iter().find(|q| q.name == name).and_then(|q| (q.value)(&case.model));
        // Exact products and sums of exact decimals, to a few roundings.
        let close = |name: &str, expected: f64| assert!(of(name).is_some_and(|v| (v - expected).abs() <= 1e-15 * expected), "{name}: {:?}", of(name));
        close("inertia_pivot_kg_m2", 1.5e5 / 3.0 * (16.0 + 144.0));
        close("tower_mass_kg", 1.5e5);
        close("sliding_mass_kg", 2.15e6);
        close("g_m_s2", 9.81);
        close("alpha_deg", (1.0f64 / 3.0).atan().to_degrees());
        close("alpha_rad", (1.0f64 / 3.0).atan());
        close("R_m", 40f64.sqrt());
        close("uplift_acceleration_g", 1.0 / 3.0);
        close("slip_acceleration_g", 0.3);
    }

    #[test]
    fn the_summary_fields_are_those_of_summary_json_in_order() {
        // summary.json flattened: an independent walk of the JSON object.
        let o = outcome("");
        let json = crate::summary_json(&o, 0.0);
        let keys: Vec<String> = crate::summary_scalars(&json).into_iter().map(|(k, _)| k).collect();
        let mut expected: Vec<String> = SUMMARY.iter().filter(|f| (f.present)(&o.layout)).map(|f| f.name.to_string()).collect();
        expected.push(WALL_TIME.name.to_string());
        assert_eq!(keys, expected);
    }
}
