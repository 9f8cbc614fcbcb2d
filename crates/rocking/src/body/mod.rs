//! The two bodies: the rocking tower and the sliding building.

mod building;
mod tower;

pub use building::{Building, NormalForce};
pub use tower::{MassInput, Section, Tower, TowerGeometry};
