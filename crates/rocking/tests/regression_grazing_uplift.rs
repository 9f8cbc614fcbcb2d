//! A grazing uplift: the ground acceleration passes the uplift threshold
//! `g tan α` by 4.3e-4 m/s² for 51 µs before falling away, and the tower
//! lifts by 4.5e-14 rad. At the instant of the uplift the rocking `θ̈` is
//! zero, computed as ±1e-16: when the rounding had the wrong sign, the step
//! after the uplift found the impact condition growing from zero at its
//! start, took that for an impact at once (at `θ = θ̇ = 0`, which stands the
//! tower again), and the uplift condition lifted it again at the same
//! instant. The run stopped: "regime switches do not settle at
//! t = 4.57995 s". The impact condition starts its regime on zero and is now
//! armed once the motion has left zero; which way it leaves was decided at
//! the uplift, by the uplift condition.
//!
//! The tower: 4 m × 12 m, on a fixed base, under the synthetic record kt_02
//! (data/records/synthetic/) at the scale where this happened. Its motion,
//! 4.5e-14 rad, is checked against the closed form of the linearised
//! equation under the record's piecewise linear acceleration.
//!
//! The limit of a grazing uplift: a harmonic whose amplitude is the uplift
//! threshold (`amplitude_ratio = 1`) touches `g tan α` at each peak and
//! never passes it, so the tower never lifts. The uplift condition there is
//! zero to rounding; where rounding passed the threshold the tower lifted,
//! never left `θ = 0` (its `θ̈` zero to rounding too), was taken to impact
//! at once, stood, and lifted again at the same instant until the run
//! stopped. Such a tower now falls straight back: a rest, no impact, and no
//! uplift again at that instant.
#![allow(clippy::unwrap_used)]

mod common;
use common::{fixed, run_logged, G};
use rocking::reference::solid_block;
use rocking::{CsvOptions, EventKind, GroundMotion, Harmonic, Initial, Record, RecordFormat, Settings};

/// The scale of kt_02 at which the run stopped.
const SCALE: f64 = 1.111_256_958_597_062_9;

/// The tower's half width and half height (m): `tan α = b / h = 1/3`.
const B: f64 = 2.0;
const H: f64 = 6.0;

fn kt_02() -> Record {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/records/synthetic/kt_02.AT2");
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("cannot read {path}: {e}"));
    Record::parse(&text, Some(RecordFormat::At2), &CsvOptions::default(), G).unwrap().scaled(SCALE)
}

/// The first lift of the tower in closed form. For `|θ|` this small (1e-14)
/// (T) on a fixed base is linear: `ψ̈ = K e(t)` for `ψ = |θ|`, with the
/// excess `e = |a_g| − g tan α` and `K = m h / I_O = 3 h / (4 (b² + h²))` for
/// a solid rectangle. The record is linear between its samples, so `ψ` is a
/// cubic on each interval, integrated here exactly from the uplift (where
/// `e = 0`) to its turning point and on to its return to zero (the first
/// impact). Returns (the uplift instant, max ψ, the impact instant, |θ̇⁻|).
fn first_lift(record: &Record) -> (f64, f64, f64, f64) {
    let (times, values) = (record.times(), record.values());
    let threshold = G * B / H;
    let k = 3.0 * H / (4.0 * (B * B + H * H));
    let j = (0..values.len() - 1).find(|&j| values[j + 1].abs() >= threshold).unwrap();
    let s = values[j + 1].signum();
    let excess = |i: usize| s * values[i] - threshold;
    let slope = |i: usize| (excess(i + 1) - excess(i)) / (times[i + 1] - times[i]);
    let uplift = times[j] - excess(j) / slope(j);
    // (ψ, ψ̇, e) at the start of each interval, the uplift's first.
    let (mut t, mut psi, mut rate, mut e) = (uplift, 0.0, 0.0, 0.0);
    let mut peak = None;
    for i in j.. {
        let c = slope(i);
        let at = |x: f64| {
            (
                psi + rate * x + k * (e * x * x / 2.0 + c * x * x * x / 6.0),
                rate + k * (e * x + c * x * x / 2.0),
            )
        };
        let h = times[i + 1] - t;
        if peak.is_none() {
            // ψ̇ = 0: the root of k c x²/2 + k e x + ψ̇ inside the interval.
            let (qa, qb, qc) = (k * c / 2.0, k * e, rate);
            let disc = qb * qb - 4.0 * qa * qc;
            let x = [(-qb - disc.sqrt()) / (2.0 * qa), (-qb + disc.sqrt()) / (2.0 * qa)]
                .into_iter()
                .filter(|x| *x > 0.0 && *x <= h)
                .fold(f64::NAN, f64::min);
            if disc >= 0.0 && !x.is_nan() {
                peak = Some(at(x).0);
            }
        }
        if let Some(peak) = peak.filter(|_| at(h).0 <= 0.0) {
            // ψ decreases from its peak: one root in the interval, by bisection.
            let (mut lo, mut hi) = (0.0, h);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if at(mid).0 > 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            return (uplift, peak, t + lo, at(lo).1.abs());
        }
        (psi, rate) = at(h);
        (t, e) = (times[i + 1], excess(i + 1));
    }
    unreachable!("the record ends before the tower lands")
}

#[test]
fn a_grazing_uplift_rocks_as_the_linearised_equation_says() {
    let record = kt_02();
    let (uplift, peak, impact, approach) = first_lift(&record);
    let settings = Settings {
        duration: 30.0,
        ..Settings::default()
    };
    let (summary, log) = run_logged(
        &fixed(solid_block(2.0 * B, 2.0 * H)),
        &GroundMotion::Record(record),
        Initial::default(),
        &settings,
    );
    assert!(summary.end_time >= 30.0, "{summary:?}");
    // The uplift instant: the record's linear piece solved for e = 0, as the
    // engine locates it on the same piece; within a few ulps of t = 4.58 s.
    let first = summary.first_uplift_time.unwrap();
    assert!((first - uplift).abs() <= 4e-15, "uplift at {first} s against {uplift} s");
    // Dropping θ from (T) changes θ̈ by at most k g |θ| ≈ 0.12 × 9.81 ×
    // 4.5e-14 = 5e-14 rad/s², against K |e| of 1e-5 to 5e-5 rad/s² over most
    // of the lift: a relative 1e-9 of the motion. 1e-7 is a hundred times
    // that, and a millionth of what a wrong rounding sign or a lost uplift
    // would change.
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-7 * b.abs();
    assert!(close(summary.max_abs_theta(), peak), "max |θ| {} against {peak}", summary.max_abs_theta());
    let landing = log.events.iter().find(|e| e.kind == EventKind::Impact).unwrap();
    // The lift lasts 9.5e-5 s: 1e-7 of it is 1e-11 s.
    assert!((landing.time - impact).abs() <= 1e-11, "first impact at {} s against {impact} s", landing.time);
    assert!(
        close(landing.before.theta_dot.abs(), approach),
        "θ̇⁻ {} against {approach}",
        landing.before.theta_dot
    );
    assert!(peak > 4e-14 && peak < 5e-14, "not the grazing lift of the case: {peak}");
}

/// Harmonics of amplitude `g tan α` (1 and 2 Hz, 6 s of shaking) under the
/// 4 m × 12 m tower and a 12 m × 12 m one (tan α = 1/3 and 1): the exact
/// motion is no motion. The uplift margin is computed to a few ulps of `g`,
/// about 1e-14 m/s²; the cosine near its peak stays within that of the
/// threshold for `2 sqrt(2e-14 / (A ω²))`, at most 2.5e-8 s here (A ω² ≥
/// 129 m/s⁴), and an excess of 1e-14 m/s² over that long lifts the tower by
/// at most `K e t² / 2` < 1e-30 rad (K < 0.2 /m). 1e-20 rad is far above
/// that and far below any motion a real uplift of these towers makes.
#[test]
fn a_harmonic_at_the_uplift_threshold_lifts_nothing() {
    for (width, tan_alpha) in [(2.0 * B, B / H), (2.0 * H, 1.0)] {
        let model = fixed(solid_block(width, 2.0 * H));
        for frequency in [1.0, 2.0] {
            let ground = GroundMotion::Harmonic(Harmonic::new(G * tan_alpha, frequency, 6.0, 0.0).unwrap());
            let settings = Settings {
                duration: 8.0,
                ..Settings::default()
            };
            let (summary, log) = run_logged(&model, &ground, Initial::default(), &settings);
            let case = format!("{width} m wide at {frequency} Hz");
            assert!(summary.end_time >= 8.0, "{case}: {summary:?}");
            assert!(summary.max_abs_theta() <= 1e-20, "{case}: max |θ| {}", summary.max_abs_theta());
            // A tower that lifts and falls straight back stands again at that instant.
            for lift in log.events.iter().filter(|e| e.kind == EventKind::Uplift) {
                let next = log.events.iter().find(|e| e.time >= lift.time && e.kind != EventKind::Uplift).unwrap();
                assert!(next.time - lift.time <= 1e-6, "{case}: the uplift at {} s ends at {} s", lift.time, next.time);
            }
        }
    }
}
