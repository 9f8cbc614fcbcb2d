//! First-order forward-mode differentiation: a value with its time derivative.
//!
//! Event location and the peaks a run reports need the time derivative of
//! quantities that are not integrated (the friction demand, the top
//! acceleration, the pivot reactions). Each equation of the model is written
//! once, generic over [`Real`], and evaluated either on `f64` (the right-hand
//! side, monomorphised to plain arithmetic) or on [`Jet`] (value and exact
//! derivative along the solution, by the chain rule). Written here rather than
//! taken from a crate: only the first derivative of a handful of operations is
//! needed, and it must use this crate's own `sin_cos` kernel (`trig`); the
//! dual-number crates bring generic linear algebra with them.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// The arithmetic the equations of the model use. Public so that the
/// stack's public functions may be generic over it, in a private module so
/// that nothing outside the crate implements it (`f64` and [`Jet`] only).
pub trait Real:
    Copy
    + From<f64>
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + Add<f64, Output = Self>
    + Sub<f64, Output = Self>
    + Mul<f64, Output = Self>
{
    /// `(sin x, cos x)`.
    fn sin_cos(self) -> (Self, Self);
    /// The value, without its derivative.
    fn value(self) -> f64;
    /// Whether it is exactly zero (its derivative too).
    fn is_zero(self) -> bool;
}

impl Real for f64 {
    #[inline(always)]
    fn sin_cos(self) -> (f64, f64) {
        crate::trig::sin_cos(self)
    }
    #[inline(always)]
    fn value(self) -> f64 {
        self
    }
    #[inline(always)]
    fn is_zero(self) -> bool {
        self == 0.0
    }
}

/// A value `v` and its time derivative `d`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Jet {
    pub(crate) v: f64,
    pub(crate) d: f64,
}

impl Jet {
    #[inline(always)]
    pub(crate) fn new(v: f64, d: f64) -> Self {
        Self { v, d }
    }
}

impl From<f64> for Jet {
    #[inline(always)]
    fn from(v: f64) -> Self {
        Self { v, d: 0.0 }
    }
}

impl Add for Jet {
    type Output = Jet;
    #[inline(always)]
    fn add(self, o: Jet) -> Jet {
        Jet::new(self.v + o.v, self.d + o.d)
    }
}
impl Sub for Jet {
    type Output = Jet;
    #[inline(always)]
    fn sub(self, o: Jet) -> Jet {
        Jet::new(self.v - o.v, self.d - o.d)
    }
}
impl Mul for Jet {
    type Output = Jet;
    #[inline(always)]
    fn mul(self, o: Jet) -> Jet {
        Jet::new(self.v * o.v, self.d * o.v + self.v * o.d)
    }
}
impl Div for Jet {
    type Output = Jet;
    #[inline(always)]
    fn div(self, o: Jet) -> Jet {
        let q = self.v / o.v;
        Jet::new(q, (self.d - q * o.d) / o.v)
    }
}
impl Neg for Jet {
    type Output = Jet;
    #[inline(always)]
    fn neg(self) -> Jet {
        Jet::new(-self.v, -self.d)
    }
}
impl Add<f64> for Jet {
    type Output = Jet;
    #[inline(always)]
    fn add(self, o: f64) -> Jet {
        Jet::new(self.v + o, self.d)
    }
}
impl Sub<f64> for Jet {
    type Output = Jet;
    #[inline(always)]
    fn sub(self, o: f64) -> Jet {
        Jet::new(self.v - o, self.d)
    }
}
impl Mul<f64> for Jet {
    type Output = Jet;
    #[inline(always)]
    fn mul(self, o: f64) -> Jet {
        Jet::new(self.v * o, self.d * o)
    }
}

impl Real for Jet {
    #[inline(always)]
    fn sin_cos(self) -> (Jet, Jet) {
        let (s, c) = crate::trig::sin_cos(self.v);
        (Jet::new(s, c * self.d), Jet::new(c, -s * self.d))
    }
    #[inline(always)]
    fn value(self) -> f64 {
        self.v
    }
    #[inline(always)]
    fn is_zero(self) -> bool {
        self.v == 0.0 && self.d == 0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// d/dt [sin(t²) / (1 + t)] at t = 0.7, against the derivative worked by hand:
    /// `(2t cos t² (1 + t) − sin t²) / (1 + t)²`. Both sides are a few roundings
    /// of the same exact value: 1e-14 relative.
    #[test]
    fn chain_rule_through_sin_and_division() {
        let t = Jet::new(0.7, 1.0);
        let (s, _) = Real::sin_cos(t * t);
        let q = s / (t + 1.0);
        let x: f64 = 0.7;
        let exact = (2.0 * x * (x * x).cos() * (1.0 + x) - (x * x).sin()) / (1.0 + x).powi(2);
        assert_relative_eq!(q.v, (x * x).sin() / (1.0 + x), max_relative = 1e-14);
        assert_relative_eq!(q.d, exact, max_relative = 1e-14);
    }
}
