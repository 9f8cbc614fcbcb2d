//! The right-hand side: the accelerations `(θ̈, ü)` of the current regime
//! under the current pieces of the inputs, at `(t, θ, θ̇)`.
//!
//! The general form is [`Kernel::accelerations`] with `a_g` and `g_e` read
//! off the pieces. It is the inner loop of every run, so two cases are
//! written out beside it, each the same numbers bit for bit (the tests
//! below):
//!
//! - without a vertical input, the constant `g` is taken, not `g + 0`
//!   evaluated at every call (2.4% fewer instructions over the 100-case sweep);
//! - the commonest case, a tower rocking on a fixed base or a stuck building
//!   under a harmonic input, is composed directly of (T) and the sine, with
//!   no match on the input's piece or the regime at every call (5% fewer
//!   instructions over the 100-case sweep).

use crate::equations::{Accelerations, Kernel};
use crate::ground::{sine, Piece};
use crate::regime::{BuildingRegime, Regime, TowerRegime};

/// The accelerations of one regime under fixed pieces of the inputs.
pub(super) trait Rhs: Copy {
    /// `(θ̈, ü)` at `t` and `(θ, θ̇)`.
    fn accelerations(&self, t: f64, theta: f64, theta_dot: f64) -> Accelerations<f64>;
}

/// The general right-hand side: any regime, any horizontal piece, a vertical one.
#[derive(Clone, Copy)]
pub(super) struct General<'a> {
    kernel: &'a Kernel,
    regime: Regime,
    piece: Piece,
    vpiece: Piece,
}

impl Rhs for General<'_> {
    #[inline(always)]
    fn accelerations(&self, t: f64, theta: f64, theta_dot: f64) -> Accelerations<f64> {
        let k = self.kernel;
        k.accelerations(self.regime, self.piece.eval(t), k.g + self.vpiece.eval(t), theta, theta_dot)
    }
}

/// [`General`] without a vertical input: `g_e = g`.
#[derive(Clone, Copy)]
pub(super) struct Horizontal<'a> {
    kernel: &'a Kernel,
    regime: Regime,
    piece: Piece,
}

impl Rhs for Horizontal<'_> {
    #[inline(always)]
    fn accelerations(&self, t: f64, theta: f64, theta_dot: f64) -> Accelerations<f64> {
        let k = self.kernel;
        k.accelerations(self.regime, self.piece.eval(t), k.g, theta, theta_dot)
    }
}

/// A tower rocking on pivot `s` on a fixed base or a stuck building under
/// the harmonic `a_g = amplitude sin(ω t + phase)`, no vertical input: (T)
/// with `Ẍ_p = a_g`, `g_e = g`.
#[derive(Clone, Copy)]
pub(super) struct HarmonicRocking<'a> {
    kernel: &'a Kernel,
    s: f64,
    amplitude: f64,
    omega: f64,
    phase: f64,
}

impl Rhs for HarmonicRocking<'_> {
    #[inline(always)]
    fn accelerations(&self, t: f64, theta: f64, _theta_dot: f64) -> Accelerations<f64> {
        let k = self.kernel;
        Accelerations {
            theta: k.tower_equation(k.lean(self.s, theta), sine(self.amplitude, self.omega, self.phase, t), k.g),
            slip: 0.0,
        }
    }
}

/// The right-hand side for a regime and the inputs' pieces: the most
/// specialised form that applies.
pub(super) enum Selected<'a> {
    HarmonicRocking(HarmonicRocking<'a>),
    Horizontal(Horizontal<'a>),
    General(General<'a>),
}

/// The right-hand side of `regime` under `piece` and, if `has_vertical`, `vpiece`.
pub(super) fn select(kernel: &Kernel, regime: Regime, piece: Piece, vpiece: Piece, has_vertical: bool) -> Selected<'_> {
    match (has_vertical, piece, regime.tower, regime.building) {
        (false, Piece::Sine { amplitude, omega, phase }, TowerRegime::Rocking(pivot), BuildingRegime::Stick) => Selected::HarmonicRocking(HarmonicRocking {
            kernel,
            s: pivot.sign(),
            amplitude,
            omega,
            phase,
        }),
        (true, ..) => Selected::General(General { kernel, regime, piece, vpiece }),
        (false, ..) => Selected::Horizontal(Horizontal { kernel, regime, piece }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ground::{GroundMotion, Harmonic};
    use crate::reference::solid_block;
    use crate::regime::{Pivot, SlipDirection};
    use crate::{Building, Model, NormalForce};

    const G: f64 = 9.81;

    fn kernel(building: bool) -> Kernel {
        let b = building.then(|| Building::new(2.0e6, 0.6, 0.5, NormalForce::Dynamic).unwrap_or_else(|e| panic!("{e}")));
        Kernel::new(&Model::new(Some(solid_block(0.5, 2.0)), b, G).unwrap_or_else(|e| panic!("{e}")))
    }

    /// A grid of instants and states over two periods of the input and the
    /// whole range of leans, both pivots.
    fn grid() -> impl Iterator<Item = (f64, f64, f64)> {
        (0..40).flat_map(|i| (0..31).flat_map(move |j| [-2.0, 0.0, 1.3].map(move |w| (0.0137 * f64::from(i), -1.5 + 0.1 * f64::from(j), w))))
    }

    /// The harmonic specialisation is [`Kernel::accelerations`] with the
    /// piece's value, bit for bit, on a fixed base and on a stuck building.
    #[test]
    fn the_harmonic_rocking_form_is_the_general_one_bit_for_bit() {
        let ground = GroundMotion::Harmonic(Harmonic::new(0.4 * G, 2.5, 10.0, 0.3).unwrap_or_else(|e| panic!("{e}")));
        let piece = ground.segment(0.1).piece;
        assert!(matches!(piece, Piece::Sine { .. }), "{piece:?}");
        for building in [false, true] {
            let k = kernel(building);
            for pivot in [Pivot::Negative, Pivot::Positive] {
                let regime = Regime {
                    tower: TowerRegime::Rocking(pivot),
                    building: BuildingRegime::Stick,
                };
                let Selected::HarmonicRocking(fast) = select(&k, regime, piece, Piece::Constant(0.0), false) else {
                    panic!("the harmonic form applies to {regime:?}");
                };
                for (t, theta, theta_dot) in grid() {
                    let general = k.accelerations(regime, piece.eval(t), G, theta, theta_dot);
                    let got = fast.accelerations(t, theta, theta_dot);
                    assert_eq!(got.theta.to_bits(), general.theta.to_bits(), "t {t}, θ {theta}");
                    assert_eq!(got.slip.to_bits(), general.slip.to_bits());
                }
            }
        }
    }

    /// Without a vertical input the general form with `g + 0` is the
    /// horizontal one with `g`, bit for bit, in every regime.
    #[test]
    fn the_horizontal_form_is_the_general_one_bit_for_bit() {
        let ground = GroundMotion::Harmonic(Harmonic::new(0.8 * G, 1.5, 10.0, 0.0).unwrap_or_else(|e| panic!("{e}")));
        let piece = ground.segment(0.2).piece;
        let k = kernel(true);
        let towers = [TowerRegime::Rest, TowerRegime::Rocking(Pivot::Negative), TowerRegime::Rocking(Pivot::Positive)];
        let buildings = [
            BuildingRegime::Stick,
            BuildingRegime::Slip(SlipDirection::Negative),
            BuildingRegime::Slip(SlipDirection::Positive),
        ];
        for tower in towers {
            for building in buildings {
                let regime = Regime { tower, building };
                let general = General {
                    kernel: &k,
                    regime,
                    piece,
                    vpiece: Piece::Constant(0.0),
                };
                let Selected::Horizontal(fast) = select(&k, regime, piece, Piece::Constant(0.0), false) else {
                    continue;
                };
                for (t, theta, theta_dot) in grid() {
                    let (a, b) = (general.accelerations(t, theta, theta_dot), fast.accelerations(t, theta, theta_dot));
                    assert_eq!(
                        (a.theta.to_bits(), a.slip.to_bits()),
                        (b.theta.to_bits(), b.slip.to_bits()),
                        "{regime:?} t {t} θ {theta}"
                    );
                }
            }
        }
    }
}
