//! Dormand–Prince 8(5,3) with Hairer's 7th-order dense output.
//!
//! Hand-written rather than taken from a crate: the event handling of this
//! project needs (a) steps that land exactly on given instants (the kinks of a
//! recorded accelerogram), (b) a dense output that is built only when an event
//! or an output sample falls in the step (three extra stages, so it is lazy),
//! and (c) restarts at every impact without reallocating. The error norm and
//! step-size control follow Hairer's `DOP853` and SciPy's `DOP853` so that
//! results are comparable step for step with what a Python user runs.
//!
//! The state is a fixed-size array: no allocation in the inner loop.

// Component loops index several arrays at once; iterators would hide the formulas.
#![allow(clippy::needless_range_loop)]

use super::dop853_tableau::{A, C, D, E3, E5};

/// Number of stages of the 8(5,3) pair.
const STAGES: usize = 12;
/// Safety factor, minimum and maximum step growth of the controller.
const SAFETY: f64 = 0.9;
const MIN_FACTOR: f64 = 0.2;
const MAX_FACTOR: f64 = 10.0;

/// Why a step could not be taken.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum StepFailure {
    /// The step size fell below the resolution of `t` (a singular or stiff right-hand side).
    StepSizeTooSmall { time: f64 },
    /// The right-hand side returned a non-finite value.
    NonFinite { time: f64 },
}

/// Polynomial of the last accepted step, valid on `[t_old, t_new]`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct DenseOutput<const N: usize> {
    pub(crate) t_old: f64,
    pub(crate) h: f64,
    pub(crate) y_old: [f64; N],
    /// `F[0..7]` of Hairer's continuous extension, highest power last.
    pub(crate) f: [[f64; N]; 7],
}

impl<const N: usize> DenseOutput<N> {
    /// The same polynomial over `(θ, θ̇, u, u̇)`, the missing components zero.
    pub(crate) fn widen(&self) -> DenseOutput<4> {
        let pad = |v: &[f64; N]| -> [f64; 4] { std::array::from_fn(|i| if i < N { v[i] } else { 0.0 }) };
        DenseOutput {
            t_old: self.t_old,
            h: self.h,
            y_old: pad(&self.y_old),
            f: std::array::from_fn(|r| pad(&self.f[r])),
        }
    }

    /// The interpolated state at `t` (meant for `t` within the step).
    #[inline]
    pub(crate) fn state(&self, t: f64) -> [f64; N] {
        let x = (t - self.t_old) / self.h;
        let mut y = [0.0; N];
        // Horner-like nesting of Hairer's contd8: alternating factors x and (1 - x).
        for (i, row) in self.f.iter().rev().enumerate() {
            let factor = if i % 2 == 0 { x } else { 1.0 - x };
            for j in 0..N {
                y[j] = (y[j] + row[j]) * factor;
            }
        }
        for j in 0..N {
            y[j] += self.y_old[j];
        }
        y
    }
}

impl<const N: usize> DenseOutput<N> {
    /// The interpolated state at `t` and its time derivative (the derivative of
    /// the same polynomial, by the product rule through the nesting of `state`).
    #[inline]
    pub(crate) fn state_and_rate(&self, t: f64) -> ([f64; N], [f64; N]) {
        let x = (t - self.t_old) / self.h;
        let mut y = [0.0; N];
        let mut dy = [0.0; N];
        for (i, row) in self.f.iter().rev().enumerate() {
            let (factor, slope) = if i % 2 == 0 { (x, 1.0) } else { (1.0 - x, -1.0) };
            for j in 0..N {
                let inner = y[j] + row[j];
                dy[j] = dy[j] * factor + inner * slope;
                y[j] = inner * factor;
            }
        }
        for j in 0..N {
            y[j] += self.y_old[j];
            dy[j] /= self.h;
        }
        (y, dy)
    }
}

/// The stepper: state of the integration at the end of the last accepted step.
#[derive(Debug, Clone)]
pub(crate) struct Dop853<const N: usize> {
    rtol: f64,
    atol: f64,
    /// Step size to try next (s).
    h: f64,
    /// Smallest step (s) allowed anywhere in the run: ten units in the last
    /// place of the end time (set by `restart`). Below it the steps could not
    /// be told apart where the run ends, and near `t = 0`, where the spacing
    /// of floats is far finer, a tolerance out of reach would otherwise creep
    /// forward by steps of 1e-30 s for ever instead of failing.
    min_step_floor: f64,
    /// Start of the last accepted step.
    pub(crate) t_old: f64,
    pub(crate) y_old: [f64; N],
    /// End of the last accepted step (the current point).
    pub(crate) t: f64,
    pub(crate) y: [f64; N],
    /// Right-hand side at the current point.
    pub(crate) f: [f64; N],
    /// Stages of the last accepted step; index 12 is `f` at its end, 13..15 the dense stages.
    k: [[f64; N]; 16],
    dense: Option<DenseOutput<N>>,
    /// Number of right-hand side evaluations so far by the stepping itself (the
    /// dense output's extra stages are not counted: they depend on what is observed).
    pub(crate) evaluations: u64,
}

impl<const N: usize> Dop853<N> {
    pub(crate) fn new(rtol: f64, atol: f64) -> Self {
        Self {
            rtol,
            atol,
            h: 0.0,
            min_step_floor: 0.0,
            t_old: 0.0,
            y_old: [0.0; N],
            t: 0.0,
            y: [0.0; N],
            f: [0.0; N],
            k: [[0.0; N]; 16],
            dense: None,
            evaluations: 0,
        }
    }

    /// The right-hand side at the start of the last accepted step (its first stage).
    pub(crate) fn f_old(&self) -> [f64; N] {
        self.k[0]
    }

    /// Starts (or restarts, after an event) at `(t, y)`. The previous step size is
    /// kept as the first guess; on the very first start one is estimated.
    pub(crate) fn restart(&mut self, rhs: &mut impl FnMut(f64, &[f64; N]) -> [f64; N], t: f64, y: [f64; N], t_bound: f64) {
        let f = rhs(t, &y);
        self.evaluations += 1;
        self.restart_with(rhs, t, y, f, t_bound);
    }

    /// [`Self::restart`] with the right-hand side at `(t, y)` already known
    /// (`rhs` is called only to estimate a first step).
    pub(crate) fn restart_with(&mut self, rhs: &mut impl FnMut(f64, &[f64; N]) -> [f64; N], t: f64, y: [f64; N], f: [f64; N], t_bound: f64) {
        self.t = t;
        self.y = y;
        self.t_old = t;
        self.y_old = y;
        self.f = f;
        self.dense = None;
        self.min_step_floor = 10.0 * ulp(t_bound.abs());
        if self.h <= 0.0 || !self.h.is_finite() {
            self.h = self.initial_step(rhs, t_bound);
        }
    }

    /// Hairer, Nørsett & Wanner, Sec. II.4: a first step from the size of `y`, `f` and `f'`.
    fn initial_step(&mut self, rhs: &mut impl FnMut(f64, &[f64; N]) -> [f64; N], t_bound: f64) -> f64 {
        let interval = t_bound - self.t;
        if interval <= 0.0 {
            return 0.0;
        }
        let scale: [f64; N] = std::array::from_fn(|j| self.atol + self.y[j].abs() * self.rtol);
        let d0 = rms(&std::array::from_fn::<f64, N, _>(|j| self.y[j] / scale[j]));
        let d1 = rms(&std::array::from_fn::<f64, N, _>(|j| self.f[j] / scale[j]));
        let h0 = if d0 < 1e-5 || d1 < 1e-5 { 1e-6 } else { 0.01 * d0 / d1 }.min(interval);
        let y1: [f64; N] = std::array::from_fn(|j| self.y[j] + h0 * self.f[j]);
        let f1 = rhs(self.t + h0, &y1);
        self.evaluations += 1;
        let d2 = rms(&std::array::from_fn::<f64, N, _>(|j| (f1[j] - self.f[j]) / scale[j])) / h0;
        let h1 = if d1 <= 1e-15 && d2 <= 1e-15 {
            (h0 * 1e-3).max(1e-6)
        } else {
            libm::pow(0.01 / d1.max(d2), 1.0 / 8.0)
        };
        (100.0 * h0).min(h1).min(interval)
    }

    /// Takes one accepted step towards `t_bound`, landing exactly on it when it is
    /// within reach. Rejected attempts are retried with a smaller step.
    pub(crate) fn step(&mut self, rhs: &mut impl FnMut(f64, &[f64; N]) -> [f64; N], t_bound: f64) -> Result<(), StepFailure> {
        let t = self.t;
        // Ten units in the last place of t: below that, t + h cannot be told
        // from t; and never below the floor set by the end of the run.
        let min_step = (10.0 * ulp(t.abs())).max(self.min_step_floor);
        let mut rejected = false;
        loop {
            // Only a first attempt is lifted to the minimum: a rejected step
            // that shrank below it is a failure (lifting it back made every
            // rejection retry the same step for ever).
            if rejected && self.h < min_step {
                return Err(StepFailure::StepSizeTooSmall { time: t });
            }
            let h_try = self.h.max(min_step);
            let mut h = h_try;
            let mut t_new = t + h;
            let truncated = t_new >= t_bound || t_bound - t_new < min_step;
            if truncated {
                t_new = t_bound;
                h = t_bound - t;
            }
            // A step that lands on `t_bound` (a kink of the input, where the
            // caller must stop) is taken however short: its length is the
            // input's, not one the error control chose. Two samples of a
            // record 1e-15 s apart made a piece shorter than ten ulps of the
            // end time, and the run failed there.
            if h <= 0.0 || (h < min_step && !truncated) {
                return Err(StepFailure::StepSizeTooSmall { time: t });
            }
            self.k[0] = self.f;
            // Stage by stage with constant indices, so the compiler drops the zero
            // entries of the tableau.
            macro_rules! stages {
                ($($s:literal)*) => {$(
                    let ys = combine::<N, $s>(&self.y, &self.k, h);
                    self.k[$s] = rhs(t + C[$s] * h, &ys);
                )*};
            }
            stages!(1 2 3 4 5 6 7 8 9 10 11);
            // Row 12 of the extended tableau holds the weights B.
            let y_new = combine::<N, 12>(&self.y, &self.k, h);
            let f_new = rhs(t_new, &y_new);
            self.evaluations += STAGES as u64;
            self.k[STAGES] = f_new;
            if !(y_new.iter().all(|v| v.is_finite()) && f_new.iter().all(|v| v.is_finite())) {
                if h <= min_step * 2.0 {
                    return Err(StepFailure::NonFinite { time: t });
                }
                // Down to the minimum at most: the last try there tells a
                // right-hand side that is non-finite at once from a step too long.
                self.h = (h * MIN_FACTOR).max(min_step);
                rejected = true;
                continue;
            }
            let err = self.error_norm(h, &y_new);
            if err < 1.0 {
                let mut factor = if err == 0.0 {
                    MAX_FACTOR
                } else {
                    (SAFETY * error_factor(err)).min(MAX_FACTOR)
                };
                if rejected {
                    factor = factor.min(1.0);
                }
                // A step cut short to land on t_bound does not shrink the next one.
                self.h = if truncated { (h * factor).max(h_try) } else { h * factor };
                self.t_old = t;
                self.y_old = self.y;
                self.t = t_new;
                self.y = y_new;
                self.f = f_new;
                self.dense = None;
                return Ok(());
            }
            self.h = h * (SAFETY * error_factor(err)).max(MIN_FACTOR);
            rejected = true;
        }
    }

    /// Hairer's combined 5th/3rd-order error estimate, scaled by `atol + rtol |y|`.
    fn error_norm(&self, h: f64, y_new: &[f64; N]) -> f64 {
        let mut e5 = [0.0; N];
        let mut e3 = [0.0; N];
        // Constant indices: the zero weights drop out at compile time.
        macro_rules! accumulate {
            ($($s:literal)*) => {$(
                for j in 0..N {
                    if E5[$s] != 0.0 {
                        e5[j] += E5[$s] * self.k[$s][j];
                    }
                    if E3[$s] != 0.0 {
                        e3[j] += E3[$s] * self.k[$s][j];
                    }
                }
            )*};
        }
        accumulate!(0 1 2 3 4 5 6 7 8 9 10 11 12);
        let mut err5 = 0.0;
        let mut err3 = 0.0;
        for j in 0..N {
            let scale = self.atol + self.y[j].abs().max(y_new[j].abs()) * self.rtol;
            err5 += (e5[j] / scale).powi(2);
            err3 += (e3[j] / scale).powi(2);
        }
        if err5 == 0.0 && err3 == 0.0 {
            return 0.0;
        }
        h.abs() * err5 / ((err5 + 0.01 * err3) * N as f64).sqrt()
    }

    /// The dense output of the last accepted step, built on first request.
    pub(crate) fn dense(&mut self, rhs: &mut impl FnMut(f64, &[f64; N]) -> [f64; N]) -> DenseOutput<N> {
        if let Some(d) = self.dense {
            return d;
        }
        let h = self.t - self.t_old;
        if h == 0.0 {
            let d = DenseOutput {
                t_old: self.t_old,
                h: 1.0,
                y_old: self.y,
                f: [[0.0; N]; 7],
            };
            self.dense = Some(d);
            return d;
        }
        // The step's stages were computed from y_old; `combine` works from `self.y`,
        // so form the extra stages explicitly.
        macro_rules! stages {
            ($($s:literal)*) => {$(
                let ys = combine::<N, $s>(&self.y_old, &self.k, h);
                self.k[$s] = rhs(self.t_old + C[$s] * h, &ys);
            )*};
        }
        stages!(13 14 15);
        let mut f = [[0.0; N]; 7];
        for j in 0..N {
            let dy = self.y[j] - self.y_old[j];
            f[0][j] = dy;
            f[1][j] = h * self.k[0][j] - dy;
            f[2][j] = 2.0 * dy - h * (self.f[j] + self.k[0][j]);
        }
        for (row, d) in f[3..].iter_mut().zip(D.iter()) {
            for (s, coef) in d.iter().enumerate() {
                if *coef != 0.0 {
                    for j in 0..N {
                        row[j] += h * coef * self.k[s][j];
                    }
                }
            }
        }
        let d = DenseOutput {
            t_old: self.t_old,
            h,
            y_old: self.y_old,
            f,
        };
        self.dense = Some(d);
        d
    }
}

/// `y + h Σ_i a_Si k_i`, the argument of stage `S`.
#[inline(always)]
fn combine<const N: usize, const S: usize>(y: &[f64; N], k: &[[f64; N]; 16], h: f64) -> [f64; N] {
    let mut ys = *y;
    for i in 0..S {
        let a = A[S][i];
        if a != 0.0 {
            for j in 0..N {
                ys[j] += h * a * k[i][j];
            }
        }
    }
    ys
}

/// `err^(-1/8)`, the controller's exponent `-1/(order + 1)` for the 7th-order
/// estimate, as three square roots (cheaper than `powf`).
#[inline]
fn error_factor(err: f64) -> f64 {
    1.0 / err.sqrt().sqrt().sqrt()
}

/// The spacing of floats at `x >= 0` (one unit in the last place).
fn ulp(x: f64) -> f64 {
    x.next_up() - x
}

/// Root mean square of a small array.
fn rms<const N: usize>(v: &[f64; N]) -> f64 {
    (v.iter().map(|x| x * x).sum::<f64>() / N as f64).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// Harmonic oscillator y'' = -y: the exact solution is (cos t, -sin t).
    #[test]
    fn harmonic_oscillator_end_point_and_dense_output() {
        let mut rhs = |_t: f64, y: &[f64; 2]| [y[1], -y[0]];
        let mut s = Dop853::<2>::new(1e-10, 1e-12);
        s.restart(&mut rhs, 0.0, [1.0, 0.0], 10.0);
        let mut steps = 0;
        while s.t < 10.0 {
            s.step(&mut rhs, 10.0).unwrap();
            steps += 1;
            let d = s.dense(&mut rhs);
            let tm = 0.5 * (s.t_old + s.t);
            let ym = d.state(tm);
            // Dense output is 7th order: its error is of the size of the local tolerance.
            assert_relative_eq!(ym[0], tm.cos(), epsilon = 1e-9);
            assert_relative_eq!(ym[1], -tm.sin(), epsilon = 1e-9);
        }
        // Lands exactly on the bound, global error of the order of rtol times the number of steps.
        assert_eq!(s.t.to_bits(), 10.0f64.to_bits());
        assert_relative_eq!(s.y[0], 10f64.cos(), epsilon = 1e-8);
        assert_relative_eq!(s.y[1], -10f64.sin(), epsilon = 1e-8);
        assert!(steps < 200, "an 8th-order method needs few steps here, took {steps}");
    }

    /// The derivative of the dense output is the exact solution's derivative
    /// to the local tolerance (1e-10; about 1e-12 is seen), and it is the
    /// derivative of `state`: a central difference over ±e agrees to its
    /// rounding error, ulp(1) / 2e ≈ 1.1e-10 for e = 1e-5 h with h ≈ 0.1
    /// (its truncation error, e² y‴ / 6, is below 1e-12).
    #[test]
    fn dense_rate_is_the_derivative() {
        let mut rhs = |_t: f64, y: &[f64; 2]| [y[1], -y[0]];
        let mut s = Dop853::<2>::new(1e-10, 1e-12);
        s.restart(&mut rhs, 0.0, [1.0, 0.0], 10.0);
        s.step(&mut rhs, 10.0).unwrap();
        s.step(&mut rhs, 10.0).unwrap();
        let d = s.dense(&mut rhs);
        let h = s.t - s.t_old;
        for x in [0.0, 0.3, 0.71, 1.0] {
            let t = s.t_old + x * h;
            let (y, dy) = d.state_and_rate(t);
            assert_eq!(y.map(f64::to_bits), d.state(t).map(f64::to_bits));
            assert_relative_eq!(dy[0], -t.sin(), epsilon = 1e-10);
            assert_relative_eq!(dy[1], -t.cos(), epsilon = 1e-10);
            let e = 1e-5 * h;
            let fd = (d.state(t + e)[0] - d.state(t - e)[0]) / (2.0 * e);
            assert_relative_eq!(dy[0], fd, epsilon = 2e-10);
        }
    }

    /// A tolerance no step can meet (the error of y' = y² near its blow-up
    /// exceeds any step's budget) ends in `StepSizeTooSmall`, within a
    /// bounded number of attempts, instead of retrying the minimum step.
    #[test]
    fn unreachable_tolerance_fails_instead_of_looping() {
        // y = 1 / (1 - t): infinite at t = 1, the end of the interval.
        let mut calls = 0u64;
        let mut rhs = |_t: f64, y: &[f64; 1]| {
            calls += 1;
            [y[0] * y[0]]
        };
        let mut s = Dop853::<1>::new(1e-300, 1e-300);
        s.restart(&mut rhs, 0.0, [1.0], 2.0);
        let mut result = Ok(());
        for _ in 0..100_000 {
            result = s.step(&mut rhs, 2.0);
            if result.is_err() {
                break;
            }
        }
        assert!(matches!(result, Err(StepFailure::StepSizeTooSmall { .. })), "{result:?}");
        // Each rejection divides the step by at least 5, so from 1 s down to
        // 10 ulp(2) = 4.4e-15 s takes about 21 attempts of 12 evaluations.
        assert!(calls < 1_000, "{calls} evaluations before failing");
    }

    /// The dense output reproduces both ends of the step exactly (up to rounding).
    #[test]
    fn dense_output_matches_step_ends() {
        let mut rhs = |t: f64, y: &[f64; 1]| [t.cos() * y[0]];
        let mut s = Dop853::<1>::new(1e-8, 1e-10);
        s.restart(&mut rhs, 0.0, [1.0], 3.0);
        s.step(&mut rhs, 3.0).unwrap();
        let d = s.dense(&mut rhs);
        assert_relative_eq!(d.state(s.t_old)[0], s.y_old[0], max_relative = 1e-14);
        assert_relative_eq!(d.state(s.t)[0], s.y[0], max_relative = 1e-14);
    }
}
