//! Time integration: an explicit Runge–Kutta pair with dense output, and event
//! location on that dense output.

pub(crate) mod bernstein;
mod dop853;
#[rustfmt::skip]
mod dop853_tableau;
mod root;

pub(crate) use dop853::{DenseOutput, Dop853, StepFailure};
pub(crate) use root::{find_crossing, find_crossing_newton};
