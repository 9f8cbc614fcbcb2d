//! The sliding base (the church without the tower): a rigid body translating on
//! its foundation with Coulomb friction (docs/src/model.md, equation (B)).

use crate::error::{in_range, non_negative, Error, Parameter, MASS_RANGE};
use crate::jet::Real;

/// The normal force of the foundation on the building used in the friction law.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum NormalForce {
    /// `N = M g`, the paper's choice (default).
    #[default]
    Constant,
    /// `N = M g + m2 R (s sin φ θ̈ − cos φ θ̇²)`: includes the vertical inertia of the rocking tower.
    Dynamic,
}

/// Coulomb's friction of the foundation on the building (docs/src/model.md,
/// "Equations of motion"), static and kinetic: the one place the law is
/// written. The tower's right-hand sides and impact law, the stack's Kane's
/// equations and impact law, and the conditions and bounds of both call it;
/// a test (`tests/friction_law_in_one_place.rs`) fails when a coefficient is
/// read anywhere else in the library.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Friction {
    mu_static: f64,
    mu_kinetic: f64,
}

impl Friction {
    /// A fixed base: static friction holds any force, so nothing slides.
    pub(crate) const FIXED: Self = Self {
        mu_static: f64::INFINITY,
        mu_kinetic: 0.0,
    };

    /// The friction of `building`, or of a fixed base without one.
    pub(crate) fn of(building: Option<&Building>) -> Self {
        building.map_or(Self::FIXED, |b| b.friction)
    }

    /// The kinetic friction law: the horizontal force of the foundation on
    /// a building sliding in the direction `σ = sgn u̇` under the normal force
    /// `normal`, `F = −μk σ N` (with the normal impulse for `N`, the friction
    /// impulse of an impact). The callers rely on it being proportional to
    /// `N` (they divide it by a mass or factor it out of a linear system, as
    /// `kinetic_friction(σ, 1)`): a law `F = −μ(…) σ N` with any other
    /// dependence fits them unchanged.
    #[inline(always)]
    pub(crate) fn kinetic_friction<T: Real>(&self, sigma: f64, normal: T) -> T {
        normal * (-self.mu_kinetic * sigma)
    }

    /// The static friction law: the foundation holds the building stuck
    /// while the horizontal force that takes, `F`, stays within `μs N` of the
    /// normal force `N`. Returned as the margin `F_toward − μs N` of the force
    /// towards one side (`F` towards `+x` starts a slip towards `−x`):
    /// negative while the building sticks. The slip conditions, the end of a
    /// slip and the impacts' stick tests (with the impulses for the forces)
    /// all call it, through [`Friction::sticks`] for `|F| <= μs N`.
    #[inline(always)]
    pub(crate) fn static_friction_margin<T: Real>(&self, toward: T, normal: T) -> T {
        toward - normal * self.mu_static
    }

    /// Whether static friction holds the building stuck, `|F| <= μs N`:
    /// [`Friction::static_friction_margin`] of `|F|` not positive.
    #[inline(always)]
    pub(crate) fn sticks(&self, force: f64, normal: f64) -> bool {
        self.static_friction_margin(force.abs(), normal) <= 0.0
    }

    /// The ground acceleration, in units of gravity, at which a stuck
    /// building carrying a standing tower starts to slip: the static margin
    /// of the force `M a` against the normal force `M g` vanishes at
    /// `a / g = μs` (docs/src/model.md, "Checks the model must report").
    pub(crate) fn slip_acceleration_g(&self) -> f64 {
        self.mu_static
    }
}

/// A sliding base, valid by construction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Building {
    mass: f64,
    friction: Friction,
    normal_force: NormalForce,
}

impl Building {
    /// A building of mass `m1` (kg, > 0, without the tower), static and kinetic
    /// friction coefficients (`0 <= μk <= μs`) and the normal-force law.
    pub fn new(mass: f64, mu_static: f64, mu_kinetic: f64, normal_force: NormalForce) -> Result<Self, Error> {
        let mass = in_range(Parameter::BuildingMass, mass, MASS_RANGE.0, MASS_RANGE.1, "kg")?;
        let mu_static = non_negative(Parameter::BuildingMuStatic, mu_static)?;
        let mu_kinetic = non_negative(Parameter::BuildingMuKinetic, mu_kinetic)?;
        if mu_kinetic > mu_static {
            return Err(Error::InvalidParameter {
                parameter: Parameter::BuildingMuKinetic,
                reason: format!("{mu_kinetic} exceeds mu_static = {mu_static}; kinetic friction cannot exceed static friction"),
            });
        }
        Ok(Self {
            mass,
            friction: Friction { mu_static, mu_kinetic },
            normal_force,
        })
    }
    /// Mass `m1` (kg), without the tower.
    pub fn mass(&self) -> f64 {
        self.mass
    }
    /// Static friction coefficient `μs`, as given (for reports; the library
    /// applies it only through its friction law).
    pub fn mu_static(&self) -> f64 {
        self.friction.mu_static
    }
    /// Kinetic friction coefficient `μk`, as given (for reports; the library
    /// applies it only through its friction law).
    pub fn mu_kinetic(&self) -> f64 {
        self.friction.mu_kinetic
    }
    /// Its foundation's friction law.
    pub(crate) fn friction(&self) -> Friction {
        self.friction
    }
    /// The normal-force law.
    pub fn normal_force(&self) -> NormalForce {
        self.normal_force
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kinetic_above_static_is_rejected() {
        let e = Building::new(1.0, 0.5, 0.6, NormalForce::Constant).unwrap_err();
        assert!(
            matches!(
                e,
                Error::InvalidParameter {
                    parameter: Parameter::BuildingMuKinetic,
                    ..
                }
            ),
            "{e}"
        );
        assert!(Building::new(1.0, -0.1, 0.0, NormalForce::Constant).is_err());
        assert!(Building::new(0.0, 0.5, 0.4, NormalForce::Constant).is_err());
        assert!(Building::new(1.0, 0.0, 0.0, NormalForce::Dynamic).is_ok());
    }
}
