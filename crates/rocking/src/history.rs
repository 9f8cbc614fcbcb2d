//! Ready-made observers: a time history sampled at a fixed spacing, and an
//! event log.

use crate::event::Event;
use crate::observer::{Flow, Observer, Sample, Step};

/// The sampling instants `k dt` (from `t = 0`) and the extra points.
#[derive(Debug, Clone)]
struct Clock {
    dt: f64,
    next: u64,
    points: Vec<(f64, f64)>,
    values: Vec<(f64, f64)>,
}

impl Clock {
    fn new(dt: f64, points: Vec<(f64, f64)>) -> Self {
        Self {
            dt,
            next: 0,
            values: Vec::with_capacity(points.len()),
            points,
        }
    }

    /// Hands `sink` every sample that falls in `step`, with the `(dx, abs_acc)`
    /// of each extra point. Sampling reads the dense output; it never changes
    /// the integration.
    fn on_step(&mut self, step: &Step<'_>, sink: &mut impl FnMut(&Sample, &[(f64, f64)]) -> Flow) -> Flow {
        loop {
            let tk = self.next as f64 * self.dt;
            // A sample within rounding of the step's end belongs to it.
            if tk > step.t1 + 1e-9 * self.dt {
                return Flow::Continue(());
            }
            let mut sample = step.sample(tk.clamp(step.t0, step.t1));
            sample.t = tk;
            self.values.clear();
            self.values.extend(self.points.iter().map(|&(x, y)| step.point(&sample, x, y)));
            self.next += 1;
            sink(&sample, &self.values)?;
        }
    }
}

/// Samples the response every `dt` seconds (from `t = 0`), with the
/// displacement and absolute acceleration of extra tower points, and hands
/// each sample to `sink` as it is made. Nothing is kept, so a history of any
/// length streams to a file in constant memory; the sink's
/// `ControlFlow::Break` ends the run.
#[derive(Debug, Clone)]
pub struct Sampler<F> {
    clock: Clock,
    sink: F,
}

impl<F: FnMut(&Sample, &[(f64, f64)]) -> Flow> Sampler<F> {
    /// A sampler every `dt` seconds (> 0) with extra points `(x, y)` (m, tower
    /// coordinates, origin at the base centre); `sink` receives each sample and
    /// the `(dx, abs_acc)` of each extra point, in the order given.
    pub fn new(dt: f64, points: Vec<(f64, f64)>, sink: F) -> Self {
        Self {
            clock: Clock::new(dt, points),
            sink,
        }
    }

    /// The sink, after the run.
    pub fn into_sink(self) -> F {
        self.sink
    }
}

impl<F: FnMut(&Sample, &[(f64, f64)]) -> Flow> Observer for Sampler<F> {
    fn wants_steps(&self) -> bool {
        true
    }

    fn on_step(&mut self, step: &Step<'_>) -> Flow {
        self.clock.on_step(step, &mut self.sink)
    }
}

/// Samples the response every `dt` seconds (from `t = 0`) like [`Sampler`],
/// and keeps every sample in memory (for arrays and figures).
#[derive(Debug, Clone)]
pub struct History {
    clock: Clock,
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
            clock: Clock::new(dt, points),
            samples: Vec::new(),
            point_values: Vec::new(),
        }
    }
}

impl Observer for History {
    fn wants_steps(&self) -> bool {
        true
    }

    fn on_step(&mut self, step: &Step<'_>) -> Flow {
        let (samples, values) = (&mut self.samples, &mut self.point_values);
        self.clock.on_step(step, &mut |sample: &Sample, points: &[(f64, f64)]| {
            samples.push(*sample);
            values.push(points.to_vec());
            Flow::Continue(())
        })
    }
}

/// Collects every event.
#[derive(Debug, Clone, Default)]
pub struct EventLog {
    /// The events, in time order.
    pub events: Vec<Event>,
}

impl Observer for EventLog {
    fn on_event(&mut self, event: &Event) -> Flow {
        self.events.push(*event);
        Flow::Continue(())
    }
}
