//! Ready-made observers: a time history sampled at a fixed spacing, and an
//! event log.

use crate::event::Event;
use crate::observer::{Observer, Sample, Step};

/// Samples the response every `dt` seconds (from `t = 0`), with the
/// displacement and absolute acceleration of extra tower points.
///
/// Sampling reads the dense output; it never changes the integration.
#[derive(Debug, Clone)]
pub struct History {
    dt: f64,
    next: u64,
    points: Vec<(f64, f64)>,
    /// The samples, in time order.
    pub samples: Vec<Sample>,
    /// For each sample, `(dx, abs_acc)` of each extra point, in the order given.
    pub point_values: Vec<Vec<(f64, f64)>>,
}

impl History {
    /// A history sampled every `dt` seconds (> 0) with extra points `(x, y)` (m,
    /// tower coordinates, origin at the base centre).
    pub fn new(dt: f64, points: Vec<(f64, f64)>) -> Self {
        Self {
            dt,
            next: 0,
            points,
            samples: Vec::new(),
            point_values: Vec::new(),
        }
    }
}

impl Observer for History {
    fn wants_steps(&self) -> bool {
        true
    }

    fn on_step(&mut self, step: &Step<'_>) {
        loop {
            let tk = self.next as f64 * self.dt;
            // A sample within rounding of the step's end belongs to it.
            if tk > step.t1 + 1e-9 * self.dt {
                return;
            }
            let mut sample = step.sample(tk.clamp(step.t0, step.t1));
            sample.t = tk;
            self.point_values.push(self.points.iter().map(|&(x, y)| step.point(&sample, x, y)).collect());
            self.samples.push(sample);
            self.next += 1;
        }
    }
}

/// Collects every event.
#[derive(Debug, Clone, Default)]
pub struct EventLog {
    /// The events, in time order.
    pub events: Vec<Event>,
}

impl Observer for EventLog {
    fn on_event(&mut self, event: &Event) {
        self.events.push(*event);
    }
}
