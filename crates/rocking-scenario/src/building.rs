//! `[building]`: the sliding base (the church without the tower).

use crate::error::Fault;
use crate::read::Section;
use rocking::{Building, NormalForce};

/// The building. `mass` and `mu_static` are required; `mu_kinetic` defaults to
/// `mu_static` (a single Coulomb coefficient), `normal_force` to "constant".
pub(crate) fn parse(s: &Section<'_>) -> Result<Building, Fault> {
    s.only_scenario_keys()?;
    let mass = s.required_number("mass", "the building's mass m1 in kg, without the tower")?;
    let mu_static = s.required_number("mu_static", "the static friction coefficient of the foundation")?;
    let mu_kinetic = s.number("mu_kinetic")?.unwrap_or(mu_static);
    let normal_force = s
        .choice("normal_force", &[("constant", NormalForce::Constant), ("dynamic", NormalForce::Dynamic)])?
        .unwrap_or_default();
    Ok(Building::new(mass, mu_static, mu_kinetic, normal_force)?)
}
