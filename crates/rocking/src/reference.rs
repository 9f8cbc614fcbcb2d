//! Closed-form and quadrature solutions that a correct implementation
//! reproduces (docs/src/validation.md), used by the tests and benchmarks.

use crate::body::{MassInput, Section, Tower, TowerGeometry};

/// A solid rectangular block `width × height` (m) of 1000 kg, depth = width:
/// the test block of the closed forms.
///
/// # Panics
/// If `width` or `height` is not a finite positive number (a test-setup error).
pub fn solid_block(width: f64, height: f64) -> Tower {
    let geometry = TowerGeometry {
        width,
        height,
        depth: None,
        section: Section::Solid,
        mass: MassInput::Mass(1000.0),
        inertia_pivot: None,
        restitution: None,
    };
    match Tower::from_geometry(&geometry) {
        Ok(t) => t,
        Err(e) => panic!("reference block {width} × {height} is invalid: {e}"),
    }
}

/// Time (s) for a block released from rest at `θ0` (0 < θ0 < α, no ground
/// motion) to reach `θ = 0`: `∫₀^θ0 dθ / sqrt(2p² (cos(α − θ0) − cos(α − θ)))`.
///
/// The integrable singularity at `θ = θ0` is removed by `θ = θ0 (1 − v²)`, and
/// the smooth integrand is integrated by composite Gauss–Legendre quadrature
/// (20 panels of 5 points: far below 1e-12 relative for these integrands).
pub fn free_rocking_time_to_impact(p: f64, alpha: f64, theta0: f64) -> f64 {
    let c0 = (alpha - theta0).cos();
    // θ = θ0 (1 − v²), dθ = −2 θ0 v dv; v from 0 (θ = θ0) to 1 (θ = 0).
    let integrand = |v: f64| {
        let theta = theta0 * (1.0 - v * v);
        let gap = c0 - (alpha - theta).cos();
        if v == 0.0 {
            // Limit: gap ≈ sin(α − θ0) θ0 v², so 2 θ0 v / sqrt(2 p² gap) → 2 θ0 / sqrt(2 p² θ0 sin(α − θ0)).
            2.0 * theta0 / (2.0 * p * p * theta0 * (alpha - theta0).sin()).sqrt()
        } else {
            2.0 * theta0 * v / (2.0 * p * p * gap).sqrt()
        }
    };
    gauss_legendre(integrand, 0.0, 1.0, 20)
}

/// Housner's small-angle time to impact, `(1/p) arccosh(1 / (1 − θ0/α))`.
pub fn housner_small_angle_time_to_impact(p: f64, alpha: f64, theta0: f64) -> f64 {
    (1.0 / (1.0 - theta0 / alpha)).acosh() / p
}

/// Final slip (m) of a block alone on a foundation (static and kinetic friction
/// `μs <= μk`... i.e. `μk <= μs`), under a rectangular pulse `a0 > μs g` (m/s²)
/// lasting `td` (s): `−[(a0 − μk g) td²/2 + ((a0 − μk g) td)² / (2 μk g)]`.
pub fn sliding_block_rectangular_pulse(a0: f64, td: f64, mu_kinetic: f64, g: f64) -> f64 {
    let excess = a0 - mu_kinetic * g;
    -(excess * td * td / 2.0 + (excess * td).powi(2) / (2.0 * mu_kinetic * g))
}

/// The shortest rectangular pulse `a0 = ratio · g` (towards `+x`, `ratio > tan α`)
/// that overturns a block at rest on a fixed base (s).
///
/// During the pulse, with `ψ = −θ >= 0` (no impact can occur: `ψ` grows),
/// energy gives `½ ψ̇² = p² [a (sin α − sin(α − ψ)) + cos α − cos(α − ψ)]`, `a = a0/g`.
/// After it, free rocking overturns iff `½ ψ̇² + p² cos(α − ψ) >= p²`, which at
/// the pulse's end holds with equality for `sin(α − ψ1) = sin α − (1 − cos α)/a`.
/// The critical duration is the time to reach `ψ1`, by quadrature (substitution
/// `ψ = ψ1 v²` removes the start's `1/sqrt(ψ)` singularity).
pub fn rectangular_pulse_overturning_duration(p: f64, alpha: f64, ratio: f64) -> f64 {
    let psi1 = alpha - (alpha.sin() - (1.0 - alpha.cos()) / ratio).asin();
    let speed2 = |psi: f64| 2.0 * p * p * (ratio * (alpha.sin() - (alpha - psi).sin()) + alpha.cos() - (alpha - psi).cos());
    let integrand = |v: f64| {
        if v == 0.0 {
            // ψ̇² ≈ 2 p² (a cos α − sin α) ψ near ψ = 0.
            2.0 * psi1.sqrt() / (2.0 * p * p * (ratio * alpha.cos() - alpha.sin())).sqrt()
        } else {
            2.0 * psi1 * v / speed2(psi1 * v * v).sqrt()
        }
    };
    gauss_legendre(integrand, 0.0, 1.0, 40)
}

/// Composite 5-point Gauss–Legendre rule on `[a, b]` with `panels` panels.
fn gauss_legendre(f: impl Fn(f64) -> f64, a: f64, b: f64, panels: usize) -> f64 {
    const X: [f64; 5] = [
        0.0,
        -0.538_469_310_105_683_1,
        0.538_469_310_105_683_1,
        -0.906_179_845_938_664,
        0.906_179_845_938_664,
    ];
    const W: [f64; 5] = [
        0.568_888_888_888_888_9,
        0.478_628_670_499_366_5,
        0.478_628_670_499_366_5,
        0.236_926_885_056_189_1,
        0.236_926_885_056_189_1,
    ];
    let h = (b - a) / panels as f64;
    (0..panels)
        .map(|i| {
            let mid = a + (i as f64 + 0.5) * h;
            X.iter().zip(W).map(|(x, w)| w * f(mid + 0.5 * h * x)).sum::<f64>() * 0.5 * h
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// For small α the exact quadrature tends to Housner's linearised formula.
    #[test]
    fn quadrature_tends_to_housner_for_small_alpha() {
        let (p, alpha) = (2.0, 0.01);
        let exact = free_rocking_time_to_impact(p, alpha, 0.5 * alpha);
        let linear = housner_small_angle_time_to_impact(p, alpha, 0.5 * alpha);
        // The linearisation error is O(α²) relative.
        assert_relative_eq!(exact, linear, max_relative = 1e-3);
    }

    #[test]
    fn gauss_legendre_integrates_a_polynomial_of_degree_9_exactly() {
        let v = gauss_legendre(|x| x.powi(9), 0.0, 2.0, 1);
        assert_relative_eq!(v, 2f64.powi(10) / 10.0, max_relative = 1e-14);
    }
}

/// The benchmark of a block carrying another (`benches/stack.rs`, and the
/// interleaved ratios of `rocking-scenario`'s example `stack_ratios`): the
/// 0.5 m × 2 m [`solid_block`] under 20 s of 0.5 g at 2 Hz (rtol 1e-8,
/// atol 1e-10), carrying a 0.3 m × 0.6 m block of the same density, on a
/// fixed base and on a sliding building (2 × 10⁴ kg, μs = 0.4, μk = 0.35,
/// dynamic normal force). Both blocks rock in both cases.
#[derive(Debug, Clone)]
pub struct StackBench {
    /// The input.
    pub ground: crate::GroundMotion,
    /// The engine's settings.
    pub settings: crate::Settings,
    /// The stack's stepper's: the same tolerances, samples only at the start
    /// and the end (the engine's run records nothing either).
    pub stack_settings: crate::stack::run::RunSettings,
    /// The lower block, the tower.
    pub tower: Tower,
    /// The block it carries.
    pub upper: crate::stack::Block,
    /// The bases, by name: none (fixed) and the sliding building.
    pub bases: [(&'static str, Option<crate::Building>); 2],
    /// Gravity (m/s²).
    pub gravity: f64,
}

/// The [`StackBench`] case.
///
/// # Panics
/// If one of its constants were refused (a setup error, as [`solid_block`]'s).
pub fn stack_bench() -> StackBench {
    const G: f64 = 9.81;
    let valid = |what: &str, e: &dyn std::fmt::Display| -> ! { panic!("the stack benchmark's {what} is invalid: {e}") };
    let harmonic = crate::Harmonic::new(0.5 * G, 2.0, 20.0, 0.0).unwrap_or_else(|e| valid("input", &e));
    // Density of the 0.5 m × 2 m block of 1000 kg: 1000 kg/m² in the plane.
    let upper = crate::stack::Block::solid(2, 0.3, 0.6, 1000.0 * 0.3 * 0.6).unwrap_or_else(|e| valid("upper block", &e));
    let building = crate::Building::new(2.0e4, 0.4, 0.35, crate::NormalForce::Dynamic).unwrap_or_else(|e| valid("building", &e));
    StackBench {
        ground: crate::GroundMotion::Harmonic(harmonic),
        settings: crate::Settings {
            duration: 20.0,
            rtol: 1e-8,
            atol: 1e-10,
        },
        stack_settings: crate::stack::run::RunSettings {
            duration: 20.0,
            rtol: 1e-8,
            atol: 1e-10,
            sample_interval: 20.0,
        },
        tower: solid_block(0.5, 2.0),
        upper,
        bases: [("fixed_base", None), ("sliding_building", Some(building))],
        gravity: G,
    }
}
