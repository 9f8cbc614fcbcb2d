//! The equations of the model, each written once (docs/src/model.md, "Equations of
//! motion", "Regimes", "Checks the model must report", "Points of the tower"),
//! generic over [`Real`] so that the right-hand side evaluates them on `f64`
//! and event location and peak finding on [`Jet`](crate::jet::Jet) (value and
//! exact time derivative along the solution):
//!
//! ```text
//! I_O θ̈ + m2 R cos φ · Ẍ_p + s m2 g_e R sin φ = 0                     (T)
//! M Ẍ_p + m2 R (cos φ · θ̈ + s sin φ · θ̇²) = F,   Ẍ_p = a_g + ü       (B)
//! N = M g_e  (constant)   or   N = M g_e + m2 R (s sin φ θ̈ − cos φ θ̇²)  (N)
//! f_x = m2 (Ẍ_p + R (cos φ θ̈ + s sin φ θ̇²)),
//! f_y = m2 (g_e + R (s sin φ θ̈ − cos φ θ̇²))                          (pivot reactions)
//! ```
//!
//! with `φ = α − s θ` (equal to `α − |θ|` on the pivot's own side and its
//! analytic continuation across `θ = 0`, which event location needs) and
//! `g_e` the effective gravity (`g` without a vertical ground motion).

use crate::body::{Building, Friction, NormalForce, Tower};
use crate::jet::Real;
use crate::model::Model;
use crate::regime::{BuildingRegime, Regime, TowerRegime};

/// The model's constants, laid out for the inner loop.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Kernel {
    pub(crate) has_tower: bool,
    pub(crate) has_building: bool,
    /// Gravity `g` (m/s²).
    pub(crate) g: f64,
    pub(crate) alpha: f64,
    pub(crate) tan_alpha: f64,
    pub(crate) sin_alpha: f64,
    pub(crate) cos_alpha: f64,
    /// `m2 R / I_O` (1/m), so that `p² = k g`.
    pub(crate) k: f64,
    /// `R` (m).
    pub(crate) radius: f64,
    /// `m2` (kg).
    pub(crate) m2: f64,
    /// `m2 R` (kg·m).
    pub(crate) m2r: f64,
    /// `I_O` (kg·m²).
    pub(crate) inertia: f64,
    /// Sliding mass `M = m1 + m2` (kg).
    pub(crate) total: f64,
    /// The foundation's friction law (a fixed base's without a building).
    pub(crate) friction: Friction,
    pub(crate) dynamic: bool,
    /// Restitution `r` of the angular velocity.
    pub(crate) restitution: f64,
    /// `b = B/2` (m).
    pub(crate) half_width: f64,
    /// `H` (m).
    pub(crate) height: f64,
}

/// `θ̈` and `ü` at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Accelerations<T> {
    /// `θ̈` (rad/s²).
    pub(crate) theta: T,
    /// `ü` (m/s²).
    pub(crate) slip: T,
}

/// `sin φ`, `cos φ` of `φ = α − s θ`, and `s`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Lean<T> {
    pub(crate) s: f64,
    pub(crate) sin_phi: T,
    pub(crate) cos_phi: T,
}

impl Kernel {
    pub(crate) fn new(model: &Model) -> Self {
        let t = model.tower();
        let b = model.building();
        let m2 = t.map_or(0.0, Tower::mass);
        let radius = t.map_or(0.0, Tower::radius);
        let inertia = t.map_or(1.0, Tower::inertia_pivot);
        let alpha = t.map_or(0.0, Tower::alpha);
        Self {
            has_tower: t.is_some(),
            has_building: b.is_some(),
            g: model.gravity(),
            alpha,
            tan_alpha: libm::tan(alpha),
            sin_alpha: libm::sin(alpha),
            cos_alpha: libm::cos(alpha),
            k: m2 * radius / inertia,
            radius,
            m2,
            m2r: m2 * radius,
            inertia,
            total: b.map_or(0.0, Building::mass) + m2,
            friction: Friction::of(b),
            dynamic: b.is_some_and(|b| b.normal_force() == NormalForce::Dynamic),
            restitution: t.map_or(1.0, Tower::restitution),
            half_width: t.map_or(0.0, Tower::half_width),
            height: t.map_or(0.0, Tower::height),
        }
    }

    /// `φ = α − s θ` and its sine and cosine.
    #[inline(always)]
    pub(crate) fn lean<T: Real>(&self, s: f64, theta: T) -> Lean<T> {
        // `Real::sin_cos`, not `f64::sin_cos` (the platform's, three times slower).
        let (sin_phi, cos_phi) = Real::sin_cos(T::from(self.alpha) - theta * s);
        Lean { s, sin_phi, cos_phi }
    }

    /// `(sin θ, cos θ)` from the lean, by the angle-difference formulas
    /// (`θ = s (α − φ)`): no second sine.
    #[inline(always)]
    pub(crate) fn rotation<T: Real>(&self, lean: Lean<T>) -> (T, T) {
        (
            (lean.cos_phi * self.sin_alpha - lean.sin_phi * self.cos_alpha) * lean.s,
            lean.cos_phi * self.cos_alpha + lean.sin_phi * self.sin_alpha,
        )
    }

    /// (T) solved for `θ̈`, the pivot line's acceleration `Ẍ_p` given:
    /// `θ̈ = −(m2 R / I_O) (s g_e sin φ + Ẍ_p cos φ)`; Housner's equation on a
    /// fixed base.
    #[inline(always)]
    pub(crate) fn tower_equation<T: Real>(&self, lean: Lean<T>, acc_pivot: T, g_e: T) -> T {
        -(g_e * lean.sin_phi * lean.s + acc_pivot * lean.cos_phi) * self.k
    }

    /// `p² = m2 g R / I_O` (1/s²) of (T) in free rocking (no input, `g_e =
    /// g`, a fixed base or a stuck building): there (T) reads
    /// `ψ̈ = −p² sin(α − ψ)` for the lean towards the pivot `ψ = s θ`, and
    /// its first integral, energy, `½ ψ̇² + p² cos(α − ψ)`, is constant. The
    /// cascade's closed forms (`cascade.rs`: the apex of a flight, its
    /// duration, the linearised interpolant) and the free motion's verdict
    /// are written with it; a test holds that energy constant along
    /// [`Kernel::tower_equation`].
    #[inline(always)]
    pub(crate) fn free_rocking_p2(&self) -> f64 {
        self.k * self.g
    }

    /// A bound of `|θ̈|` from (T) with `Ẍ_p = a_g` (a stuck building or a
    /// fixed base), given upper bounds of `g_e` and `|a_g|`:
    /// `|θ̈| = k |s g_e sin φ + a_g cos φ| <= k sqrt(g_e² + a_g²)` (Cauchy–Schwarz).
    /// Returns `(k sqrt(g_e² + a_g²), sqrt(g_e² + a_g²))`: the bound and the
    /// reach [`Kernel::tower_jerk_bound`] needs.
    #[inline(always)]
    pub(crate) fn tower_acceleration_bound(&self, g_e: f64, a_max: f64) -> (f64, f64) {
        let reach = (g_e * g_e + a_max * a_max).sqrt();
        (self.k * reach, reach)
    }

    /// A bound of `|θ⃛|` from (T) with `Ẍ_p = a_g`: differentiating along
    /// the motion (`φ̇ = −s θ̇`),
    /// `θ⃛ = −k [(s ġ_e sin φ + ȧ_g cos φ) + θ̇ (s a_g sin φ − g_e cos φ)]`, so
    /// `|θ⃛| <= k [sqrt(ġ_e² + ȧ_g²) + max|θ̇| sqrt(g_e² + a_g²)]`, given upper
    /// bounds of `|ġ_e|`, `|ȧ_g|` and `|θ̇|`; `reach` is the second root, from
    /// [`Kernel::tower_acceleration_bound`].
    #[inline(always)]
    pub(crate) fn tower_jerk_bound(&self, reach: f64, g_rate: f64, a_rate: f64, theta_dot_max: f64) -> f64 {
        self.k * ((g_rate * g_rate + a_rate * a_rate).sqrt() + theta_dot_max * reach)
    }

    /// (B) solved for the friction force: `F = M Ẍ_p + m2 R (cos φ θ̈ + s sin φ θ̇²)`.
    #[inline(always)]
    pub(crate) fn building_equation<T: Real>(&self, lean: Lean<T>, theta_dot: T, theta_ddot: T, acc_pivot: T) -> T {
        acc_pivot * self.total + (lean.cos_phi * theta_ddot + lean.sin_phi * theta_dot * theta_dot * lean.s) * self.m2r
    }

    /// (N): the normal force of the foundation on the building, `M g_e`
    /// (constant) or `M g_e + m2 R (s sin φ θ̈ − cos φ θ̇²)` (dynamic).
    #[inline(always)]
    pub(crate) fn normal_force<T: Real>(&self, lean: Lean<T>, theta_dot: T, theta_ddot: T, g_e: T) -> T {
        let weight = g_e * self.total;
        if self.dynamic {
            weight + (lean.sin_phi * theta_ddot * lean.s - lean.cos_phi * theta_dot * theta_dot) * self.m2r
        } else {
            weight
        }
    }

    /// The uplift threshold of a standing tower: `|Ẍ_p| > g_e tan α` lifts it
    /// (docs/src/model.md, "Regimes and transitions": rest → rocking).
    #[inline(always)]
    pub(crate) fn uplift_threshold<T: Real>(&self, g_e: T) -> T {
        g_e * self.tan_alpha
    }

    /// The pivot line's acceleration `Ẍ_p` of a sliding building with the tower
    /// standing on it: (B) with `θ̇ = θ̈ = 0` and the kinetic friction of
    /// `N = M g_e` (both normal-force laws), divided by `M`.
    #[inline(always)]
    pub(crate) fn resting_slide<T: Real>(&self, sigma: f64, g_e: T) -> T {
        self.friction.kinetic_friction(sigma, g_e)
    }

    /// Bounds of `|ü|` and `|u⃛|` over a step for a building sliding under a
    /// standing tower, `ü = Ẍ_p − a_g` with `Ẍ_p` from [`Kernel::resting_slide`]
    /// (proportional to `g_e`): `|ü| <= |Ẍ_p(g_e max)| + max|a_g|` and
    /// `|u⃛| <= |Ẍ_p(max|ġ_e|)| + max|ȧ_g|`, given upper bounds of `g_e`,
    /// `|ġ_e|`, `|a_g|` and `|ȧ_g|` on the step.
    #[inline(always)]
    pub(crate) fn resting_slide_bounds(&self, g_e: f64, g_rate: f64, a_max: f64, a_rate: f64) -> (f64, f64) {
        (self.resting_slide(1.0, g_e).abs() + a_max, self.resting_slide(1.0, g_rate).abs() + a_rate)
    }

    /// The pivot line's acceleration `Ẍ_p` under a standing tower: the ground's
    /// on a stuck building (or none), [`Kernel::resting_slide`] on a sliding one.
    #[inline(always)]
    pub(crate) fn pivot_acceleration_at_rest<T: Real>(&self, building: BuildingRegime, a_g: T, g_e: T) -> T {
        match building {
            BuildingRegime::Stick => a_g,
            BuildingRegime::Slip(dir) => self.resting_slide(dir.sign(), g_e),
        }
    }

    /// The stick demand: the friction force `F_req` that keeps the building stuck
    /// (`ü = 0`, so `Ẍ_p = a_g`), (B) with `θ̈` from (T), and the normal force (N)
    /// at that instant. The building slips when `|F_req| > μs N`.
    #[inline(always)]
    pub(crate) fn stick_demand<T: Real>(&self, tower: TowerRegime, a_g: T, g_e: T, theta: T, theta_dot: T) -> (T, T) {
        match tower {
            TowerRegime::Rest => (a_g * self.total, g_e * self.total),
            TowerRegime::Rocking(pivot) => {
                let lean = self.lean(pivot.sign(), theta);
                self.rocking_stick_demand(lean, theta_dot, self.tower_equation(lean, a_g, g_e), a_g, g_e)
            }
        }
    }

    /// Whether a stuck building under a standing tower slips before the tower
    /// can lift when a jump of the input passes both thresholds at once:
    /// derived from the two laws, it does if the ground acceleration that
    /// lifts the tower, `|Ẍ_p| = |a_g| = g_e tan α` ([`Kernel::uplift_threshold`]),
    /// already asks of static friction more than it holds under the resting
    /// stick demand ([`Kernel::stick_demand`], [`Friction::static_friction_margin`](crate::body::Friction::static_friction_margin)).
    /// Both thresholds are proportional to `g_e` (the resting demand and its
    /// normal force are the complex's mass times `a_g` and `g_e`, for both
    /// normal-force laws), so one `g_e` decides for all: `μs < tan α`.
    /// Sliding then carries the tower at `μk g_e < g_e tan α`, and it stays
    /// standing (a 1.5 g rectangular pulse under a building with `μs = 0.2`
    /// once lifted the tower first and reported an uplift and an impact at
    /// `t = 0` while θ stayed 0).
    pub(crate) fn slips_before_uplift(&self) -> bool {
        let (force, normal) = self.stick_demand(TowerRegime::Rest, self.uplift_threshold(1.0), 1.0, 0.0, 0.0);
        self.has_tower && self.has_building && self.friction.static_friction_margin(force, normal) > 0.0
    }

    /// [`Kernel::stick_demand`] of a rocking tower whose lean and `θ̈` (from
    /// (T) with `Ẍ_p = a_g`) are known.
    #[inline(always)]
    pub(crate) fn rocking_stick_demand<T: Real>(&self, lean: Lean<T>, theta_dot: T, theta_ddot: T, a_g: T, g_e: T) -> (T, T) {
        (
            self.building_equation(lean, theta_dot, theta_ddot, a_g),
            self.normal_force(lean, theta_dot, theta_ddot, g_e),
        )
    }

    /// `θ̈` and `ü` in `regime` for ground acceleration `a_g`, effective gravity
    /// `g_e` and state `(θ, θ̇)`.
    #[inline(always)]
    pub(crate) fn accelerations<T: Real>(&self, regime: Regime, a_g: T, g_e: T, theta: T, theta_dot: T) -> Accelerations<T> {
        let lean = match regime.tower {
            TowerRegime::Rest => None,
            TowerRegime::Rocking(pivot) => Some(self.lean(pivot.sign(), theta)),
        };
        self.accelerations_leaning(regime.building, lean, a_g, g_e, theta_dot)
    }

    /// [`Kernel::accelerations`] where the tower's lean is known (`None` for a
    /// standing tower): for a caller that needs the lean too, one sine less.
    #[inline(always)]
    pub(crate) fn accelerations_leaning<T: Real>(&self, building: BuildingRegime, lean: Option<Lean<T>>, a_g: T, g_e: T, theta_dot: T) -> Accelerations<T> {
        let zero = T::from(0.0);
        match (lean, building) {
            (None, BuildingRegime::Stick) => Accelerations { theta: zero, slip: zero },
            (None, BuildingRegime::Slip(dir)) => Accelerations {
                theta: zero,
                slip: self.resting_slide(dir.sign(), g_e) - a_g,
            },
            (Some(lean), BuildingRegime::Stick) => Accelerations {
                theta: self.tower_equation(lean, a_g, g_e),
                slip: zero,
            },
            (Some(lean), BuildingRegime::Slip(dir)) => {
                let (theta_ddot, acc_pivot) = self.rocking_on_sliding_building(lean, dir.sign(), theta_dot, g_e);
                Accelerations {
                    theta: theta_ddot,
                    slip: acc_pivot - a_g,
                }
            }
        }
    }

    /// (T) and (B) with `F = −μk σ N` and (N): a linear 2×2 system in
    /// `(θ̈, Ẍ_p)`, solved directly. Returns NaN where it has no solution
    /// (Painlevé's paradox of the dynamic normal force: a light building under
    /// high friction), which stops the integrator with the time.
    #[inline(always)]
    pub(crate) fn rocking_on_sliding_building<T: Real>(&self, lean: Lean<T>, sigma: f64, theta_dot: T, g_e: T) -> (T, T) {
        let s = lean.s;
        // F / N: the kinetic friction law is proportional to N.
        let per_normal = self.friction.kinetic_friction(sigma, 1.0);
        let w2 = theta_dot * theta_dot;
        // (T):  I θ̈ + c Ẍ_p = t_rhs, with c = m2 R cos φ.
        let c = lean.cos_phi * self.m2r;
        let t_rhs = -(lean.sin_phi * g_e * (s * self.m2r));
        // (B) with F = (F/N) N, N from (N) split into its θ̈ term and the rest:
        //   (c − [dyn] (F/N) s m2 R sin φ) θ̈ + M Ẍ_p = −s m2 R sin φ θ̇² + F(N₀).
        let zero_acc = T::from(0.0);
        let n0 = self.normal_force(lean, theta_dot, zero_acc, g_e);
        let a21 = if self.dynamic { c - lean.sin_phi * (per_normal * s * self.m2r) } else { c };
        let b_rhs = -(lean.sin_phi * w2 * (s * self.m2r)) + self.friction.kinetic_friction(sigma, n0);
        let det = T::from(self.inertia * self.total) - c * a21;
        if det.value() <= 0.0 {
            return (T::from(f64::NAN), T::from(f64::NAN));
        }
        let theta_ddot = (t_rhs * self.total - c * b_rhs) / det;
        let acc_pivot = (b_rhs * self.inertia - a21 * t_rhs) / det;
        (theta_ddot, acc_pivot)
    }

    /// The pivot reactions per unit tower mass, `(f_x, f_y) / m2` (m/s²)
    /// (docs/src/model.md, "What the model does not cover"); a standing tower has
    /// `(Ẍ_p, g_e)`.
    #[inline(always)]
    pub(crate) fn pivot_reactions<T: Real>(&self, lean: Option<Lean<T>>, theta_dot: T, theta_ddot: T, acc_pivot: T, g_e: T) -> (T, T) {
        let Some(lean) = lean else { return (acc_pivot, g_e) };
        let w2 = theta_dot * theta_dot;
        (
            acc_pivot + (lean.cos_phi * theta_ddot + lean.sin_phi * w2 * lean.s) * self.radius,
            g_e + (lean.sin_phi * theta_ddot * lean.s - lean.cos_phi * w2) * self.radius,
        )
    }

    /// The top centre `(0, H)`'s kinematics: [`Kernel::point_kinematics`]
    /// of that point, the one the summary's peaks (`max_top_displacement`,
    /// `max_top_abs_acceleration`), the screening's watched top and the
    /// history's `top_dx`, `top_abs_acc` all read. `s`: the pivot sign of a
    /// rocking tower (`None` at rest).
    #[inline(always)]
    pub(crate) fn top_kinematics<T: Real>(&self, s: Option<f64>, rotation: (T, T), theta_dot: T, theta_ddot: T, acc_pivot: T) -> (T, T) {
        self.point_kinematics(s, (0.0, self.height), rotation, theta_dot, theta_ddot, acc_pivot)
    }

    /// Point kinematics (paper eqs. 7–13 with docs/src/model.md's rotation): the
    /// horizontal displacement relative to the building and the absolute
    /// horizontal acceleration of the tower point `(x, y)` (tower coordinates,
    /// origin at the base centre), at rest `(0, Ẍ_p)`. Relative to the pivot
    /// `(s b, 0)` the point sits at `Rot(θ) (x − s b, y)`; `rotation` is
    /// `(sin θ, cos θ)`.
    #[inline(always)]
    pub(crate) fn point_kinematics<T: Real>(&self, s: Option<f64>, (x, y): (f64, f64), rotation: (T, T), theta_dot: T, theta_ddot: T, acc_pivot: T) -> (T, T) {
        let Some(s) = s else { return (T::from(0.0), acc_pivot) };
        let xr = x - s * self.half_width;
        let (sin_t, cos_t) = rotation;
        let dx = cos_t * xr + sin_t * y - xr;
        let lever = cos_t * y - sin_t * xr;
        let centripetal = cos_t * xr + sin_t * y;
        (dx, acc_pivot + lever * theta_ddot - centripetal * theta_dot * theta_dot)
    }
}

#[cfg(test)]
mod tests {
    //! The bounds the step's screening relies on, against the equations they
    //! come from: random states and inputs, each equation evaluated with its
    //! exact time derivative (on jets), must stay inside. A bound that is too
    //! tight fails here, not by skipping a transition in a run. Each bound is
    //! also shown to be reached (to 1e-6) where the equation says it is, so a
    //! loose bound is seen as well.

    use super::*;
    use crate::condition::Condition;
    use crate::jet::Jet;
    use crate::reference::solid_block;
    use crate::regime::{SlipDirection, State};
    use crate::{Building, NormalForce};
    use proptest::prelude::*;

    const G: f64 = 9.81;

    fn kernel(width: f64, height: f64, mu_k: f64) -> Kernel {
        let building = Building::new(2.0e6, 1.25, mu_k, NormalForce::Constant).unwrap_or_else(|e| panic!("{e}"));
        Kernel::new(&Model::new(Some(solid_block(width, height)), Some(building), G).unwrap_or_else(|e| panic!("{e}")))
    }

    /// Rounding of the bound against that of the equation: a few operations
    /// on numbers of the same size, each within half an ulp; the screening
    /// pads every bound by a relative 1e-9 on top.
    const ROUNDING: f64 = 1e-14;

    /// The top centre by hand: about the pivot `(s b, 0)` it sits at
    /// `(−s b, H)`, turned by θ, so it moves by `H sin θ + s b (1 − cos θ)`
    /// and accelerates by `Ẍ_p + θ̈ (H cos θ + s b sin θ) − θ̇² (H sin θ −
    /// s b cos θ)`; at rest, with the ground. To rounding (a few ulps of
    /// the largest term).
    #[test]
    fn top_kinematics_by_hand() {
        let k = kernel(2.0, 6.0, 0.5);
        let (b, h) = (1.0, 6.0);
        for (s, theta) in [(1.0, 0.3), (-1.0, -0.2), (1.0, 1e-6)] {
            let (theta_dot, theta_ddot, acc_pivot) = (0.7, -1.3, 2.1);
            let (sin_t, cos_t) = (f64::sin(theta), f64::cos(theta));
            let (dx, acc) = k.top_kinematics(Some(s), (sin_t, cos_t), theta_dot, theta_ddot, acc_pivot);
            let dx_hand = h * sin_t + s * b * (1.0 - cos_t);
            let acc_hand = acc_pivot + theta_ddot * (h * cos_t + s * b * sin_t) - theta_dot * theta_dot * (h * sin_t - s * b * cos_t);
            assert!(
                (dx - dx_hand).abs() <= 1e-14 * h && (acc - acc_hand).abs() <= 1e-14 * 10.0,
                "{dx} {dx_hand} {acc} {acc_hand}"
            );
        }
        assert_eq!(k.top_kinematics(None, (0.0, 1.0), 0.0, 0.0, 2.5), (0.0, 2.5));
    }

    proptest! {
        /// The free rocking energy `½ ψ̇² + p² cos(α − ψ)` of
        /// [`Kernel::free_rocking_p2`] is the first integral of (T): its
        /// time derivative along [`Kernel::tower_equation`] (no input,
        /// `g_e = g`), `ψ̇ (ψ̈ + p² sin(α − ψ))`, is zero to the rounding of
        /// its two terms, for every lean, speed and pivot. A change of (T)
        /// that the cascade's closed forms do not follow fails here.
        #[test]
        fn free_rocking_energy_is_the_first_integral_of_t(
            width in 0.2..4.0f64, slender in 1.5..8.0f64, lean in 0.0..1.0f64, speed in -3.0..3.0f64, positive in any::<bool>(),
        ) {
            let k = kernel(width, slender * width, 0.5);
            let s = if positive { 1.0 } else { -1.0 };
            let psi = lean * k.alpha;
            let theta_ddot = k.tower_equation(k.lean(s, Jet::new(s * psi, s * speed)), Jet::from(0.0), Jet::from(G));
            let p2 = k.free_rocking_p2();
            let (inertial, restoring) = (speed * s * theta_ddot.v, speed * p2 * (k.alpha - psi).sin());
            prop_assert!((inertial + restoring).abs() <= ROUNDING * (inertial.abs() + restoring.abs() + f64::MIN_POSITIVE), "{inertial} + {restoring}");
            prop_assert!((p2 - G * k.m2r / k.inertia).abs() <= ROUNDING * p2);
        }

        /// The static friction law's three readings agree: the end of a
        /// slip and the impacts stick (`Friction::sticks`) exactly where
        /// neither slip condition of the stuck building is positive, so a
        /// building that stops cannot be set sliding again at the same
        /// instant by the conditions, nor the reverse; and both are Coulomb's
        /// `|F| <= μs N` (μs = 1.25 here), written out by hand.
        #[test]
        fn static_friction_is_one_law(force in -3.0e7..3.0e7f64, normal in 0.0..2.5e7f64, on_the_edge in any::<bool>()) {
            let k = kernel(1.0, 4.0, 0.5);
            // Half the cases exactly on the edge, |F| = μs N (1.25 N is exact for these N).
            let force = if on_the_edge { force.signum() * 1.25 * normal } else { force };
            let sticks = k.friction.sticks(force, normal);
            prop_assert_eq!(sticks, force.abs() <= 1.25 * normal);
            let holds = |c: Condition| c.slip_margin(&k, force, normal) > 0.0;
            prop_assert_eq!(sticks, !holds(Condition::SlipNegative) && !holds(Condition::SlipPositive));
        }

        /// (T) with `Ẍ_p = a_g`: `|θ̈|` and `|θ⃛|` inside
        /// [`Kernel::tower_acceleration_bound`] and [`Kernel::tower_jerk_bound`]
        /// for every lean, pivot, velocity and input within the given maxima.
        #[test]
        fn tower_equation_stays_inside_its_bounds(
            width in 0.2..4.0f64, slender in 1.5..8.0f64,
            theta in -1.5..1.5f64, theta_dot in -3.0..3.0f64, positive in any::<bool>(),
            a_g in -1.0..1.0f64, a_rate in -1.0..1.0f64, g_e in 0.2..1.0f64, g_rate in -1.0..1.0f64,
            a_max in 0.0..20.0f64, a_rate_max in 0.0..500.0f64, g_max in 9.81..20.0f64, g_rate_max in 0.0..500.0f64,
        ) {
            let k = kernel(width, slender * width, 0.5);
            let s = if positive { 1.0 } else { -1.0 };
            let lean = k.lean(s, Jet::new(theta, theta_dot));
            let theta_ddot = k.tower_equation(lean, Jet::new(a_g * a_max, a_rate * a_rate_max), Jet::new(g_e * g_max, g_rate * g_rate_max));
            let (bound, reach) = k.tower_acceleration_bound(g_max, a_max);
            prop_assert!(theta_ddot.v.abs() <= bound * (1.0 + ROUNDING), "θ̈ = {} > {bound}", theta_ddot.v);
            let jerk = k.tower_jerk_bound(reach, g_rate_max, a_rate_max, theta_dot.abs());
            prop_assert!(theta_ddot.d.abs() <= jerk * (1.0 + ROUNDING), "θ⃛ = {} > {jerk}", theta_ddot.d);
        }

        /// A building sliding under a standing tower: `|ü|` and `|u⃛|` inside
        /// [`Kernel::resting_slide_bounds`], both directions of slip.
        #[test]
        fn resting_slide_stays_inside_its_bounds(
            mu_k in 0.0..1.2f64, positive in any::<bool>(),
            a_g in -1.0..1.0f64, a_rate in -1.0..1.0f64, g_e in 0.2..1.0f64, g_rate in -1.0..1.0f64,
            a_max in 0.0..20.0f64, a_rate_max in 0.0..500.0f64, g_max in 9.81..20.0f64, g_rate_max in 0.0..500.0f64,
        ) {
            let k = kernel(1.0, 4.0, mu_k);
            let dir = if positive { SlipDirection::Positive } else { SlipDirection::Negative };
            let regime = Regime { tower: TowerRegime::Rest, building: BuildingRegime::Slip(dir) };
            let zero = Jet::from(0.0);
            let acc = k.accelerations(regime, Jet::new(a_g * a_max, a_rate * a_rate_max), Jet::new(g_e * g_max, g_rate * g_rate_max), zero, zero);
            let (bound, rate_bound) = k.resting_slide_bounds(g_max, g_rate_max, a_max, a_rate_max);
            prop_assert!(acc.slip.v.abs() <= bound * (1.0 + ROUNDING), "ü = {} > {bound}", acc.slip.v);
            prop_assert!(acc.slip.d.abs() <= rate_bound * (1.0 + ROUNDING), "u⃛ = {} > {rate_bound}", acc.slip.d);
        }
    }

    /// The bounds are reached: (T)'s `|θ̈|` where `(sin φ, cos φ)` is parallel
    /// to `(s g_e, a_g)`, and the resting slide's `|ü|` where the friction and
    /// the ground push the same way, and each term of `|θ⃛|`'s bound where it
    /// alone acts. A bound made looser than the equation by
    /// more than 1e-6 fails here.
    #[test]
    fn the_bounds_are_sharp() {
        let k = kernel(1.0, 4.0, 0.6);
        let (g_e, a_g, s) = (G, 3.0, 1.0);
        // φ = atan2(s g_e, a_g), so θ = s (α − φ).
        let phi = (s * g_e).atan2(a_g);
        let theta_ddot = k.tower_equation(k.lean(s, s * (k.alpha - phi)), a_g, g_e);
        let (bound, reach) = k.tower_acceleration_bound(g_e, a_g);
        assert!((theta_ddot.abs() / bound - 1.0).abs() < 1e-6, "{theta_ddot} against {bound}");
        // θ⃛'s first term alone (θ̇ = 0): φ = atan2(s ġ_e, ȧ_g).
        let (g_rate, a_rate) = (40.0, 30.0);
        let phi = (s * g_rate).atan2(a_rate);
        let jet = k.tower_equation(k.lean(s, Jet::from(s * (k.alpha - phi))), Jet::new(a_g, a_rate), Jet::new(g_e, g_rate));
        let jerk = k.tower_jerk_bound(reach, g_rate, a_rate, 0.0);
        assert!((jet.d.abs() / jerk - 1.0).abs() < 1e-6, "{} against {jerk}", jet.d);
        // Its second alone (constant inputs): φ = atan2(−s a_g, g_e).
        let theta_dot = 2.0;
        let phi = (-s * a_g).atan2(g_e);
        let jet = k.tower_equation(k.lean(s, Jet::new(s * (k.alpha - phi), theta_dot)), Jet::from(a_g), Jet::from(g_e));
        let jerk = k.tower_jerk_bound(reach, 0.0, 0.0, theta_dot);
        assert!((jet.d.abs() / jerk - 1.0).abs() < 1e-6, "{} against {jerk}", jet.d);
        let regime = Regime {
            tower: TowerRegime::Rest,
            building: BuildingRegime::Slip(SlipDirection::Positive),
        };
        let acc = k.accelerations(regime, a_g, g_e, 0.0, 0.0);
        let (bound, _) = k.resting_slide_bounds(g_e, 0.0, a_g, 0.0);
        assert!((acc.slip.abs() / bound - 1.0).abs() < 1e-12, "{} against {bound}", acc.slip);
    }

    /// [`Kernel::slips_before_uplift`] against the two conditions it orders,
    /// as the run evaluates them ([`Condition::value`] under a standing tower
    /// on a stuck building): raising `|a_g|` from 0 by steps of `1e-4 g_e`
    /// (either sign), a slip condition holds first exactly where it says so.
    /// Blocks with `tan α` = 1/4, 1/2 and 1/6, `μs` from 0.02 to 1.2 (kept
    /// `1e-3` off `tan α`, several steps), both normal-force laws, `g_e` = g and
    /// 4 m/s² (a vertical input): both orders must be met.
    #[test]
    fn slips_before_uplift_orders_the_slip_and_uplift_conditions_as_the_run_evaluates_them() {
        let regime = Regime {
            tower: TowerRegime::Rest,
            building: BuildingRegime::Stick,
        };
        let mut orders = [0; 2];
        for (width, height) in [(0.5, 2.0), (1.0, 2.0), (1.0, 6.0)] {
            for normal in [NormalForce::Constant, NormalForce::Dynamic] {
                for i in 0..60 {
                    let mu_s = 0.02 + 0.02 * f64::from(i);
                    if (mu_s - width / height).abs() < 1e-3 {
                        continue;
                    }
                    let building = Building::new(2.0e6, mu_s, 0.5 * mu_s, normal).unwrap_or_else(|e| panic!("{e}"));
                    let k = Kernel::new(&Model::new(Some(solid_block(width, height)), Some(building), G).unwrap_or_else(|e| panic!("{e}")));
                    for g_e in [G, 4.0] {
                        let holds = |c: Condition, a_g: f64| c.value(&k, regime, a_g, g_e, &State::default()) > 0.0;
                        let first = |pair: [Condition; 2]| {
                            (1..=20_000)
                                .find(|&n| {
                                    let a = 1e-4 * g_e * f64::from(n);
                                    pair.iter().any(|&c| holds(c, a) || holds(c, -a))
                                })
                                .unwrap_or_else(|| panic!("{pair:?} never holds"))
                        };
                        let slip = first([Condition::SlipNegative, Condition::SlipPositive]);
                        let uplift = first([Condition::UpliftNegative, Condition::UpliftPositive]);
                        assert_eq!(k.slips_before_uplift(), slip < uplift, "B/H = {width}/{height}, μs = {mu_s}, g_e = {g_e}");
                        orders[usize::from(slip < uplift)] += 1;
                    }
                }
            }
        }
        assert!(orders.iter().all(|&n| n > 50), "{orders:?}");
    }
}
