//! The two bodies: the rocking tower and the sliding building.

mod building;
mod tower;

pub(crate) use building::Friction;
pub use building::{Building, NormalForce};
pub use tower::{MassInput, Section, Tower, TowerGeometry};
