//! # rocking
//!
//! The seismic response of a slender rigid body (a bell tower, a statue, a
//! column) that may rock on its base, standing on a building that may slide on
//! its foundation with static and kinetic friction: Housner's rocking block
//! coupled with a Coulomb slider. The non-smooth dynamics are integrated with
//! every regime change (uplift, impact, stick, slip, reversal, overturning)
//! located by root finding on the integrator's dense output.
//!
//! The physics is that of `docs/src/model.md`: equations (T)–(B), sign conventions
//! (`θ > 0` leans towards `+x`; a positive ground acceleration drives `θ` and the
//! slip `u` negative), regimes and transitions.
//!
//! ```
//! use rocking::{simulate, Building, GroundMotion, Harmonic, Initial, MassInput, Model, NormalForce, Section, Settings, Tower, TowerGeometry};
//!
//! let g = 9.81;
//! let tower = Tower::from_geometry(&TowerGeometry {
//!     width: 4.0, height: 12.0, depth: None, section: Section::Solid,
//!     mass: MassInput::Mass(1.5e5), inertia_pivot: None, restitution: None,
//! })?;
//! let building = Building::new(2.0e6, 1.25, 1.0, NormalForce::Constant)?;
//! let model = Model::new(Some(tower), Some(building), g)?;
//! // 0.5 g at 2 Hz for 4 s; tan α = 1/3, so the tower rocks, and 0.5 g < μs g: the church holds.
//! let ground = GroundMotion::Harmonic(Harmonic::new(0.5 * g, 2.0, 4.0, 0.0)?);
//! let summary = simulate(&model, &ground, Initial::default(), &Settings { duration: 6.0, ..Settings::default() }, &mut ())?;
//! assert!(summary.impacts > 0 && !summary.overturned());
//! assert!(summary.first_slip_time.is_none());
//! # Ok::<(), rocking::Error>(())
//! ```

mod body;
mod cascade;
mod condition;
mod engine;
mod equations;
mod error;
mod event;
mod extrema;
mod ground;
mod history;
mod impact;
mod integrator;
mod jet;
mod model;
mod observer;
pub mod reference;
mod regime;
mod response;
mod simulate;
pub mod stack;
mod trig;

pub use body::{Building, MassInput, NormalForce, Section, Tower, TowerGeometry};
pub use error::{Error, Parameter};
pub use event::{Event, EventKind};
pub use ground::{AccelerationUnit, CsvOptions, GroundMotion, Harmonic, Pulse, PulseShape, Record, RecordError, RecordFormat, Ricker};
pub use history::{EventLog, History, Sampler};
pub use model::{Derived, Model};
pub use observer::{Flow, Halt, Observer, Sample, Step};
pub use regime::{BuildingRegime, Motion, Pivot, Regime, SlipDirection, State, TowerRegime};
pub use response::{free_motion_overturns, EndReason, EndState, Summary};
pub use simulate::{simulate, simulate_with_vertical, Initial, Settings, MAX_ATOL, MAX_RTOL, MIN_ATOL, MIN_RTOL, REST_ANGULAR_VELOCITY};
