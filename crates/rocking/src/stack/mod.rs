//! A stack of rigid blocks on the building: the tower (block 1) carrying a
//! belfry, the drums of a column, a statue on its pedestal.
//!
//! Blocks `k = 1 … N` stand centred on one another, block 1 on the building.
//! Block `k` has width `B_k` (no wider than the block below), height `H_k`,
//! mass `m_k` and moment of inertia `J_k` about its own centre of mass. Each
//! interface `k` (block `k` on block `k − 1`, the building for `k = 1`) is
//! either stuck (block `k` moves with the one below) or rocking on the corner
//! `s_k = ±1` of block `k`'s base; blocks never slide on one another. The
//! building sticks to its foundation or slips on it with Coulomb friction.
//! `θ_k` is block `k`'s rotation relative to block `k − 1` (positive leaning
//! towards `+x`, as the tower's) and `φ_k = θ_1 + … + θ_k` its absolute
//! rotation.
//!
//! The pieces, each a law of the model written once:
//!
//! - [`geometry`]: positions as sums of rotated vectors and their Jacobians
//!   with respect to the coordinates of a regime;
//! - [`dynamics`]: the equations of motion in Kane's form (mass matrix and
//!   forces per regime, the foundation's friction), the friction a sticking
//!   building needs, and the loads an interface carries (its uplift condition);
//! - [`impact`]: the impact of an interface on its other corner by
//!   generalised momentum, with the foundation's friction impulse, and the
//!   impulsive load a seated interface carries meanwhile;
//! - [`run`]: a time-stepper over the regimes, events located by root finding
//!   on the integrator's dense output.
//!
//! For one block on a building these are the tower's equations (T)–(B) and its
//! impact law; `tests` checks them against the engine's own functions.
//!
//! A model with blocks runs through [`crate::simulate`] like the tower alone:
//!
//! ```
//! use rocking::stack::Block;
//! use rocking::{simulate, EventKind, EventLog, GroundMotion, Harmonic, Initial, MassInput, Model, Section, Settings, Tower, TowerGeometry};
//!
//! let g = 9.81;
//! let shaft = Tower::from_geometry(&TowerGeometry {
//!     width: 4.0, height: 12.0, depth: None, section: Section::Solid,
//!     mass: MassInput::Mass(1.5e5), inertia_pivot: None, restitution: None,
//! })?;
//! // A belfry 3.2 m × 4.5 m of 30 t (its inertia that of a solid block: J = m (B² + H²)/12).
//! let belfry = Block::solid(2, 3.2, 4.5, 3.0e4).expect("a valid block");
//! let model = Model::new(Some(shaft), None, g)?.with_blocks(&[belfry])?;
//! let ground = GroundMotion::Harmonic(Harmonic::new(0.8 * g, 2.0, 6.0, 0.0)?);
//! let mut log = EventLog::default();
//! let summary = simulate(&model, &ground, Initial::default(), &Settings { duration: 8.0, ..Settings::default() }, &mut log)?;
//! // The tower's quantities are the shaft's; the blocks' are in `summary.stack`.
//! let stack = summary.stack.expect("a stacked run");
//! let belfry_run = stack.blocks()[0];
//! assert!(summary.impacts > 0 && belfry_run.impacts > 0);
//! assert!(belfry_run.max_abs_theta / belfry.alpha() < 1.0 && stack.overturned_block.is_none());
//! // Events say whose they are: 0 the tower's (and the building's), 1 the belfry's.
//! let belfry_impacts = log.events.iter().filter(|e| e.block == 1 && e.kind == EventKind::Impact).count();
//! assert_eq!(belfry_impacts, belfry_run.impacts);
//! # Ok::<(), rocking::Error>(())
//! ```

// Matrices and their rows are indexed by coordinate, as in the formulas.
#![allow(clippy::needless_range_loop)]

pub mod dynamics;
pub mod geometry;
pub mod impact;
mod linalg;
pub mod run;
mod simulate;
#[cfg(test)]
mod tests;

use crate::body::{Building, Friction, Tower};
use crate::regime::{BuildingRegime, Pivot};
use arrayvec::ArrayVec;
pub(crate) use simulate::simulate;
pub use simulate::StackSummary;

/// The most blocks a stack may have.
pub const MAX_BLOCKS: usize = 6;

/// What is wrong with a stack's description.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StackError {
    /// A block's dimension, mass or inertia is not a positive finite number.
    #[error("block {index}: {what} must be a positive finite number, got {value}")]
    NotPositive {
        /// Position of the block in the stack (1 is the tower).
        index: usize,
        /// Which quantity.
        what: &'static str,
        /// The value given.
        value: f64,
    },
    /// A block is wider than the one it stands on.
    #[error("block {index}: width {width} m exceeds the width {below} m of the block below")]
    WiderThanBelow {
        /// Position of the block in the stack.
        index: usize,
        /// Its width (m).
        width: f64,
        /// The width of the block below (m).
        below: f64,
    },
    /// No block, or more than [`MAX_BLOCKS`].
    #[error("a stack has 1 to {MAX_BLOCKS} blocks, got {0}")]
    Count(usize),
    /// Gravity is not a positive finite number.
    #[error("gravity must be a positive finite number, got {0}")]
    Gravity(f64),
}

/// One rigid rectangular block of the stack.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Block {
    width: f64,
    height: f64,
    mass: f64,
    inertia_centre: f64,
}

fn positive(index: usize, what: &'static str, value: f64) -> Result<f64, StackError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(StackError::NotPositive { index, what, value })
    }
}

impl Block {
    /// A block of width `B`, height `H` (m), mass `m` (kg) and moment of
    /// inertia `J` about its own centre of mass (kg·m²). `index` (1 for the
    /// tower) only names the block in an error.
    pub fn new(index: usize, width: f64, height: f64, mass: f64, inertia_centre: f64) -> Result<Self, StackError> {
        Ok(Self {
            width: positive(index, "width", width)?,
            height: positive(index, "height", height)?,
            mass: positive(index, "mass", mass)?,
            inertia_centre: positive(index, "inertia_centre", inertia_centre)?,
        })
    }

    /// A solid uniform block: `J = m (B² + H²) / 12`.
    pub fn solid(index: usize, width: f64, height: f64, mass: f64) -> Result<Self, StackError> {
        Self::new(index, width, height, mass, mass * (width * width + height * height) / 12.0)
    }

    /// The tower as block 1: `B = 2 R sin α`, `H = 2 R cos α` and, by the
    /// parallel-axis theorem, `J = I_O − m R²`.
    pub fn from_tower(tower: &Tower) -> Self {
        let radius = tower.radius();
        Self {
            width: 2.0 * tower.half_width(),
            height: tower.height(),
            mass: tower.mass(),
            inertia_centre: tower.inertia_pivot() - tower.mass() * radius * radius,
        }
    }

    /// Width `B` (m).
    pub fn width(&self) -> f64 {
        self.width
    }
    /// Height `H` (m).
    pub fn height(&self) -> f64 {
        self.height
    }
    /// Mass `m` (kg).
    pub fn mass(&self) -> f64 {
        self.mass
    }
    /// Moment of inertia `J` about the centre of mass (kg·m²).
    pub fn inertia_centre(&self) -> f64 {
        self.inertia_centre
    }
    /// Slenderness `α = atan(B / H)` (rad): the angle past which it falls
    /// on a base that stays put.
    pub fn alpha(&self) -> f64 {
        libm::atan2(self.width, self.height)
    }
    /// Moment of inertia about a base corner, `I_O = J + m (B² + H²) / 4`.
    pub fn inertia_corner(&self) -> f64 {
        self.inertia_centre + self.mass * (self.width * self.width + self.height * self.height) / 4.0
    }
}

/// The mass (kg) of a column of blocks seated on one another, each centred
/// on the one below (`blocks[0]` the lowest), and the height (m) of its
/// centre of mass above the lowest one's base:
/// `h = Σ m_i (z_i + H_i/2) / Σ m_i`, `z_i = H_0 + … + H_(i−1)` the height of
/// block i's base. The one place it is written: the stack's bodies (the
/// blocks above an interface turning as one) and the assessment's column as
/// one rigid block both call it.
pub fn column_centre(blocks: &[Block]) -> (f64, f64) {
    let (mut mass, mut moment, mut base) = (0.0, 0.0, 0.0);
    for block in blocks {
        mass += block.mass;
        moment += block.mass * (base + block.height / 2.0);
        base += block.height;
    }
    (mass, moment / mass)
}

/// The blocks, the building under them (none: a fixed base) and gravity.
#[derive(Debug, Clone, PartialEq)]
pub struct Stack {
    blocks: ArrayVec<Block, MAX_BLOCKS>,
    /// The blocks `k … N` as one body, for each `k` (constants of the
    /// equations where interface `k` alone rocks, read at every evaluation).
    bodies: ArrayVec<dynamics::Body, MAX_BLOCKS>,
    building: Option<Building>,
    gravity: f64,
}

impl Stack {
    /// A stack of `blocks` (block 1 first), each no wider than the one below,
    /// on `building` (or a fixed base), under gravity `g` (m/s²).
    pub fn new(blocks: &[Block], building: Option<Building>, gravity: f64) -> Result<Self, StackError> {
        if blocks.is_empty() || blocks.len() > MAX_BLOCKS {
            return Err(StackError::Count(blocks.len()));
        }
        if !(gravity.is_finite() && gravity > 0.0) {
            return Err(StackError::Gravity(gravity));
        }
        for (k, pair) in blocks.windows(2).enumerate() {
            // To rounding: a tower's width comes back from R and α within a few ulps.
            if pair[1].width > pair[0].width * (1.0 + 4.0 * f64::EPSILON) {
                return Err(StackError::WiderThanBelow {
                    index: k + 2,
                    width: pair[1].width,
                    below: pair[0].width,
                });
            }
        }
        Ok(Self {
            blocks: blocks.iter().copied().collect(),
            bodies: (0..blocks.len()).map(|k| dynamics::Body::above(blocks, k)).collect(),
            building,
            gravity,
        })
    }
    /// The blocks, block 1 first.
    pub fn blocks(&self) -> &[Block] {
        &self.blocks
    }
    /// The number of blocks `N`.
    pub fn len(&self) -> usize {
        self.blocks.len()
    }
    /// Never true: a stack has at least one block.
    pub fn is_empty(&self) -> bool {
        self.blocks.is_empty()
    }
    /// The building, `None` on a fixed base.
    pub fn building(&self) -> Option<&Building> {
        self.building.as_ref()
    }
    /// Gravity `g` (m/s²).
    pub fn gravity(&self) -> f64 {
        self.gravity
    }
    /// The building's mass `m1` (kg), 0 on a fixed base.
    pub(crate) fn building_mass(&self) -> f64 {
        self.building.map_or(0.0, |b| b.mass())
    }
    /// The foundation's friction law (a fixed base's without a building).
    pub(crate) fn friction(&self) -> Friction {
        Friction::of(self.building.as_ref())
    }
    /// `μk σ`: the kinetic friction law per unit normal force, with the sign
    /// of the force moved to the other side of Kane's equations (the law is
    /// proportional to `N`, so it factors out of them).
    pub(crate) fn friction_per_normal(&self, sigma: f64) -> f64 {
        -self.friction().kinetic_friction(sigma, 1.0)
    }
    /// The total sliding mass `m1 + Σ m_k` (kg).
    pub fn total_mass(&self) -> f64 {
        self.building_mass() + self.bodies[0].mass
    }
}

/// What one interface does.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Interface {
    /// Block `k` moves with the block below (`θ_k = θ̇_k = 0`).
    #[default]
    Stuck,
    /// Block `k` rocks on the corner `s_k` of its base.
    Rocking(Pivot),
}

impl Interface {
    /// `s_k` of a rocking interface.
    pub fn pivot(self) -> Option<Pivot> {
        match self {
            Interface::Stuck => None,
            Interface::Rocking(p) => Some(p),
        }
    }
}

/// A regime of the stack: one state per interface and the building's.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct StackRegime {
    /// Interface `k` at index `k − 1`; the entries past the stack's blocks are stuck.
    pub interfaces: [Interface; MAX_BLOCKS],
    /// The building's regime (always stick on a fixed base).
    pub building: BuildingRegime,
}

impl StackRegime {
    /// Everything at rest.
    pub const REST: StackRegime = StackRegime {
        interfaces: [Interface::Stuck; MAX_BLOCKS],
        building: BuildingRegime::Stick,
    };

    /// The regime with interface `k` (0-based) set to `interface`.
    pub fn with(mut self, k: usize, interface: Interface) -> Self {
        self.interfaces[k] = interface;
        self
    }
    /// The regime with the building's regime set.
    pub fn with_building(mut self, building: BuildingRegime) -> Self {
        self.building = building;
        self
    }
}

/// The state of a stack: each interface's rotation and the building's slip.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StackState {
    /// `θ_k` (rad) at index `k − 1`.
    pub theta: [f64; MAX_BLOCKS],
    /// `θ̇_k` (rad/s) at index `k − 1`.
    pub theta_dot: [f64; MAX_BLOCKS],
    /// Slip `u` (m) of the building.
    pub slip: f64,
    /// Slip velocity `u̇` (m/s).
    pub slip_vel: f64,
}
