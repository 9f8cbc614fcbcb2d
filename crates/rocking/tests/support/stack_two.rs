//! The shaft and belfry of the stack tests, and the hand kinematics of a
//! two-block stack on a fixed base for the impact and run tests, written independently of the library's geometry: block 1 on its
//! corner `O_1 = (s_1 b_1, 0)` at `θ_1`, block 2 on the corner `O_2` of block
//! 1's top at `θ_2` relative to it; velocities by the rigid-body rule
//! `v(P) = ω (P − O)^⊥`, `(x, y)^⊥ = (y, −x)` for a clockwise `ω`.
//!
//! An impact's velocities from the balances of angular momentum that its
//! impulses leave alone: the impulses act at the new corner of the interface
//! that lands and at the corners kept by the others (the ground on block 1,
//! block 1 on block 2), so the clockwise angular momentum `L_{O_j}` of the
//! blocks from `j` up about the corner `O_j` of each interface `j` rocking
//! after the impact (the new one for the interface that lands) is the same
//! after as before. A seated interface adds no unknown and no balance. For a
//! block landing on a seated one (the belfry on a shaft that stays put) this
//! is Housner's `I_O θ̇⁺ = (I_O − 2 m b²) θ̇⁻`.
#![allow(dead_code)]

use rocking::stack::Block;

/// The shaft of the stack tests: 4 m × 20 m, 3.2e5 kg, solid.
pub fn shaft() -> Block {
    Block::solid(1, 4.0, 20.0, 3.2e5).expect("a valid shaft")
}

/// The belfry of the stack tests: 3 m × 6 m, 4e4 kg, solid.
pub fn belfry() -> Block {
    Block::solid(2, 3.0, 6.0, 4.0e4).expect("a valid belfry")
}

pub struct Two {
    pub m: [f64; 2],
    pub j: [f64; 2],
    pub g: [[f64; 2]; 2],
    pub o: [[f64; 2]; 2],
}

/// `R(φ) v`, clockwise.
pub fn rot(phi: f64, v: [f64; 2]) -> [f64; 2] {
    [v[0] * phi.cos() + v[1] * phi.sin(), -v[0] * phi.sin() + v[1] * phi.cos()]
}

fn add(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] + b[0], a[1] + b[1]]
}

fn scale(a: [f64; 2], k: f64) -> [f64; 2] {
    [a[0] * k, a[1] * k]
}

impl Two {
    pub fn new(lower: Block, upper: Block, s1: f64, theta1: f64, s2: f64, theta2: f64) -> Self {
        let (b1, h1) = (lower.width() / 2.0, lower.height());
        let (b2, h2) = (upper.width() / 2.0, upper.height());
        let o1 = [s1 * b1, 0.0];
        let g1 = add(o1, rot(theta1, [-s1 * b1, h1 / 2.0]));
        let o2 = add(o1, rot(theta1, [-s1 * b1 + s2 * b2, h1]));
        let g2 = add(o2, rot(theta1 + theta2, [-s2 * b2, h2 / 2.0]));
        Self {
            m: [lower.mass(), upper.mass()],
            j: [lower.inertia_centre(), upper.inertia_centre()],
            g: [g1, g2],
            o: [o1, o2],
        }
    }

    pub fn velocities(&self, w1: f64, w2: f64) -> [[f64; 2]; 2] {
        let perp = |p: [f64; 2], o: [f64; 2]| [p[1] - o[1], -(p[0] - o[0])];
        let v1 = scale(perp(self.g[0], self.o[0]), w1);
        let v2 = add(scale(perp(self.g[1], self.o[0]), w1), scale(perp(self.g[1], self.o[1]), w2));
        [v1, v2]
    }

    /// Clockwise angular momentum about `a` of the blocks from `from` up.
    pub fn angular_momentum(&self, a: [f64; 2], from: usize, w1: f64, w2: f64) -> f64 {
        let v = self.velocities(w1, w2);
        let omega = [w1, w1 + w2];
        (from..2)
            .map(|i| {
                let r = [self.g[i][0] - a[0], self.g[i][1] - a[1]];
                -(r[0] * v[i][1] - r[1] * v[i][0]) * self.m[i] + self.j[i] * omega[i]
            })
            .sum()
    }

    /// Kinetic energy.
    pub fn kinetic_energy(&self, w1: f64, w2: f64) -> f64 {
        let v = self.velocities(w1, w2);
        let omega = [w1, w1 + w2];
        (0..2)
            .map(|i| 0.5 * self.m[i] * (v[i][0].powi(2) + v[i][1].powi(2)) + 0.5 * self.j[i] * omega[i].powi(2))
            .sum()
    }
}

/// `(θ̇_1⁺, θ̇_2⁺)` of an impact: `before` with the corners before it and
/// velocities `(w1, w2)`, `after` with the corners after it, `rocking` the
/// interfaces rocking after it (a seated one has `θ̇⁺ = 0`). One balance per
/// rocking interface, solved by Cramer's rule.
pub fn balance(after: &Two, before: &Two, rocking: [bool; 2], w1: f64, w2: f64) -> (f64, f64) {
    let l = |j: usize| before.angular_momentum(after.o[j], j, w1, w2);
    let row = |j: usize| [after.angular_momentum(after.o[j], j, 1.0, 0.0), after.angular_momentum(after.o[j], j, 0.0, 1.0)];
    match rocking {
        [true, true] => {
            let (r1, r2) = (row(0), row(1));
            let (l1, l2) = (l(0), l(1));
            let det = r1[0] * r2[1] - r1[1] * r2[0];
            ((l1 * r2[1] - r1[1] * l2) / det, (r1[0] * l2 - l1 * r2[0]) / det)
        }
        [true, false] => (l(0) / row(0)[0], 0.0),
        [false, true] => (0.0, l(1) / row(1)[1]),
        [false, false] => (0.0, 0.0),
    }
}
