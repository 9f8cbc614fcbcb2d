//! The capacity of a tower as one rigid block overturning about a base corner
//! at its springing level (Circolare 21 gennaio 2019 n. 7, §C8.7.1.2.1.3–
//! C8.7.1.2.1.6, local mechanisms; the kinematic analysis of a rigid body).
//!
//! With `b`, `h` the horizontal and vertical distances from the corner to the
//! centre of mass, `α = atan(b/h)`, `R = sqrt(b² + h²)`, the control point the
//! centre of mass and θ the rotation:
//!
//! ```text
//! α0 = b / h                           activation multiplier (§C8.7.1.2.1.3)
//! e* = 1, M* = m                       one rigid body (§C8.7.1.2.1.4)
//! a0* = α0 g / (e* FC)                 spectral acceleration of activation (§C8.7.1.2.1.4)
//! d0 = R sin α = b                     displacement at which a* vanishes (θ = α)
//! exact:  a*(θ) = g tan(α − θ) / FC,  d*(θ) = R (sin α − sin(α − θ))
//! linear: a*(d) = a0* (1 − d/d0)
//! d_SLV = 0.4 d0, d_SLC = 0.6 d0       ultimate displacements (§C8.7.1.2.1.6)
//! T_SLV = 1.68 π sqrt(d_SLV / a*(d_SLV)), T_SLC = 1.56 π sqrt(d_SLC / a*(d_SLC))
//! ```

use crate::error::{invalid, Error};
use crate::outputs::number;
use rocking::stack::Block;
use std::f64::consts::PI;
use std::fmt;
use std::str::FromStr;

/// The confidence factor FC when none is given: 1.35, knowledge level LC1
/// (Circolare 2019 §C8.5.4, Tab. C8.5.IV).
pub use rocking_scenario::DEFAULT_CONFIDENCE_FACTOR;

/// Which capacity curve the checks read.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum CurveKind {
    /// `a*(d) = a0* (1 − d/d0)`, the Circolare's worked cases' straight line (the default).
    #[default]
    Linear,
    /// The rigid body's own curve, `a*(θ) = g tan(α − θ)/FC`, `d*(θ) = R (sin α − sin(α − θ))`.
    Exact,
}

impl CurveKind {
    /// `"linear"` or `"exact"`.
    pub fn as_str(self) -> &'static str {
        match self {
            CurveKind::Linear => "linear",
            CurveKind::Exact => "exact",
        }
    }
}

impl fmt::Display for CurveKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl FromStr for CurveKind {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self, Error> {
        match s {
            "linear" => Ok(CurveKind::Linear),
            "exact" => Ok(CurveKind::Exact),
            other => Err(invalid("capacity", format!("must be \"linear\" or \"exact\", got \"{other}\""))),
        }
    }
}

/// The activation multiplier `α0 = b / h` (Circolare 2019 §C8.7.1.2.1.3): the
/// ratio of horizontal to vertical load that starts the overturning of a rigid
/// block about a corner at distances `b` (horizontal) and `h` (vertical) from
/// its centre of mass (= tan α).
pub fn activation_multiplier(b: f64, h: f64) -> f64 {
    b / h
}

/// The spectral acceleration of activation `a0* = α0 g / (e* FC)` (m/s²)
/// (Circolare 2019 §C8.7.1.2.1.4, eq. C8.7.1.8), `g` in m/s².
pub fn activation_acceleration(alpha0: f64, e_star: f64, confidence_factor: f64, g: f64) -> f64 {
    alpha0 * g / (e_star * confidence_factor)
}

/// The displacement of the control point at which the capacity vanishes,
/// `d0 = R sin α` (m): the centre of mass over the corner, θ = α.
pub fn collapse_displacement(radius: f64, alpha: f64) -> f64 {
    radius * libm::sin(alpha)
}

/// The ultimate displacement of the life-safety limit state `d_SLV = 0.4 d0` (m)
/// (Circolare 2019 §C8.7.1.2.1.6).
pub fn ultimate_displacement_slv(d0: f64) -> f64 {
    0.4 * d0
}

/// The ultimate displacement of the collapse limit state `d_SLC = 0.6 d0` (m)
/// (Circolare 2019 §C8.7.1.2.1.6).
pub fn ultimate_displacement_slc(d0: f64) -> f64 {
    0.6 * d0
}

/// The linear capacity curve `a*(d) = a0* (1 − d/d0)` (m/s²) at the spectral
/// displacement `d` (m) (Circolare 2019 §C8.7.1.2.1.5, the straight line of its
/// worked cases).
pub fn linear_capacity_curve(a0_star: f64, d0: f64, d: f64) -> f64 {
    a0_star * (1.0 - d / d0)
}

/// The exact capacity curve of a rigid block at the rotation θ (rad): the
/// spectral displacement `d*(θ) = R (sin α − sin(α − θ))` (m) and acceleration
/// `a*(θ) = g tan(α − θ) / FC` (m/s²) (Circolare 2019 §C8.7.1.2.1.5; the
/// equilibrium of the rotated block, e* = 1).
pub fn exact_capacity_curve(alpha: f64, radius: f64, confidence_factor: f64, g: f64, theta: f64) -> (f64, f64) {
    (
        radius * (libm::sin(alpha) - libm::sin(alpha - theta)),
        g * libm::tan(alpha - theta) / confidence_factor,
    )
}

/// The exact curve's acceleration at the displacement `d` (m) in [0, d0]: the
/// rotation of [`exact_capacity_curve`] solved for, `θ = α − asin(sin α − d/R)`.
pub fn exact_acceleration_at(alpha: f64, radius: f64, confidence_factor: f64, g: f64, d: f64) -> f64 {
    let theta = alpha - libm::asin((libm::sin(alpha) - d / radius).clamp(-1.0, 1.0));
    exact_capacity_curve(alpha, radius, confidence_factor, g, theta).1
}

/// The secant period at the life-safety ultimate displacement,
/// `T_SLV = 1.68 π sqrt(d_SLV / a*(d_SLV))` (s) (Circolare 2019 eq. C8.7.1.10), `d` in m and `a` in m/s².
pub fn secant_period_slv(d_slv: f64, a_at_d_slv: f64) -> f64 {
    1.68 * PI * (d_slv / a_at_d_slv).sqrt()
}

/// The secant period at the collapse ultimate displacement,
/// `T_SLC = 1.56 π sqrt(d_SLC / a*(d_SLC))` (s) (Circolare 2019 eq. C8.7.1.11).
pub fn secant_period_slc(d_slc: f64, a_at_d_slc: f64) -> f64 {
    1.56 * PI * (d_slc / a_at_d_slc).sqrt()
}

/// The mass (kg) of a column of blocks standing at rest, each centred on the
/// one below (`blocks[0]` the lowest), and the height (m) of its centre of
/// mass above the lowest block's base: `h = Σ m_i (z_i + H_i/2) / Σ m_i`,
/// `z_i = H_0 + … + H_(i−1)` the height of block i's base. The blocks turning
/// as one rigid body about a corner of the lowest one's base are a mechanism
/// whose `b` is half the lowest one's width and whose `h` is this.
pub fn rigid_column_centre(blocks: &[Block]) -> (f64, f64) {
    rocking::stack::column_centre(blocks)
}

/// The capacity of a tower as one rigid block on its springing level.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Capacity {
    /// Slenderness α = atan(b/h) (rad).
    pub alpha: f64,
    /// Distance R from the corner to the centre of mass (m).
    pub radius: f64,
    /// Gravity g (m/s²).
    pub g: f64,
    /// Confidence factor FC (≥ 1).
    pub confidence_factor: f64,
    /// The curve the checks read.
    pub curve: CurveKind,
    /// Activation multiplier α0 = b/h.
    pub alpha0: f64,
    /// Participating mass fraction e* (1: one rigid body).
    pub e_star: f64,
    /// Participating mass M* (kg).
    pub m_star: f64,
    /// Spectral acceleration of activation a0* (m/s²).
    pub a0_star: f64,
    /// Displacement at which the capacity vanishes d0 (m).
    pub d0: f64,
    /// Ultimate displacement of the life-safety state d_SLV (m).
    pub d_slv: f64,
    /// Ultimate displacement of the collapse state d_SLC (m).
    pub d_slc: f64,
    /// Secant period at d_SLV (s).
    pub t_slv: f64,
    /// Secant period at d_SLC (s).
    pub t_slc: f64,
}

/// The largest slenderness accepted: a block with α ≥ π/2 has no overturning mechanism.
const MAX_ALPHA: f64 = std::f64::consts::FRAC_PI_2;

impl Capacity {
    /// The capacity of a block of mass `mass` (kg, > 0) whose centre of mass is
    /// at `radius` (m, > 0) from the corner at the slenderness `alpha` (rad, in
    /// (0, π/2)), under gravity `g` (m/s², > 0), with confidence factor FC
    /// (≥ 1) and the curve `curve`. Every number of the capacity is finite,
    /// a0*, d0 and the secant periods > 0: inputs whose products leave the
    /// floating-point numbers (g = 1e-310 m/s²) are refused.
    pub fn new(mass: f64, radius: f64, alpha: f64, g: f64, confidence_factor: f64, curve: CurveKind) -> Result<Self, Error> {
        for (name, value) in [("mass", mass), ("radius", radius), ("g", g)] {
            if !(value.is_finite() && value > 0.0) {
                return Err(invalid(name, format!("must be a finite number > 0, got {value}")));
            }
        }
        if !(alpha.is_finite() && alpha > 0.0 && alpha < MAX_ALPHA) {
            return Err(invalid("alpha", format!("must be in (0, π/2) rad, got {alpha}")));
        }
        if !(confidence_factor.is_finite() && confidence_factor >= 1.0) {
            return Err(invalid(
                "confidence_factor",
                format!("must be a finite number >= 1 (FC: 1.35, 1.2 or 1 for knowledge levels LC1–LC3), got {confidence_factor}"),
            ));
        }
        let (b, h) = (radius * libm::sin(alpha), radius * libm::cos(alpha));
        let alpha0 = activation_multiplier(b, h);
        let e_star = 1.0;
        let a0_star = activation_acceleration(alpha0, e_star, confidence_factor, g);
        let d0 = collapse_displacement(radius, alpha);
        let (d_slv, d_slc) = (ultimate_displacement_slv(d0), ultimate_displacement_slc(d0));
        let mut capacity = Self {
            alpha,
            radius,
            g,
            confidence_factor,
            curve,
            alpha0,
            e_star,
            m_star: e_star * mass,
            a0_star,
            d0,
            d_slv,
            d_slc,
            t_slv: 0.0,
            t_slc: 0.0,
        };
        capacity.t_slv = secant_period_slv(d_slv, capacity.acceleration_at(d_slv));
        capacity.t_slc = secant_period_slc(d_slc, capacity.acceleration_at(d_slc));
        // Valid inputs whose products leave the floating-point numbers: g =
        // 1e-310 m/s² makes a0* vanish and the secant periods infinite.
        let numbers = [capacity.a0_star, capacity.d0, capacity.t_slv, capacity.t_slc];
        if !numbers.iter().all(|x| x.is_finite() && *x > 0.0) {
            return Err(invalid(
                "capacity",
                format!(
                    "out of the floating-point range (each must be a finite number > 0): a0* = {} m/s², d0 = {} m, T_SLV = {} s, \
                     T_SLC = {} s, from g = {} m/s², R = {} m, α = {} rad, FC = {}",
                    number(capacity.a0_star),
                    number(capacity.d0),
                    number(capacity.t_slv),
                    number(capacity.t_slc),
                    number(g),
                    number(radius),
                    number(alpha),
                    number(confidence_factor)
                ),
            ));
        }
        Ok(capacity)
    }

    /// The capacity of the tower of `model` (an error without one): with
    /// blocks on it, the tower and every block turning as one rigid body
    /// about a corner of the tower's base ([`Capacity::of_column`]).
    pub fn of_model(model: &rocking::Model, confidence_factor: f64, curve: CurveKind) -> Result<Self, Error> {
        Self::of_block(model, 0, confidence_factor, curve)
    }

    /// The capacity of the mechanism of block `k` of `model` (0 the tower, `k`
    /// the `k`-th block above it): block `k` and the blocks above it turning as
    /// one rigid body about a corner of block `k`'s base ([`Capacity::of_column`]).
    /// A tower alone is its own `R` and `α`.
    pub fn of_block(model: &rocking::Model, k: usize, confidence_factor: f64, curve: CurveKind) -> Result<Self, Error> {
        let tower = model
            .tower()
            .ok_or_else(|| invalid("tower", "an assessment needs a [tower]: the capacity is that of the tower rocking"))?;
        match model.stack() {
            None if k == 0 => Self::new(tower.mass(), tower.radius(), tower.alpha(), model.gravity(), confidence_factor, curve),
            Some(stack) if k < stack.len() => Self::of_column(&stack.blocks()[k..], model.gravity(), confidence_factor, curve),
            _ => Err(invalid("block", format!("the tower carries no block {k}"))),
        }
    }

    /// The capacity of a column of blocks (`blocks[0]` the lowest) turning as
    /// one rigid body about a corner of the lowest one's base: `b` half its
    /// width, `h` and the mass of [`rigid_column_centre`], `R = √(b² + h²)`,
    /// `α = atan(b/h)`; e* = 1 and M* the whole column's mass.
    pub fn of_column(blocks: &[Block], g: f64, confidence_factor: f64, curve: CurveKind) -> Result<Self, Error> {
        let lowest = blocks.first().ok_or_else(|| invalid("block", "a column has at least one block"))?;
        let (mass, h) = rigid_column_centre(blocks);
        let b = lowest.width() / 2.0;
        Self::new(mass, libm::hypot(b, h), libm::atan2(b, h), g, confidence_factor, curve)
    }

    /// The spectral acceleration a* (m/s²) of the chosen curve at the
    /// displacement `d` (m, in [0, d0]).
    pub fn acceleration_at(&self, d: f64) -> f64 {
        match self.curve {
            CurveKind::Linear => linear_capacity_curve(self.a0_star, self.d0, d),
            CurveKind::Exact => exact_acceleration_at(self.alpha, self.radius, self.confidence_factor, self.g, d),
        }
    }

    /// The control point's spectral displacement (m) at a rotation θ (rad): `R (sin α − sin(α − θ))`.
    pub fn displacement_at_rotation(&self, theta: f64) -> f64 {
        exact_capacity_curve(self.alpha, self.radius, self.confidence_factor, self.g, theta).0
    }

    /// `count` (≥ 2) points `(d*, a*)` (m, m/s²) of the chosen curve from d = 0 to d0:
    /// evenly spaced in d for the linear curve, in θ (0 to α) for the exact one.
    pub fn curve_points(&self, count: usize) -> Vec<(f64, f64)> {
        let n = count.max(2) - 1;
        (0..=n)
            .map(|k| {
                let x = k as f64 / n as f64;
                match self.curve {
                    CurveKind::Linear => (x * self.d0, linear_capacity_curve(self.a0_star, self.d0, x * self.d0)),
                    CurveKind::Exact => exact_capacity_curve(self.alpha, self.radius, self.confidence_factor, self.g, x * self.alpha),
                }
            })
            .collect()
    }
}
