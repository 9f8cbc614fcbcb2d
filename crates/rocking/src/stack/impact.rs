//! The impact of an interface on its other corner, by generalised momentum.
//!
//! When a rocking `θ_k` reaches 0 the pivot flips, `s_k → −s_k`: a perfectly
//! plastic impact at the new corner (no bounce, no slip there), every other
//! contact kept. The velocities after it are those of the new coordinates
//! `q⁺` (the same interfaces rocking, `k` on its other corner, and the slip
//! `u` whenever there is a building) whose generalised momenta equal those of
//! the motion before it, plus the foundation's friction impulse `P`:
//!
//! ```text
//! M⁺ q̇⁺ = Σ_i [ m_i (∂G_i/∂q⁺)ᵀ Ġ_i⁻ + J_i (∂φ_i/∂q⁺) φ̇_i⁻ ] + P e_u
//! ```
//!
//! with `M⁺` the mass matrix of Kane's equations in `q⁺` and the building a
//! body of mass `m1` moving with `u`. Each row is the balance of an impulse
//! that the new contact does not enter: the angular momentum of the blocks
//! above interface `j` about its corner, the horizontal momentum of
//! everything for `u`. The foundation's normal impulse is the change of the
//! total vertical momentum, `N_imp = Σ_i m_i (ẏ_i⁺ − ẏ_i⁻)`.
//!
//! Friction impulse (Coulomb's law for impulses): the building sticks through
//! the impact (`u̇⁺ = 0`, drop `u` from `q⁺`; the `u` row gives the `P` this
//! needs) when `|P| ≤ μs N_imp`; otherwise it slides, `P = −μk σ N_imp` with
//! `σ = −sgn P_stick`, again one linear system.
//!
//! A `θ̇_k⁺` of the sign opposite to `θ̇_k⁻` would turn block `k` back about
//! its new corner, pushing the old one into the block below: the impact ends
//! with interface `k` stuck instead (`θ_k` dropped from `q⁺`), and the
//! friction decision is made again.
//!
//! For one block on a fixed base the single row is Housner's balance about the
//! new corner, `I_O θ̇⁺ = (I_O − 2 m b²) θ̇⁻`; on a building it is the
//! one-tower law of the engine.

use super::dynamics::Frame;
use super::geometry::{cross, dot, sub, Coordinate, Coordinates, Pose, Vec2, MAX_COORDINATES};
use super::linalg::{solve, Matrix};
use super::{Interface, Stack, StackRegime, StackState, MAX_BLOCKS};
use crate::regime::{BuildingRegime, SlipDirection};

/// What an impact leaves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactOutcome {
    /// The regime after it: interface `k` on its other corner, or stuck.
    pub regime: StackRegime,
    /// The state after it (`θ_k = 0`; velocities after the impact).
    pub state: StackState,
    /// The foundation's normal impulse `N_imp` (N·s; 0 on a fixed base).
    pub normal_impulse: f64,
    /// The foundation's friction impulse `P` (N·s).
    pub friction_impulse: f64,
    /// The largest `|M_imp| / (V_imp B_j / 2)` over the interfaces seated
    /// through the impact (0 where there are none).
    pub seat_impulse_ratio: f64,
}

/// The velocities of the bodies: `Ġ_i` relative to the ground and `φ̇_i`.
#[derive(Debug, Clone, Copy)]
struct Velocities {
    centre: [Vec2; MAX_BLOCKS],
    rotation: [f64; MAX_BLOCKS],
}

impl Velocities {
    fn of(stack: &Stack, pose: &Pose, state: &StackState) -> Self {
        let mut v = Self {
            centre: [[0.0; 2]; MAX_BLOCKS],
            rotation: [0.0; MAX_BLOCKS],
        };
        for i in 0..stack.len() {
            v.centre[i] = pose.point_velocity(i, pose.centre(i), state);
            v.rotation[i] = pose.phi_dot[i];
        }
        v
    }
}

/// The result of the momentum balance in one set of coordinates.
struct Balance {
    velocities: [f64; MAX_COORDINATES],
    building: BuildingRegime,
    normal_impulse: f64,
    friction_impulse: f64,
}

impl Stack {
    /// The impact of interface `k` (0-based) in `regime` at `state` (`θ_k` is
    /// taken as 0).
    pub fn impact(&self, regime: &StackRegime, state: &StackState, k: usize) -> ImpactOutcome {
        let Interface::Rocking(pivot) = regime.interfaces[k] else {
            return ImpactOutcome {
                regime: *regime,
                state: *state,
                normal_impulse: 0.0,
                friction_impulse: 0.0,
                seat_impulse_ratio: 0.0,
            };
        };
        let mut at = *state;
        at.theta[k] = 0.0;
        if !matches!(regime.building, BuildingRegime::Slip(_)) {
            at.slip_vel = 0.0;
        }
        let flipped = regime.with(k, Interface::Rocking(pivot.flipped()));
        if at.theta_dot[k] == 0.0 {
            // No approach velocity, no impulse: the pivot changes side at rest.
            return ImpactOutcome {
                regime: flipped,
                state: at,
                normal_impulse: 0.0,
                friction_impulse: 0.0,
                seat_impulse_ratio: 0.0,
            };
        }
        let before = Velocities::of(self, &Pose::new(self, regime, &at), &at);
        let mut after_regime = flipped;
        let mut balance = self.momentum_balance(&after_regime, &at, &before);
        let coords = Coordinates::with_slip(self, &after_regime, self.building.is_some());
        let theta_after = coords.index(Coordinate::Theta(k)).map_or(0.0, |a| balance.velocities[a]);
        if theta_after * at.theta_dot[k] < 0.0 {
            after_regime = regime.with(k, Interface::Stuck);
            balance = self.momentum_balance(&after_regime, &at, &before);
        }
        after_regime.building = balance.building;
        let mut out = at;
        out.theta_dot = [0.0; MAX_BLOCKS];
        out.slip_vel = 0.0;
        let full = Coordinates::with_slip(self, &after_regime, self.building.is_some());
        for (a, c) in full.list().iter().enumerate() {
            match *c {
                Coordinate::Slip => out.slip_vel = balance.velocities[a],
                Coordinate::Theta(j) => out.theta_dot[j] = balance.velocities[a],
            }
        }
        let pose_after = Pose::new(self, &after_regime, &out);
        let after = Velocities::of(self, &pose_after, &out);
        let seat_impulse_ratio = (0..self.len())
            .filter(|&j| j != k && after_regime.interfaces[j] == Interface::Stuck)
            .map(|j| self.seat_impulse_ratio(&pose_after, &before, &after, j))
            .fold(0.0, f64::max);
        ImpactOutcome {
            regime: after_regime,
            state: out,
            normal_impulse: balance.normal_impulse,
            friction_impulse: balance.friction_impulse,
            seat_impulse_ratio,
        }
    }

    /// The generalised-momentum balance in the coordinates of `after` (with
    /// `u` where there is a building), and the friction decision.
    fn momentum_balance(&self, after: &StackRegime, at: &StackState, before: &Velocities) -> Balance {
        let has_building = self.building.is_some();
        let pose = Pose::new(self, after, at);
        let coords = Coordinates::with_slip(self, after, has_building);
        let frame = Frame::new(&coords, &pose);
        let n = frame.coords.len();
        let (mut m, _) = self.kane_system::<f64, MAX_COORDINATES, MAX_BLOCKS>(&frame, 0.0, 0.0, 0.0);
        // Generalised momenta before, the vertical momentum before, and the
        // vertical momentum per unit of each new velocity.
        let mut p = [0.0; MAX_COORDINATES];
        let mut vertical_per = [0.0; MAX_COORDINATES];
        let mut vertical_before = 0.0;
        for (i, block) in self.blocks.iter().enumerate() {
            vertical_before += block.mass * before.centre[i][1];
            for a in 0..n {
                p[a] += block.mass * dot(frame.jac(i, a), before.centre[i]) + block.inertia_centre * frame.rot(i, a) * before.rotation[i];
                vertical_per[a] += block.mass * frame.jac(i, a)[1];
            }
        }
        let vertical_impulse = |q: &[f64; MAX_COORDINATES]| (0..n).map(|a| vertical_per[a] * q[a]).sum::<f64>() - vertical_before;
        let Some(building) = self.building else {
            let mut q = p;
            solve(&mut m, &mut q, n);
            return Balance {
                normal_impulse: vertical_impulse(&q),
                velocities: q,
                building: BuildingRegime::Stick,
                friction_impulse: 0.0,
            };
        };
        // `u` is coordinate 0; the building's own momentum m1 u̇⁻ enters its row.
        p[0] += self.building_mass() * at.slip_vel;
        // Stick: u̇⁺ = 0, the other rows alone.
        let mut reduced: Matrix = [[0.0; MAX_COORDINATES]; MAX_COORDINATES];
        let mut reduced_p = [0.0; MAX_COORDINATES];
        for a in 1..n {
            reduced_p[a - 1] = p[a];
            for b in 1..n {
                reduced[a - 1][b - 1] = m[a][b];
            }
        }
        solve(&mut reduced, &mut reduced_p, n - 1);
        let mut stick = [0.0; MAX_COORDINATES];
        stick[1..n].copy_from_slice(&reduced_p[..n - 1]);
        let p_stick = (1..n).map(|b| m[0][b] * stick[b]).sum::<f64>() - p[0];
        let n_stick = vertical_impulse(&stick);
        let stuck = Balance {
            velocities: stick,
            building: BuildingRegime::Stick,
            normal_impulse: n_stick,
            friction_impulse: p_stick,
        };
        if building.friction().sticks(p_stick, n_stick.max(0.0)) {
            return stuck;
        }
        // Slide: P = −μk σ N_imp = −μk σ (Σ_b vertical_per_b q̇_b − vertical_before).
        let sigma = -p_stick.signum();
        let friction = self.friction_per_normal(sigma);
        let mut ms = m;
        for b in 0..n {
            ms[0][b] += friction * vertical_per[b];
        }
        let mut ps = p;
        ps[0] += friction * vertical_before;
        let mut q = ps;
        let det = solve(&mut ms, &mut q, n);
        if !(det > 0.0 && q[0] * sigma > 0.0 && q[..n].iter().all(|v| v.is_finite())) {
            // The sliding solution contradicts its own direction: Coulomb's
            // law admits only the stuck one.
            return stuck;
        }
        let normal_impulse = vertical_impulse(&q);
        Balance {
            velocities: q,
            building: BuildingRegime::Slip(SlipDirection::of_sign(sigma)),
            normal_impulse,
            friction_impulse: -friction * normal_impulse,
        }
    }

    /// `|M_imp| / (V_imp B_j / 2)` of the seated interface `j` through an
    /// impact: the impulse the blocks `j … N` receive through it, `V_imp` its
    /// component normal to the supporting surface, and its moment about `C_j`,
    /// `M_imp = Σ_{i≥j} (G_i − C_j) × m_i ΔĠ_i − Σ_{i≥j} J_i Δφ̇_i` (as `M_k`
    /// with momentum changes for forces). Above 1 the base cannot carry it:
    /// the model keeps the interface seated all the same. Infinite where the
    /// seat would have to pull (`V_imp ≤ 0` with a moment).
    fn seat_impulse_ratio(&self, pose: &Pose, before: &Velocities, after: &Velocities, j: usize) -> f64 {
        let mut impulse = [0.0, 0.0];
        let mut moment = 0.0;
        for i in j..self.len() {
            let block = &self.blocks[i];
            let dv = sub(after.centre[i], before.centre[i]);
            let di = [block.mass * dv[0], block.mass * dv[1]];
            impulse[0] += di[0];
            impulse[1] += di[1];
            moment += cross(sub(pose.centre[i], pose.base[j]), di) - block.inertia_centre * (after.rotation[i] - before.rotation[i]);
        }
        let normal = dot(impulse, pose.normal(j));
        let capacity = normal * self.blocks[j].width / 2.0;
        if capacity > 0.0 {
            moment.abs() / capacity
        } else if moment == 0.0 {
            0.0
        } else {
            f64::INFINITY
        }
    }
}
