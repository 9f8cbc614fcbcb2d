//! Free rocking in closed form: the end of an impact cascade.
//!
//! After the ground motion has ended, a tower rocking on a fixed base (or on a
//! building that stays stuck) loses a fraction of its speed at each impact and
//! comes to rest through a geometric cascade of ever shorter flights: with
//! `θ̇` falling from about 1e-3 to the rest threshold of 1e-9 rad/s, hundreds
//! of impacts within a fraction of a second, each costing the integrator a
//! restart and a few steps. Between impacts the motion is conservative
//! (docs/src/validation.md), so each flight is known exactly:
//!
//! - a flight that leaves `θ = 0` at the speed `ω = |θ̇|` rises to the apex
//!   `ψm` (`ψ = s θ`, the lean towards the pivot) where the energy
//!   `½ I_O θ̇² + m2 g R cos(α − ψ)` has turned `ω` into height:
//!   `cos(α − ψm) − cos α = ω² / (2p²)`, `p² = m2 g R / I_O`;
//! - it returns to `θ = 0` with the speed it left with (the motion is
//!   reversible in time: `θ̈` depends on `θ` alone), so the next impact takes
//!   `ω` to `r ω` exactly as the impact law says;
//! - its duration is twice the time from `θ = 0` to the apex, the quadrature
//!   of docs/src/model.md, `T = 2 ∫₀^ψm dψ / sqrt(2p² (cos(α − ψm) − cos(α − ψ)))`.
//!
//! **Why this is exact to the solver's tolerance.** The apex is solved by
//! Newton to a few ulps. The quadrature is written in a form without
//! cancellation or singularity (see [`Kernel::free_rocking_flight_time`]):
//! its integrand is an analytic function of `v²` whose relative variation on
//! `[0, 1]` is `ψm cot α / 2` to first order, so Gauss–Legendre with six nodes
//! (exact for polynomials of degree 11) errs by about `(ψm cot α)⁶`, below
//! 1e-12 relative for the flights taken here (`ψm <= 0.1 √rtol`, 1e-5 rad
//! at the default tolerance, and `ψm cot α <= 1e-2`). Impact times and speeds are
//! therefore those of the exact solution to rounding, while integration
//! gives them to `rtol`. The summary's peaks along a flight (of `θ`, of the
//! top's acceleration, of the pivot's friction demand and of the building's
//! stick demand) are functions of `ψ` alone (with `a_g = 0`, `θ̈` and `θ̇²`
//! are), the same on the way up and down; each is smooth, so on `[0, ψm]` it
//! differs from the larger of its values at the ends by at most
//! `max|q''| ψm² / 8`, a relative `ψm² / 8 <= rtol / 800` for these
//! quantities (their second derivatives in `ψ` are of their own size). The
//! ends are the impacts, recorded as any impact, and the apex is recorded
//! here.
//!
//! **When it does not apply** (the caller integrates instead): while any
//! ground motion, horizontal or vertical, is left to come (a flight could be
//! pushed); on a building that slides, or that could start to slide during
//! the flight (the stick demand is checked at the impact and at the apex, with
//! a margin far above the `ψm²` bound); when the flight would end after the
//! run; and for larger flights, where the peaks inside could exceed the
//! ends' by more than the tolerance, or where `ψm cot α > 1e-2` (a very
//! slender body), where six nodes would no longer be enough.
//!
//! Between the ends, the states given to observers (the history at output
//! instants) come from the equation linearized about `θ = 0`,
//! `ψ̈ = −p² (sin α − ψ cos α)`, solved in closed form; the term dropped is
//! `p² sin α ψ² / 2`, which moves `ψ` by less than `p² ψm² T² / 4`, about
//! 1e-15 rad for these flights, far below `atol`.

// The Gauss–Legendre constants are written with the digits tables publish.
#![allow(clippy::excessive_precision)]

use crate::equations::Kernel;
use crate::regime::State;
use crate::trig::sin;

/// Gauss–Legendre nodes and weights on `[0, 1]`, six points (the classical
/// values on `[−1, 1]` mapped by `x ↦ (x + 1) / 2`). Written out because six
/// constants do not call for a quadrature crate.
const GAUSS_NODES: [f64; 6] = [
    0.033_765_242_898_423_986,
    0.169_395_306_766_867_74,
    0.380_690_406_958_401_55,
    0.619_309_593_041_598_45,
    0.830_604_693_233_132_26,
    0.966_234_757_101_576_01,
];
const GAUSS_WEIGHTS: [f64; 6] = [
    0.085_662_246_189_585_17,
    0.180_380_786_524_069_3,
    0.233_956_967_286_345_52,
    0.233_956_967_286_345_52,
    0.180_380_786_524_069_3,
    0.085_662_246_189_585_17,
];

/// One free flight between two impacts, from `t0` on the pivot of sign `s`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Flight {
    /// Pivot sign: `ψ = s θ >= 0` during the flight.
    pub(crate) s: f64,
    /// Start (s).
    pub(crate) t0: f64,
    /// `ψ̇` at the start (rad/s, > 0).
    pub(crate) omega: f64,
    /// Apex `ψm` (rad).
    pub(crate) apex: f64,
    /// The building's slip, constant through the flight (m).
    pub(crate) slip: f64,
    /// Duration (s).
    pub(crate) duration: f64,
    /// `λ = p √(cos α)` of the linearized equation (1/s).
    lambda: f64,
    tan_alpha: f64,
}

impl Kernel {
    /// The apex `ψm` of a free flight that leaves `θ = 0` at `ω` (rad/s):
    /// energy conservation, `cos(α − ψm) − cos α = ω² / (2p²)`, written
    /// `2 sin(α − ψm/2) sin(ψm/2) = ω² / (2p²)` so that a small `ψm` keeps its
    /// digits, and solved by Newton (the left side's derivative is
    /// `sin(α − ψm)`). `None` if the tower would go over (`ψm >= α`).
    pub(crate) fn free_rocking_apex(&self, omega: f64) -> Option<f64> {
        let p2 = self.free_rocking_p2();
        let c = omega * omega / (2.0 * p2);
        if c >= 1.0 - self.cos_alpha {
            return None;
        }
        // The small-ψm value, then Newton: the left side is concave in ψm, so
        // the iterates approach from below without overshooting past α.
        let mut psi = c / self.sin_alpha;
        for _ in 0..50 {
            let f = 2.0 * sin(self.alpha - 0.5 * psi) * sin(0.5 * psi) - c;
            let step = f / sin(self.alpha - psi);
            psi -= step;
            if step.abs() <= 4.0 * f64::EPSILON * psi {
                break;
            }
        }
        (psi > 0.0 && psi < self.alpha).then_some(psi)
    }

    /// The duration of a free flight from `θ = 0` to the apex `ψm` and back
    /// (s): docs/src/model.md's quadrature
    /// `T = 2 ∫₀^ψm dψ / sqrt(2p² (cos(α − ψm) − cos(α − ψ)))`.
    ///
    /// With `ψ = ψm (1 − v²)` and
    /// `cos(α − ψm) − cos(α − ψ) = 2 sin(α − ψm + ψm v²/2) sin(ψm v²/2)`,
    /// `T = 4 √ψm ∫₀¹ dv / sqrt(2p² sin(α − ψm + ψm v²/2) sinc(ψm v²/2))`
    /// (`sinc x = sin x / x`): no difference of nearly equal cosines, no
    /// singularity at the apex, and `2 ω / (p² sin α)` as `ψm → 0`.
    pub(crate) fn free_rocking_flight_time(&self, apex: f64) -> f64 {
        let p2 = self.free_rocking_p2();
        let integral: f64 = GAUSS_NODES
            .iter()
            .zip(GAUSS_WEIGHTS)
            .map(|(&v, w)| {
                let x = 0.5 * apex * v * v;
                let sinc = if x == 0.0 { 1.0 } else { sin(x) / x };
                w / (2.0 * p2 * sin(self.alpha - apex + x) * sinc).sqrt()
            })
            .sum();
        4.0 * apex.sqrt() * integral
    }

    /// The free flight that starts at `t0` on the pivot `s` with `θ̇ = s ω`,
    /// the building (if any) stuck at `slip`, if its apex is at most `max_apex`.
    pub(crate) fn free_flight(&self, s: f64, t0: f64, omega: f64, slip: f64, max_apex: f64) -> Option<Flight> {
        // The quadrature's error bound (module docs) needs ψm cot α small:
        // at most 1e-2 here, an error below 1e-12 of the flight time.
        let apex = self
            .free_rocking_apex(omega)
            .filter(|&apex| apex <= max_apex && apex * self.cos_alpha <= 1e-2 * self.sin_alpha)?;
        Some(Flight {
            s,
            t0,
            omega,
            apex,
            slip,
            duration: self.free_rocking_flight_time(apex),
            lambda: (self.free_rocking_p2() * self.cos_alpha).sqrt(),
            tan_alpha: self.tan_alpha,
        })
    }
}

impl Flight {
    /// The state `(θ, θ̇, u, u̇)` at `t` in the flight, from the linearized
    /// equation (module docs): `ψ = (ω/λ) sinh λτ − 2 tan α sinh²(λτ/2)`,
    /// `τ = t − t0`.
    pub(crate) fn state(&self, t: f64) -> State {
        let x = self.lambda * (t - self.t0);
        let (sh, ch, sh2) = (libm::sinh(x), libm::cosh(x), libm::sinh(0.5 * x));
        let psi = self.omega / self.lambda * sh - 2.0 * self.tan_alpha * sh2 * sh2;
        let psi_dot = self.omega * ch - self.tan_alpha * self.lambda * sh;
        State {
            theta: self.s * psi,
            theta_dot: self.s * psi_dot,
            slip: self.slip,
            slip_vel: 0.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::solid_block;
    use crate::Model;

    const G: f64 = 9.81;

    fn kernel(width: f64, height: f64) -> Kernel {
        Kernel::new(&Model::new(Some(solid_block(width, height)), None, G).unwrap_or_else(|e| panic!("{e}")))
    }

    /// Six Gauss–Legendre points integrate polynomials of degree up to 11
    /// exactly (to rounding of the 16-digit constants) and not degree 12.
    #[test]
    fn gauss_legendre_is_exact_to_degree_eleven() {
        for k in 0..=12 {
            let sum: f64 = GAUSS_NODES.iter().zip(GAUSS_WEIGHTS).map(|(&v, w)| w * v.powi(k)).sum();
            let exact = 1.0 / f64::from(k + 1);
            if k <= 11 {
                assert!((sum - exact).abs() < 4e-16, "degree {k}: {sum} against {exact}");
            } else {
                assert!((sum - exact).abs() > 1e-9, "degree 12 is not exact");
            }
        }
    }

    /// The apex against energy conservation written directly,
    /// `cos(α − ψm) − cos α = ω² / (2p²)`, to the rounding of that difference
    /// of cosines (a few ulps of 1 over the difference); and the small-flight
    /// limit `ω² / (2p² sin α)`.
    #[test]
    fn apex_conserves_energy() {
        let k = kernel(0.5, 2.0);
        let p2 = k.k * G;
        for omega in [0.1, 0.3, 0.6] {
            let apex = k.free_rocking_apex(omega).unwrap_or_else(|| panic!("{omega}"));
            let lhs = (k.alpha - apex).cos() - k.alpha.cos();
            assert!((lhs / (omega * omega / (2.0 * p2)) - 1.0).abs() < 8.0 * f64::EPSILON / lhs, "ω = {omega}");
        }
        let omega = 1e-6;
        let apex = k.free_rocking_apex(omega).unwrap_or_else(|| panic!("{omega}"));
        // The next term is relative `ψm cot α / 2`, 1e-12 here.
        assert!((apex / (omega * omega / (2.0 * p2 * k.alpha.sin())) - 1.0).abs() < 1e-11);
        // Beyond the energy that lifts the centre of mass over the pivot: no flight.
        let over = (2.0 * p2 * (1.0 - k.alpha.cos())).sqrt();
        assert!(k.free_rocking_apex(1.0001 * over).is_none());
    }

    /// The flight time against two independent forms: the small-flight limit
    /// `2ω / (p² sin α)` (relative error `O(ψm cot α)`, 1e-12 here), and, for
    /// a flight of apex 1e-5 rad (the largest taken at rtol 1e-8), the time of
    /// the linearized equation `(2/λ) artanh(ω / (λ tan α))`. The two times
    /// differ by a relative 2.8e-11 to 3.1e-11 on these blocks, second order
    /// in ψm (1e-10): an error of the quadrature's first order would show as
    /// 1e-5.
    #[test]
    fn flight_time_against_its_limits() {
        for (width, height) in [(0.5, 2.0), (0.2, 2.0), (1.0, 1.5)] {
            let k = kernel(width, height);
            let p2 = k.k * G;
            let omega = 1e-7;
            let apex = k.free_rocking_apex(omega).unwrap_or_else(|| panic!("{omega}"));
            let limit = 2.0 * omega / (p2 * k.alpha.sin());
            assert!((k.free_rocking_flight_time(apex) / limit - 1.0).abs() < 1e-10, "{width} × {height}");

            let apex = 1e-5;
            let omega = (2.0 * p2 * ((k.alpha - apex).cos() - k.alpha.cos())).sqrt();
            let lambda = (p2 * k.alpha.cos()).sqrt();
            let linear = 2.0 / lambda * (omega / (lambda * k.alpha.tan())).atanh();
            let t = k.free_rocking_flight_time(apex);
            assert!((t / linear - 1.0).abs() < apex * apex, "{width} × {height}: {t} against {linear}");
        }
    }

    /// The interpolant returns to θ = 0 at the end of the flight with the speed
    /// it left with (reversed), to the linearization's `ψm²` (module docs), and
    /// its apex is the energy's.
    #[test]
    fn interpolant_closes_the_flight() {
        let k = kernel(0.5, 2.0);
        let omega = 1e-3;
        let f = k.free_flight(-1.0, 2.0, omega, 0.0, 1.0).unwrap_or_else(|| panic!("{omega}"));
        let start = f.state(f.t0);
        assert_eq!((start.theta, start.theta_dot), (0.0, -omega));
        let end = f.state(f.t0 + f.duration);
        assert!(end.theta.abs() < 1e-15 && (end.theta_dot - omega).abs() < 1e-12 * omega, "{end:?}");
        let mid = f.state(f.t0 + 0.5 * f.duration);
        assert!(
            (-mid.theta / f.apex - 1.0).abs() < 1e-6 && mid.theta_dot.abs() < 1e-9,
            "{mid:?} against {}",
            f.apex
        );
    }
}
