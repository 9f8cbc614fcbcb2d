//! Response spectra of records: the pseudo-acceleration `PSA(T, ξ) = ω² max|x(t)|`
//! of the linear oscillator `ẍ + 2ξωẋ + ω²x = −a_g(t)`, computed exactly for the
//! piecewise-linear record (Nigam & Jennings 1969), the maximum taken over the
//! sample instants (as is the practice) of the record and of a free tail at the
//! same spacing, two periods long (a free motion's largest excursion comes within
//! its first half period).

use crate::elastic::check_damping;
use crate::error::{invalid, Error};
use crate::oscillator::NigamJennings;
use rocking::Record;
use std::f64::consts::PI;

/// The default damping of a response spectrum (% of critical).
pub const DEFAULT_DAMPING_PCT: f64 = 5.0;

/// The default periods of a response spectrum: from 0.02 s to 4 s, 100 values, log-spaced.
pub const DEFAULT_PERIODS: PeriodGrid = PeriodGrid {
    from: 0.02,
    to: 4.0,
    count: 100,
};

/// How many free periods follow the record.
const TAIL_PERIODS: f64 = 2.0;

/// The most periods a [`PeriodGrid`] gives: 10,000 log-spaced over 0.02–4 s
/// are 0.05% apart, far finer than a spectrum's features; each period walks
/// every record, so a count typed with a few zeros too many would run for
/// hours and fill the memory instead of being refused.
pub const MAX_PERIODS: usize = 10_000;

/// The most oscillator steps one call may take (the record's samples and the
/// free tail's `2T/dt` at each period, summed over the periods): a few
/// seconds of work. A period of 10¹² s after a record of 0.01 s, or a record
/// of three samples 10⁻⁹ s apart at the default periods, would take 10¹⁴ or
/// 10¹⁰ steps (hours) and is refused instead. The spectrum of a 100 s record
/// sampled at 1 ms over 10,000 periods takes 10⁹.
pub const MAX_STEPS: f64 = 2e9;

/// Log-spaced periods: `count` values from `from` to `to` (s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PeriodGrid {
    /// The first period (s, > 0).
    pub from: f64,
    /// The last period (s, > from).
    pub to: f64,
    /// How many (≥ 2).
    pub count: usize,
}

impl PeriodGrid {
    /// The periods, checked: `0 < from < to`, `2 ≤ count ≤` [`MAX_PERIODS`]; the ends exact.
    pub fn periods(&self) -> Result<Vec<f64>, Error> {
        let PeriodGrid { from, to, count } = *self;
        if !(from.is_finite() && to.is_finite() && from > 0.0 && to > from) {
            return Err(invalid("periods", format!("need 0 < FROM < TO (s), got {from} to {to}")));
        }
        if count < 2 {
            return Err(invalid("periods", format!("need at least 2 periods, got {count}")));
        }
        if count > MAX_PERIODS {
            return Err(invalid("periods", format!("at most {MAX_PERIODS} periods, got {count}")));
        }
        let ratio = libm::log(to / from) / (count - 1) as f64;
        Ok((0..count)
            .map(|k| if k + 1 == count { to } else { from * libm::exp(ratio * k as f64) })
            .collect())
    }
}

/// The relative displacement of the oscillator at each sample instant of a record
/// and of its free tail.
#[derive(Debug, Clone, PartialEq)]
pub struct OscillatorResponse {
    /// The instants (s): the record's samples, then the tail's.
    pub times: Vec<f64>,
    /// The relative displacement `x` (m) at each.
    pub displacements: Vec<f64>,
}

/// Checks a period (s): finite and > 0.
fn check_period(period: f64) -> Result<f64, Error> {
    if period.is_finite() && period > 0.0 {
        Ok(period)
    } else {
        Err(invalid("period", format!("must be a finite number > 0 (s), got {period}")))
    }
}

/// The sample spacing of the free tail: the record's step, or its mean spacing.
fn tail_spacing(record: &Record) -> f64 {
    let times = record.times();
    record.time_step().unwrap_or((record.duration() - times[0]) / (times.len() - 1) as f64)
}

/// The steps of the free tail after `record` at `period`: two periods at the record's spacing.
fn tail_steps(record: &Record, period: f64) -> f64 {
    (TAIL_PERIODS * period / tail_spacing(record)).ceil().max(1.0)
}

/// Refuses a walk of `record` over `periods` (s, each checked) that would
/// take more than [`MAX_STEPS`] steps, before any is taken.
fn check_steps(record: &Record, periods: &[f64]) -> Result<(), Error> {
    let samples = record.times().len() as f64;
    let steps: f64 = periods.iter().map(|&t| samples + tail_steps(record, t)).sum();
    if steps > MAX_STEPS {
        let longest = periods.iter().copied().fold(0.0, f64::max);
        return Err(invalid(
            "periods",
            format!(
                "a record of {samples} samples {} s apart over the periods up to {longest} s takes {steps:.3e} oscillator steps \
                 (its samples and a free tail of 2 periods at each period), more than {MAX_STEPS:.0e}: give shorter periods, or a record with a coarser time step",
                tail_spacing(record)
            ),
        ));
    }
    Ok(())
}

/// Walks the oscillator of `period` (s) and `damping_pct` over the record and its
/// free tail from rest at the first sample, calling `visit(t, x)` at each instant.
fn walk(record: &Record, period: f64, damping_pct: f64, mut visit: impl FnMut(f64, f64)) {
    let omega = 2.0 * PI / period;
    let xi = damping_pct / 100.0;
    let (times, values) = (record.times(), record.values());
    // A record read from a file with a time step has samples k·dt, whose
    // differences wander by an ulp: one map for all of them.
    let uniform = record.time_step().map(|dt| NigamJennings::new(omega, xi, dt));
    let (mut x, mut v) = (0.0, 0.0);
    visit(times[0], x);
    for k in 1..times.len() {
        let map = uniform.unwrap_or_else(|| NigamJennings::new(omega, xi, times[k] - times[k - 1]));
        (x, v) = map.step(x, v, values[k - 1], values[k]);
        visit(times[k], x);
    }
    // The free tail, at the record's (mean) spacing: a_g = 0 after the last sample.
    let spacing = tail_spacing(record);
    let free = NigamJennings::new(omega, xi, spacing);
    // Within MAX_STEPS (checked by the callers): a count that fits.
    let steps = tail_steps(record, period) as usize;
    let end = record.duration();
    for k in 1..=steps {
        (x, v) = free.step(x, v, 0.0, 0.0);
        visit(end + k as f64 * spacing, x);
    }
}

/// The relative displacement of the oscillator of `period` (s, > 0) and
/// `damping_pct` (% of critical, [0, 100)) at the record's sample instants and
/// its free tail's, from rest: the exact solution for the piecewise-linear record.
pub fn oscillator_response(record: &Record, period: f64, damping_pct: f64) -> Result<OscillatorResponse, Error> {
    check_period(period)?;
    check_damping(damping_pct)?;
    check_steps(record, &[period])?;
    let mut out = OscillatorResponse {
        times: Vec::new(),
        displacements: Vec::new(),
    };
    walk(record, period, damping_pct, |t, x| {
        out.times.push(t);
        out.displacements.push(x);
    });
    Ok(out)
}

/// The pseudo-spectral acceleration `PSA(T, ξ) = ω² max|x|` (m/s², in the record's
/// units) of a record at `period` (s, > 0) and `damping_pct` (% of critical,
/// [0, 100)), the maximum over the sample instants of the record and of a free
/// tail two periods long (Nigam & Jennings 1969).
pub fn pseudo_acceleration(record: &Record, period: f64, damping_pct: f64) -> Result<f64, Error> {
    check_period(period)?;
    check_damping(damping_pct)?;
    check_steps(record, &[period])?;
    let mut peak = 0.0f64;
    walk(record, period, damping_pct, |_, x| peak = peak.max(x.abs()));
    let omega = 2.0 * PI / period;
    Ok(omega * omega * peak)
}

/// The pseudo-acceleration spectrum (m/s², in the record's units) of a record at
/// each of `periods` (s) and `damping_pct` (% of critical); refused when it
/// would take more than [`MAX_STEPS`] steps.
pub fn response_spectrum(record: &Record, periods: &[f64], damping_pct: f64) -> Result<Vec<f64>, Error> {
    for &t in periods {
        check_period(t)?;
    }
    // All the periods' steps counted before the first is taken.
    check_steps(record, periods)?;
    periods.iter().map(|&t| pseudo_acceleration(record, t, damping_pct)).collect()
}
