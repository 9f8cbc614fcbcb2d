//! Running a case: the summary, the derived quantities, and the history and
//! events when asked for.

use crate::columns::Layout;
use crate::error::{Error, Fault};
use crate::scenario::Case;
use rocking::{simulate_with_vertical, Derived, Event, EventLog, Flow, History, Observer, Step, Summary};

/// What to record besides the summary.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct RunOptions {
    /// Sample the response every `output_dt` (for `history.csv`).
    pub history: bool,
    /// Keep every event (for `events.csv`).
    pub events: bool,
}

impl RunOptions {
    /// Everything: history and events.
    pub const ALL: Self = Self { history: true, events: true };
    /// The summary only (a sweep).
    pub const SUMMARY: Self = Self { history: false, events: false };
}

/// The result of a run.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// The scenario's name.
    pub name: String,
    /// What the run found.
    pub summary: Summary,
    /// α, R, p, r, … (`None` for an absent body).
    pub derived: Derived,
    /// The time history, if asked for.
    pub history: Option<History>,
    /// Every event, if asked for (else empty).
    pub events: Vec<Event>,
    /// Which optional columns and fields the outputs have.
    pub layout: Layout,
    /// The blocks on the tower, the lowest first (`[[block]]`).
    pub blocks: Vec<rocking::stack::Block>,
}

/// The observer of a run: a history and an event log, each optional.
struct Recorder {
    history: Option<History>,
    events: Option<EventLog>,
}

impl Observer for Recorder {
    fn wants_steps(&self) -> bool {
        self.history.is_some()
    }
    fn on_step(&mut self, step: &Step<'_>) -> Flow {
        match &mut self.history {
            Some(h) => h.on_step(step),
            None => Flow::Continue(()),
        }
    }
    fn on_event(&mut self, event: &Event) -> Flow {
        match &mut self.events {
            Some(log) => log.on_event(event),
            None => Flow::Continue(()),
        }
    }
}

impl Case {
    /// Which optional columns and fields its outputs have.
    pub fn layout(&self) -> Layout {
        Layout {
            points: self.points.len(),
            vertical: self.vertical.is_some(),
            blocks: self.blocks,
        }
    }

    /// Runs the case. A failure of the integration names the scenario file.
    pub fn run(&self, options: RunOptions) -> Result<Outcome, Error> {
        self.run_observed(options, &mut ())
    }

    /// Runs the case, reporting its steps and events to `observer` as well
    /// (a history streamed to a file, a check for Ctrl-C), which may stop or
    /// fail the run ([`rocking::Error::Stopped`], [`rocking::Error::Observer`]).
    pub fn run_observed(&self, options: RunOptions, observer: &mut impl Observer) -> Result<Outcome, Error> {
        let mut recorder = Recorder {
            history: options.history.then(|| History::new(self.output_dt, self.points.clone())),
            events: options.events.then(EventLog::default),
        };
        let summary = simulate_with_vertical(
            &self.model,
            &self.ground,
            self.vertical.as_ref(),
            self.initial,
            &self.settings,
            &mut (&mut recorder, observer),
        )
        .map_err(|e| Fault::from(e).in_file(&self.file))?;
        Ok(Outcome {
            name: self.name.clone(),
            summary,
            derived: self.model.derived(),
            history: recorder.history,
            events: recorder.events.map(|log| log.events).unwrap_or_default(),
            layout: self.layout(),
            blocks: self.model.blocks().to_vec(),
        })
    }
}
