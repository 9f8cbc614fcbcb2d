//! `[ground]`: the horizontal ground acceleration.
//!
//! Amplitudes are given in g (converted with `simulation.g`) or as
//! `amplitude_ratio = a_p / (g tan α)`; frequencies in Hz or as
//! `frequency_ratio = ω / p`. A record is read from `file`, resolved against the
//! scenario file's folder, when the scenario is built, or taken from `text`
//! (the file's content, where there is no file system: the web page).

use crate::error::{io_reason, ErrorKind, Fault};
use crate::read::{finite, non_negative, positive, Section};
use rocking::{AccelerationUnit, CsvOptions, GroundMotion, Harmonic, Pulse, PulseShape, Record, RecordFormat, Ricker, Tower};
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

/// The types of ground motion, as written in `type`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GroundKind {
    /// No ground motion (free rocking or sliding from the initial state).
    None,
    /// `A sin(2π f t + φ)` for `duration` seconds.
    Harmonic,
    /// One sine cycle.
    SinePulse,
    /// One cosine cycle.
    CosinePulse,
    /// A constant acceleration for `duration` seconds.
    RectangularPulse,
    /// A Ricker wavelet.
    Ricker,
    /// A recorded accelerogram.
    Record,
}

/// The ground types by the name written in `type`.
pub(crate) const KINDS: &[(&str, GroundKind)] = &[
    ("harmonic", GroundKind::Harmonic),
    ("sine-pulse", GroundKind::SinePulse),
    ("cosine-pulse", GroundKind::CosinePulse),
    ("rectangular-pulse", GroundKind::RectangularPulse),
    ("ricker", GroundKind::Ricker),
    ("record", GroundKind::Record),
    ("none", GroundKind::None),
];

impl GroundKind {
    /// The name used in `type`.
    pub fn as_str(self) -> &'static str {
        KINDS.iter().find(|(_, k)| *k == self).map_or("none", |(name, _)| name)
    }

    /// The keys this type takes (each documented in [`crate::keys::SCENARIO_KEYS`]),
    /// besides the table `vertical`, which any type of `[ground]` may hold.
    pub(crate) fn keys(self) -> &'static [&'static str] {
        match self {
            GroundKind::None => &["type"],
            GroundKind::Harmonic => &["type", "amplitude", "amplitude_ratio", "frequency", "frequency_ratio", "duration", "phase"],
            GroundKind::SinePulse | GroundKind::CosinePulse => &["type", "amplitude", "amplitude_ratio", "frequency", "frequency_ratio"],
            GroundKind::RectangularPulse => &["type", "amplitude", "amplitude_ratio", "duration"],
            GroundKind::Ricker => &["type", "amplitude", "amplitude_ratio", "frequency", "frequency_ratio", "t0"],
            GroundKind::Record => &["type", "file", "text", "format", "scale", "units", "dt"],
        }
    }
}

/// The ground motion as resolved from the scenario, for reports (`rocking check`).
#[derive(Debug, Clone, PartialEq)]
pub struct GroundInfo {
    /// The `type`.
    pub kind: GroundKind,
    /// Amplitude (in g), after `amplitude_ratio` is resolved.
    pub amplitude_g: Option<f64>,
    /// Frequency (Hz), after `frequency_ratio` is resolved.
    pub frequency_hz: Option<f64>,
    /// Time after which the ground is still (s); `None` for no motion.
    pub end_time_s: Option<f64>,
    /// Phase (rad) of a harmonic.
    pub phase_rad: Option<f64>,
    /// Centre of a Ricker wavelet (s).
    pub t0_s: Option<f64>,
    /// The record, for `type = "record"`.
    pub record: Option<RecordInfo>,
}

/// What was read from a record file.
#[derive(Debug, Clone, PartialEq)]
pub struct RecordInfo {
    /// The file, resolved against the scenario's folder.
    pub file: PathBuf,
    /// Its layout, given or guessed.
    pub format: RecordFormat,
    /// Number of samples.
    pub samples: usize,
    /// Time step (s) if the samples are evenly spaced.
    pub time_step_s: Option<f64>,
    /// Time of the last sample (s).
    pub duration_s: f64,
    /// The factor applied to every value.
    pub scale: f64,
}

/// A record still to be read (when the scenario is built).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct RecordSpec {
    /// The table it was given in (`ground` or `ground.vertical`), for the keys errors name.
    section: &'static str,
    /// The file, or [`TEXT_NAME`] for a record given as `text`.
    file: PathBuf,
    /// The content given as `text` (then nothing is read from disk).
    text: Option<std::sync::Arc<str>>,
    format: Option<RecordFormat>,
    scale: f64,
    csv: CsvOptions,
    /// Keys given that apply to CSV files only.
    csv_keys: Vec<&'static str>,
}

/// `[ground]` once parsed: a ready motion, or a record to read.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum GroundSpec {
    Ready(GroundMotion, GroundInfo),
    Record(RecordSpec),
}

impl GroundSpec {
    /// The record file read, if any (resolved against the scenario's folder).
    pub(crate) fn record_file(&self) -> Option<&Path> {
        match self {
            GroundSpec::Record(r) => r.file(),
            GroundSpec::Ready(..) => None,
        }
    }

    /// The motion (m/s²) and its description, reading the record if there is
    /// one (from `cache` if it was read before).
    pub(crate) fn load(&self, g: f64, cache: Option<&RecordCache>) -> Result<(GroundMotion, GroundInfo), Fault> {
        match self {
            GroundSpec::Ready(motion, info) => Ok((motion.clone(), info.clone())),
            GroundSpec::Record(spec) => match cache {
                Some(cache) => spec.load_cached(g, cache),
                None => spec.load(g),
            },
        }
    }
}

/// What the ratios need from the rest of the scenario.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Context<'a> {
    pub(crate) tower: Option<&'a Tower>,
    pub(crate) g: f64,
    /// The simulated time (s): a harmonic without `duration` shakes throughout.
    pub(crate) duration: f64,
    /// The folder against which a relative record path is resolved.
    pub(crate) folder: &'a Path,
}

/// The table of `[ground]` that holds the vertical ground acceleration.
pub(crate) const VERTICAL: &str = "vertical";

/// Parses `[ground]`: the horizontal motion, and the vertical one if the
/// table `[ground.vertical]` is given (the same types and keys, positive
/// upwards).
pub(crate) fn parse(s: &Section<'_>, cx: &Context<'_>) -> Result<(GroundSpec, Option<GroundSpec>), Fault> {
    let vertical = match s.get(VERTICAL) {
        Some(v) => Some(parse_motion(&Section::new("ground.vertical", v)?, cx)?),
        None => None,
    };
    Ok((parse_motion(s, cx)?, vertical))
}

/// Parses one motion table: `[ground]` (where `vertical` is a table of its
/// own) or `[ground.vertical]` (where it is not a key).
fn parse_motion(s: &Section<'_>, cx: &Context<'_>) -> Result<GroundSpec, Fault> {
    let kind = s.choice("type", KINDS)?.ok_or_else(|| {
        let names: Vec<String> = KINDS.iter().map(|(n, _)| format!("\"{n}\"")).collect();
        Fault::new(s.key("type"), ErrorKind::Missing(format!("required: one of {}", names.join(", "))))
    })?;
    let horizontal = s.name() == "ground";
    let mut valid = kind.keys().to_vec();
    if horizontal {
        valid.push(VERTICAL);
    }
    let valid = &valid[..];
    // A key of another type is "not applicable"; any other unknown key is refused below.
    let type_keys: Vec<&str> = KINDS.iter().flat_map(|(_, k)| k.keys().iter().copied()).collect();
    for key in s.keys() {
        if type_keys.contains(&key) && !valid.contains(&key) {
            return Err(Fault::new(
                s.key(key),
                ErrorKind::NotApplicable(format!("does not apply to type = \"{}\" (its keys: {})", kind.as_str(), valid.join(", "))),
            ));
        }
    }
    s.only(valid)?;
    s.exclusive("amplitude", "amplitude_ratio")?;
    s.exclusive("frequency", "frequency_ratio")?;
    let mut info = GroundInfo {
        kind,
        amplitude_g: None,
        frequency_hz: None,
        end_time_s: None,
        phase_rad: None,
        t0_s: None,
        record: None,
    };
    let g = cx.g;
    let motion = match kind {
        GroundKind::None => GroundMotion::None,
        GroundKind::Record => return parse_record(s, cx.folder).map(GroundSpec::Record),
        GroundKind::Harmonic => {
            let a = amplitude(s, cx, true)?;
            let f = frequency(s, cx)?;
            let duration = positive(&s.key("duration"), s.number("duration")?.unwrap_or(cx.duration))?;
            let phase = finite(&s.key("phase"), s.number("phase")?.unwrap_or(0.0))?;
            info.phase_rad = Some(phase);
            (info.amplitude_g, info.frequency_hz) = (Some(a), Some(f));
            GroundMotion::Harmonic(Harmonic::new(a * g, f, duration, phase)?)
        }
        GroundKind::SinePulse | GroundKind::CosinePulse => {
            let a = amplitude(s, cx, false)?;
            let f = frequency(s, cx)?;
            let shape = if kind == GroundKind::SinePulse {
                PulseShape::Sine
            } else {
                PulseShape::Cosine
            };
            (info.amplitude_g, info.frequency_hz) = (Some(a), Some(f));
            GroundMotion::Pulse(Pulse::cycle(shape, a * g, f)?)
        }
        GroundKind::RectangularPulse => {
            let a = amplitude(s, cx, false)?;
            let key = s.key("duration");
            let duration = s
                .number("duration")?
                .ok_or_else(|| Fault::new(&key, ErrorKind::Missing("required for type = \"rectangular-pulse\": its length in s".into())))?;
            info.amplitude_g = Some(a);
            GroundMotion::Pulse(Pulse::rectangular(a * g, positive(&key, duration)?)?)
        }
        GroundKind::Ricker => {
            let a = amplitude(s, cx, false)?;
            let f = frequency(s, cx)?;
            let t0 = s.number("t0")?.map(|t0| positive(&s.key("t0"), t0)).transpose()?;
            (info.amplitude_g, info.frequency_hz) = (Some(a), Some(f));
            info.t0_s = Some(t0.unwrap_or(1.5 / f));
            GroundMotion::Ricker(Ricker::new(a * g, f, t0)?)
        }
    };
    info.end_time_s = (kind != GroundKind::None).then(|| motion.end_time());
    Ok(GroundSpec::Ready(motion, info))
}

/// The amplitude in g, from `amplitude` or `amplitude_ratio · tan α`.
/// A harmonic takes `>= 0` (its phase gives the sign); a pulse any sign.
fn amplitude(s: &Section<'_>, cx: &Context<'_>, non_negative_only: bool) -> Result<f64, Fault> {
    let check = |key: &str, v: f64| if non_negative_only { non_negative(key, v) } else { finite(key, v) };
    let bounded = |key: &str, a: f64| -> Result<f64, Fault> {
        if a.abs() > MAX_PEAK_G {
            return Err(Fault::invalid(
                key,
                format!("{a} g is above {MAX_PEAK_G} g (the strongest recorded motions stay below 5 g)"),
            ));
        }
        Ok(a)
    };
    if let Some(a) = s.number("amplitude")? {
        let key = s.key("amplitude");
        return bounded(&key, check(&key, a)?);
    }
    let key = s.key("amplitude_ratio");
    let Some(ratio) = s.number("amplitude_ratio")? else {
        return Err(Fault::new(
            s.key("amplitude"),
            ErrorKind::Missing("required: the peak ground acceleration in g (or amplitude_ratio)".into()),
        ));
    };
    let ratio = check(&key, ratio)?;
    let tower = cx.tower.ok_or_else(|| {
        Fault::new(
            &key,
            ErrorKind::NotApplicable("needs a [tower]: it is a multiple of the tower's uplift acceleration g tan α".into()),
        )
    })?;
    bounded(&key, ratio * tower.alpha().tan())
}

/// The frequency in Hz, from `frequency` or `frequency_ratio · p / 2π`.
fn frequency(s: &Section<'_>, cx: &Context<'_>) -> Result<f64, Fault> {
    if let Some(f) = s.number("frequency")? {
        return positive(&s.key("frequency"), f);
    }
    let key = s.key("frequency_ratio");
    let Some(ratio) = s.number("frequency_ratio")? else {
        return Err(Fault::new(
            s.key("frequency"),
            ErrorKind::Missing("required: the frequency in Hz (or frequency_ratio)".into()),
        ));
    };
    let ratio = positive(&key, ratio)?;
    let tower = cx.tower.ok_or_else(|| {
        Fault::new(
            &key,
            ErrorKind::NotApplicable("needs a [tower]: it is a multiple of the tower's frequency parameter p".into()),
        )
    })?;
    Ok(ratio * tower.frequency_parameter(cx.g) / (2.0 * PI))
}

/// The values of `units`, the acceleration units of a CSV record.
pub const ACCELERATION_UNITS: [(&str, AccelerationUnit); 3] = [
    ("g", AccelerationUnit::G),
    ("m/s2", AccelerationUnit::MetersPerSecond2),
    ("cm/s2", AccelerationUnit::CentimetersPerSecond2),
];

/// How a record given as `text` is named in messages and reports.
const TEXT_NAME: &str = "<text>";

fn parse_record(s: &Section<'_>, folder: &Path) -> Result<RecordSpec, Fault> {
    s.exclusive("file", "text")?;
    let text = s.string("text")?.map(std::sync::Arc::<str>::from);
    let file = match (s.string("file")?, &text) {
        (Some(""), _) => return Err(Fault::invalid(s.key("file"), "must not be empty")),
        (Some(file), _) => folder.join(file),
        (None, Some(_)) => PathBuf::from(TEXT_NAME),
        (None, None) => {
            return Err(Fault::new(
                s.key("file"),
                ErrorKind::Missing("required for type = \"record\": the record's path (or its content as text)".into()),
            ))
        }
    };
    let format = s.choice("format", &[("at2", RecordFormat::At2), ("esm", RecordFormat::Esm), ("csv", RecordFormat::Csv)])?;
    let units = s.choice("units", &ACCELERATION_UNITS)?;
    let dt = s.number("dt")?.map(|dt| positive(&s.key("dt"), dt)).transpose()?;
    let csv_keys: Vec<&'static str> = [("units", units.is_some()), ("dt", dt.is_some())]
        .into_iter()
        .filter(|&(_, given)| given)
        .map(|(k, _)| k)
        .collect();
    if let (Some(f), Some(key)) = (format, csv_keys.first()) {
        if f != RecordFormat::Csv {
            return Err(csv_only(s, key, f));
        }
    }
    Ok(RecordSpec {
        section: s.name(),
        file,
        text,
        format,
        scale: finite(&s.key("scale"), s.number("scale")?.unwrap_or(1.0))?,
        csv: CsvOptions {
            units: units.unwrap_or_default(),
            dt,
        },
        csv_keys,
    })
}

/// The peak of `record` in g (gravity `g`, m/s²) when it is above
/// [`MAX_PEAK_G`]: no ground motion is that strong, the units or the scale
/// are wrong. `None` for a record within the bound.
pub(crate) fn peak_beyond_bound(record: &Record, g: f64) -> Option<f64> {
    let peak_g = record.peak().0 / g;
    // Record values are finite (the reader checks), so the peak is a number.
    (peak_g > MAX_PEAK_G).then_some(peak_g)
}

/// What is wrong with a record `what` ("FILE peaks at") that peaks at `peak_g` g,
/// above [`MAX_PEAK_G`].
pub(crate) fn too_strong(what: &str, peak_g: f64) -> String {
    format!("{what} {peak_g:.3e} g, above {MAX_PEAK_G} g (the strongest recorded motions stay below 5 g: check the units and the scale)")
}

/// The name of a record format as written in `format`.
pub fn record_format_name(format: RecordFormat) -> &'static str {
    match format {
        RecordFormat::Csv => "csv",
        RecordFormat::At2 => "at2",
        RecordFormat::Esm => "esm",
    }
}

fn csv_only(s: &Section<'_>, key: &str, format: RecordFormat) -> Fault {
    Fault::new(
        s.key(key),
        ErrorKind::NotApplicable(format!(
            "applies only to format = \"csv\", not \"{}\" (whose files carry their units and time step)",
            record_format_name(format)
        )),
    )
}

impl RecordSpec {
    /// The record file (resolved); `None` for a record given as `text`.
    pub(crate) fn file(&self) -> Option<&Path> {
        self.text.is_none().then_some(self.file.as_path())
    }

    /// Reads the record (or takes it from `cache`, where a record read
    /// earlier with the same file, format, CSV options and g is kept): the
    /// motion (m/s²) and what was read.
    pub(crate) fn load_cached(&self, g: f64, cache: &RecordCache) -> Result<(GroundMotion, GroundInfo), Fault> {
        // The scale is applied after the cache: cases that differ only by it share a read.
        let key = (RecordSpec { scale: 1.0, ..self.clone() }, g.to_bits());
        let mut entries = cache.entries.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        let (record, format) = match entries.iter().find(|(k, _)| *k == key) {
            Some((_, read)) => read.clone(),
            None => {
                let read = key.0.read(g)?;
                if entries.len() >= cache.capacity {
                    entries.remove(0);
                }
                entries.push((key, read.clone()));
                read
            }
        };
        drop(entries);
        self.finish(record, format, g)
    }

    /// Reads the record: the motion (m/s²) and what was read.
    pub(crate) fn load(&self, g: f64) -> Result<(GroundMotion, GroundInfo), Fault> {
        let (record, format) = self.read(g)?;
        self.finish(record, format, g)
    }

    /// The dotted name of `key` of this record's table.
    fn key(&self, key: &str) -> String {
        format!("{}.{key}", self.section)
    }

    /// Reads and parses the file, unscaled.
    fn read(&self, g: f64) -> Result<(Record, RecordFormat), Fault> {
        let (key, text) = match &self.text {
            Some(text) => (self.key("text"), std::borrow::Cow::Borrowed(&**text)),
            None => {
                let text = read_text(&self.file).map_err(|(reason, os_error)| {
                    Fault::new(
                        self.key("file"),
                        ErrorKind::Read {
                            path: self.file.clone(),
                            reason,
                            os_error,
                        },
                    )
                })?;
                (self.key("file"), std::borrow::Cow::Owned(text))
            }
        };
        let malformed = |source| {
            Fault::new(
                &key,
                ErrorKind::Record {
                    path: self.file.clone(),
                    source,
                },
            )
        };
        let format = match self.format {
            Some(f) => f,
            None => Record::guess_format(&text).map_err(malformed)?,
        };
        if let (RecordFormat::At2 | RecordFormat::Esm, Some(k)) = (format, self.csv_keys.first()) {
            return Err(Fault::new(
                self.key(k),
                ErrorKind::NotApplicable(format!(
                    "applies only to CSV records, and {} reads as \"{}\" (whose files carry their units and time step)",
                    self.file.display(),
                    record_format_name(format)
                )),
            ));
        }
        let record = Record::parse(&text, Some(format), &self.csv, g).map_err(malformed)?;
        Ok((record, format))
    }

    /// The motion and its description, once read: `record` scaled by `scale`.
    fn finish(&self, record: Record, format: RecordFormat, g: f64) -> Result<(GroundMotion, GroundInfo), Fault> {
        let record = record.scaled(self.scale);
        if let Some(peak_g) = peak_beyond_bound(&record, g) {
            // The scale is the one given (1 when absent): exact comparison is meant.
            let (key, what) = if self.scale.to_bits() == 1.0f64.to_bits() {
                (self.key("file"), format!("{} peaks at", self.file.display()))
            } else {
                (self.key("scale"), format!("{} scaled by {} peaks at", self.file.display(), self.scale))
            };
            return Err(Fault::invalid(key, too_strong(&what, peak_g)));
        }
        let info = GroundInfo {
            kind: GroundKind::Record,
            amplitude_g: None,
            frequency_hz: None,
            end_time_s: Some(record.duration()),
            phase_rad: None,
            t0_s: None,
            record: Some(RecordInfo {
                file: self.file.clone(),
                format,
                samples: record.len(),
                time_step_s: record.time_step(),
                duration_s: record.duration(),
                scale: self.scale,
            }),
        };
        Ok((GroundMotion::Record(record), info))
    }
}

/// Largest peak ground acceleration accepted, in g (an amplitude or a
/// record's peak after its scale): far above any earthquake, and far below
/// where the arithmetic of a run loses its meaning.
pub const MAX_PEAK_G: f64 = 100.0;

/// Largest record file read (bytes): 64 bytes a sample leaves room for 1e7 samples.
pub const MAX_RECORD_BYTES: u64 = 640 << 20;

/// The text of a record file, refusing what is not a regular file (a device
/// like `/dev/urandom` never ends) or is larger than [`MAX_RECORD_BYTES`]; or
/// why not (without the OS error number) and the OS error code if any.
fn read_text(path: &Path) -> Result<String, (String, Option<i32>)> {
    crate::file::read_text(path, MAX_RECORD_BYTES).map_err(|e| (io_reason(&e), e.raw_os_error()))
}

/// Records already read, so that the cases of a sweep read a record file once
/// (a sweep over the scale of one accelerogram would otherwise read and parse
/// it for every case), and the towers of an inventory read each record of
/// their set once. Holds at most its capacity of records
/// ([`RecordCache::CAPACITY`] by default), the oldest dropped first; a record
/// that fails to read is not kept (every case that needs it reports the
/// failure). Shared by the threads that build cases.
#[derive(Debug)]
pub struct RecordCache {
    entries: std::sync::Mutex<Vec<(RecordKey, (Record, RecordFormat))>>,
    capacity: usize,
}

/// What a read depends on: the file, format and CSV options (scale 1), and g's bits.
type RecordKey = (RecordSpec, u64);

impl RecordCache {
    /// Records kept at most by default (a sweep over `ground.file` cycles through more).
    pub const CAPACITY: usize = 8;

    /// A cache that keeps up to `capacity` records (at least one).
    pub fn with_capacity(capacity: usize) -> Self {
        Self {
            entries: std::sync::Mutex::default(),
            capacity: capacity.max(1),
        }
    }
}

impl Default for RecordCache {
    fn default() -> Self {
        Self::with_capacity(Self::CAPACITY)
    }
}

impl Clone for RecordCache {
    /// An empty cache of the same capacity: what was read is not part of a sweep's value.
    fn clone(&self) -> Self {
        Self::with_capacity(self.capacity)
    }
}
