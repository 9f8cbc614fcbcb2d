//! Positions of the stack as sums of rotated vectors, and their Jacobians.
//!
//! With `R(φ) = [[cos φ, sin φ], [−sin φ, cos φ]]` (a clockwise rotation by
//! `φ`, so that a positive `θ` leans a block towards `+x`), and positions
//! measured from the pivot line's place on the building `(X_p, 0)`:
//!
//! ```text
//! C_0 = 0,   H_0 = 0,   φ_0 = 0                                (the springing level)
//! O_k = C_{k−1} + R(φ_{k−1}) (s_k B_k/2, H_{k−1})             (the corner block k rocks on)
//! C_k = O_k + R(φ_k) (−s_k B_k/2, 0)                           (block k's base centre)
//! G_k = C_k + R(φ_k) (0, H_k/2)                                (its centre of mass)
//! ```
//!
//! A stuck interface has `θ_k = 0`, so `φ_k = φ_{k−1}` and its corner drops
//! out: `C_k = C_{k−1} + R(φ_{k−1}) (0, H_{k−1})`.
//!
//! Derivatives. `∂R(φ)v/∂φ` is the vector `w = R(φ)v` turned a quarter
//! clockwise, `J(w) = (w_y, −w_x)`, and `∂²R(φ)v/∂φ² = −w`. Every point `P` of
//! block `i` is `X_p e_x` plus vectors of the frames `1 … i`; a rocking `θ_k`
//! (`k ≤ i`) turns all frames from `k` up about the corner `O_k`, so
//!
//! ```text
//! ∂P/∂θ_k = J(P − O_k),   ∂P/∂u = e_x,   ∂φ_i/∂θ_k = 1 (k ≤ i)
//! P̈ = Ẍ_p e_x + Σ_k θ̈_k J(P − O_k) − Σ_j φ̇_j² W_j(P)
//! ```
//!
//! with `W_j(P)` the part of `P`'s sum in frame `j`. Since `W_j(P) = (P − O_j) −
//! (P − O_{j+1})`, the last sum is `−Σ_k (φ̇_k² − φ̇_{k−1}²) (P − O_k)` over the
//! rocking interfaces `k ≤ i` (a stuck one has `φ̇_k = φ̇_{k−1}` and adds nothing).

use super::{Stack, StackRegime, StackState, MAX_BLOCKS};
use crate::jet::Real;
use crate::regime::BuildingRegime;
use arrayvec::ArrayVec;

/// The most coordinates a regime has: the slip and one per interface.
pub const MAX_COORDINATES: usize = MAX_BLOCKS + 1;

/// A plane vector `(x, y)`, of plain numbers or of [`Jet`](crate::jet::Jet)s
/// (values with their time derivatives).
pub type Vec2<T = f64> = [T; 2];

/// `R(φ) v`, given `(sin φ, cos φ)`.
#[inline(always)]
pub(crate) fn rotate<T: Real>((sin, cos): (T, T), v: Vec2<T>) -> Vec2<T> {
    [v[0] * cos + v[1] * sin, -v[0] * sin + v[1] * cos]
}

/// `J(w) = (w_y, −w_x)`: the velocity of the point `w` away from a centre of
/// rotation per unit of clockwise angular velocity.
#[inline(always)]
pub(crate) fn turn<T: Real>(w: Vec2<T>) -> Vec2<T> {
    [w[1], -w[0]]
}

/// `a × b = a_x b_y − a_y b_x` (counter-clockwise positive).
#[inline(always)]
pub(crate) fn cross<T: Real>(a: Vec2<T>, b: Vec2<T>) -> T {
    a[0] * b[1] - a[1] * b[0]
}

#[inline(always)]
pub(crate) fn dot<T: Real>(a: Vec2<T>, b: Vec2<T>) -> T {
    a[0] * b[0] + a[1] * b[1]
}

#[inline(always)]
pub(crate) fn sub<T: Real>(a: Vec2<T>, b: Vec2<T>) -> Vec2<T> {
    [a[0] - b[0], a[1] - b[1]]
}

#[inline(always)]
pub(crate) fn add<T: Real>(a: Vec2<T>, b: Vec2<T>) -> Vec2<T> {
    [a[0] + b[0], a[1] + b[1]]
}

#[inline(always)]
pub(crate) fn scale<T: Real>(a: Vec2<T>, k: T) -> Vec2<T> {
    [a[0] * k, a[1] * k]
}

/// A number as a vector's component: `T::from(x)`.
#[inline(always)]
pub(crate) fn real<T: Real>(x: f64) -> T {
    T::from(x)
}

/// One generalised coordinate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Coordinate {
    /// The building's slip `u`.
    Slip,
    /// The rotation `θ_k` of the rocking interface `k` (0-based index).
    Theta(usize),
}

/// The coordinates `q` of a regime: `u` when the building slips, then `θ_k`
/// of every rocking interface, bottom up.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Coordinates {
    list: ArrayVec<Coordinate, MAX_COORDINATES>,
    /// How many of them (the first ones) move block `i`.
    moving: [usize; MAX_BLOCKS],
}

impl Coordinates {
    /// The coordinates of `regime`.
    pub fn of(stack: &Stack, regime: &StackRegime) -> Self {
        let slip = stack.building.is_some() && matches!(regime.building, BuildingRegime::Slip(_));
        Self::with_slip(stack, regime, slip)
    }

    /// The rocking interfaces of `regime`, with the slip or without it.
    #[inline]
    pub fn with_slip(stack: &Stack, regime: &StackRegime, slip: bool) -> Self {
        let mut list = ArrayVec::new();
        let mut moving = [0; MAX_BLOCKS];
        if slip {
            list.push(Coordinate::Slip);
        }
        for k in 0..stack.len() {
            if regime.interfaces[k].pivot().is_some() {
                list.push(Coordinate::Theta(k));
            }
            moving[k] = list.len();
        }
        Self { list, moving }
    }

    /// The coordinates in order.
    pub fn list(&self) -> &[Coordinate] {
        &self.list
    }
    /// How many.
    pub fn len(&self) -> usize {
        self.list.len()
    }
    /// No coordinate: everything moves with the ground.
    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }
    /// How many of them move block `i`: the first ones, the slip and the
    /// `θ_k` with `k ≤ i`. The partials of the others on block `i` vanish.
    pub(crate) fn moving(&self, i: usize) -> usize {
        self.moving[i]
    }
    /// The index of the slip, if it is one of them: 0, the slip comes first.
    pub(crate) fn slip(&self) -> Option<usize> {
        (self.list.first() == Some(&Coordinate::Slip)).then_some(0)
    }
    /// The index of `c`, if it is one of them.
    pub fn index(&self, c: Coordinate) -> Option<usize> {
        self.list.iter().position(|&x| x == c)
    }
    /// The velocities `q̇` of these coordinates in `state`.
    pub fn velocities(&self, state: &StackState) -> ArrayVec<f64, MAX_COORDINATES> {
        self.list
            .iter()
            .map(|c| match *c {
                Coordinate::Slip => state.slip_vel,
                Coordinate::Theta(k) => state.theta_dot[k],
            })
            .collect()
    }
}

/// Where every block is at one instant of one regime, and how fast it turns:
/// of plain numbers, or of [`Jet`](crate::jet::Jet)s that carry each
/// position's time derivative along the motion; of a stack of `N` blocks at
/// most (a run's own are sized to its stack, so that they copy no more).
#[derive(Debug, Clone)]
pub struct Pose<T = f64, const N: usize = MAX_BLOCKS> {
    n: usize,
    /// `s_k` of the rocking interfaces, `None` for the stuck ones.
    pub(crate) pivots: [Option<f64>; N],
    /// Absolute rotation `φ_k`.
    pub(crate) phi: [T; N],
    /// `φ̇_k`.
    pub(crate) phi_dot: [T; N],
    /// `(sin φ_{k−1}, cos φ_{k−1})`: the rotation of the surface block `k`
    /// stands on.
    support: [(T, T); N],
    /// `C_k`.
    pub(crate) base: [Vec2<T>; N],
    /// `G_k`.
    pub(crate) centre: [Vec2<T>; N],
    /// `O_k` (a rocking interface's only).
    pub(crate) corner: [Vec2<T>; N],
}

impl Pose {
    /// The pose of `stack` in `regime` and `state` (a stuck interface's `θ_k`
    /// and `θ̇_k` are taken as 0 whatever the state holds).
    #[inline(always)]
    pub fn new(stack: &Stack, regime: &StackRegime, state: &StackState) -> Self {
        Self::of(stack, regime, &state.theta, &state.theta_dot)
    }

    /// `G_k` relative to `(X_p, 0)` (block index `k` 0-based).
    pub fn centre(&self, k: usize) -> Vec2 {
        self.centre[k]
    }
    /// `C_k` relative to `(X_p, 0)`.
    pub fn base(&self, k: usize) -> Vec2 {
        self.base[k]
    }
    /// `φ_k`.
    pub fn phi(&self, k: usize) -> f64 {
        self.phi[k]
    }

    /// The velocity of a point `p` of block `i` relative to the ground:
    /// `u̇ e_x + Σ_k θ̇_k J(P − O_k)`.
    pub fn point_velocity(&self, i: usize, p: Vec2, state: &StackState) -> Vec2 {
        let mut v = [state.slip_vel, 0.0];
        for k in 0..=i {
            if self.pivots[k].is_some() {
                v = add(v, scale(turn(sub(p, self.corner[k])), state.theta_dot[k]));
            }
        }
        v
    }
}

impl<T: Real, const N: usize> Pose<T, N> {
    /// The pose at the rotations `θ_k` and their rates `θ̇_k` (of the rocking
    /// interfaces; a stuck interface's are taken as 0), given for every
    /// block; `stack` has at most `N` blocks.
    #[inline(always)]
    pub(crate) fn of(stack: &Stack, regime: &StackRegime, theta: &[T], theta_dot: &[T]) -> Self {
        let (zero, one) = (real::<T>(0.0), real::<T>(1.0));
        let n = stack.len();
        debug_assert!(n <= N, "a pose of {N} blocks at most for a stack of {n}");
        let mut pose = Self {
            n,
            pivots: [None; N],
            phi: [zero; N],
            phi_dot: [zero; N],
            support: [(zero, one); N],
            base: [[zero; 2]; N],
            centre: [[zero; 2]; N],
            corner: [[zero; 2]; N],
        };
        let (mut phi_below, mut phi_dot_below) = (zero, zero);
        let mut rot_below = (zero, one);
        let mut base_below = [zero, zero];
        let mut height_below = 0.0;
        for (k, block) in stack.blocks.iter().enumerate() {
            pose.support[k] = rot_below;
            let (phi, phi_dot, rot, base) = match regime.interfaces[k].pivot() {
                Some(p) => {
                    let s = p.sign();
                    pose.pivots[k] = Some(s);
                    let phi = phi_below + theta[k];
                    let rot = phi.sin_cos();
                    let corner = add(base_below, rotate(rot_below, [real(s * block.width / 2.0), real(height_below)]));
                    pose.corner[k] = corner;
                    (
                        phi,
                        phi_dot_below + theta_dot[k],
                        rot,
                        add(corner, rotate(rot, [real(-s * block.width / 2.0), zero])),
                    )
                }
                None => (
                    phi_below,
                    phi_dot_below,
                    rot_below,
                    add(base_below, rotate(rot_below, [zero, real(height_below)])),
                ),
            };
            pose.phi[k] = phi;
            pose.phi_dot[k] = phi_dot;
            pose.base[k] = base;
            pose.centre[k] = add(base, rotate(rot, [zero, real(block.height / 2.0)]));
            (phi_below, phi_dot_below, rot_below, base_below, height_below) = (phi, phi_dot, rot, base, block.height);
        }
        pose
    }

    /// The number of blocks.
    pub fn len(&self) -> usize {
        self.n
    }
    /// Never true.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// The unit normal `R(φ_{k−1}) e_y` of the surface block `k` stands on.
    pub(crate) fn normal(&self, k: usize) -> Vec2<T> {
        rotate(self.support[k], [real(0.0), real(1.0)])
    }
    /// The unit tangent `R(φ_{k−1}) e_x` of that surface.
    pub(crate) fn tangent(&self, k: usize) -> Vec2<T> {
        rotate(self.support[k], [real(1.0), real(0.0)])
    }

    /// `∂P/∂q_c` for a point `p` of block `i`.
    #[inline]
    pub(crate) fn point_jacobian(&self, i: usize, p: Vec2<T>, c: Coordinate) -> Vec2<T> {
        match c {
            Coordinate::Slip => [real(1.0), real(0.0)],
            Coordinate::Theta(k) if k <= i => turn(sub(p, self.corner[k])),
            Coordinate::Theta(_) => [real(0.0), real(0.0)],
        }
    }

    /// `∂φ_i/∂q_c`.
    #[inline]
    pub(crate) fn rotation_jacobian(&self, i: usize, c: Coordinate) -> f64 {
        match c {
            Coordinate::Theta(k) if k <= i => 1.0,
            _ => 0.0,
        }
    }

    /// The velocity-squared part of `P̈` for a point `p` of block `i`:
    /// `−Σ_k (φ̇_k² − φ̇_{k−1}²) (P − O_k)`.
    #[inline]
    pub(crate) fn point_quadratic(&self, i: usize, p: Vec2<T>) -> Vec2<T> {
        let mut acc = [real(0.0), real(0.0)];
        let mut below = real(0.0);
        for k in 0..=i {
            let now = self.phi_dot[k] * self.phi_dot[k];
            if self.pivots[k].is_some() {
                acc = sub(acc, scale(sub(p, self.corner[k]), now - below));
            }
            below = now;
        }
        acc
    }
}
