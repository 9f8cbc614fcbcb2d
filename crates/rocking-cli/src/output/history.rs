//! `history.csv`: the columns of [`rocking_scenario::columns::HISTORY`] present
//! in the run's layout, then those of each extra point. Written row by row as
//! the run goes ([`HistoryWriter`] is the sink of a [`rocking::Sampler`]), so
//! memory does not grow with the history's length.

use super::write_value;
use anyhow::Context;
use rocking::{Flow, Halt, Sample};
use rocking_scenario::columns::{history_header, history_values, HistoryRow, Layout, HISTORY, HISTORY_POINTS};
use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

/// Writes the rows of `history.csv` to a file as they come.
pub struct HistoryWriter {
    csv: csv::Writer<BufWriter<File>>,
    layout: Layout,
    buffer: ryu::Buffer,
    /// The name given in messages (the final path, not the staging one).
    shown: PathBuf,
    /// The first write error, reported after the run stops.
    error: Option<csv::Error>,
}

impl HistoryWriter {
    /// Creates `path` and writes the header; `shown` names the file in errors.
    pub fn create(path: &Path, shown: &Path, layout: Layout) -> anyhow::Result<Self> {
        let context = || format!("cannot write {}", shown.display());
        let file = File::create(path).with_context(context)?;
        let mut csv = csv::Writer::from_writer(BufWriter::new(file));
        csv.write_record(history_header(HISTORY, HISTORY_POINTS, &layout)).with_context(context)?;
        Ok(Self {
            csv,
            layout,
            buffer: ryu::Buffer::new(),
            shown: shown.to_path_buf(),
            error: None,
        })
    }

    /// Writes one row; a failed write ends the run.
    pub fn row(&mut self, sample: &Sample, points: &[(f64, f64)]) -> Flow {
        match self.write_row(sample, points) {
            Ok(()) => Flow::Continue(()),
            Err(e) => {
                let message = format!("cannot write {}: {e}", self.shown.display());
                self.error = Some(e);
                Flow::Break(Halt::Fail(message))
            }
        }
    }

    fn write_row(&mut self, sample: &Sample, points: &[(f64, f64)]) -> Result<(), csv::Error> {
        let mut result = Ok(());
        let (csv, buffer) = (&mut self.csv, &mut self.buffer);
        history_values(HISTORY, HISTORY_POINTS, &self.layout, HistoryRow { sample, points }, |v| {
            if result.is_ok() {
                result = write_value(csv, buffer, v);
            }
        });
        result?;
        csv.write_record(None::<&[u8]>)
    }

    /// Flushes the file; the first error of the run if there was one.
    pub fn finish(mut self) -> anyhow::Result<()> {
        let context = || format!("cannot write {}", self.shown.display());
        if let Some(e) = self.error.take() {
            return Err(e).with_context(context);
        }
        self.csv.flush().with_context(context)
    }
}
