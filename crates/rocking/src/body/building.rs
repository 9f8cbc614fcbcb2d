//! The sliding base (the church without the tower): a rigid body translating on
//! its foundation with Coulomb friction (docs/src/model.md, equation (B)).

use crate::error::{in_range, non_negative, Error, Parameter, MASS_RANGE};

/// The normal force of the foundation on the building used in the friction law.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum NormalForce {
    /// `N = M g`, the paper's choice (default).
    #[default]
    Constant,
    /// `N = M g + m2 R (s sin φ θ̈ − cos φ θ̇²)`: includes the vertical inertia of the rocking tower.
    Dynamic,
}

/// A sliding base, valid by construction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Building {
    mass: f64,
    mu_static: f64,
    mu_kinetic: f64,
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
            mu_static,
            mu_kinetic,
            normal_force,
        })
    }
    /// Mass `m1` (kg), without the tower.
    pub fn mass(&self) -> f64 {
        self.mass
    }
    /// Static friction coefficient `μs`.
    pub fn mu_static(&self) -> f64 {
        self.mu_static
    }
    /// Kinetic friction coefficient `μk`.
    pub fn mu_kinetic(&self) -> f64 {
        self.mu_kinetic
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
