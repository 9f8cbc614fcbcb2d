//! The regimes of the two bodies (docs/src/model.md, "Regimes and transitions") and the state.

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
/// and the building's slip relative to the ground.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct State {
    /// Rotation `θ` (rad), positive leaning towards `+x`.
    pub theta: f64,
    /// Angular velocity `θ̇` (rad/s).
    pub theta_dot: f64,
    /// Slip `u` (m), positive towards `+x`.
    pub slip: f64,
    /// Slip velocity `u̇` (m/s).
    pub slip_vel: f64,
}

impl State {
    #[inline]
    pub(crate) fn from_array(y: [f64; 4]) -> Self {
        Self {
            theta: y[0],
            theta_dot: y[1],
            slip: y[2],
            slip_vel: y[3],
        }
    }
}
