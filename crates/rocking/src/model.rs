//! The coupled system and its equations of motion (model.md, (T)–(B)):
//!
//! ```text
//! I_O θ̈ + m2 R cos φ · Ẍ_p + s m2 g R sin φ = 0                     (T)
//! M Ẍ_p + m2 R (cos φ · θ̈ + s sin φ · θ̇²) = F,   Ẍ_p = a_g + ü       (B)
//! N = M g  (constant)   or   N = M g + m2 R (s sin φ θ̈ − cos φ θ̇²)  (dynamic)
//! ```
//!
//! with `φ = α − s θ` (equal to `α − |θ|` on the pivot's own side and its
//! analytic continuation across `θ = 0`, which event location needs).

use crate::body::{Building, NormalForce, Tower};
use crate::error::{positive, Error, Parameter};
use crate::regime::{BuildingRegime, Pivot, Regime, SlipDirection, TowerRegime};
use crate::trig::sin_cos;

/// A tower, a building, or both, under gravity `g`. Valid by construction.
#[derive(Debug, Clone, PartialEq)]
pub struct Model {
    tower: Option<Tower>,
    building: Option<Building>,
    gravity: f64,
}

/// Quantities derived from a model without running it (what `rocking check` prints).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Derived {
    /// Slenderness `α` (rad); `None` without a tower.
    pub alpha: Option<f64>,
    /// `R` (m).
    pub radius: Option<f64>,
    /// Frequency parameter `p` (rad/s).
    pub p: Option<f64>,
    /// Restitution `r` of the angular velocity.
    pub restitution: Option<f64>,
    /// Moment of inertia about a base corner (kg·m²).
    pub inertia_pivot: Option<f64>,
    /// Tower mass `m2` (kg).
    pub tower_mass: Option<f64>,
    /// Ground acceleration that uplifts the tower on a fixed base, `tan α` (in g).
    pub uplift_acceleration_g: Option<f64>,
    /// Ground acceleration that makes the building (with the tower at rest) slip, `μs` (in g).
    pub slip_acceleration_g: Option<f64>,
    /// Total sliding mass `M = m1 + m2` (kg).
    pub sliding_mass: Option<f64>,
}

/// Largest gravity accepted (m/s²).
pub const MAX_GRAVITY: f64 = 1e3;

impl Model {
    /// A model of a tower on a fixed base, a building alone, or a tower on a
    /// building, with gravity `g` (m/s², > 0).
    pub fn new(tower: Option<Tower>, building: Option<Building>, gravity: f64) -> Result<Self, Error> {
        let gravity = positive(Parameter::Gravity, gravity)?;
        if gravity > MAX_GRAVITY {
            return Err(Error::InvalidParameter {
                parameter: Parameter::Gravity,
                reason: format!("must be at most {MAX_GRAVITY:.0e} m/s² (a hundred times the Earth's; beyond it the time scale √(R/g) of any tower shrinks below what a run can step through), got {gravity:e}"),
            });
        }
        if tower.is_none() && building.is_none() {
            return Err(Error::InvalidParameter {
                parameter: Parameter::Bodies,
                reason: "a scenario needs a [tower], a [building], or both".into(),
            });
        }
        Ok(Self { tower, building, gravity })
    }
    /// The tower, if any.
    pub fn tower(&self) -> Option<&Tower> {
        self.tower.as_ref()
    }
    /// The building, if any.
    pub fn building(&self) -> Option<&Building> {
        self.building.as_ref()
    }
    /// Gravity (m/s²).
    pub fn gravity(&self) -> f64 {
        self.gravity
    }
    /// Derived quantities.
    pub fn derived(&self) -> Derived {
        let t = self.tower.as_ref();
        Derived {
            alpha: t.map(Tower::alpha),
            radius: t.map(Tower::radius),
            p: t.map(|t| t.frequency_parameter(self.gravity)),
            restitution: t.map(Tower::restitution),
            inertia_pivot: t.map(Tower::inertia_pivot),
            tower_mass: t.map(Tower::mass),
            uplift_acceleration_g: t.map(|t| t.alpha().tan()),
            slip_acceleration_g: self.building.as_ref().map(Building::mu_static),
            sliding_mass: self.building.as_ref().map(|b| b.mass() + t.map_or(0.0, Tower::mass)),
        }
    }
}

/// The accelerations of a regime at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Accelerations {
    /// `θ̈` (rad/s²).
    pub(crate) theta: f64,
    /// `ü` (m/s²).
    pub(crate) slip: f64,
}

/// The model's constants, laid out for the inner loop.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Kernel {
    pub(crate) has_tower: bool,
    pub(crate) has_building: bool,
    pub(crate) g: f64,
    pub(crate) alpha: f64,
    pub(crate) tan_alpha: f64,
    sin_alpha: f64,
    cos_alpha: f64,
    /// `m2 R / I_O` (1/m·… so that `p² = k g`).
    k: f64,
    pub(crate) radius: f64,
    /// `m2 R`.
    m2r: f64,
    inertia: f64,
    /// Sliding mass `M` (kg).
    total: f64,
    pub(crate) mu_s: f64,
    mu_k: f64,
    pub(crate) dynamic: bool,
    pub(crate) restitution: f64,
    pub(crate) half_width: f64,
    pub(crate) height: f64,
}

impl Kernel {
    pub(crate) fn new(model: &Model) -> Self {
        let t = model.tower.as_ref();
        let b = model.building.as_ref();
        let m2 = t.map_or(0.0, Tower::mass);
        let radius = t.map_or(0.0, Tower::radius);
        let inertia = t.map_or(1.0, Tower::inertia_pivot);
        let alpha = t.map_or(0.0, Tower::alpha);
        Self {
            has_tower: t.is_some(),
            has_building: b.is_some(),
            g: model.gravity,
            alpha,
            tan_alpha: alpha.tan(),
            sin_alpha: alpha.sin(),
            cos_alpha: alpha.cos(),
            k: m2 * radius / inertia,
            radius,
            m2r: m2 * radius,
            inertia,
            total: b.map_or(0.0, Building::mass) + m2,
            mu_s: b.map_or(f64::INFINITY, Building::mu_static),
            mu_k: b.map_or(0.0, Building::mu_kinetic),
            dynamic: b.is_some_and(|b| b.normal_force() == NormalForce::Dynamic),
            restitution: t.map_or(1.0, Tower::restitution),
            half_width: t.map_or(0.0, Tower::half_width),
            height: t.map_or(0.0, Tower::height),
        }
    }

    /// `θ̈` and `ü` in `regime` for ground acceleration `a_g` and state `y = [θ, θ̇, u, u̇]`.
    #[inline(always)]
    pub(crate) fn accelerations(&self, regime: Regime, a_g: f64, y: &[f64; 4]) -> Accelerations {
        match (regime.tower, regime.building) {
            (TowerRegime::Rest, BuildingRegime::Stick) => Accelerations::default(),
            // The whole complex slides as one body: M (a_g + ü) = −μk σ M g.
            (TowerRegime::Rest, BuildingRegime::Slip(dir)) => Accelerations {
                theta: 0.0,
                slip: -self.mu_k * dir.sign() * self.g - a_g,
            },
            (TowerRegime::Rocking(pivot), BuildingRegime::Stick) => {
                let s = pivot.sign();
                let (sin_phi, cos_phi) = sin_cos(self.alpha - s * y[0]);
                // (T) with Ẍ_p = a_g: Housner's equation.
                Accelerations {
                    theta: -self.k * (s * self.g * sin_phi + a_g * cos_phi),
                    slip: 0.0,
                }
            }
            (TowerRegime::Rocking(pivot), BuildingRegime::Slip(dir)) => self.rocking_on_slip(pivot.sign(), dir.sign(), a_g, y),
        }
    }

    /// (T)–(B) with `F = −μk σ N`: a linear 2×2 system in `(θ̈, Ẍ_p)`, solved directly.
    #[inline]
    fn rocking_on_slip(&self, s: f64, sigma: f64, a_g: f64, y: &[f64; 4]) -> Accelerations {
        let (sin_phi, cos_phi) = sin_cos(self.alpha - s * y[0]);
        let w2 = y[1] * y[1];
        let c = self.m2r * cos_phi;
        let friction = self.mu_k * sigma;
        // Row (T): I θ̈ + c A = −s m2 R g sin φ.
        let rhs_t = -s * self.m2r * self.g * sin_phi;
        // Row (B): (c + [dyn] μk σ s m2 R sin φ) θ̈ + M A = −s m2 R sin φ θ̇² − μk σ (M g − [dyn] m2 R cos φ θ̇²).
        let (a21, normal_static) = if self.dynamic {
            (c + friction * s * self.m2r * sin_phi, self.total * self.g - self.m2r * cos_phi * w2)
        } else {
            (c, self.total * self.g)
        };
        let rhs_b = -s * self.m2r * sin_phi * w2 - friction * normal_static;
        let det = self.inertia * self.total - c * a21;
        if det <= 0.0 {
            // Painlevé's paradox of the dynamic normal force (a light building, high
            // friction): no acceleration satisfies both equations. NaN stops the
            // integrator, which reports the time.
            return Accelerations {
                theta: f64::NAN,
                slip: f64::NAN,
            };
        }
        let theta = (rhs_t * self.total - c * rhs_b) / det;
        let acc_pivot = (self.inertia * rhs_b - a21 * rhs_t) / det;
        Accelerations { theta, slip: acc_pivot - a_g }
    }

    /// The friction force `F_req` the foundation must supply to keep the building
    /// stuck (`ü = 0`), and the normal force `N` at that instant.
    #[inline]
    pub(crate) fn stick_demand(&self, tower: TowerRegime, a_g: f64, y: &[f64; 4]) -> (f64, f64) {
        match tower {
            TowerRegime::Rest => (self.total * a_g, self.total * self.g),
            TowerRegime::Rocking(pivot) => {
                let s = pivot.sign();
                let (sin_phi, cos_phi) = sin_cos(self.alpha - s * y[0]);
                let w2 = y[1] * y[1];
                let theta_dd = -self.k * (s * self.g * sin_phi + a_g * cos_phi);
                let force = self.total * a_g + self.m2r * (cos_phi * theta_dd + s * sin_phi * w2);
                let normal = if self.dynamic {
                    self.total * self.g + self.m2r * (s * sin_phi * theta_dd - cos_phi * w2)
                } else {
                    self.total * self.g
                };
                (force, normal)
            }
        }
    }

    /// The pivot the tower would start rocking on, if it stands and the pivot
    /// line accelerates beyond `g tan α` (model.md: rest → rocking).
    #[inline]
    pub(crate) fn uplift_margin(&self, acc_pivot: f64) -> f64 {
        acc_pivot.abs() - self.g * self.tan_alpha
    }

    /// Horizontal acceleration of the pivot line `Ẍ_p` with the tower at rest.
    #[inline]
    pub(crate) fn pivot_acceleration_at_rest(&self, building: BuildingRegime, a_g: f64) -> f64 {
        match building {
            BuildingRegime::Stick => a_g,
            BuildingRegime::Slip(dir) => -self.mu_k * dir.sign() * self.g,
        }
    }

    /// Horizontal displacement relative to the building and absolute horizontal
    /// acceleration of a point `(x, y)` of the tower (tower coordinates, origin at
    /// the base centre), paper eqs. (7)–(13) with model.md's rotation.
    #[inline]
    pub(crate) fn point(&self, pivot: Option<Pivot>, x: f64, yp: f64, state: &[f64; 4], acc: Accelerations, a_g: f64) -> (f64, f64) {
        let base = a_g + acc.slip;
        let Some(pivot) = pivot else { return (0.0, base) };
        let xr = x - pivot.sign() * self.half_width;
        let (sin_t, cos_t) = sin_cos(state[0]);
        let dx = cos_t * xr + sin_t * yp - xr;
        let lever = -sin_t * xr + cos_t * yp;
        let centripetal = cos_t * xr + sin_t * yp;
        (dx, base + lever * acc.theta - centripetal * state[1] * state[1])
    }

    /// The instantaneous checks of model.md: the absolute horizontal
    /// acceleration of the top centre (m/s²) and the pivot reactions per unit
    /// tower mass `(f_x, f_y) / m2` (m/s²), sharing one `sin_cos(θ)`
    /// (`φ = α − s θ` by the angle-difference formulas).
    #[inline]
    pub(crate) fn checks(&self, pivot: Option<Pivot>, state: &[f64; 4], acc: Accelerations, a_g: f64) -> (f64, f64, f64) {
        let acc_pivot = a_g + acc.slip;
        let Some(pivot) = pivot else { return (acc_pivot, acc_pivot, self.g) };
        let s = pivot.sign();
        let (sin_t, cos_t) = sin_cos(state[0]);
        let w2 = state[1] * state[1];
        // The top centre (0, H), relative to the pivot (s b, 0): eqs. (7)–(13).
        let xr = -s * self.half_width;
        let top = acc_pivot + (-sin_t * xr + cos_t * self.height) * acc.theta - (cos_t * xr + sin_t * self.height) * w2;
        let sin_phi = self.sin_alpha * cos_t - s * self.cos_alpha * sin_t;
        let cos_phi = self.cos_alpha * cos_t + s * self.sin_alpha * sin_t;
        let fx = acc_pivot + self.radius * (cos_phi * acc.theta + s * sin_phi * w2);
        let fy = self.g + self.radius * (s * sin_phi * acc.theta - cos_phi * w2);
        (top, fx, fy)
    }

    /// The slip direction a stuck building starts sliding in under demand `force`.
    pub(crate) fn slip_direction(force: f64) -> SlipDirection {
        SlipDirection::of_sign(-force)
    }
}
