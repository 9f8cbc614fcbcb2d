//! A stack at rest (every interface stuck, the building sticking or none)
//! under a record: nothing moves relative to the ground, so the run goes from
//! one monotone stretch of the input to the next with no integration, and
//! the first transition is where the input first reaches its threshold.
//!
//! Checked against the closed form of a piecewise-linear record: at rest
//! every block moves with the ground, so the lowest interface lifts where
//! `|a_g|` first reaches `Stack::uplift_thresholds()[0]`, and a building
//! slips where it first reaches `μs g` (the friction it needs `M a_g`, the
//! normal force `M g`), each on a linear piece of the record: the instant is
//! the linear interpolation's. A window above the threshold that a sample
//! does not show (the record's first peak, 0.8 of it, and a later dip below
//! minus it between samples) must not be missed, nor one that is not there
//! taken.
#![allow(clippy::unwrap_used)]

mod common;
use common::G;
use rocking::stack::run::{run, RunSettings, StackEventKind};
use rocking::stack::{Block, Stack, StackState};
use rocking::{reference::solid_block, Building, GroundMotion, NormalForce, Record};

/// The record through `(t, a)`: 0 at 0 s, 0.8 of `threshold` at 0.5 s, −0.5
/// of it at 1 s, 1.2 of it at 1.5 s, 0 at 2 s; and where it first reaches
/// `threshold`, on its rise from −0.5 to 1.2 of it.
fn record(threshold: f64) -> (GroundMotion, f64) {
    let values = [0.0, 0.8, -0.5, 1.2, 0.0].map(|v| v * threshold);
    let record = Record::from_samples(vec![0.0, 0.5, 1.0, 1.5, 2.0], values.to_vec()).unwrap();
    let first = 1.0 + 0.5 * (1.0 - -0.5) / (1.2 - -0.5);
    (GroundMotion::Record(record), first)
}

fn settings() -> RunSettings {
    RunSettings {
        duration: 3.0,
        rtol: 1e-8,
        atol: 1e-10,
        sample_interval: 0.1,
    }
}

#[test]
fn a_standing_stack_lifts_where_the_record_reaches_its_threshold() {
    let tower = solid_block(0.5, 2.0);
    let upper = Block::solid(2, 0.3, 0.6, 1000.0 * 0.3 * 0.6).unwrap();
    let stack = Stack::new(&[Block::from_tower(&tower), upper], None, G).unwrap();
    let threshold = stack.uplift_thresholds()[0];
    let (ground, first) = record(threshold);
    let out = run(&stack, &ground, &StackState::default(), &settings()).unwrap();
    let uplift = out.events.iter().find(|e| e.kind == StackEventKind::Uplift(0)).map(|e| e.time).unwrap();
    // The root of a linear condition, located by the bracketing search to a
    // few ulps of the time (1e-15 s): 1e-12 s leaves room for the search's
    // stopping rule.
    assert!((uplift - first).abs() < 1e-12, "uplift at {uplift} against {first}");
    // Nothing before it.
    assert_eq!(out.events[0].kind, StackEventKind::Uplift(0), "{:?}", out.events[0]);
    // Every sample of the rest before it holds the state at rest.
    let before: Vec<_> = out.samples.iter().filter(|s| s.time < first).collect();
    assert_eq!(before.len(), 15);
    assert!(before.iter().all(|s| s.state == StackState::default()), "{before:?}");
}

#[test]
fn a_standing_stack_on_a_building_slips_where_the_record_reaches_mu_s_g() {
    let tower = solid_block(0.5, 2.0);
    let upper = Block::solid(2, 0.3, 0.6, 1000.0 * 0.3 * 0.6).unwrap();
    // μs g below the uplift threshold: the building slips first.
    let mu_s = 0.2;
    let building = Building::new(2.0e4, mu_s, 0.15, NormalForce::Dynamic).unwrap();
    let stack = Stack::new(&[Block::from_tower(&tower), upper], Some(building), G).unwrap();
    assert!(mu_s * G < stack.uplift_thresholds()[0]);
    let (ground, first) = record(mu_s * G);
    let out = run(&stack, &ground, &StackState::default(), &settings()).unwrap();
    assert_eq!(out.events[0].kind, StackEventKind::Slip, "{:?}", out.events[0]);
    // As above: the root of a linear condition.
    assert!((out.events[0].time - first).abs() < 1e-12, "slip at {} against {first}", out.events[0].time);
}

#[test]
fn a_record_below_the_threshold_is_run_without_a_step() {
    let tower = solid_block(0.5, 2.0);
    let stack = Stack::new(&[Block::from_tower(&tower)], None, G).unwrap();
    // 0.99 of g tan α at most: the block stands throughout.
    let (ground, _) = record(0.99 / 1.2 * G * tower.alpha().tan());
    let out = run(&stack, &ground, &StackState::default(), &settings()).unwrap();
    assert!(out.events.is_empty(), "{:?}", out.events);
    assert_eq!(out.evaluations, 0);
    // One sample every 0.1 s over the 3 s, all at rest.
    assert_eq!(out.samples.len(), 31);
    assert!(out.samples.iter().all(|s| s.state == StackState::default()));
}
