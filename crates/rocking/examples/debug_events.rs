//! Prints the events of a frictionless-building case (debugging aid).
use rocking::{reference::solid_block, simulate, Building, EventLog, GroundMotion, Initial, Model, NormalForce, Settings};
fn main() -> Result<(), rocking::Error> {
    let tower = solid_block(0.5, 2.0);
    let model = Model::new(Some(tower), Some(Building::new(2000.0, 0.0, 0.0, NormalForce::Constant)?), 9.81)?;
    let mut log = EventLog::default();
    let s = simulate(
        &model,
        &GroundMotion::None,
        Initial {
            theta: 0.7 * tower.alpha(),
            theta_dot: 0.0,
        },
        &Settings {
            duration: 1.0,
            rtol: 1e-11,
            atol: 1e-13,
        },
        &mut log,
    )?;
    for e in &log.events {
        println!(
            "{:.9} {:?} th {:.3e} thd {:.4e}->{:.4e} u {:.4e} ud {:.4e}->{:.4e} {:?}",
            e.time, e.kind, e.before.theta, e.before.theta_dot, e.after.theta_dot, e.after.slip, e.before.slip_vel, e.after.slip_vel, e.regime
        );
    }
    println!("{s:?}");
    Ok(())
}
