//! What is watched at an instant: the regime's conditions, the top
//! centre's absolute acceleration and the pivot reactions, each with its
//! exact time derivative along the solution (a [`Jet`]).

use crate::condition::{Condition, MAX_CONDITIONS};
use crate::equations::{Accelerations, Kernel};
use crate::ground::Piece;
use crate::integrator::DenseOutput;
use crate::jet::Jet;
use crate::regime::{BuildingRegime, Regime, State, TowerRegime};

/// The quantities examined over a step, at one instant, each with its exact
/// time derivative along the solution.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Watched {
    /// The conditions of the regime, in the order of [`conditions`](crate::condition::conditions).
    pub(super) conditions: [Jet; MAX_CONDITIONS],
    /// Absolute horizontal acceleration of the top centre (m/s²), while rocking.
    pub(super) top: Jet,
    /// Pivot reactions per unit tower mass `(f_x, f_y) / m2` (m/s²), while rocking.
    pub(super) fx: Jet,
    pub(super) fy: Jet,
}

/// [`Watched`] at `(t, y)` under the input's horizontal and vertical
/// pieces; `acc`, the accelerations there, if known (a rocking tower on a
/// stuck building does not need them: its `θ̈` does not depend on `θ̇`).
#[inline(always)]
pub(super) fn watched(
    kernel: &Kernel,
    regime: Regime,
    (piece, vpiece): (&Piece, &Piece),
    list: &[Condition],
    t: f64,
    y: &State,
    acc: Option<Accelerations<f64>>,
) -> Watched {
    let a_g = piece.eval_jet(t);
    // No vertical input (a constant piece) spares a call per instant.
    let g_e = match *vpiece {
        Piece::Constant(a_v) => Jet::from(kernel.g + a_v),
        _ => Jet::from(kernel.g) + vpiece.eval_jet(t),
    };
    let mut conditions = [Jet::default(); MAX_CONDITIONS];
    let TowerRegime::Rocking(pivot) = regime.tower else {
        let acc = acc.unwrap_or_else(|| kernel.accelerations(regime, a_g.v, g_e.v, y.theta, y.theta_dot));
        let yj = y.jets(acc);
        for (slot, c) in conditions.iter_mut().zip(list) {
            *slot = c.value(kernel, regime, a_g, g_e, &yj);
        }
        return Watched {
            conditions,
            ..Watched::default()
        };
    };
    let s = pivot.sign();
    let lean = kernel.lean(s, Jet::new(y.theta, y.theta_dot));
    let mut yj;
    let (theta_ddot, acc_pivot) = match regime.building {
        BuildingRegime::Stick => {
            let theta_ddot = kernel.tower_equation(lean, a_g, g_e);
            yj = y.jets(Accelerations {
                theta: theta_ddot.v,
                slip: 0.0,
            });
            (theta_ddot, a_g)
        }
        BuildingRegime::Slip(dir) => {
            let acc = acc.unwrap_or_else(|| kernel.accelerations(regime, a_g.v, g_e.v, y.theta, y.theta_dot));
            yj = y.jets(acc);
            kernel.rocking_on_sliding_building(lean, dir.sign(), yj.theta_dot, g_e)
        }
    };
    yj.theta = Jet::new(y.theta, y.theta_dot);
    let demand = (!list.is_empty() && regime.building == BuildingRegime::Stick && kernel.has_building)
        .then(|| kernel.rocking_stick_demand(lean, yj.theta_dot, theta_ddot, a_g, g_e));
    for (slot, &c) in conditions.iter_mut().zip(list) {
        *slot = match (c, demand) {
            // What `value` gives, without its call (not inlined: inlining it
            // everywhere cost 7 M instructions of the sweep, the call here 2.7 M).
            (Condition::Impact | Condition::Overturn, _) => c.theta_margin(s, yj.theta),
            (Condition::SlipNegative | Condition::SlipPositive, Some((force, normal))) => c.slip_margin(kernel, force, normal),
            _ => c.value(kernel, regime, a_g, g_e, &yj),
        };
    }
    let top = kernel.top_kinematics(Some(s), kernel.rotation(lean), yj.theta_dot, theta_ddot, acc_pivot).1;
    let (fx, fy) = kernel.pivot_reactions(Some(lean), yj.theta_dot, theta_ddot, acc_pivot, g_e);
    Watched { conditions, top, fx, fy }
}

/// [`Watched`] at `t` on a step's dense output.
#[inline]
pub(super) fn watched_on<const N: usize>(kernel: &Kernel, regime: Regime, pieces: (&Piece, &Piece), list: &[Condition], d: &DenseOutput<N>, t: f64) -> Watched {
    watched(kernel, regime, pieces, list, t, &State::from_components(&d.state(t)), None)
}

/// The one condition `c` with its time derivative at `t` on a step's dense
/// output (root finding on it needs nothing else [`watched`] computes).
#[inline]
pub(super) fn condition_on<const N: usize>(kernel: &Kernel, regime: Regime, pieces: (&Piece, &Piece), c: Condition, d: &DenseOutput<N>, t: f64) -> Jet {
    let y = State::from_components(&d.state(t));
    let a_g = pieces.0.eval_jet(t);
    let g_e = Jet::from(kernel.g) + pieces.1.eval_jet(t);
    let acc = kernel.accelerations(regime, a_g.v, g_e.v, y.theta, y.theta_dot);
    c.value(kernel, regime, a_g, g_e, &y.jets(acc))
}

/// The accelerations in a right-hand side `f = (θ̇, θ̈, u̇, ü)`.
#[inline(always)]
pub(super) fn accelerations_of(f: &State) -> Accelerations<f64> {
    Accelerations {
        theta: f.theta_dot,
        slip: f.slip_vel,
    }
}
