//! Recorded accelerograms: samples linearly interpolated, zero after the last
//! sample; readers for CSV, PEER NGA `.AT2` and ESM/ITACA ASCII files.

mod at2;
mod csv;
mod esm;
mod scan;

use super::{Piece, Segment};

/// Why a record could not be read or built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RecordError {
    /// A problem on a given line of the file (1-based).
    #[error("line {line}: {reason}")]
    Line {
        /// 1-based line number.
        line: usize,
        /// What is wrong.
        reason: String,
    },
    /// A problem with the record as a whole (sample count, time step, format).
    #[error("{0}")]
    Invalid(String),
}

/// The layout of a record file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RecordFormat {
    /// Comma-separated: `time,acceleration` columns, or one acceleration column with a given `dt`.
    Csv,
    /// PEER NGA `.AT2`: four header lines, values in g.
    At2,
    /// ESM / ITACA ASCII: `KEY: value` header lines, one value per line.
    Esm,
}

/// Units of acceleration values in a file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum AccelerationUnit {
    /// Multiples of gravity (default).
    #[default]
    G,
    /// m/s².
    MetersPerSecond2,
    /// cm/s² (gal).
    CentimetersPerSecond2,
}

impl AccelerationUnit {
    /// The factor to m/s², with gravity `g` (m/s²) for [`AccelerationUnit::G`].
    pub fn to_si(self, g: f64) -> f64 {
        match self {
            AccelerationUnit::G => g,
            AccelerationUnit::MetersPerSecond2 => 1.0,
            AccelerationUnit::CentimetersPerSecond2 => 0.01,
        }
    }
}

/// Options of the CSV layout.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CsvOptions {
    /// Units of the acceleration column.
    pub units: AccelerationUnit,
    /// Time step (s) when the file has a single acceleration column.
    pub dt: Option<f64>,
}

/// A ground-acceleration record: strictly increasing sample times (s, the first >= 0)
/// and accelerations (m/s²).
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    times: Vec<f64>,
    values: Vec<f64>,
}

impl Record {
    /// Samples every `dt` seconds from `t = 0`; values in m/s².
    pub fn uniform(dt: f64, values: Vec<f64>) -> Result<Self, RecordError> {
        if !(dt.is_finite() && dt > 0.0) {
            return Err(RecordError::Invalid(format!("time step must be a finite number > 0, got {dt}")));
        }
        let times = (0..values.len()).map(|k| k as f64 * dt).collect();
        Self::from_samples(times, values)
    }

    /// Samples at given times (s, strictly increasing, the first >= 0); values in m/s².
    pub fn from_samples(times: Vec<f64>, values: Vec<f64>) -> Result<Self, RecordError> {
        if times.len() != values.len() {
            return Err(RecordError::Invalid(format!("{} times but {} values", times.len(), values.len())));
        }
        if times.len() < 2 {
            return Err(RecordError::Invalid(format!("a record needs at least 2 samples, got {}", times.len())));
        }
        if let Some(k) = values.iter().position(|v| !v.is_finite()) {
            return Err(RecordError::Invalid(format!("sample {} is not a finite number", k + 1)));
        }
        if !(times[0].is_finite() && times[0] >= 0.0) {
            return Err(RecordError::Invalid(format!("the first time must be >= 0, got {}", times[0])));
        }
        if let Some(k) = times.windows(2).position(|w| !(w[1].is_finite() && w[1] > w[0])) {
            return Err(RecordError::Invalid(format!(
                "times must increase strictly: sample {} at {} after {}",
                k + 2,
                times[k + 1],
                times[k]
            )));
        }
        Ok(Self { times, values })
    }

    /// Reads a record from the text of a file. `format: None` guesses the layout
    /// from the content. `g` (m/s²) converts values given in g.
    pub fn parse(text: &str, format: Option<RecordFormat>, csv: &CsvOptions, g: f64) -> Result<Self, RecordError> {
        let format = match format {
            Some(f) => f,
            None => Self::guess_format(text)?,
        };
        match format {
            RecordFormat::Csv => csv::parse(text, csv, g),
            RecordFormat::At2 => at2::parse(text, g),
            RecordFormat::Esm => esm::parse(text, g),
        }
    }

    /// Guesses the layout of a record file from its first lines.
    pub fn guess_format(text: &str) -> Result<RecordFormat, RecordError> {
        if esm::looks_like(text) {
            Ok(RecordFormat::Esm)
        } else if at2::looks_like(text) {
            Ok(RecordFormat::At2)
        } else if csv::looks_like(text) {
            Ok(RecordFormat::Csv)
        } else {
            Err(RecordError::Invalid(
                "cannot tell the format (not an AT2 header with NPTS and DT, not ESM `KEY: value` lines, not numeric CSV): give `format`".into(),
            ))
        }
    }

    /// The record with every value multiplied by `factor`.
    pub fn scaled(&self, factor: f64) -> Self {
        Self {
            times: self.times.clone(),
            values: self.values.iter().map(|v| v * factor).collect(),
        }
    }
    /// Sample times (s).
    pub fn times(&self) -> &[f64] {
        &self.times
    }
    /// Sample values (m/s²).
    pub fn values(&self) -> &[f64] {
        &self.values
    }
    /// Number of samples.
    pub fn len(&self) -> usize {
        self.values.len()
    }
    /// Always false: a record has at least two samples.
    pub fn is_empty(&self) -> bool {
        self.values.is_empty()
    }
    /// The time step (s) if the samples are evenly spaced (to 1e-9 relative).
    pub fn time_step(&self) -> Option<f64> {
        let dt = (self.duration() - self.times[0]) / (self.len() - 1) as f64;
        self.times.windows(2).all(|w| ((w[1] - w[0]) - dt).abs() <= 1e-9 * dt).then_some(dt)
    }
    /// Time of the last sample (s).
    pub fn duration(&self) -> f64 {
        self.times[self.times.len() - 1]
    }
    /// Peak `|a|` (m/s²) and its time (s); the sign is in [`Record::values`].
    pub fn peak(&self) -> (f64, f64) {
        let (k, v) = self
            .values
            .iter()
            .enumerate()
            .fold((0, 0.0f64), |(bk, bv), (k, v)| if v.abs() > bv.abs() { (k, *v) } else { (bk, bv) });
        (v.abs(), self.times[k])
    }

    pub(super) fn segment(&self, t: f64) -> Option<Segment> {
        let n = self.times.len();
        if t >= self.times[n - 1] {
            return None;
        }
        if t < self.times[0] {
            return Some(Segment {
                piece: Piece::Constant(0.0),
                end: self.times[0],
                kink: self.times[0],
            });
        }
        // The sample interval [t_k, t_k+1) that holds t.
        let k = self.times.partition_point(|&tk| tk <= t) - 1;
        let (t0, t1) = (self.times[k], self.times[k + 1]);
        let slope = (self.values[k + 1] - self.values[k]) / (t1 - t0);
        Some(Segment {
            piece: Piece::Linear { t0, a0: self.values[k], slope },
            end: t1,
            kink: t1,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// A file of the El Centro 1940 record of the repository (`data/records/`);
    /// a missing file fails the test rather than skipping it.
    fn elcentro(extension: &str) -> String {
        let path = format!("{}/../../data/records/elcentro_1940_ns.{extension}", env!("CARGO_MANIFEST_DIR"));
        std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("cannot read {path}: {e}"))
    }

    #[test]
    fn el_centro_at2() {
        let text = elcentro("AT2");
        assert_eq!(Record::guess_format(&text), Ok(RecordFormat::At2));
        let record = Record::parse(&text, None, &CsvOptions::default(), 9.81).expect("valid AT2");
        assert_eq!(record.len(), 1559);
        assert_relative_eq!(record.time_step().expect("uniform"), 0.02, max_relative = 1e-12);
        let (peak, t) = record.peak();
        assert_relative_eq!(peak / 9.81, 0.31882, max_relative = 1e-12);
        assert_relative_eq!(t, 2.02, max_relative = 1e-12);
        // The peak is negative: -0.31882 g, sample 101.
        assert_relative_eq!(record.values()[101] / 9.81, -0.31882, max_relative = 1e-12);
    }

    #[test]
    fn el_centro_esm_equals_at2() {
        let (at2, esm) = (elcentro("AT2"), elcentro("ASC"));
        assert_eq!(Record::guess_format(&esm), Ok(RecordFormat::Esm));
        let at2 = Record::parse(&at2, Some(RecordFormat::At2), &CsvOptions::default(), 9.81).expect("valid AT2");
        let esm = Record::parse(&esm, None, &CsvOptions::default(), 9.81).expect("valid ESM");
        assert_eq!(esm.len(), 1559);
        assert_relative_eq!(esm.time_step().expect("uniform"), 0.02, max_relative = 1e-12);
        // Both in g: the ESM file was written with 981 cm/s² per g.
        for (e, a) in esm.values().iter().zip(at2.values()) {
            assert_relative_eq!(e * 100.0 / 981.0, a / 9.81, max_relative = 1e-6);
        }
    }

    #[test]
    fn guesses_each_format() {
        assert_eq!(Record::guess_format("a\nb\nc\nNPTS=  2, DT= .01 SEC\n1.0 2.0\n"), Ok(RecordFormat::At2));
        assert_eq!(Record::guess_format("EVENT_NAME: X\nSAMPLING_INTERVAL_S: 0.01\n"), Ok(RecordFormat::Esm));
        assert_eq!(Record::guess_format("time,acc\n0.0,0.1\n"), Ok(RecordFormat::Csv));
        assert!(matches!(Record::guess_format("some text\nmore text\n"), Err(RecordError::Invalid(_))));
    }
}
