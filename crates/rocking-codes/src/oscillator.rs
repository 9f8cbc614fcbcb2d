//! The exact response of a damped linear oscillator to a piecewise-linear
//! ground acceleration (Nigam & Jennings 1969).
//!
//! On a sample interval of length Δt the forcing of `ẍ + 2ξωẋ + ω²x = −a_g(t)`
//! is linear, so the solution is a linear particular solution plus the free
//! damped motion; the state at the interval's end is a fixed linear map of the
//! state and the two samples at its start:
//!
//! ```text
//! [x, ẋ](t + Δt) = A [x, ẋ](t) + B [a_g(t), a_g(t + Δt)]
//! ```
//!
//! Nigam, N. C., Jennings, P. C. (1969). Calculation of response spectra from
//! strong-motion earthquake records. Bull. Seismol. Soc. Am. 59(2), 909–922.

/// The exact one-interval map of the oscillator `ẍ + 2ξωẋ + ω²x = −a_g(t)`, `a_g`
/// linear on the interval (Nigam & Jennings 1969, eqs. 2.3–2.6, derived here as a
/// particular solution plus the free motion).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NigamJennings {
    /// The free motion's map: `[x, ẋ] ← a [x, ẋ]`.
    a: [[f64; 2]; 2],
    /// The forcing's: `+ b [a_g(t), a_g(t + Δt)]`.
    b: [[f64; 2]; 2],
}

impl NigamJennings {
    /// The map over an interval `dt` (s, > 0) of an oscillator of circular frequency
    /// `omega` (rad/s, > 0) and damping ratio `xi` (fraction of critical, [0, 1)).
    pub fn new(omega: f64, xi: f64, dt: f64) -> Self {
        let root = (1.0 - xi * xi).sqrt();
        let omega_d = omega * root;
        let e = libm::exp(-xi * omega * dt);
        let (s, c) = (libm::sin(omega_d * dt), libm::cos(omega_d * dt));
        // Free motion x = e^{−ξωt}(C1 cos ωd t + C2 sin ωd t) from (x0, v0).
        let a = [
            [e * (c + xi * omega / omega_d * s), e * s / omega_d],
            [-e * omega * omega / omega_d * s, e * (c - xi * omega / omega_d * s)],
        ];
        // Particular solution x_p = p0 + p1 τ of the forcing −(a0 + (a1 − a0) τ/Δt):
        // p1 = −(a1 − a0)/(ω² Δt), p0 = −a0/ω² − 2ξ p1/ω; each linear in (a0, a1).
        let w2 = omega * omega;
        let p1 = [1.0 / (w2 * dt), -1.0 / (w2 * dt)];
        let p0 = [-1.0 / w2 - 2.0 * xi / omega * p1[0], -2.0 * xi / omega * p1[1]];
        // x(Δt) = A11 (x0 − p0) + A12 (v0 − p1) + p0 + p1 Δt; v(Δt) = A21 (x0 − p0) + A22 (v0 − p1) + p1.
        let mut b = [[0.0; 2]; 2];
        for k in 0..2 {
            b[0][k] = (1.0 - a[0][0]) * p0[k] + (dt - a[0][1]) * p1[k];
            b[1][k] = -a[1][0] * p0[k] + (1.0 - a[1][1]) * p1[k];
        }
        Self { a, b }
    }

    /// The state `(x, ẋ)` (m, m/s) at the interval's end from the state at its start
    /// and the ground accelerations `a0`, `a1` (m/s²) at its ends.
    #[inline]
    pub fn step(&self, x: f64, v: f64, a0: f64, a1: f64) -> (f64, f64) {
        let (a, b) = (&self.a, &self.b);
        (
            a[0][0] * x + a[0][1] * v + b[0][0] * a0 + b[0][1] * a1,
            a[1][0] * x + a[1][1] * v + b[1][0] * a0 + b[1][1] * a1,
        )
    }
}
