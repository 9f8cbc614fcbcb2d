//! The regimes of the two bodies (docs/src/model.md, "Regimes and transitions") and the state.

use crate::equations::Accelerations;
use crate::jet::Jet;

/// Side of the base corner the tower pivots on, `s = sgn θ`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Pivot {
    /// The `−x` corner (`θ < 0`, leaning towards `−x`).
    Negative,
    /// The `+x` corner (`θ > 0`).
    Positive,
}

impl Pivot {
    /// `s = ±1`.
    #[inline]
    pub fn sign(self) -> f64 {
        match self {
            Pivot::Negative => -1.0,
            Pivot::Positive => 1.0,
        }
    }
    /// The other corner.
    pub fn flipped(self) -> Self {
        match self {
            Pivot::Negative => Pivot::Positive,
            Pivot::Positive => Pivot::Negative,
        }
    }
    /// The pivot of sign `x` (`x >= 0` gives [`Pivot::Positive`]).
    pub fn of_sign(x: f64) -> Self {
        if x < 0.0 {
            Pivot::Negative
        } else {
            Pivot::Positive
        }
    }
}

/// What the tower does.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TowerRegime {
    /// Standing on its base, moving with the building (`θ = θ̇ = 0`); also the
    /// regime of an absent tower.
    Rest,
    /// Rocking on a base corner.
    Rocking(Pivot),
}

/// Direction of a building's slip, `σ = sgn u̇`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SlipDirection {
    /// Sliding towards `−x`.
    Negative,
    /// Sliding towards `+x`.
    Positive,
}

impl SlipDirection {
    /// `σ = ±1`.
    #[inline]
    pub fn sign(self) -> f64 {
        match self {
            SlipDirection::Negative => -1.0,
            SlipDirection::Positive => 1.0,
        }
    }
    /// The direction of sign `x` (`x >= 0` gives [`SlipDirection::Positive`]).
    pub fn of_sign(x: f64) -> Self {
        if x < 0.0 {
            SlipDirection::Negative
        } else {
            SlipDirection::Positive
        }
    }
}

/// What the building does.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BuildingRegime {
    /// Moving with the ground (`u̇ = ü = 0`); also the regime of a fixed base.
    Stick,
    /// Sliding on the foundation.
    Slip(SlipDirection),
}

/// The regimes of both bodies.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Regime {
    /// The tower's regime.
    pub tower: TowerRegime,
    /// The building's regime.
    pub building: BuildingRegime,
}

/// The four combined motions (the paper's three plus rest), as written in `history.csv`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Motion {
    /// Nothing moves relative to the ground.
    Rest,
    /// The tower rocks; the building moves with the ground.
    Rocking,
    /// The whole complex slides; the tower stands.
    Sliding,
    /// The tower rocks on a sliding building.
    RockingSliding,
}

impl Motion {
    /// All motions, in the order of [`Motion::index`].
    pub const ALL: [Motion; 4] = [Motion::Rest, Motion::Rocking, Motion::Sliding, Motion::RockingSliding];

    /// The name used in output files: `rest`, `rocking`, `sliding`, `rocking_sliding`.
    pub fn as_str(self) -> &'static str {
        match self {
            Motion::Rest => "rest",
            Motion::Rocking => "rocking",
            Motion::Sliding => "sliding",
            Motion::RockingSliding => "rocking_sliding",
        }
    }
    /// Position in [`Motion::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }
}

impl Regime {
    /// Both bodies at rest.
    pub const REST: Regime = Regime {
        tower: TowerRegime::Rest,
        building: BuildingRegime::Stick,
    };

    /// The combined motion.
    pub fn motion(self) -> Motion {
        match (self.tower, self.building) {
            (TowerRegime::Rest, BuildingRegime::Stick) => Motion::Rest,
            (TowerRegime::Rocking(_), BuildingRegime::Stick) => Motion::Rocking,
            (TowerRegime::Rest, BuildingRegime::Slip(_)) => Motion::Sliding,
            (TowerRegime::Rocking(_), BuildingRegime::Slip(_)) => Motion::RockingSliding,
        }
    }
}

/// The state of the two bodies: the tower's rotation relative to the building
/// and the building's slip relative to the ground. Inside the engine the same
/// four names carry other numbers too: the state's time derivative
/// `(θ̇, θ̈, u̇, ü)`, or each component with its own derivative (a jet).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct State<T = f64> {
    /// Rotation `θ` (rad), positive leaning towards `+x`.
    pub theta: T,
    /// Angular velocity `θ̇` (rad/s).
    pub theta_dot: T,
    /// Slip `u` (m), positive towards `+x`.
    pub slip: T,
    /// Slip velocity `u̇` (m/s).
    pub slip_vel: T,
}

impl State {
    /// The state from the components the integrator carries: the first `N`
    /// of `(θ, θ̇, u, u̇)` (2 on a fixed base, 4 on a building), the others zero.
    #[inline(always)]
    pub(crate) fn from_components<const N: usize>(y: &[f64; N]) -> Self {
        let c = |i: usize| if i < N { y[i] } else { 0.0 };
        Self {
            theta: c(0),
            theta_dot: c(1),
            slip: c(2),
            slip_vel: c(3),
        }
    }

    /// The first `N` components of `(θ, θ̇, u, u̇)`: what the integrator carries.
    #[inline(always)]
    pub(crate) fn components<const N: usize>(self) -> [f64; N] {
        let all = [self.theta, self.theta_dot, self.slip, self.slip_vel];
        std::array::from_fn(|i| all[i])
    }

    /// The time derivative `(θ̇, θ̈, u̇, ü)` of the state, given its accelerations.
    #[inline(always)]
    pub(crate) fn rate(self, acc: Accelerations<f64>) -> Self {
        Self {
            theta: self.theta_dot,
            theta_dot: acc.theta,
            slip: self.slip_vel,
            slip_vel: acc.slip,
        }
    }

    /// Each component with its time derivative along the solution.
    #[inline(always)]
    pub(crate) fn jets(self, acc: Accelerations<f64>) -> State<Jet> {
        State {
            theta: Jet::new(self.theta, self.theta_dot),
            theta_dot: Jet::new(self.theta_dot, acc.theta),
            slip: Jet::new(self.slip, self.slip_vel),
            slip_vel: Jet::new(self.slip_vel, acc.slip),
        }
    }

    /// Whether two states are the same bit for bit (what a cache may rely on).
    #[inline(always)]
    pub(crate) fn same_bits(self, other: Self) -> bool {
        let bits = |s: Self| [s.theta, s.theta_dot, s.slip, s.slip_vel].map(f64::to_bits);
        bits(self) == bits(other)
    }
}
