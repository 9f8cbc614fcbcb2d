//! The stack's equations of motion in Kane's form, the friction a sticking
//! building needs, and the loads each interface carries.
//!
//! For every coordinate `q_a` of the regime (Lagrange's equations written as
//! Kane's: the virtual work of the inertia and gravity forces along each
//! coordinate equals that of the applied ones), summed over the building
//! (mass `m1`, no rotation, `∂/∂u = e_x`) and the blocks:
//!
//! ```text
//! Σ_i m_i (∂G_i/∂q_a) · (G̈_i + g_e e_y) + Σ_i J_i (∂φ_i/∂q_a) φ̈_i = Q_a
//! ```
//!
//! with absolute accelerations `G̈_i = Ẍ_p e_x + Σ_b (∂G_i/∂q_b) q̈_b + c_i`
//! (`c_i` the velocity-squared part, [`Pose::point_quadratic`]),
//! `φ̈_i = Σ_b (∂φ_i/∂q_b) q̈_b`, `Q_u = F` the foundation's friction and
//! `Q_θ = 0`. In matrix form `M q̈ = f + F e_u` with
//!
//! ```text
//! M_ab = Σ_i m_i (∂G_i/∂q_a)·(∂G_i/∂q_b) + Σ_i J_i (∂φ_i/∂q_a)(∂φ_i/∂q_b)
//! f_a  = −Σ_i m_i (∂G_i/∂q_a) · (a_g e_x + c_i + g_e e_y)
//! ```
//!
//! The normal force on the foundation is `N = g_e Σ m` ("constant") or
//! `N = Σ m_i (g_e + ÿ_i)` ("dynamic"); while the building slips,
//! `F = −μk σ N`, and the dynamic `N`'s `q̈` terms move to the left-hand side:
//! still one linear system, solved directly. For one block this is (T)–(B).
//!
//! While the building sticks, the friction it needs is the horizontal
//! momentum rate of everything on it, `F_req = m1 a_g + Σ_i m_i Ẍ_i`.

use super::geometry::{add, cross, dot, real, rotate, scale, sub, Coordinate, Coordinates, Pose, Vec2, MAX_COORDINATES};
use super::linalg::{solve, Matrix};
use super::{Stack, StackRegime, StackState, MAX_BLOCKS};
use crate::body::NormalForce;
use crate::jet::Real;
use crate::regime::BuildingRegime;
use arrayvec::ArrayVec;

/// The kinematics of one instant in one set of coordinates: the pose, and for
/// each block `∂G_i/∂q`, `∂φ_i/∂q` and the velocity-squared part of `G̈_i`.
#[derive(Debug, Clone)]
pub struct Frame<'p, T = f64, const N: usize = MAX_BLOCKS> {
    /// The coordinates.
    pub coords: &'p Coordinates,
    /// Where the blocks are.
    pub pose: &'p Pose<T, N>,
    pub(crate) quad: [Vec2<T>; N],
}

impl<'p, T: Real, const N: usize> Frame<'p, T, N> {
    /// The frame of `pose` in `coords`.
    #[inline(always)]
    pub(crate) fn new(coords: &'p Coordinates, pose: &'p Pose<T, N>) -> Self {
        let mut quad = [[real(0.0); 2]; N];
        for (i, q) in quad.iter_mut().enumerate().take(pose.len()) {
            *q = pose.point_quadratic(i, pose.centre[i]);
        }
        Self { coords, pose, quad }
    }

    /// `∂G_i/∂q_a` (0 for `a ≥ coords.moving(i)`). Computed where it is
    /// used: a few operations, cheaper than storing a table of them at every
    /// evaluation.
    #[inline(always)]
    pub(crate) fn jac(&self, i: usize, a: usize) -> Vec2<T> {
        self.pose.point_jacobian(i, self.pose.centre[i], self.coords.list()[a])
    }

    /// `∂φ_i/∂q_a`.
    #[inline(always)]
    pub(crate) fn rot(&self, i: usize, a: usize) -> f64 {
        self.pose.rotation_jacobian(i, self.coords.list()[a])
    }
}

/// The state of motion at one instant: the accelerations of the regime's
/// coordinates and of every body (of plain numbers, or of
/// [`Jet`](crate::jet::Jet)s carrying their time derivatives), of a stack of
/// `N` blocks at most.
#[derive(Debug, Clone)]
pub struct Snapshot<T = f64, const N: usize = MAX_BLOCKS> {
    /// Where the blocks are.
    pub pose: Pose<T, N>,
    /// `θ̈_k` (rad/s², 0 for a stuck interface) at index `k − 1`.
    pub theta_ddot: [T; N],
    /// `ü` (m/s², 0 while the building sticks).
    pub slip_acc: T,
    /// `G̈_i`, absolute (with the ground's `a_g`).
    pub centre_acc: [Vec2<T>; N],
    /// `φ̈_i`.
    pub rotation_acc: [T; N],
    /// The ground's acceleration `a_g` (m/s²).
    pub a_g: T,
    /// The effective gravity `g_e` (m/s²).
    pub g_e: T,
}

/// What the blocks `k … N` need from the block below (the building for
/// `k = 1`): the resultant force split along that block's base and normal to
/// it, and the counter-clockwise moment about `C_k`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InterfaceLoad<T = f64> {
    /// Component along the supporting surface `R(φ_{k−1}) e_x` (N).
    pub tangential: T,
    /// Component normal to it, `R(φ_{k−1}) e_y` (N); the resultant of `V_k`
    /// and `T_k` on the surface's normal, equal to `V_k` on an upright block.
    pub normal: T,
    /// `M_k` (N·m), counter-clockwise positive.
    pub moment: T,
}

/// `θ̈_k` by interface and `ü` from the accelerations of `coords`.
#[inline]
fn split<T: Real, const N: usize>(coords: &Coordinates, q_ddot: &[T; MAX_COORDINATES]) -> ([T; N], T) {
    let mut theta_ddot = [real(0.0); N];
    let mut slip_acc = real(0.0);
    for (a, c) in coords.list().iter().enumerate() {
        match *c {
            Coordinate::Slip => slip_acc = q_ddot[a],
            Coordinate::Theta(k) => theta_ddot[k] = q_ddot[a],
        }
    }
    (theta_ddot, slip_acc)
}

/// When the slip is one of `coords`, the direction `σ` its kinetic friction
/// opposes (0 if `regime`'s building sticks, as [`Stack::kane_system`] takes
/// it); `None` without the slip.
fn slip_direction(coords: &Coordinates, regime: &StackRegime) -> Option<f64> {
    coords.slip().map(|_| match regime.building {
        BuildingRegime::Slip(d) => d.sign(),
        BuildingRegime::Stick => 0.0,
    })
}

/// The arms of two rocking blocks that [`Stack::two_rocking`] reads:
/// `r_1 = G_1 − O_1`, `d = O_2 − O_1`, `r_2 = G_2 − O_2` (so that `G_2 −
/// O_1 = d + r_2`), and the absolute angular velocities `φ̇_1`, `φ̇_2`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct TwoArms<T> {
    r1: Vec2<T>,
    d: Vec2<T>,
    r2: Vec2<T>,
    w1: T,
    w2: T,
}

impl TwoArms<f64> {
    /// The arms at `θ`, `θ̇` on the corners `s` (geometry.rs's positions,
    /// without the rest of the pose: the right-hand side needs no more).
    #[inline(always)]
    fn of(stack: &Stack, s: [f64; 2], theta: [f64; 2], theta_dot: [f64; 2]) -> Self {
        let [lower, upper] = [&stack.blocks[0], &stack.blocks[1]];
        let (rot1, rot2) = (crate::trig::sin_cos(theta[0]), crate::trig::sin_cos(theta[0] + theta[1]));
        Self {
            r1: rotate(rot1, [-s[0] * lower.width / 2.0, lower.height / 2.0]),
            d: rotate(rot1, [(s[1] * upper.width - s[0] * lower.width) / 2.0, lower.height]),
            r2: rotate(rot2, [-s[1] * upper.width / 2.0, upper.height / 2.0]),
            w1: theta_dot[0],
            w2: theta_dot[0] + theta_dot[1],
        }
    }
}

impl<T: Real> TwoArms<T> {
    /// The arms read from a pose of two rocking blocks.
    #[inline]
    fn in_pose<const N: usize>(pose: &Pose<T, N>) -> Self {
        Self {
            r1: sub(pose.centre[0], pose.corner[0]),
            d: sub(pose.corner[1], pose.corner[0]),
            r2: sub(pose.centre[1], pose.corner[1]),
            w1: pose.phi_dot[0],
            w2: pose.phi_dot[1],
        }
    }
}

/// The arm of the blocks `k … N` turning as one body about the corner `O_k`
/// of block `k` (every other interface stuck), which [`Stack::one_rocking`]
/// reads: `r = G − O_k`, `G` their centre of mass, and `φ̇_k`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct OneArm<T> {
    r: Vec2<T>,
    w: T,
}

impl OneArm<f64> {
    /// The arm at `θ_k`, `θ̇_k` on the corner `s` (every interface below `k`
    /// stuck: block `k`'s base is level, `φ_k = θ_k`).
    #[inline(always)]
    fn of(stack: &Stack, k: usize, s: f64, theta: f64, theta_dot: f64) -> Self {
        let body = stack.body_above(k);
        Self {
            r: rotate(crate::trig::sin_cos(theta), [-s * stack.blocks[k].width / 2.0, body.centre_height]),
            w: theta_dot,
        }
    }
}

impl<T: Real> OneArm<T> {
    /// The arm read from a pose where only interface `k` rocks.
    #[inline]
    fn in_pose<const N: usize>(stack: &Stack, pose: &Pose<T, N>, k: usize) -> Self {
        let mut moment = [real::<T>(0.0); 2];
        for (i, block) in stack.blocks.iter().enumerate().skip(k) {
            moment = add(moment, scale(sub(pose.centre[i], pose.corner[k]), real::<T>(block.mass)));
        }
        Self {
            r: scale(moment, real::<T>(1.0 / stack.body_above(k).mass)),
            w: pose.phi_dot[k],
        }
    }
}

/// The blocks `k … N` taken as one rigid body, seated on one another.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Body {
    /// Their mass (kg).
    pub(crate) mass: f64,
    /// The height of their centre of mass above block `k`'s base (m); it lies
    /// on block `k`'s axis, every block being centred on the one below.
    pub(crate) centre_height: f64,
    /// Their moment of inertia about either corner of block `k`'s base
    /// (kg·m²): `Σ_i J_i + m_i ((B_k/2)² + z_i²)`, `z_i` block `i`'s centre
    /// height above that base.
    pub(crate) inertia_corner: f64,
    /// The length of the arm from either corner of block `k`'s base to their
    /// centre of mass (m): `sqrt((B_k/2)² + z²)`, `z` the centre's height.
    pub(crate) arm: f64,
}

impl Body {
    /// The blocks `blocks[k..]`, seated on one another, as one body.
    pub(crate) fn above(blocks: &[super::Block], k: usize) -> Self {
        let half = blocks[k].width / 2.0;
        let (mass, centre_height) = super::column_centre(&blocks[k..]);
        let (mut inertia, mut base) = (0.0, 0.0);
        for block in &blocks[k..] {
            let z = base + block.height / 2.0;
            inertia += block.inertia_centre + block.mass * (half * half + z * z);
            base += block.height;
        }
        Self {
            mass,
            centre_height,
            inertia_corner: inertia,
            arm: half.hypot(centre_height),
        }
    }
}

impl InterfaceLoad<crate::jet::Jet> {
    /// The load's values, without their time derivatives.
    pub(crate) fn values(&self) -> InterfaceLoad {
        InterfaceLoad {
            tangential: self.tangential.v,
            normal: self.normal.v,
            moment: self.moment.v,
        }
    }
}

impl InterfaceLoad {
    /// The friction the interface needs, `|T'| / N'` (along and normal to the
    /// supporting surface): blocks never slide on one another in the model,
    /// so a demand above the interface's friction coefficient is reported,
    /// not acted on (for the tower, Shenton's `|f_x| / f_y`). Infinite where
    /// `N' ≤ 0`: the blocks above are in free flight.
    pub fn friction_demand(&self) -> f64 {
        if self.normal > 0.0 {
            self.tangential.abs() / self.normal
        } else {
            f64::INFINITY
        }
    }
}

impl Stack {
    /// Mass matrix and forces `M q̈ = f` of Kane's equations for `frame`,
    /// including the foundation's kinetic friction when `coords` has the slip
    /// (`sigma` its direction), in the leading `n × n` block of matrices of
    /// order `C ≥ n` (`n` the number of coordinates). Block `i` enters only
    /// the rows and columns of the coordinates that move it: the others'
    /// partials are exact zeros.
    #[inline]
    pub(crate) fn kane_system<T: Real, const C: usize, const N: usize>(&self, frame: &Frame<T, N>, sigma: f64, a_g: T, g_e: T) -> (Matrix<T, C>, [T; C]) {
        let n = frame.coords.len();
        let mut m: Matrix<T, C> = [[real(0.0); C]; C];
        let mut f = [real(0.0); C];
        let m1 = self.building_mass();
        for (i, block) in self.blocks.iter().enumerate() {
            let load = [a_g + frame.quad[i][0], g_e + frame.quad[i][1]];
            let moving = frame.coords.moving(i);
            // Block `i`'s partials, once for all the pairs they enter.
            let (mut jac, mut rot) = ([[real(0.0); 2]; C], [0.0; C]);
            for a in 0..moving {
                (jac[a], rot[a]) = (frame.jac(i, a), frame.rot(i, a));
            }
            for a in 0..moving {
                for b in a..moving {
                    let inertia: T = real(block.inertia_centre * rot[a] * rot[b]);
                    m[a][b] = m[a][b] + (dot(jac[a], jac[b]) * block.mass + inertia);
                }
                f[a] = f[a] - dot(jac[a], load) * block.mass;
            }
        }
        for a in 0..n {
            for b in 0..a {
                m[a][b] = m[b][a];
            }
        }
        if let Some(u) = frame.coords.slip() {
            m[u][u] = m[u][u] + m1;
            f[u] = f[u] - a_g * m1;
            let friction = self.friction_per_normal(sigma);
            let weight = g_e * self.total_mass();
            if self.dynamic_normal_force() {
                let mut rest = weight;
                for (i, block) in self.blocks.iter().enumerate() {
                    rest = rest + frame.quad[i][1] * block.mass;
                    for b in 0..frame.coords.moving(i) {
                        m[u][b] = m[u][b] + frame.jac(i, b)[1] * (friction * block.mass);
                    }
                }
                f[u] = f[u] - rest * friction;
            } else {
                f[u] = f[u] - weight * friction;
            }
        }
        (m, f)
    }

    pub(crate) fn dynamic_normal_force(&self) -> bool {
        self.building.is_some_and(|b| b.normal_force() == NormalForce::Dynamic)
    }

    /// `q̈` from Kane's equations of `regime` in `frame`, NaN where the system
    /// has no solution (Painlevé's paradox of the dynamic normal force, a
    /// light building under high friction).
    #[inline]
    fn solve_kane<T: Real, const N: usize>(&self, frame: &Frame<T, N>, regime: &StackRegime, a_g: T, g_e: T) -> [T; MAX_COORDINATES] {
        let slip = slip_direction(frame.coords, regime);
        if self.rocking_pair(regime).is_some() {
            let ([t1, t2], slip_acc) = self.two_rocking(&TwoArms::in_pose(frame.pose), slip, a_g, g_e);
            let mut q_ddot = [real(0.0); MAX_COORDINATES];
            // In the coordinates' order: the slip first, if it is one.
            let first = match slip {
                Some(_) => [slip_acc, t1, t2],
                None => [t1, t2, real(0.0)],
            };
            q_ddot[..3].copy_from_slice(&first);
            return q_ddot;
        }
        if let Some((k, _)) = self.rocking_one(regime) {
            let (theta_ddot, slip_acc) = self.one_rocking(k, &OneArm::in_pose(self, frame.pose, k), slip, a_g, g_e);
            let mut q_ddot = [real(0.0); MAX_COORDINATES];
            // In the coordinates' order: the slip first, if it is one.
            match slip {
                Some(_) => (q_ddot[0], q_ddot[1]) = (slip_acc, theta_ddot),
                None => q_ddot[0] = theta_ddot,
            }
            return q_ddot;
        }
        // Without the slip among the coordinates, its friction is not read.
        let sigma = slip.unwrap_or(0.0);
        // The system's order as a constant where it is small (one or two
        // blocks, with the slip or without), so that its loops are unrolled
        // and free of bounds checks: a third fewer instructions per
        // evaluation of two rocking blocks than one padded system for every
        // order. Larger systems, rarer, share one padded code.
        match frame.coords.len() {
            0 => [real(0.0); MAX_COORDINATES],
            1 => self.solve_kane_of::<T, 1, N>(frame, sigma, a_g, g_e),
            2 => self.solve_kane_of::<T, 2, N>(frame, sigma, a_g, g_e),
            3 => self.solve_kane_of::<T, 3, N>(frame, sigma, a_g, g_e),
            _ => self.solve_kane_of::<T, MAX_COORDINATES, N>(frame, sigma, a_g, g_e),
        }
    }

    /// [`Stack::solve_kane`] in matrices of order `C` (the number of
    /// coordinates or more), `q̈` padded with zeros.
    #[inline]
    fn solve_kane_of<T: Real, const C: usize, const N: usize>(&self, frame: &Frame<T, N>, sigma: f64, a_g: T, g_e: T) -> [T; MAX_COORDINATES] {
        let (mut m, mut q) = self.kane_system::<T, C, N>(frame, sigma, a_g, g_e);
        if solve(&mut m, &mut q, frame.coords.len()) > 0.0 {
            let mut q_ddot = [real(0.0); MAX_COORDINATES];
            q_ddot[..C].copy_from_slice(&q);
            q_ddot
        } else {
            [real(f64::NAN); MAX_COORDINATES]
        }
    }

    /// The corners `(s_1, s_2)` when the stack is two blocks that both rock
    /// in `regime`: where [`Stack::two_rocking`] replaces the generic solve.
    #[inline]
    fn rocking_pair(&self, regime: &StackRegime) -> Option<[f64; 2]> {
        match (self.len(), regime.interfaces[0].pivot(), regime.interfaces[1].pivot()) {
            (2, Some(lower), Some(upper)) => Some([lower.sign(), upper.sign()]),
            _ => None,
        }
    }

    /// Kane's equations of two blocks that both rock ([`Stack::kane_system`]
    /// solved, written out; the right-hand side of most of a belfry's run),
    /// from the arms `arms` of the pose, with the slip as a coordinate when
    /// `sigma` is given (its kinetic friction opposing `σ`, 0 while the
    /// building sticks) or without it: `(θ̈_1, θ̈_2)` and `ü` (0 without the
    /// slip), NaN where the system has no solution.
    ///
    /// With the partials `∂G_1/∂θ_1 = J(r_1)`, `∂G_2/∂θ_1 = J(e)`,
    /// `∂G_2/∂θ_2 = J(r_2)` ([`TwoArms`]), every `∂φ/∂θ` 1 or 0, and
    /// `J(w)·J(v) = w·v`, `J(w)·l = l × w`:
    ///
    /// ```text
    /// A = [ m_1 |r_1|² + J_1 + m_2 |e|² + J_2    m_2 e·r_2 + J_2 ]
    ///     [ m_2 e·r_2 + J_2                      m_2 |r_2|² + J_2 ]
    /// f = −[ m_1 l_1 × r_1 + m_2 l_2 × e,  m_2 l_2 × r_2 ]
    /// ```
    ///
    /// with the loads `l_i = a_g e_x + g_e e_y + c_i` and the velocity-squared
    /// parts `c_1 = −φ̇_1² r_1`, `c_2 = −φ̇_1² d − φ̇_2² r_2`. The slip adds the
    /// row `M_uu ü + c·θ̈ = f_u` and the column `b ü` to `A θ̈ = f`, with
    /// `b = (m_1 r_1y + m_2 e_y, m_2 r_2y)`, `c = b` less `μk σ (m_1 r_1x +
    /// m_2 e_x, m_2 r_2x)` for the dynamic normal force: eliminated through
    /// `A` (symmetric, positive definite), `ü = (f_u − c·A⁻¹f) / (M_uu −
    /// c·A⁻¹b)`, and the system is singular where that denominator is not
    /// positive (the full determinant is `det A` times it), as
    /// [`Stack::kane_system`]'s solve says. Tested against it (`tests`).
    #[inline(always)]
    pub(crate) fn two_rocking<T: Real>(&self, arms: &TwoArms<T>, sigma: Option<f64>, a_g: T, g_e: T) -> ([T; 2], T) {
        let [lower, upper] = [&self.blocks[0], &self.blocks[1]];
        let (m1, m2) = (lower.mass, upper.mass);
        let TwoArms { r1, d, r2, w1, w2 } = *arms;
        let e = add(d, r2);
        let c1 = scale(r1, -(w1 * w1));
        let c2 = sub(scale(d, -(w1 * w1)), scale(r2, w2 * w2));
        let (l1, l2) = ([a_g + c1[0], g_e + c1[1]], [a_g + c2[0], g_e + c2[1]]);
        let a11 = dot(r1, r1) * m1 + lower.inertia_centre + dot(e, e) * m2 + upper.inertia_centre;
        let a12 = dot(e, r2) * m2 + upper.inertia_centre;
        let a22 = dot(r2, r2) * m2 + upper.inertia_centre;
        let f = [-(cross(l1, r1) * m1 + cross(l2, e) * m2), -(cross(l2, r2) * m2)];
        let det = a11 * a22 - a12 * a12;
        let nan = real::<T>(f64::NAN);
        if det.value() <= 0.0 {
            return ([nan; 2], nan);
        }
        let solve_a = |v: [T; 2]| [(v[0] * a22 - a12 * v[1]) / det, (a11 * v[1] - a12 * v[0]) / det];
        let x = solve_a(f);
        let Some(sigma) = sigma else { return (x, real(0.0)) };
        let mu = self.friction_per_normal(sigma);
        let b = [r1[1] * m1 + e[1] * m2, r2[1] * m2];
        let weight = g_e * self.total_mass();
        let pushed = -(a_g * self.building_mass() + l1[0] * m1 + l2[0] * m2);
        let (c, f_u) = if self.dynamic_normal_force() {
            (
                [b[0] - (r1[0] * m1 + e[0] * m2) * mu, b[1] - r2[0] * (m2 * mu)],
                pushed - (weight + c1[1] * m1 + c2[1] * m2) * mu,
            )
        } else {
            (b, pushed - weight * mu)
        };
        let y = solve_a(b);
        let schur = real::<T>(self.total_mass()) - dot(c, y);
        if schur.value() <= 0.0 || !schur.value().is_finite() {
            return ([nan; 2], nan);
        }
        let slip_acc = (f_u - dot(c, x)) / schur;
        ([x[0] - y[0] * slip_acc, x[1] - y[1] * slip_acc], slip_acc)
    }

    /// The blocks `k … N` as one rigid body ([`Body`]), computed with the stack.
    pub(crate) fn body_above(&self, k: usize) -> Body {
        self.bodies[k]
    }

    /// The interface `k` and its corner `s_k` when it is the only one that
    /// rocks in `regime`: where [`Stack::one_rocking`] replaces the generic
    /// solve.
    #[inline]
    pub(crate) fn rocking_one(&self, regime: &StackRegime) -> Option<(usize, f64)> {
        let mut rocking = (0..self.len()).filter_map(|k| regime.interfaces[k].pivot().map(|p| (k, p.sign())));
        let one = rocking.next()?;
        rocking.next().is_none().then_some(one)
    }

    /// Kane's equations where interface `k` alone rocks ([`Stack::kane_system`]
    /// solved, written out): the blocks `k … N` turn as one rigid body about
    /// the corner `O_k` ([`Body`]: its mass `m`, its moment of inertia `I_O`
    /// about the corner) and those below move with the building. From the
    /// arm `r = G − O_k` to the body's centre of mass ([`OneArm`]), with the
    /// slip as a coordinate when `sigma` is given (as in
    /// [`Stack::two_rocking`]): `(θ̈_k, ü)`, NaN where the system has no
    /// solution.
    ///
    /// Every block of the body has `∂G_i/∂θ_k = J(G_i − O_k)` and
    /// `∂φ_i/∂θ_k = 1`, and its velocity-squared part `−φ̇_k² (G_i − O_k)`
    /// crosses its own arm to zero; summed over the body, with the load `l =
    /// (a_g − φ̇_k² r_x, g_e − φ̇_k² r_y)` of its centre of mass:
    ///
    /// ```text
    /// I_O θ̈_k = −m l × r
    /// ```
    ///
    /// (for one block on a fixed base, (T)). The slip adds the row `M ü + c
    /// θ̈_k = f_u` (`M` everything the building carries and itself) and the
    /// column `b ü`, `b = m r_y`, `c = b` less `μk σ m r_x` for the dynamic
    /// normal force, `f_u = −a_g (M − m) − m l_x` less the friction:
    /// `ü = (f_u − c x) / (M − c y)` with `x = −m l × r / I_O`, `y = b / I_O`,
    /// singular where that denominator is not positive. Tested against the
    /// generic solve (`tests`).
    #[inline(always)]
    pub(crate) fn one_rocking<T: Real>(&self, k: usize, arm: &OneArm<T>, sigma: Option<f64>, a_g: T, g_e: T) -> (T, T) {
        let body = self.body_above(k);
        let m = body.mass;
        let OneArm { r, w } = *arm;
        let quadratic = scale(r, -(w * w));
        let load = [a_g + quadratic[0], g_e + quadratic[1]];
        let per_inertia = 1.0 / body.inertia_corner;
        let x = -(cross(load, r) * (m * per_inertia));
        let Some(sigma) = sigma else { return (x, real(0.0)) };
        let mu = self.friction_per_normal(sigma);
        let total = self.total_mass();
        let b = r[1] * m;
        let weight = g_e * total;
        let pushed = -(a_g * (total - m) + load[0] * m);
        let (c, f_u) = if self.dynamic_normal_force() {
            (b - r[0] * (m * mu), pushed - (weight + quadratic[1] * m) * mu)
        } else {
            (b, pushed - weight * mu)
        };
        let y = b * per_inertia;
        let schur = real::<T>(total) - c * y;
        if schur.value() <= 0.0 || !schur.value().is_finite() {
            let nan = real::<T>(f64::NAN);
            return (nan, nan);
        }
        let slip_acc = (f_u - c * x) / schur;
        (x - y * slip_acc, slip_acc)
    }

    /// A bound of `|θ̈_k|` from [`Stack::one_rocking`] without the slip (the
    /// building sticks, or there is none), given upper bounds of `g_e` and
    /// `|a_g|`. There the velocity-squared part crosses the arm to zero:
    /// `I_O θ̈_k = m (g_e r_x − a_g r_y)`, and the arm's length `|r|` is
    /// constant (the body is rigid), so `|θ̈_k| <= (m |r| / I_O) sqrt(g_e² +
    /// a_g²)` (Cauchy–Schwarz), reached where the arm is normal to `(a_g,
    /// g_e)`. Returns the bound and `sqrt(g_e² + a_g²)`, the reach
    /// [`Stack::one_rocking_jerk_bound`] needs. As the tower's
    /// (`Kernel::tower_acceleration_bound`), with the body's constants.
    pub(crate) fn one_rocking_acceleration_bound(&self, k: usize, g_e: f64, a_max: f64) -> (f64, f64) {
        let reach = g_e.hypot(a_max);
        (self.one_rocking_rate(k) * reach, reach)
    }

    /// A bound of `|θ⃛_k|` from [`Stack::one_rocking`] without the slip:
    /// differentiating `I_O θ̈_k = m (g_e r_x − a_g r_y)` along the motion
    /// (`ṙ = θ̇_k J r`, `|ṙ| = |θ̇_k| |r|`, `g_e` constant), `I_O θ⃛_k = m
    /// (−ȧ_g r_y + (g_e, −a_g) · ṙ)`, so `|θ⃛_k| <= (m |r| / I_O) (|ȧ_g| +
    /// max|θ̇_k| sqrt(g_e² + a_g²))`, given upper bounds of `|ȧ_g|` and
    /// `|θ̇_k|`; `reach` from [`Stack::one_rocking_acceleration_bound`].
    pub(crate) fn one_rocking_jerk_bound(&self, k: usize, reach: f64, a_rate: f64, theta_dot_max: f64) -> f64 {
        self.one_rocking_rate(k) * (a_rate + theta_dot_max * reach)
    }

    /// `m |r| / I_O` of the body above interface `k` (1/m).
    fn one_rocking_rate(&self, k: usize) -> f64 {
        let body = self.body_above(k);
        body.mass * body.arm / body.inertia_corner
    }

    /// `θ̈_k` (0 for a stuck interface) and `ü` of `regime` at `state`: the
    /// right-hand side of a run, without the bodies' accelerations of
    /// [`Stack::snapshot`].
    #[inline]
    pub fn accelerations(&self, regime: &StackRegime, state: &StackState, a_g: f64, g_e: f64) -> ([f64; MAX_BLOCKS], f64) {
        self.accelerations_in(&Coordinates::of(self, regime), regime, state, a_g, g_e)
    }

    /// [`Stack::accelerations`] with the regime's coordinates built once
    /// (a run's right-hand side, evaluated a dozen times a step).
    #[inline]
    pub(crate) fn accelerations_in(&self, coords: &Coordinates, regime: &StackRegime, state: &StackState, a_g: f64, g_e: f64) -> ([f64; MAX_BLOCKS], f64) {
        if let Some(corners) = self.rocking_pair(regime) {
            let arms = TwoArms::of(self, corners, [state.theta[0], state.theta[1]], [state.theta_dot[0], state.theta_dot[1]]);
            let ([t1, t2], slip_acc) = self.two_rocking(&arms, slip_direction(coords, regime), a_g, g_e);
            let mut theta_ddot = [0.0; MAX_BLOCKS];
            (theta_ddot[0], theta_ddot[1]) = (t1, t2);
            return (theta_ddot, slip_acc);
        }
        if let Some((k, s)) = self.rocking_one(regime) {
            let arm = OneArm::of(self, k, s, state.theta[k], state.theta_dot[k]);
            let (t, slip_acc) = self.one_rocking(k, &arm, slip_direction(coords, regime), a_g, g_e);
            let mut theta_ddot = [0.0; MAX_BLOCKS];
            theta_ddot[k] = t;
            return (theta_ddot, slip_acc);
        }
        let pose = Pose::new(self, regime, state);
        let frame = Frame::new(coords, &pose);
        let q_ddot = self.solve_kane(&frame, regime, a_g, g_e);
        split(frame.coords, &q_ddot)
    }

    /// Everything about the motion at one instant: `q̈` from Kane's equations
    /// of `regime` (NaN where the system has no solution) and the bodies'
    /// accelerations.
    #[inline]
    pub fn snapshot(&self, regime: &StackRegime, state: &StackState, a_g: f64, g_e: f64) -> Snapshot {
        self.snapshot_of(regime, &state.theta, &state.theta_dot, a_g, g_e)
    }

    /// [`Stack::snapshot`] at the rotations `θ_k` and rates `θ̇_k`: on
    /// [`Jet`](crate::jet::Jet)s (`θ_k` with `θ̇_k`, `θ̇_k` with `θ̈_k`, `a_g`
    /// with its rate), every quantity with its exact time derivative along
    /// the motion; given for every block, the stack of `N` blocks at most.
    #[inline]
    pub(crate) fn snapshot_of<T: Real, const N: usize>(&self, regime: &StackRegime, theta: &[T], theta_dot: &[T], a_g: T, g_e: T) -> Snapshot<T, N> {
        let pose = Pose::of(self, regime, theta, theta_dot);
        let coords = Coordinates::of(self, regime);
        let frame = Frame::new(&coords, &pose);
        let q_ddot = self.solve_kane(&frame, regime, a_g, g_e);
        let (theta_ddot, slip_acc) = split(frame.coords, &q_ddot);
        let mut centre_acc = [[real(0.0); 2]; N];
        let mut rotation_acc = [real(0.0); N];
        for i in 0..self.len() {
            let mut acc = [a_g + frame.quad[i][0], frame.quad[i][1]];
            for a in 0..frame.coords.moving(i) {
                acc[0] = acc[0] + frame.jac(i, a)[0] * q_ddot[a];
                acc[1] = acc[1] + frame.jac(i, a)[1] * q_ddot[a];
                rotation_acc[i] = rotation_acc[i] + q_ddot[a] * frame.rot(i, a);
            }
            centre_acc[i] = acc;
        }
        Snapshot {
            pose,
            theta_ddot,
            slip_acc,
            centre_acc,
            rotation_acc,
            a_g,
            g_e,
        }
    }

    /// The normal force of the foundation on the building in `snap`:
    /// `g_e Σ m` (constant) or `Σ m_i (g_e + ÿ_i)` (dynamic).
    pub fn normal_force<T: Real, const N: usize>(&self, snap: &Snapshot<T, N>) -> T {
        let weight = snap.g_e * self.total_mass();
        if self.dynamic_normal_force() {
            let mut blocks = real::<T>(0.0);
            for (b, acc) in self.blocks.iter().zip(&snap.centre_acc) {
                blocks = blocks + acc[1] * b.mass;
            }
            weight + blocks
        } else {
            weight
        }
    }

    /// The friction force on the building, `F = m1 Ẍ_p + Σ_i m_i Ẍ_i`: while it
    /// sticks (`Ẍ_p = a_g`), the `F_req` it needs; it slips when
    /// `|F_req| > μs N`.
    pub fn friction_force<T: Real, const N: usize>(&self, snap: &Snapshot<T, N>) -> T {
        let mut blocks = real::<T>(0.0);
        for (b, acc) in self.blocks.iter().zip(&snap.centre_acc) {
            blocks = blocks + acc[0] * b.mass;
        }
        (snap.a_g + snap.slip_acc) * self.building_mass() + blocks
    }

    /// The load interface `k` (0-based: 0 is the tower on the building)
    /// carries in `snap`: with `(T_k, V_k) = Σ_{i≥k} m_i (G̈_i + g_e e_y)`,
    /// its components along and normal to the supporting surface, and
    /// `M_k = Σ_{i≥k} (G_i − C_k) × m_i (G̈_i + g_e e_y) − Σ_{i≥k} J_i φ̈_i`
    /// (`φ` is clockwise positive, hence the minus).
    pub fn interface_load<T: Real, const N: usize>(&self, snap: &Snapshot<T, N>, k: usize) -> InterfaceLoad<T> {
        let pose = &snap.pose;
        let mut force = [real::<T>(0.0), real(0.0)];
        let mut moment = real::<T>(0.0);
        for i in k..self.len() {
            let block = &self.blocks[i];
            let f = scale([snap.centre_acc[i][0], snap.centre_acc[i][1] + snap.g_e], real(block.mass));
            force[0] = force[0] + f[0];
            force[1] = force[1] + f[1];
            moment = moment + (cross(sub(pose.centre[i], pose.base[k]), f) - snap.rotation_acc[i] * block.inertia_centre);
        }
        InterfaceLoad {
            tangential: dot(force, pose.tangent(k)),
            normal: dot(force, pose.normal(k)),
            moment,
        }
    }

    /// The uplift condition of a stuck interface `k`: `|M_k| − N_k B_k / 2`,
    /// positive when the base can no longer give the moment the blocks above
    /// need; block `k` then rocks on the corner `s_k = sgn M_k`. For one block
    /// standing on the ground (`M = −m (H/2) Ẍ_p`, `N = m g_e`) it is positive
    /// exactly when `|Ẍ_p| > g_e tan α`.
    pub fn uplift_margin<T: Real, const N: usize>(&self, snap: &Snapshot<T, N>, k: usize) -> (T, f64) {
        let load = self.interface_load(snap, k);
        let corner = load.moment.value().signum();
        (load.moment * corner - load.normal * (self.blocks[k].width / 2.0), corner)
    }

    /// The horizontal ground acceleration (m/s², in either direction) that
    /// lifts each interface of the stack standing at rest on a sticking
    /// building (or a fixed base), from [`Stack::uplift_margin`]: at rest
    /// every block moves with the ground, so `M_k` is linear in `a_g` and
    /// `N_k` does not depend on it; the threshold is where `|M_k| = N_k B_k/2`.
    /// For one block, `g tan α`.
    pub fn uplift_thresholds(&self) -> ArrayVec<f64, MAX_BLOCKS> {
        let rest = StackState::default();
        let still = self.snapshot(&StackRegime::REST, &rest, 0.0, self.gravity);
        let pushed = self.snapshot(&StackRegime::REST, &rest, 1.0, self.gravity);
        (0..self.len())
            .map(|k| {
                let (at0, at1) = (self.interface_load(&still, k), self.interface_load(&pushed, k));
                (at0.normal * self.blocks[k].width / 2.0 - at0.moment.abs()) / (at1.moment - at0.moment).abs()
            })
            .collect()
    }
}

impl Stack {
    /// The pose, the building's slip velocity (0 unless it slips) and the
    /// velocity `Ġ_i` of every block relative to the ground.
    fn velocities(&self, regime: &StackRegime, state: &StackState) -> (Pose, f64, [Vec2; MAX_BLOCKS]) {
        let pose = Pose::new(self, regime, state);
        let slip_vel = if matches!(regime.building, BuildingRegime::Slip(_)) {
            state.slip_vel
        } else {
            0.0
        };
        let moving = StackState { slip_vel, ..*state };
        let mut v = [[0.0; 2]; MAX_BLOCKS];
        for (i, vi) in v.iter_mut().enumerate().take(self.len()) {
            *vi = pose.point_velocity(i, pose.centre(i), &moving);
        }
        (pose, slip_vel, v)
    }

    /// The mechanical energy of the stack and the building in the ground's
    /// frame (J): `Σ_i [½ m_i |Ġ_i|² + ½ J_i φ̇_i² + m_i g y_i] + ½ m1 u̇²`,
    /// `y_i` the height of `G_i` above the springing level. Conserved between
    /// events with no ground motion and no friction work.
    pub fn energy(&self, regime: &StackRegime, state: &StackState) -> f64 {
        let (pose, slip_vel, v) = self.velocities(regime, state);
        let mut energy = 0.5 * self.building_mass() * slip_vel * slip_vel;
        for (i, block) in self.blocks.iter().enumerate() {
            let spin = pose.phi_dot[i];
            energy += 0.5 * block.mass * dot(v[i], v[i]) + 0.5 * block.inertia_centre * spin * spin + block.mass * self.gravity * pose.centre(i)[1];
        }
        energy
    }

    /// The horizontal momentum relative to the ground, `m1 u̇ + Σ_i m_i Ẋ_i`
    /// (kg·m/s): the foundation's friction is its only horizontal force
    /// besides the ground's motion.
    pub fn horizontal_momentum(&self, regime: &StackRegime, state: &StackState) -> f64 {
        let (_, slip_vel, v) = self.velocities(regime, state);
        self.building_mass() * slip_vel + self.blocks.iter().zip(&v).map(|(b, vi)| b.mass * vi[0]).sum::<f64>()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::Building;
    use crate::jet::Jet;
    use crate::regime::{Pivot, SlipDirection};
    use crate::stack::{Block, Interface};

    const G: f64 = 9.81;

    /// A 4 m × 12 m shaft of 150 t carrying a 3.2 m × 4.5 m belfry of 30 t.
    fn stack(building: Option<Building>) -> Stack {
        let shaft = Block::solid(1, 4.0, 12.0, 1.5e5).unwrap();
        let belfry = Block::solid(2, 3.2, 4.5, 3.0e4).unwrap();
        Stack::new(&[shaft, belfry], building, G).unwrap()
    }

    /// `θ̈` and `ü` of [`Stack::kane_system`] solved by elimination: the
    /// generic path, which the written-out [`Stack::two_rocking`] replaces.
    fn generic<T: Real>(stack: &Stack, regime: &StackRegime, theta: &[T; MAX_BLOCKS], theta_dot: &[T; MAX_BLOCKS], a_g: T, g_e: T) -> ([T; MAX_BLOCKS], T) {
        generic_in(stack, &Coordinates::of(stack, regime), regime, theta, theta_dot, a_g, g_e)
    }

    /// [`generic`] in the coordinates `coords`.
    fn generic_in<T: Real>(
        stack: &Stack,
        coords: &Coordinates,
        regime: &StackRegime,
        theta: &[T; MAX_BLOCKS],
        theta_dot: &[T; MAX_BLOCKS],
        a_g: T,
        g_e: T,
    ) -> ([T; MAX_BLOCKS], T) {
        let pose: Pose<T> = Pose::of(stack, regime, theta, theta_dot);
        let frame = Frame::new(coords, &pose);
        let sigma = slip_direction(coords, regime).unwrap_or(0.0);
        split(coords, &stack.solve_kane_of::<T, MAX_COORDINATES, MAX_BLOCKS>(&frame, sigma, a_g, g_e))
    }

    /// Both interfaces rocking, on every pair of corners, on a fixed base and
    /// on a sticking or slipping building (both normal-force laws): the
    /// written-out equations equal the generic assembly and solve. Both are a
    /// few dozen roundings of terms of order `g / H` (a few rad/s²) away from
    /// the exact values; 1e-12 of the larger of 1 and the value leaves a
    /// thousand ulps, while a wrong term (the smallest, the dynamic normal
    /// force's velocity-squared part, is above 1e-3 here) would fail.
    #[test]
    fn two_rocking_blocks_written_out_equal_the_generic_solve() {
        let mut buildings = vec![None];
        for normal in [NormalForce::Constant, NormalForce::Dynamic] {
            buildings.push(Some(Building::new(4.0e5, 0.5, 0.4, normal).unwrap()));
        }
        let states = [
            (0.05, -0.02, -0.3, 0.8),
            (-0.12, 0.2, 0.7, -1.5),
            (0.01, 0.0, 0.0, 0.0),
            (-0.3, -0.1, -0.9, 0.4),
        ];
        let mut compared = 0;
        for building in buildings {
            let stack = stack(building);
            for s1 in [Pivot::Negative, Pivot::Positive] {
                for s2 in [Pivot::Negative, Pivot::Positive] {
                    for slip in [
                        BuildingRegime::Stick,
                        BuildingRegime::Slip(SlipDirection::Positive),
                        BuildingRegime::Slip(SlipDirection::Negative),
                    ] {
                        let regime = StackRegime::REST
                            .with(0, Interface::Rocking(s1))
                            .with(1, Interface::Rocking(s2))
                            .with_building(slip);
                        for &(t1, t2, w1, w2) in &states {
                            let mut state = StackState::default();
                            (state.theta[0], state.theta[1], state.theta_dot[0], state.theta_dot[1]) = (t1, t2, w1, w2);
                            for a_g in [0.0, 3.7, -6.2] {
                                for g_e in [G, G + 2.5] {
                                    let coords = Coordinates::of(&stack, &regime);
                                    let (fast, fast_u) = stack.accelerations_in(&coords, &regime, &state, a_g, g_e);
                                    let (slow, slow_u) = generic(&stack, &regime, &state.theta, &state.theta_dot, a_g, g_e);
                                    // On jets (θ with θ̇, θ̇ with θ̈, a_g with a rate): the
                                    // snapshot's solve, values and time derivatives.
                                    let jets =
                                        |x: &[f64; MAX_BLOCKS], dx: &[f64; MAX_BLOCKS]| -> [Jet; MAX_BLOCKS] { std::array::from_fn(|k| Jet::new(x[k], dx[k])) };
                                    let (theta, theta_dot) = (jets(&state.theta, &state.theta_dot), jets(&state.theta_dot, &slow));
                                    let (a_g_jet, g_e_jet) = (Jet::new(a_g, 25.0), Jet::from(g_e));
                                    let snap: Snapshot<Jet> = stack.snapshot_of(&regime, &theta, &theta_dot, a_g_jet, g_e_jet);
                                    let (jet, jet_u) = generic(&stack, &regime, &theta, &theta_dot, a_g_jet, g_e_jet);
                                    let mut pairs = vec![(fast[0], slow[0]), (fast[1], slow[1]), (fast_u, slow_u)];
                                    for (a, b) in [(snap.theta_ddot[0], jet[0]), (snap.theta_ddot[1], jet[1]), (snap.slip_acc, jet_u)] {
                                        pairs.extend([(a.v, b.v), (a.d, b.d)]);
                                    }
                                    for (a, b) in pairs {
                                        assert!(
                                            (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1.0),
                                            "{regime:?} {state:?} a_g={a_g} g_e={g_e}: {a} vs {b}"
                                        );
                                    }
                                    compared += 1;
                                }
                            }
                        }
                    }
                }
            }
        }
        assert_eq!(compared, 3 * 4 * 3 * 4 * 3 * 2);
    }

    /// The property tests' base `0..5`: a fixed base (0), or a building
    /// heavy enough that the system stays regular, slipping either way under
    /// either normal-force law.
    fn base_of(base: usize) -> (Option<Building>, BuildingRegime) {
        let normal = if base.is_multiple_of(2) {
            NormalForce::Constant
        } else {
            NormalForce::Dynamic
        };
        let building = (base > 0).then(|| Building::new(1.0e7, 0.5, 0.3, normal).unwrap());
        let slip = match base {
            0 => BuildingRegime::Stick,
            1 | 2 => BuildingRegime::Slip(SlipDirection::Positive),
            _ => BuildingRegime::Slip(SlipDirection::Negative),
        };
        (building, slip)
    }

    proptest::proptest! {
        /// Any two blocks (the upper no wider than the lower, masses a
        /// hundredfold apart either way), any pose and input, every pair of
        /// corners, on a fixed base or a building slipping either way (both
        /// normal-force laws, a building heavy enough that the system stays
        /// regular): the written-out equations equal the generic solve.
        /// The two differ by their roundings' order: 3e-14 of the value at
        /// most over 20,000 cases (1e-14 fails); 1e-12 leaves a margin of
        /// 30, and a wrong term is far above it.
        #[test]
        fn any_two_rocking_blocks_written_out_equal_the_generic_solve(
            widths in (0.5..5.0f64, 0.1..1.0f64), heights in (1.0..20.0f64, 0.3..10.0f64), masses in (1.0e3..1.0e5f64, 1.0e3..1.0e5f64),
            theta in (-1.2..1.2f64, -1.2..1.2f64), theta_dot in (-4.0..4.0f64, -4.0..4.0f64), a_g in -20.0..20.0f64,
            corners in (proptest::bool::ANY, proptest::bool::ANY), base in 0..5usize,
        ) {
            let lower = Block::solid(1, widths.0, heights.0, masses.0).unwrap();
            let upper = Block::solid(2, widths.0 * widths.1, heights.1, masses.1).unwrap();
            let (building, slip) = base_of(base);
            let stack = Stack::new(&[lower, upper], building, G).unwrap();
            let pivot = |positive: bool| Interface::Rocking(if positive { Pivot::Positive } else { Pivot::Negative });
            let regime = StackRegime::REST.with(0, pivot(corners.0)).with(1, pivot(corners.1)).with_building(slip);
            let mut state = StackState::default();
            (state.theta[0], state.theta[1], state.theta_dot[0], state.theta_dot[1]) = (theta.0, theta.1, theta_dot.0, theta_dot.1);
            let (fast, fast_u) = stack.accelerations_in(&Coordinates::of(&stack, &regime), &regime, &state, a_g, G);
            let (slow, slow_u) = generic(&stack, &regime, &state.theta, &state.theta_dot, a_g, G);
            for (a, b) in [(fast[0], slow[0]), (fast[1], slow[1]), (fast_u, slow_u)] {
                proptest::prop_assert!((a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1.0), "{regime:?} {state:?}: {a} vs {b}");
            }
        }
    }

    /// With the slip among the coordinates while the building sticks (no
    /// kinetic friction: `σ = 0`, as an impact's coordinates have it), the
    /// written-out equations put `ü` first, as the generic solve does, and
    /// equal it (to 1e-12 of the value, as above).
    #[test]
    fn two_rocking_blocks_written_out_take_the_slip_of_a_sticking_building() {
        for normal in [NormalForce::Constant, NormalForce::Dynamic] {
            let stack = stack(Some(Building::new(4.0e5, 0.5, 0.4, normal).unwrap()));
            let regime = StackRegime::REST
                .with(0, Interface::Rocking(Pivot::Positive))
                .with(1, Interface::Rocking(Pivot::Negative));
            let coords = Coordinates::with_slip(&stack, &regime, true);
            let mut state = StackState::default();
            (state.theta[0], state.theta[1], state.theta_dot[0], state.theta_dot[1]) = (0.05, -0.1, 0.4, -0.9);
            let (fast, fast_u) = stack.accelerations_in(&coords, &regime, &state, 2.0, G);
            let (slow, slow_u) = generic_in(&stack, &coords, &regime, &state.theta, &state.theta_dot, 2.0, G);
            // The building moves: its acceleration is not the ground's.
            assert!(slow_u.abs() > 1e-6, "{slow_u}");
            for (a, b) in [(fast[0], slow[0]), (fast[1], slow[1]), (fast_u, slow_u)] {
                assert!((a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1.0), "{normal:?}: {a} vs {b}");
            }
        }
    }

    /// Where the dynamic normal force makes the slipping system singular (a
    /// light building under high kinetic friction, Painlevé's paradox), the
    /// written-out equations, of two rocking blocks and of one rocking
    /// interface, say so as the generic solve does: NaN on the same side of
    /// the boundary, for μk from 0.2 to 6, both sides met for each.
    #[test]
    fn written_out_equations_are_singular_where_the_generic_solve_is() {
        let rocking = Interface::Rocking(Pivot::Positive);
        let slipping = StackRegime::REST.with_building(BuildingRegime::Slip(SlipDirection::Positive));
        for regime in [slipping.with(0, rocking).with(1, rocking), slipping.with(0, rocking)] {
            let (mut singular, mut regular) = (0, 0);
            for step in 1..=30 {
                let mu_k = 0.2 * f64::from(step);
                let stack = stack(Some(Building::new(2.0e3, mu_k, mu_k, NormalForce::Dynamic).unwrap()));
                // On the corners, the blocks upright, slipping towards their corners.
                let state = StackState::default();
                let coords = Coordinates::of(&stack, &regime);
                let (fast, _) = stack.accelerations_in(&coords, &regime, &state, 0.0, G);
                let (slow, _) = generic(&stack, &regime, &state.theta, &state.theta_dot, 0.0, G);
                assert_eq!(fast[0].is_nan(), slow[0].is_nan(), "{regime:?} μk = {mu_k}: {fast:?} vs {slow:?}");
                if slow[0].is_nan() {
                    singular += 1;
                } else {
                    regular += 1;
                }
            }
            assert!(singular > 0 && regular > 0, "{regime:?}: {singular} singular, {regular} regular");
        }
    }

    /// The shaft and belfry of [`stack`] seated on one another, by hand: 180 t;
    /// the centre at (150 · 6 + 30 · (12 + 2.25)) / 180 = 7.375 m; about a
    /// corner of the shaft's base, `J_1 + m_1 (2² + 6²) + J_2 + m_2 (2² +
    /// 14.25²)` with `J = m (B² + H²) / 12`: 2,000,000 + 6,000,000 +
    /// 76,225 + 6,211,875 = 14,288,100 kg·m². The belfry alone is its own block
    /// (`I_O = J + m (B² + H²) / 4`). A few roundings of numbers of order
    /// 1e7: 1e-14 relative.
    #[test]
    fn the_body_above_an_interface_by_hand() {
        let stack = stack(None);
        let body = stack.body_above(0);
        for (got, want) in [(body.mass, 1.8e5), (body.centre_height, 7.375), (body.inertia_corner, 14_288_100.0)] {
            assert!((got - want).abs() <= 1e-14 * want, "{got} vs {want}");
        }
        let belfry = stack.body_above(1);
        let want = stack.blocks()[1].inertia_corner();
        assert!((belfry.inertia_corner - want).abs() <= 1e-14 * want, "{} vs {want}", belfry.inertia_corner);
        assert_eq!((belfry.mass, belfry.centre_height), (3.0e4, 2.25));
        // The arms from a corner: sqrt(2² + 7.375²) = sqrt(58.390625) and sqrt(1.6² + 2.25²) = sqrt(7.6225).
        for (got, want) in [(body.arm, 7.641_375_857_788_963), (belfry.arm, 2.760_887_538_455_705)] {
            assert!((got - want).abs() <= 1e-14 * want, "{got} vs {want}");
        }
    }

    /// The bounds of `|θ̈_k|` and `|θ⃛_k|` where one interface rocks on a
    /// fixed base or a sticking building hold at every pose, rate and input
    /// (θ̈ from the written-out equations, θ⃛ from them on jets), for one, two
    /// and three blocks, every interface and corner; and the first is
    /// sharp: over 3,600 angles a full turn round, the largest `|θ̈_k|`
    /// comes within 1e-6 of it (Cauchy–Schwarz is met where the arm is
    /// normal to `(a_g, g_e)`, which the grid passes within 0.0009 rad: 1 −
    /// cos 0.0009 = 4e-7). 1e-12 relative: a few roundings of terms of the
    /// bound's size. Forgetting the half-width in the arm's length (the
    /// centre's height alone) fails.
    #[test]
    fn one_rocking_bounds_hold_and_are_reached() {
        let mut compared = 0;
        for building in [None, Some(Building::new(4.0e5, 0.5, 0.4, NormalForce::Dynamic).unwrap())] {
            for stack in stacks(building) {
                for k in 0..stack.len() {
                    for pivot in [Pivot::Negative, Pivot::Positive] {
                        let regime = StackRegime::REST.with(k, Interface::Rocking(pivot));
                        for (a_g, a_rate) in [(0.0f64, 0.0f64), (3.7, -40.0), (-6.2, 15.0)] {
                            for theta_dot in [0.0f64, 0.8, -2.5] {
                                let (bound, reach) = stack.one_rocking_acceleration_bound(k, G, a_g.abs());
                                let jerk = stack.one_rocking_jerk_bound(k, reach, a_rate.abs(), theta_dot.abs());
                                let mut largest = 0.0f64;
                                for i in 0..3600 {
                                    let theta = (i as f64 / 3600.0 - 0.5) * std::f64::consts::TAU;
                                    let arm = OneArm::of(&stack, k, pivot.sign(), theta, theta_dot);
                                    let (theta_ddot, _) = stack.one_rocking(k, &arm, None, a_g, G);
                                    let mut angles = [Jet::default(); MAX_BLOCKS];
                                    let mut rates = [Jet::default(); MAX_BLOCKS];
                                    (angles[k], rates[k]) = (Jet::new(theta, theta_dot), Jet::new(theta_dot, theta_ddot));
                                    let pose: Pose<Jet> = Pose::of(&stack, &regime, &angles, &rates);
                                    let (on_jets, _) = stack.one_rocking(k, &OneArm::in_pose(&stack, &pose, k), None, Jet::new(a_g, a_rate), Jet::from(G));
                                    assert!(theta_ddot.abs() <= bound * (1.0 + 1e-12), "θ̈ {theta_ddot} above {bound}");
                                    assert!(on_jets.d.abs() <= jerk * (1.0 + 1e-12), "θ⃛ {} above {jerk}", on_jets.d);
                                    largest = largest.max(theta_ddot.abs());
                                    compared += 1;
                                }
                                assert!(largest >= bound * (1.0 - 1e-6), "largest |θ̈| {largest} against the bound {bound}");
                            }
                        }
                    }
                }
            }
        }
        assert_eq!(compared, 2 * 6 * 2 * 9 * 3600);
    }

    /// A shaft, a belfry and a lantern on it (three blocks), or the shaft and
    /// belfry of [`stack`], or the shaft alone.
    fn stacks(building: Option<Building>) -> Vec<Stack> {
        let shaft = Block::solid(1, 4.0, 12.0, 1.5e5).unwrap();
        let belfry = Block::solid(2, 3.2, 4.5, 3.0e4).unwrap();
        let lantern = Block::solid(3, 1.2, 2.0, 2.0e3).unwrap();
        [vec![shaft], vec![shaft, belfry], vec![shaft, belfry, lantern]]
            .iter()
            .map(|blocks| Stack::new(blocks, building, G).unwrap())
            .collect()
    }

    /// One interface rocking, any of them, every other stuck, on either
    /// corner, on a fixed base and on a sticking or slipping building (both
    /// normal-force laws), for one, two and three blocks: the written-out
    /// equations of the body above it equal the generic assembly and solve,
    /// on numbers and on jets (values and time derivatives), to 1e-12 of the
    /// larger of 1 and the value, as for two rocking blocks: both are a few
    /// dozen roundings away from the exact values, and a wrong term (the
    /// smallest, the dynamic normal force's velocity-squared part, is above
    /// 1e-3 here) would fail.
    #[test]
    fn one_rocking_interface_written_out_equals_the_generic_solve() {
        let mut buildings = vec![None];
        for normal in [NormalForce::Constant, NormalForce::Dynamic] {
            buildings.push(Some(Building::new(4.0e5, 0.5, 0.4, normal).unwrap()));
        }
        let states = [(0.05, -0.3), (-0.12, 1.5), (0.01, 0.0), (-0.3, 0.9)];
        let mut compared = 0;
        for building in buildings {
            for stack in stacks(building) {
                for k in 0..stack.len() {
                    for pivot in [Pivot::Negative, Pivot::Positive] {
                        for slip in [
                            BuildingRegime::Stick,
                            BuildingRegime::Slip(SlipDirection::Positive),
                            BuildingRegime::Slip(SlipDirection::Negative),
                        ] {
                            let regime = StackRegime::REST.with(k, Interface::Rocking(pivot)).with_building(slip);
                            assert_eq!(stack.rocking_one(&regime), Some((k, pivot.sign())));
                            for &(theta, theta_dot) in &states {
                                let mut state = StackState::default();
                                (state.theta[k], state.theta_dot[k]) = (theta, theta_dot);
                                for a_g in [0.0, 3.7, -6.2] {
                                    for g_e in [G, G + 2.5] {
                                        let coords = Coordinates::of(&stack, &regime);
                                        let (fast, fast_u) = stack.accelerations_in(&coords, &regime, &state, a_g, g_e);
                                        let (slow, slow_u) = generic(&stack, &regime, &state.theta, &state.theta_dot, a_g, g_e);
                                        let jets = |x: &[f64; MAX_BLOCKS], dx: &[f64; MAX_BLOCKS]| -> [Jet; MAX_BLOCKS] {
                                            std::array::from_fn(|i| Jet::new(x[i], dx[i]))
                                        };
                                        let (theta_j, theta_dot_j) = (jets(&state.theta, &state.theta_dot), jets(&state.theta_dot, &slow));
                                        let (a_g_jet, g_e_jet) = (Jet::new(a_g, 25.0), Jet::from(g_e));
                                        let snap: Snapshot<Jet> = stack.snapshot_of(&regime, &theta_j, &theta_dot_j, a_g_jet, g_e_jet);
                                        let (jet, jet_u) = generic(&stack, &regime, &theta_j, &theta_dot_j, a_g_jet, g_e_jet);
                                        let mut pairs = vec![(fast[k], slow[k]), (fast_u, slow_u)];
                                        for (a, b) in [(snap.theta_ddot[k], jet[k]), (snap.slip_acc, jet_u)] {
                                            pairs.extend([(a.v, b.v), (a.d, b.d)]);
                                        }
                                        for (a, b) in pairs {
                                            assert!(
                                                (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1.0),
                                                "{} blocks {regime:?} {state:?} a_g={a_g} g_e={g_e}: {a} vs {b}",
                                                stack.len()
                                            );
                                        }
                                        compared += 1;
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
        // 3 bases × (1 + 2 + 3) interfaces × 2 corners × 3 building regimes × 4 states × 3 a_g × 2 g_e.
        assert_eq!(compared, 3 * 6 * 2 * 3 * 4 * 3 * 2);
    }

    /// Two rocking interfaces, or none, are not the written-out case.
    #[test]
    fn one_rocking_interface_is_only_one() {
        let stack = stack(None);
        let rocking = Interface::Rocking(Pivot::Positive);
        assert_eq!(stack.rocking_one(&StackRegime::REST), None);
        assert_eq!(stack.rocking_one(&StackRegime::REST.with(0, rocking).with(1, rocking)), None);
        assert_eq!(stack.rocking_one(&StackRegime::REST.with(1, rocking)), Some((1, 1.0)));
    }

    proptest::proptest! {
        /// Any two or three blocks (each no wider than the one below, masses
        /// a hundredfold apart either way), any one of them rocking, any pose
        /// and input, either corner, on a fixed base or a building slipping
        /// either way (both normal-force laws): the written-out equations
        /// equal the generic solve to 1e-12 of the value, as for two rocking
        /// blocks.
        #[test]
        fn any_one_rocking_interface_written_out_equals_the_generic_solve(
            widths in (0.5..5.0f64, 0.1..1.0f64, 0.1..1.0f64), heights in (1.0..20.0f64, 0.3..10.0f64, 0.3..5.0f64),
            masses in (1.0e3..1.0e5f64, 1.0e3..1.0e5f64, 1.0e2..1.0e5f64), three in proptest::bool::ANY, which in 0..3usize,
            theta in -1.2..1.2f64, theta_dot in -4.0..4.0f64, a_g in -20.0..20.0f64, corner in proptest::bool::ANY, base in 0..5usize,
        ) {
            let lower = Block::solid(1, widths.0, heights.0, masses.0).unwrap();
            let upper = Block::solid(2, widths.0 * widths.1, heights.1, masses.1).unwrap();
            let top = Block::solid(3, widths.0 * widths.1 * widths.2, heights.2, masses.2).unwrap();
            let blocks = if three { vec![lower, upper, top] } else { vec![lower, upper] };
            let k = which % blocks.len();
            let (building, slip) = base_of(base);
            let stack = Stack::new(&blocks, building, G).unwrap();
            let pivot = if corner { Pivot::Positive } else { Pivot::Negative };
            let regime = StackRegime::REST.with(k, Interface::Rocking(pivot)).with_building(slip);
            let mut state = StackState::default();
            (state.theta[k], state.theta_dot[k]) = (theta, theta_dot);
            let (fast, fast_u) = stack.accelerations_in(&Coordinates::of(&stack, &regime), &regime, &state, a_g, G);
            let (slow, slow_u) = generic(&stack, &regime, &state.theta, &state.theta_dot, a_g, G);
            for (a, b) in [(fast[k], slow[k]), (fast_u, slow_u)] {
                proptest::prop_assert!((a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1.0), "{regime:?} {state:?}: {a} vs {b}");
            }
        }
    }

    /// With the slip among the coordinates while the building sticks (`σ =
    /// 0`, as an impact's coordinates have it), the written-out equations of
    /// one rocking interface put `ü` first, as the generic solve does, and
    /// equal it (to 1e-12 of the value, as above).
    #[test]
    fn one_rocking_interface_written_out_takes_the_slip_of_a_sticking_building() {
        for normal in [NormalForce::Constant, NormalForce::Dynamic] {
            let stack = stack(Some(Building::new(4.0e5, 0.5, 0.4, normal).unwrap()));
            for k in 0..2 {
                let regime = StackRegime::REST.with(k, Interface::Rocking(Pivot::Positive));
                let coords = Coordinates::with_slip(&stack, &regime, true);
                let mut state = StackState::default();
                (state.theta[k], state.theta_dot[k]) = (0.05, 0.4);
                let (fast, fast_u) = stack.accelerations_in(&coords, &regime, &state, 2.0, G);
                let (slow, slow_u) = generic_in(&stack, &coords, &regime, &state.theta, &state.theta_dot, 2.0, G);
                assert!(slow_u.abs() > 1e-6, "{slow_u}");
                for (a, b) in [(fast[k], slow[k]), (fast_u, slow_u)] {
                    assert!((a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1.0), "{normal:?} k = {k}: {a} vs {b}");
                }
            }
        }
    }
}
