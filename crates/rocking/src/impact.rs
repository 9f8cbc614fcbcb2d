//! The impact of the tower on its new corner (docs/src/model.md, "Impact on a building
//! that can slide").
//!
//! At `θ = 0` the pivot flips from `s` to `−s`, with impulsive reactions at the
//! new corner and at the foundation only. With `b = B/2`, `h = H/2` and `P` the
//! foundation's horizontal friction impulse:
//!
//! ```text
//! I_O θ̇⁺ + m2 h u̇⁺ = r I_O θ̇⁻ + m2 h u̇⁻      (angular momentum about the new corner)
//! M (u̇⁺ − u̇⁻) + m2 h (θ̇⁺ − θ̇⁻) = P          (horizontal momentum of both bodies)
//! N_imp = −s m2 b (θ̇⁺ + θ̇⁻) ≥ 0               (the foundation's normal impulse)
//! ```
//!
//! Coulomb's law for impulses: the building sticks through the impact
//! (`u̇⁺ = 0`) when the impulse that needs satisfies `|P| ≤ μs N_imp`; otherwise
//! it slides with `P = −μk σ N_imp`, `σ = sgn u̇⁺ = −sgn P_stick`. On a fixed
//! base, or a building that stays stuck from rest, this is Housner's
//! `θ̇⁺ = r θ̇⁻`. `r` is the ratio of angular velocities (the ratio of kinetic
//! energies is `r²`).

use crate::equations::Kernel;
use crate::regime::{BuildingRegime, SlipDirection};

/// Velocities just after an impact and the building's regime.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct AfterImpact {
    /// `θ̇⁺` (rad/s).
    pub(crate) theta_dot: f64,
    /// `u̇⁺` (m/s).
    pub(crate) slip_vel: f64,
    /// Stuck (`u̇⁺ = 0`) or sliding.
    pub(crate) building: BuildingRegime,
}

impl Kernel {
    /// The impact law: velocities after an impact on pivot `s` (the corner the
    /// tower leaves), from `θ̇⁻` and `u̇⁻`, the building in regime `building`
    /// before it.
    pub(crate) fn impact_law(&self, s: f64, theta_dot: f64, slip_vel: f64, building: BuildingRegime) -> AfterImpact {
        let r = self.restitution;
        if !self.has_building {
            return AfterImpact {
                theta_dot: r * theta_dot,
                slip_vel: 0.0,
                building: BuildingRegime::Stick,
            };
        }
        if theta_dot == 0.0 {
            // No approach velocity, no impulse (the pivot changes side at rest
            // relative to the building): the building keeps its motion.
            return AfterImpact {
                theta_dot: 0.0,
                slip_vel,
                building,
            };
        }
        let inertia = self.inertia;
        let m2h = self.m2 * 0.5 * self.height;
        let m2b = self.m2 * self.half_width;
        let total = self.total;
        // Angular momentum about the new corner after the impact.
        let angular = r * inertia * theta_dot + m2h * slip_vel;
        // Stick through the impact: u̇⁺ = 0.
        let theta_stick = angular / inertia;
        let p_stick = -total * slip_vel + m2h * (theta_stick - theta_dot);
        let n_imp = -s * m2b * (theta_stick + theta_dot);
        let stick = AfterImpact {
            theta_dot: theta_stick,
            slip_vel: 0.0,
            building: BuildingRegime::Stick,
        };
        if p_stick.abs() <= self.mu_s * n_imp.max(0.0) {
            return stick;
        }
        // Slide: P = −μk σ N_imp = c (θ̇⁺ + θ̇⁻) with c = μk σ s m2 b, so
        //   I θ̇⁺ + m2 h u̇⁺ = angular,
        //   (m2 h − c) θ̇⁺ + M u̇⁺ = M u̇⁻ + (m2 h + c) θ̇⁻.
        let sigma = -p_stick.signum();
        let c = self.mu_k * sigma * s * m2b;
        let q = total * slip_vel + (m2h + c) * theta_dot;
        let det = inertia * total - m2h * (m2h - c);
        let theta_after = (angular * total - m2h * q) / det;
        let slip_after = (inertia * q - (m2h - c) * angular) / det;
        if !(det > 0.0 && slip_after * sigma > 0.0 && theta_after.is_finite()) {
            // The sliding solution contradicts its own direction: Coulomb's
            // law then admits only the stuck one.
            return stick;
        }
        AfterImpact {
            theta_dot: theta_after,
            slip_vel: slip_after,
            building: BuildingRegime::Slip(SlipDirection::of_sign(sigma)),
        }
    }
}
