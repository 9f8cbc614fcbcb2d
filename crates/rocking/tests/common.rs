//! Shared builders for the physics tests.
#![allow(dead_code, missing_docs, clippy::unwrap_used)]

use rocking::stack::Block;
use rocking::{
    reference::solid_block, simulate, Building, EventLog, GroundMotion, Harmonic, History, Initial, Model, NormalForce, Settings, Step, Summary, Tower,
};

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

/// The bench's two blocks (a 0.5 m × 2 m block of 1000 kg carrying a 0.3 m ×
/// 0.6 m one of the same density) on `building` (or a fixed base) under
/// 0.5 g at 2 Hz for `duration`, at rtol 1e-8.
pub fn two_blocks(building: Option<Building>, duration: f64) -> (Model, GroundMotion, Settings) {
    let upper = Block::solid(2, 0.3, 0.6, 1000.0 * 0.3 * 0.6).unwrap();
    let model = Model::new(Some(block()), building, G).unwrap().with_blocks(&[upper]).unwrap();
    let ground = GroundMotion::Harmonic(Harmonic::new(0.5 * G, 2.0, duration, 0.0).unwrap());
    let settings = Settings {
        duration,
        rtol: 1e-8,
        atol: 1e-10,
    };
    (model, ground, settings)
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

/// The largest value of `f` on an observed step: the best of `per_step`
/// samples, then golden-section search on the bracket around it (a second
/// method for the peaks a run locates on its own).
pub fn step_max(step: &Step<'_>, per_step: usize, f: &dyn Fn(f64) -> f64) -> f64 {
    let h = (step.t1 - step.t0) / per_step as f64;
    let (mut best_t, mut best) = (step.t0, f(step.t0));
    for i in 1..=per_step {
        let t = (step.t0 + i as f64 * h).min(step.t1);
        let v = f(t);
        if v > best {
            (best_t, best) = (t, v);
        }
    }
    let (mut a, mut b) = ((best_t - h).max(step.t0), (best_t + h).min(step.t1));
    let ratio = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..80 {
        let (c, d) = (b - ratio * (b - a), a + ratio * (b - a));
        if f(c) > f(d) {
            b = d;
        } else {
            a = c;
        }
    }
    best.max(f(0.5 * (a + b)))
}
