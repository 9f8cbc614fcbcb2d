//! The coupled system: a tower, a building, or both, under gravity. Its
//! equations of motion are in `equations.rs`.

use crate::body::{Building, Tower};
use crate::error::{positive, Error, Parameter};
use crate::stack::{Block, Stack, StackError, MAX_BLOCKS};

/// A tower, a building, or both, under gravity `g`. Valid by construction.
#[derive(Debug, Clone, PartialEq)]
pub struct Model {
    tower: Option<Tower>,
    building: Option<Building>,
    gravity: f64,
    /// The blocks stacked on the tower, the lowest first (none: the tower alone).
    blocks: Vec<Block>,
}

/// Quantities derived from a model without running it (what `rocking check` prints).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Derived {
    /// Slenderness `α` (rad); `None` without a tower.
    pub alpha: Option<f64>,
    /// `R` (m).
    pub radius: Option<f64>,
    /// Frequency parameter `p` (rad/s).
    pub p: Option<f64>,
    /// Restitution `r` of the angular velocity.
    pub restitution: Option<f64>,
    /// Moment of inertia about a base corner (kg·m²).
    pub inertia_pivot: Option<f64>,
    /// Tower mass `m2` (kg).
    pub tower_mass: Option<f64>,
    /// Ground acceleration that uplifts the tower on a fixed base, `tan α` (in g).
    pub uplift_acceleration_g: Option<f64>,
    /// Ground acceleration that makes the building (with the tower at rest) slip, `μs` (in g).
    pub slip_acceleration_g: Option<f64>,
    /// Total sliding mass `M = m1 + m2` (kg).
    pub sliding_mass: Option<f64>,
}

/// Largest gravity accepted (m/s²).
pub const MAX_GRAVITY: f64 = 1e3;

impl Model {
    /// A model of a tower on a fixed base, a building alone, or a tower on a
    /// building, with gravity `g` (m/s², > 0).
    pub fn new(tower: Option<Tower>, building: Option<Building>, gravity: f64) -> Result<Self, Error> {
        let gravity = positive(Parameter::Gravity, gravity)?;
        if gravity > MAX_GRAVITY {
            return Err(Error::InvalidParameter {
                parameter: Parameter::Gravity,
                reason: format!("must be at most {MAX_GRAVITY:.0e} m/s² (a hundred times the Earth's; beyond it the time scale √(R/g) of any tower shrinks below what a run can step through), got {gravity:e}"),
            });
        }
        if tower.is_none() && building.is_none() {
            return Err(Error::InvalidParameter {
                parameter: Parameter::Bodies,
                reason: "a scenario needs a [tower], a [building], or both".into(),
            });
        }
        Ok(Self {
            tower,
            building,
            gravity,
            blocks: Vec::new(),
        })
    }
    /// The model with `blocks` stacked on its tower, the lowest first, each
    /// standing centred on the one below and no wider than it (a belfry on
    /// its shaft, the drums of a column; docs/src/model.md, "A stack of
    /// blocks"). [`crate::simulate`] then runs the stack; without blocks it
    /// runs the tower alone, as before. A restitution given to the tower
    /// applies to a tower alone: with blocks above it, it is an error.
    pub fn with_blocks(self, blocks: &[Block]) -> Result<Self, Error> {
        let invalid = |reason: String| Error::InvalidParameter {
            parameter: Parameter::Blocks,
            reason,
        };
        if blocks.is_empty() {
            return Ok(Self { blocks: Vec::new(), ..self });
        }
        let Some(tower) = self.tower else {
            return Err(invalid("blocks stand on a tower: give a [tower]".into()));
        };
        if blocks.len() > MAX_BLOCKS - 1 {
            return Err(invalid(format!("at most {} blocks stand on the tower, got {}", MAX_BLOCKS - 1, blocks.len())));
        }
        if (tower.restitution() - tower.housner_restitution()).abs() > 1e-12 {
            return Err(Error::InvalidParameter {
                parameter: Parameter::TowerRestitution,
                reason: "applies to a tower alone: with blocks above it, every impact follows the generalized-momentum law of the stack".into(),
            });
        }
        let mut all = vec![Block::from_tower(&tower)];
        all.extend_from_slice(blocks);
        Stack::new(&all, self.building, self.gravity).map_err(|e| match e {
            StackError::WiderThanBelow { index, width, below } => invalid(format!(
                "block {} is {width} m wide, wider than the {below} m of the {} below it",
                index - 1,
                if index == 2 { "tower".to_string() } else { format!("block {}", index - 2) }
            )),
            other => invalid(other.to_string()),
        })?;
        Ok(Self {
            blocks: blocks.to_vec(),
            ..self
        })
    }
    /// The blocks stacked on the tower, the lowest first.
    pub fn blocks(&self) -> &[Block] {
        &self.blocks
    }
    /// The tower and the blocks on it as a [`Stack`]; `None` without blocks.
    pub fn stack(&self) -> Option<Stack> {
        let tower = self.tower.as_ref().filter(|_| !self.blocks.is_empty())?;
        let mut all = vec![Block::from_tower(tower)];
        all.extend_from_slice(&self.blocks);
        Stack::new(&all, self.building, self.gravity).ok()
    }
    /// The tower, if any.
    pub fn tower(&self) -> Option<&Tower> {
        self.tower.as_ref()
    }
    /// The building, if any.
    pub fn building(&self) -> Option<&Building> {
        self.building.as_ref()
    }
    /// Gravity (m/s²).
    pub fn gravity(&self) -> f64 {
        self.gravity
    }
    /// Derived quantities.
    pub fn derived(&self) -> Derived {
        let t = self.tower.as_ref();
        Derived {
            alpha: t.map(Tower::alpha),
            radius: t.map(Tower::radius),
            p: t.map(|t| t.frequency_parameter(self.gravity)),
            restitution: t.map(Tower::restitution),
            inertia_pivot: t.map(Tower::inertia_pivot),
            tower_mass: t.map(Tower::mass),
            uplift_acceleration_g: t.map(|t| libm::tan(t.alpha())),
            slip_acceleration_g: self.building.as_ref().map(|b| b.friction().slip_acceleration_g()),
            sliding_mass: self.building.as_ref().map(|b| b.mass() + t.map_or(0.0, Tower::mass)),
        }
    }
}
