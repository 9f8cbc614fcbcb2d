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
//! it slides with the kinetic friction of `N_imp`
//! ([`Friction::kinetic_friction`](crate::body::Friction::kinetic_friction), `P = −μk σ N_imp`), `σ = sgn u̇⁺ = −sgn P_stick`. On a fixed
//! base, or a building that stays stuck from rest, this is Housner's
//! `θ̇⁺ = r θ̇⁻`. `r` is the ratio of angular velocities (the ratio of kinetic
//! energies is `r²`).
//!
//! Where that law gives a `θ̇⁺` of the sign opposite to `θ̇⁻` (a small `r`, or a
//! building that was sliding and sticks), the tower would turn back about its
//! new corner, pushing the old one into the building: it ends the impact at
//! rest on its base instead ([`Kernel::impact_to_rest`]).

use crate::equations::Kernel;
use crate::regime::{BuildingRegime, SlipDirection};
use crate::simulate::{impact_ends_at_rest, REST_ANGULAR_VELOCITY};

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
        let after = if self.friction.sticks(p_stick, n_imp.max(0.0)) {
            stick
        } else {
            self.impact_sliding(s, theta_dot, slip_vel, angular, p_stick).unwrap_or(stick)
        };
        if after.theta_dot * theta_dot < 0.0 {
            return self.cut_at_rest(self.impact_to_rest(s, theta_dot, slip_vel));
        }
        self.cut_at_rest(after)
    }

    /// The end of an accumulation of ever smaller impacts (applied to every
    /// impact with an approach velocity on a building). A tower left with
    /// `|θ̇⁺|` below [`REST_ANGULAR_VELOCITY`] stands (the run puts it at
    /// rest); a building left sliding slower than the tower's centre of mass
    /// moves at that rate, `|u̇⁺| < REST_ANGULAR_VELOCITY R`, stops with it.
    /// Without this cut, a building that slides after each impact with
    /// `μk > tan α` lifts the standing tower again (it decelerates faster
    /// than `g tan α`), the tower falls back, and the next impact sets the
    /// building sliding again, each cycle some 40 times smaller than the last
    /// and never the last.
    ///
    /// It is the model's threshold for the end of accumulating impacts (the
    /// transition impact → rest), not a closed form: the ratio of one such
    /// cycle to the next comes out of the coupled motion of both bodies, not
    /// out of a law, so the series has no closed sum. On a fixed base or a
    /// building that stays stuck the series is Housner's geometric one, and
    /// `cascade.rs` jumps its flights in closed form down to the same
    /// threshold, every impact reported.
    fn cut_at_rest(&self, after: AfterImpact) -> AfterImpact {
        if impact_ends_at_rest(after.theta_dot) && after.slip_vel.abs() < REST_ANGULAR_VELOCITY * self.radius {
            AfterImpact {
                slip_vel: 0.0,
                building: BuildingRegime::Stick,
                ..after
            }
        } else {
            after
        }
    }

    /// The impact law with the building sliding through it: `P = −μk σ N_imp`,
    /// `σ = −sgn P_stick`, from the angular momentum `angular` about the new
    /// corner. `None` where the sliding solution contradicts its own direction
    /// (Coulomb's law then admits only the stuck one).
    fn impact_sliding(&self, s: f64, theta_dot: f64, slip_vel: f64, angular: f64, p_stick: f64) -> Option<AfterImpact> {
        let inertia = self.inertia;
        let m2h = self.m2 * 0.5 * self.height;
        let m2b = self.m2 * self.half_width;
        let total = self.total;
        // Slide: P is the kinetic friction of N_imp = −s m2 b (θ̇⁺ + θ̇⁻),
        // P = c (θ̇⁺ + θ̇⁻) with c the friction of N = −s m2 b, so
        //   I θ̇⁺ + m2 h u̇⁺ = angular,
        //   (m2 h − c) θ̇⁺ + M u̇⁺ = M u̇⁻ + (m2 h + c) θ̇⁻.
        let sigma = -p_stick.signum();
        let c = self.friction.kinetic_friction(sigma, -s * m2b);
        let q = total * slip_vel + (m2h + c) * theta_dot;
        let det = inertia * total - m2h * (m2h - c);
        let theta_after = (angular * total - m2h * q) / det;
        let slip_after = (inertia * q - (m2h - c) * angular) / det;
        if !(det > 0.0 && slip_after * sigma > 0.0 && theta_after.is_finite()) {
            return None;
        }
        Some(AfterImpact {
            theta_dot: theta_after,
            slip_vel: slip_after,
            building: BuildingRegime::Slip(SlipDirection::of_sign(sigma)),
        })
    }

    /// The impact that ends at rest (docs/src/model.md, "Impact on a building
    /// that can slide"): `θ̇⁺ = 0` replaces the angular momentum balance, the
    /// normal impulse is `N_imp = −s m2 b θ̇⁻`, and the friction decision is
    /// made again with the horizontal momentum of both bodies,
    /// `M (u̇⁺ − u̇⁻) − m2 h θ̇⁻ = P`: the building sticks (`u̇⁺ = 0`) if the `P`
    /// that needs, `P_stick = −M u̇⁻ − m2 h θ̇⁻`, satisfies `|P_stick| <= μs N_imp`;
    /// otherwise it slides with `P = −μk σ N_imp`, `σ = −sgn P_stick`, so that
    /// `u̇⁺ = u̇⁻ + (m2 h θ̇⁻ + P) / M` (of sign σ, as `μk <= μs`).
    fn impact_to_rest(&self, s: f64, theta_dot: f64, slip_vel: f64) -> AfterImpact {
        let m2h = self.m2 * 0.5 * self.height;
        let n_imp = (-s * self.m2 * self.half_width * theta_dot).max(0.0);
        let p_stick = -self.total * slip_vel - m2h * theta_dot;
        if self.friction.sticks(p_stick, n_imp) {
            return AfterImpact {
                theta_dot: 0.0,
                slip_vel: 0.0,
                building: BuildingRegime::Stick,
            };
        }
        let sigma = -p_stick.signum();
        let impulse = self.friction.kinetic_friction(sigma, n_imp);
        AfterImpact {
            theta_dot: 0.0,
            slip_vel: slip_vel + (m2h * theta_dot + impulse) / self.total,
            building: BuildingRegime::Slip(SlipDirection::of_sign(sigma)),
        }
    }
}
