//! Shared builders for the physics tests.
#![allow(dead_code, missing_docs, clippy::unwrap_used)]

use rocking::{reference::solid_block, simulate, Building, EventLog, GroundMotion, History, Initial, Model, NormalForce, Settings, Summary, Tower};

pub const G: f64 = 9.81;

/// The block of the speed benchmark: 0.5 m × 2 m, 1000 kg.
pub fn block() -> Tower {
    solid_block(0.5, 2.0)
}

pub fn fixed(tower: Tower) -> Model {
    Model::new(Some(tower), None, G).unwrap()
}

pub fn on_building(tower: Tower, mass: f64, mu_s: f64, mu_k: f64, normal: NormalForce) -> Model {
    Model::new(Some(tower), Some(Building::new(mass, mu_s, mu_k, normal).unwrap()), G).unwrap()
}

/// Tight tolerances: the closed forms are checked far below these.
pub fn tight(duration: f64) -> Settings {
    Settings {
        duration,
        rtol: 1e-11,
        atol: 1e-13,
    }
}

pub fn run(model: &Model, ground: &GroundMotion, initial: Initial, settings: &Settings) -> Summary {
    simulate(model, ground, initial, settings, &mut ()).unwrap()
}

pub fn run_logged(model: &Model, ground: &GroundMotion, initial: Initial, settings: &Settings) -> (Summary, EventLog) {
    let mut log = EventLog::default();
    let s = simulate(model, ground, initial, settings, &mut log).unwrap();
    (s, log)
}

pub fn run_history(model: &Model, ground: &GroundMotion, initial: Initial, settings: &Settings, dt: f64) -> (Summary, History, EventLog) {
    let mut obs = (History::new(dt, vec![]), EventLog::default());
    let s = simulate(model, ground, initial, settings, &mut obs).unwrap();
    (s, obs.0, obs.1)
}
