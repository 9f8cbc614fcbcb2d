//! The rocking block (the tower above the springing level): mass, inertia about
//! a base corner, `R`, `α` and restitution (docs/src/model.md, "Bodies and symbols").

use crate::error::{in_range, non_negative, positive, Error, Parameter, DENSITY_RANGE, INERTIA_RANGE, LENGTH_RANGE, MASS_RANGE};

/// Cross-section of a tower given by its outer dimensions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Section {
    /// A uniform rectangular prism `B × D × H`.
    Solid,
    /// A uniform rectangular tube, outer `B × D`, open at both ends.
    Hollow {
        /// Wall thickness `t` (m), `0 < 2t < min(B, D)`.
        wall_thickness: f64,
    },
}

/// How the mass of a tower given by its geometry is known.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MassInput {
    /// The mass `m2` itself (kg), > 0.
    Mass(f64),
    /// The density (kg/m³), > 0; the mass is density × volume of the section.
    Density(f64),
}

/// A tower described by its outer dimensions; turned into a [`Tower`] by
/// [`Tower::from_geometry`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TowerGeometry {
    /// Width `B` (m) in the plane of rocking, > 0.
    pub width: f64,
    /// Height `H` (m) above the rocking base, > 0.
    pub height: f64,
    /// Depth `D` (m) out of the plane, > 0 (default: the width).
    pub depth: Option<f64>,
    /// Solid or hollow section.
    pub section: Section,
    /// The mass, directly or as a density.
    pub mass: MassInput,
    /// Moment of inertia about a base corner (kg·m²); overrides the section's value.
    pub inertia_pivot: Option<f64>,
    /// Coefficient of restitution of the angular velocity, in `[0, 1]`; overrides Housner's.
    pub restitution: Option<f64>,
}

/// A rigid rocking block, valid by construction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tower {
    mass: f64,
    inertia_pivot: f64,
    radius: f64,
    alpha: f64,
    restitution: f64,
}

/// A length of the tower (m), within [`LENGTH_RANGE`].
fn length(parameter: Parameter, value: f64) -> Result<f64, Error> {
    in_range(parameter, value, LENGTH_RANGE.0, LENGTH_RANGE.1, "m")
}

impl Tower {
    /// A tower from its outer dimensions, section and mass or density
    /// (docs/src/model.md: solid `I_O = m (B² + H²) / 3`; hollow: outer prism minus inner
    /// prism about the centroid, then `I_O = I_c + m R²`).
    pub fn from_geometry(geometry: &TowerGeometry) -> Result<Self, Error> {
        let width = length(Parameter::TowerWidth, geometry.width)?;
        let height = length(Parameter::TowerHeight, geometry.height)?;
        let depth = length(Parameter::TowerDepth, geometry.depth.unwrap_or(width))?;
        // Areas and centroidal "width² + H²" sums of the outer and (for a tube) inner prisms.
        let (area, inertia_per_density) = match geometry.section {
            Section::Solid => (width * depth, width * depth * height * (width * width + height * height) / 12.0),
            Section::Hollow { wall_thickness } => {
                let t = length(Parameter::TowerWallThickness, wall_thickness)?;
                if 2.0 * t >= width.min(depth) {
                    return Err(Error::InvalidParameter {
                        parameter: Parameter::TowerWallThickness,
                        reason: format!("{t} m leaves no hollow: twice the wall must be less than the width and the depth"),
                    });
                }
                let (wi, di) = (width - 2.0 * t, depth - 2.0 * t);
                let outer = width * depth * height * (width * width + height * height) / 12.0;
                let inner = wi * di * height * (wi * wi + height * height) / 12.0;
                (width * depth - wi * di, outer - inner)
            }
        };
        let volume = area * height;
        let (mass, density) = match geometry.mass {
            MassInput::Mass(m) => {
                let m = in_range(Parameter::TowerMass, m, MASS_RANGE.0, MASS_RANGE.1, "kg")?;
                (m, m / volume)
            }
            MassInput::Density(rho) => {
                let rho = in_range(Parameter::TowerDensity, rho, DENSITY_RANGE.0, DENSITY_RANGE.1, "kg/m³")?;
                (rho * volume, rho)
            }
        };
        if !(MASS_RANGE.0..=MASS_RANGE.1).contains(&mass) {
            // Only a density can get here: the mass it gives is out of scale.
            return Err(Error::InvalidParameter {
                parameter: Parameter::TowerDensity,
                reason: format!(
                    "{density:e} kg/m³ over {volume:e} m³ gives a mass of {mass:e} kg, outside {:e} to {:e} kg",
                    MASS_RANGE.0, MASS_RANGE.1
                ),
            });
        }
        let (b, h) = (width / 2.0, height / 2.0);
        let radius = libm::hypot(b, h);
        let inertia_pivot = match geometry.inertia_pivot {
            Some(i) => in_range(Parameter::TowerInertiaPivot, i, INERTIA_RANGE.0, INERTIA_RANGE.1, "kg·m²")?,
            None => density * inertia_per_density + mass * radius * radius,
        };
        Self::from_properties(mass, inertia_pivot, radius, libm::atan2(b, h), geometry.restitution)
    }

    /// A tower from its mechanical properties: mass `m2` (kg), inertia about a
    /// base corner `I_O` (kg·m², > `m2 R²`), `R` (m) and `α` (rad, in (0, π/2)),
    /// and optionally the restitution `r` (default: Housner's
    /// `1 − 2 m2 R² sin²α / I_O`).
    pub fn from_properties(mass: f64, inertia_pivot: f64, radius: f64, alpha: f64, restitution: Option<f64>) -> Result<Self, Error> {
        let mass = in_range(Parameter::TowerMass, mass, MASS_RANGE.0, MASS_RANGE.1, "kg")?;
        let inertia_pivot = positive(Parameter::TowerInertiaPivot, inertia_pivot)?;
        let radius = length(Parameter::TowerRadius, radius)?;
        let alpha = positive(Parameter::TowerAlpha, alpha)?;
        if alpha >= std::f64::consts::FRAC_PI_2 {
            return Err(Error::InvalidParameter {
                parameter: Parameter::TowerAlpha,
                reason: format!("must be below π/2, got {alpha}"),
            });
        }
        let point_inertia = mass * radius * radius;
        if inertia_pivot <= point_inertia {
            return Err(Error::InvalidParameter {
                parameter: Parameter::TowerInertiaPivot,
                reason: format!("{inertia_pivot} kg·m² is not above m R² = {point_inertia} kg·m² (parallel-axis theorem)"),
            });
        }
        let housner = housner_restitution(mass, inertia_pivot, radius, alpha);
        let restitution = match restitution {
            Some(r) => {
                let r = non_negative(Parameter::TowerRestitution, r)?;
                if r > 1.0 {
                    return Err(Error::InvalidParameter {
                        parameter: Parameter::TowerRestitution,
                        reason: format!("must be at most 1, got {r}"),
                    });
                }
                r
            }
            None if housner < 0.0 => {
                return Err(Error::InvalidParameter {
                    parameter: Parameter::TowerRestitution,
                    reason: format!("Housner's value {housner:.4} is negative for this squat block: give one in [0, 1]"),
                })
            }
            None => housner,
        };
        Ok(Self {
            mass,
            inertia_pivot,
            radius,
            alpha,
            restitution,
        })
    }

    /// The same body rocking about two points `inset` (m) inside its base
    /// corners, a hinge moved inward by a masonry of finite compressive
    /// strength: its mass and its inertia about its centre of mass kept,
    /// `b' = b − inset`, `R' = √(b'² + h²)`, `α' = atan(b'/h)`,
    /// `I_O' = I_G + m R'²` (`I_G = I_O − m R²`), and Housner's restitution
    /// about the new points unless `restitution` overrides it. `inset` must be
    /// in `[0, b)`; an error otherwise.
    pub fn with_pivot_inset(&self, inset: f64, restitution: Option<f64>) -> Result<Self, Error> {
        let (b, h) = (self.half_width(), self.radius * libm::cos(self.alpha));
        if !(inset.is_finite() && (0.0..b).contains(&inset)) {
            return Err(Error::InvalidParameter {
                parameter: Parameter::TowerRadius,
                reason: format!("a pivot {inset} m inside the corners of a base {} m wide leaves no base to rock on", 2.0 * b),
            });
        }
        let centroidal = self.inertia_pivot - self.mass * self.radius * self.radius;
        let b_inset = b - inset;
        let radius = libm::hypot(b_inset, h);
        Self::from_properties(
            self.mass,
            centroidal + self.mass * radius * radius,
            radius,
            libm::atan2(b_inset, h),
            restitution,
        )
    }

    /// Housner's coefficient of restitution of this tower's geometry,
    /// `r = 1 − 2 m R² sin²α / I_O` (whatever [`Tower::restitution`] was given).
    pub fn housner_restitution(&self) -> f64 {
        housner_restitution(self.mass, self.inertia_pivot, self.radius, self.alpha)
    }

    /// Mass `m2` (kg).
    pub fn mass(&self) -> f64 {
        self.mass
    }
    /// Moment of inertia about a base corner `I_O` (kg·m²).
    pub fn inertia_pivot(&self) -> f64 {
        self.inertia_pivot
    }
    /// Distance `R` from a base corner to the centre of mass (m).
    pub fn radius(&self) -> f64 {
        self.radius
    }
    /// Slenderness angle `α = atan(b/h)` (rad).
    pub fn alpha(&self) -> f64 {
        self.alpha
    }
    /// Half width `b = R sin α` (m).
    pub fn half_width(&self) -> f64 {
        self.radius * libm::sin(self.alpha)
    }
    /// Height `H = 2 R cos α` (m).
    pub fn height(&self) -> f64 {
        2.0 * self.radius * libm::cos(self.alpha)
    }
    /// Ratio of angular velocities after and before an impact, `θ̇⁺ = r θ̇⁻`.
    /// (The ratio of kinetic energies is its square.)
    pub fn restitution(&self) -> f64 {
        self.restitution
    }
    /// Frequency parameter `p = sqrt(m2 g R / I_O)` (rad/s) for gravity `g` (m/s²).
    pub fn frequency_parameter(&self, g: f64) -> f64 {
        (self.mass * g * self.radius / self.inertia_pivot).sqrt()
    }
}

/// Housner's restitution of the angular velocity at an impact of a block on
/// a fixed base (docs/src/model.md, "Restitution"): angular momentum about the new
/// corner conserved, `r = 1 − 2 m R² sin²α / I_O`. The one place it is
/// written: the tower's default and the stack's check that its tower's
/// restitution was not overridden both call it.
fn housner_restitution(mass: f64, inertia_pivot: f64, radius: f64, alpha: f64) -> f64 {
    let point_inertia = mass * radius * radius;
    1.0 - 2.0 * point_inertia * libm::sin(alpha).powi(2) / inertia_pivot
}

#[cfg(test)]
mod tests {

    /// A solid 4 m × 12 m block (m = 1.5e5 kg) rocking on points 0.15 m inside
    /// its corners, by hand: I_G = m (B² + H²)/12 = 1.9e6 kg·m², b' = 1.85 m,
    /// h = 6 m, I_O' = I_G + m (b'² + h²); r = 1 − 2 m b'² / I_O'. No inset
    /// is the block itself. Round-off of a few operations: 1e-14.
    #[test]
    fn a_pivot_inset_keeps_the_centroidal_inertia() {
        let geometry = TowerGeometry {
            width: 4.0,
            height: 12.0,
            depth: None,
            section: Section::Solid,
            mass: MassInput::Mass(1.5e5),
            inertia_pivot: None,
            restitution: None,
        };
        let t = Tower::from_geometry(&geometry).unwrap_or_else(|e| panic!("{e}"));
        let same = t.with_pivot_inset(0.0, None).unwrap_or_else(|e| panic!("{e}"));
        assert_relative_eq!(same.inertia_pivot(), t.inertia_pivot(), max_relative = 1e-14);
        assert_relative_eq!(same.radius(), t.radius(), max_relative = 1e-14);
        assert_relative_eq!(same.alpha(), t.alpha(), max_relative = 1e-14);
        let inset = t.with_pivot_inset(0.15, None).unwrap_or_else(|e| panic!("{e}"));
        let m = 1.5e5;
        let ig = m * (16.0 + 144.0) / 12.0;
        let io = ig + m * (1.85f64.powi(2) + 36.0);
        assert_relative_eq!(inset.inertia_pivot(), io, max_relative = 1e-14);
        assert_relative_eq!(inset.radius(), (1.85f64.powi(2) + 36.0).sqrt(), max_relative = 1e-14);
        assert_relative_eq!(inset.alpha(), (1.85f64 / 6.0).atan(), max_relative = 1e-14);
        assert_relative_eq!(inset.restitution(), 1.0 - 2.0 * m * 1.85f64.powi(2) / io, max_relative = 1e-14);
        // A given restitution is kept; an inset reaching the centre is refused.
        assert_eq!(t.with_pivot_inset(0.15, Some(0.9)).map(|t| t.restitution()).ok(), Some(0.9));
        assert!(t.with_pivot_inset(2.0, None).is_err());
    }

    use super::*;
    use approx::assert_relative_eq;

    fn solid(width: f64, height: f64, mass: f64) -> TowerGeometry {
        TowerGeometry {
            width,
            height,
            depth: None,
            section: Section::Solid,
            mass: MassInput::Mass(mass),
            inertia_pivot: None,
            restitution: None,
        }
    }

    /// Solid rectangle: I_O = (4/3) m R² and r = 1 − 1.5 sin²α (paper eq. 3).
    #[test]
    fn solid_rectangle_matches_housner() {
        let t = Tower::from_geometry(&solid(4.0, 12.0, 1.5e5)).unwrap();
        let r = 2f64.hypot(6.0);
        assert_relative_eq!(t.radius(), r, max_relative = 1e-15);
        assert_relative_eq!(t.inertia_pivot(), 4.0 / 3.0 * 1.5e5 * r * r, max_relative = 1e-14);
        assert_relative_eq!(t.restitution(), 1.0 - 1.5 * t.alpha().sin().powi(2), max_relative = 1e-14);
        assert_relative_eq!(t.frequency_parameter(9.81), (3.0 * 9.81 / (4.0 * r)).sqrt(), max_relative = 1e-14);
    }

    /// A tube with walls of vanishing thickness tends to a thin shell; with a
    /// wall of half the width it would be solid. Check an intermediate one by
    /// hand: B = D = 4, t = 1, H = 12, ρ = 1 → outer 192 kg, inner 48 kg.
    #[test]
    fn hollow_section_by_hand() {
        let mut g = solid(4.0, 12.0, 1.0);
        g.section = Section::Hollow { wall_thickness: 1.0 };
        g.mass = MassInput::Density(1.0);
        let t = Tower::from_geometry(&g).unwrap();
        assert_relative_eq!(t.mass(), 144.0, max_relative = 1e-15);
        let ic = 192.0 * (16.0 + 144.0) / 12.0 - 48.0 * (4.0 + 144.0) / 12.0;
        assert_relative_eq!(t.inertia_pivot(), ic + 144.0 * 40.0, max_relative = 1e-14);
    }

    #[test]
    fn rejects_bad_values() {
        assert!(Tower::from_geometry(&solid(-1.0, 12.0, 1.0)).is_err());
        assert!(Tower::from_geometry(&solid(1.0, f64::NAN, 1.0)).is_err());
        let mut g = solid(4.0, 12.0, 1.0);
        g.section = Section::Hollow { wall_thickness: 2.0 };
        assert!(Tower::from_geometry(&g).is_err());
        assert!(Tower::from_properties(1.0, 0.5, 1.0, 0.2, None).is_err());
        assert!(Tower::from_properties(1.0, 2.0, 1.0, 0.2, Some(1.5)).is_err());
    }
}
