//! Regression: a stacked run read the tower's top acceleration (and each
//! interface's friction demand) at the ends of 16 equal parts of every step,
//! so a peak between two of them was read low by the curvature over a
//! sixteenth of a step: 6.7e-5 low on the bench's two blocks on a fixed base
//! (5.85654 against 5.85693 m/s²). The peaks are now located on the
//! solution, on their exact time derivatives, as the tower's are.
//!
//! Checked against a second method: a dense sampling of the run's own
//! motion through an observer (its steps' samples, 200 per step, each
//! computed by `Stack::accelerations` on plain numbers, not on the jets the
//! run locates its peaks with), refined by golden-section search around the
//! best sample of each step.
#![allow(clippy::unwrap_used)]

mod common;
use rocking::{simulate, Building, Flow, Initial, NormalForce, Observer, Step};
use std::ops::ControlFlow;

/// The largest top acceleration of the observed steps.
struct Dense {
    per_step: usize,
    top: f64,
}

impl Observer for Dense {
    fn wants_steps(&self) -> bool {
        true
    }
    fn on_step(&mut self, step: &Step<'_>) -> Flow {
        if step.t1 > step.t0 {
            self.top = self.top.max(common::step_max(step, self.per_step, &|t| step.sample(t).top_abs_acc.abs()));
        }
        ControlFlow::Continue(())
    }
}

/// The bench's two blocks ([`common::two_blocks`]) for 20 s.
fn check(building: Option<Building>) {
    let (model, ground, settings) = common::two_blocks(building, 20.0);
    let bare = simulate(&model, &ground, Initial::default(), &settings, &mut ()).unwrap();
    let mut dense = Dense { per_step: 200, top: 0.0 };
    let watched = simulate(&model, &ground, Initial::default(), &settings, &mut dense).unwrap();
    // Both blocks rock: the peaks are those of a coupled motion.
    let stack = bare.stack.unwrap();
    assert!(
        bare.impacts > 0 && stack.blocks()[0].impacts > 0,
        "{} {}",
        bare.impacts,
        stack.blocks()[0].impacts
    );
    // The same run whether observed or not.
    assert_eq!(bare.max_top_abs_acceleration.to_bits(), watched.max_top_abs_acceleration.to_bits());
    // Both locate the same maximum of the same motion: the run's to the
    // 1e-12 relative of its extremum search (`VALUE_RTOL`), the golden
    // section to rounding (8e-15 measured); the sampling at 16 points per
    // step was 6.7e-5 low.
    let rel = (bare.max_top_abs_acceleration - dense.top).abs() / dense.top;
    assert!(rel <= 1e-12, "top: {} vs {} ({rel:e})", bare.max_top_abs_acceleration, dense.top);
}

#[test]
fn two_blocks_on_a_fixed_base() {
    check(None);
}

#[test]
fn two_blocks_on_a_sliding_building() {
    check(Some(Building::new(2.0e4, 0.4, 0.35, NormalForce::Dynamic).unwrap()));
}
