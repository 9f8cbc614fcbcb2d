//! Response spectra of records against closed forms (a harmonic's steady state,
//! a rectangular pulse) and against a second method (a fine-step Runge–Kutta
//! integration of the same oscillator).

use approx::assert_relative_eq;
use rocking::{CsvOptions, Record};
use rocking_codes::{oscillator_response, pseudo_acceleration, response_spectrum, Error, PeriodGrid, DEFAULT_PERIODS};
use std::f64::consts::PI;

const G: f64 = 9.81;

fn el_centro() -> Record {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/records/elcentro_1940_ns.AT2");
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("cannot read {path}: {e}"));
    Record::parse(&text, None, &CsvOptions::default(), G).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn ok<T>(r: Result<T, Error>) -> T {
    r.unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn harmonic_reaches_the_closed_form_steady_state() {
    // a_g = A sin Ωt; steady state x = −A [(ω² − Ω²) sin Ωt − 2ξωΩ cos Ωt] / ((ω² − Ω²)² + (2ξωΩ)²).
    let (amplitude, big_omega, period, xi) = (2.0, 2.0 * PI * 1.5, 0.5, 0.05);
    let omega = 2.0 * PI / period;
    let dt = 5e-4;
    let n = 120_001; // 60 s
    let values = (0..n).map(|k| amplitude * (big_omega * k as f64 * dt).sin()).collect();
    let record = ok(Record::uniform(dt, values).map_err(|e| Error::Fit(e.to_string())));
    let response = ok(oscillator_response(&record, period, 100.0 * xi));
    let (d, e) = (omega * omega - big_omega * big_omega, 2.0 * xi * omega * big_omega);
    let amplitude_x = amplitude / (d * d + e * e).sqrt();
    // The recurrence is exact for the chord between samples; the chords differ from
    // the sine by (ΩΔt)²/12 of A on average over an interval (its component at Ω),
    // 9e-6 here. The transient has decayed by e^{−ξω·40 s} = 1e-11 by t = 40 s.
    let tol = 2.0 * (big_omega * dt).powi(2) / 12.0;
    let mut peak = 0.0f64;
    for (&t, &x) in response.times.iter().zip(&response.displacements) {
        if (40.0..=60.0).contains(&t) {
            let exact = -amplitude * (d * (big_omega * t).sin() - e * (big_omega * t).cos()) / (d * d + e * e);
            assert!((x - exact).abs() <= tol * amplitude_x, "t = {t}: {x} against {exact}");
            peak = peak.max(x.abs());
        }
    }
    // The pseudo-acceleration of the steady state, ω² X, over the last 20 s.
    assert_relative_eq!(omega * omega * peak, omega * omega * amplitude_x, max_relative = tol);
}

/// The closed-form response to a constant ground acceleration `a` from rest:
/// `x = −(a/ω²)[1 − e^{−ξωt}(cos ωd t + ξ/√(1−ξ²) sin ωd t)]` and its velocity.
fn step_response(a: f64, omega: f64, xi: f64, t: f64) -> (f64, f64) {
    let r = (1.0 - xi * xi).sqrt();
    let wd = omega * r;
    let e = (-xi * omega * t).exp();
    let x = -a / (omega * omega) * (1.0 - e * ((wd * t).cos() + xi / r * (wd * t).sin()));
    let v = -a / (omega * omega) * (omega / r) * e * (wd * t).sin();
    (x, v)
}

#[test]
fn rectangular_pulse_against_the_closed_form() {
    // a_g = 3 m/s² for 0 ≤ t ≤ 0.37 s, then nothing: the pulse, then a free motion
    // from the pulse's end state. The closed form at the same instants (the record's
    // 0.005 s and the tail's, two periods) gives the same maximum.
    let (a, td, dt): (f64, f64, f64) = (3.0, 0.37, 0.005);
    let n = (td / dt).round() as usize + 1;
    let record = ok(Record::uniform(dt, vec![a; n]).map_err(|e| Error::Fit(e.to_string())));
    for (period, damping) in [(0.2, 5.0), (0.5, 2.0), (1.3, 10.0), (3.0, 0.0)] {
        let omega = 2.0 * PI / period;
        let xi = damping / 100.0;
        let (x0, v0) = step_response(a, omega, xi, record.duration());
        let wd = omega * (1.0 - xi * xi).sqrt();
        let tail = (2.0 * period / dt).ceil() as usize;
        let mut peak = 0.0f64;
        for k in 0..n + tail {
            let t = k as f64 * dt;
            let x = if k < n {
                step_response(a, omega, xi, t).0
            } else {
                let s = t - record.duration();
                (-xi * omega * s).exp() * (x0 * (wd * s).cos() + (v0 + xi * omega * x0) / wd * (wd * s).sin())
            };
            peak = peak.max(x.abs());
        }
        // Round-off of a few hundred steps of a contracting recurrence: far under 1e-10.
        assert_relative_eq!(ok(pseudo_acceleration(&record, period, damping)), omega * omega * peak, max_relative = 1e-10);
    }
}

/// ω² max|x| over the sample instants (and a free tail of two periods), by the
/// classical fourth-order Runge–Kutta method at `substeps` steps per sample interval.
fn runge_kutta_psa(record: &Record, period: f64, xi: f64, substeps: usize) -> f64 {
    let omega = 2.0 * PI / period;
    let (times, values) = (record.times(), record.values());
    let accel = |x: f64, v: f64, ag: f64| -ag - 2.0 * xi * omega * v - omega * omega * x;
    let (mut x, mut v, mut peak) = (0.0f64, 0.0f64, 0.0f64);
    let interval = |t0: f64, t1: f64, a0: f64, a1: f64, x: &mut f64, v: &mut f64| {
        let h = (t1 - t0) / substeps as f64;
        let ag = |s: f64| a0 + (a1 - a0) * s / (t1 - t0);
        for m in 0..substeps {
            let s = m as f64 * h;
            let (k1x, k1v) = (*v, accel(*x, *v, ag(s)));
            let (k2x, k2v) = (*v + 0.5 * h * k1v, accel(*x + 0.5 * h * k1x, *v + 0.5 * h * k1v, ag(s + 0.5 * h)));
            let (k3x, k3v) = (*v + 0.5 * h * k2v, accel(*x + 0.5 * h * k2x, *v + 0.5 * h * k2v, ag(s + 0.5 * h)));
            let (k4x, k4v) = (*v + h * k3v, accel(*x + h * k3x, *v + h * k3v, ag(s + h)));
            *x += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
            *v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        }
    };
    for k in 1..times.len() {
        interval(times[k - 1], times[k], values[k - 1], values[k], &mut x, &mut v);
        peak = peak.max(x.abs());
    }
    let spacing = (record.duration() - times[0]) / (times.len() - 1) as f64;
    for _ in 0..(2.0 * period / spacing).ceil() as usize {
        interval(0.0, spacing, 0.0, 0.0, &mut x, &mut v);
        peak = peak.max(x.abs());
    }
    omega * omega * peak
}

#[test]
fn el_centro_against_fine_step_runge_kutta() {
    // RK4 at 400 steps per 0.02 s sample: ωh ≤ 0.016 at T = 0.02 s, a global
    // error of order (ωh)⁴ ~ 1e-7 of the response; the test asks 1e-6.
    let record = el_centro();
    for period in [0.02, 0.1, 0.35, 1.0, 4.0] {
        let exact = ok(pseudo_acceleration(&record, period, 5.0));
        let rk = runge_kutta_psa(&record, period, 0.05, 400);
        assert_relative_eq!(exact, rk, max_relative = 1e-6);
    }
}

#[test]
fn uneven_samples_against_fine_step_runge_kutta() {
    // Samples at uneven times (spacing 0.004–0.016 s): the map is rebuilt on each interval.
    let times: Vec<f64> = (0..400).map(|k| k as f64 * 0.01 + 0.003 * (k as f64 * 1.7).sin()).collect();
    let values: Vec<f64> = times.iter().map(|t| 2.0 * (5.0 * t).sin() * (-0.3 * t).exp() + (13.0 * t).cos()).collect();
    let record = ok(Record::from_samples(times, values).map_err(|e| Error::Fit(e.to_string())));
    assert!(record.time_step().is_none());
    for period in [0.05, 0.7, 2.5] {
        // ωh ≤ 126·0.016/400 = 0.005: RK4's error ~ 1e-9.
        assert_relative_eq!(
            ok(pseudo_acceleration(&record, period, 5.0)),
            runge_kutta_psa(&record, period, 0.05, 400),
            max_relative = 1e-6
        );
    }
}

#[test]
fn psa_scales_with_the_record_and_tends_to_pga_at_short_periods() {
    let record = el_centro();
    let periods = ok(DEFAULT_PERIODS.periods());
    assert_eq!(periods.len(), 100);
    assert_relative_eq!(periods[0], 0.02, max_relative = 1e-15);
    assert_relative_eq!(periods[99], 4.0, max_relative = 1e-15);
    let psa = ok(response_spectrum(&record, &periods, 5.0));
    let doubled = ok(response_spectrum(&record.scaled(2.0), &periods, 5.0));
    for (a, b) in psa.iter().zip(&doubled) {
        // Linear oscillator: exactly proportional, to the round-off of the recurrence.
        assert_relative_eq!(2.0 * a, *b, max_relative = 1e-12);
    }
    // A very stiff oscillator follows the ground: PSA(0.005 s) → PGA (0.3188 g). The
    // oscillator lags the chord by 2ξ/ω·ȧ_g; 2% is that lag at El Centro's steepest slope.
    let stiff = ok(pseudo_acceleration(&record, 0.005, 5.0));
    assert_relative_eq!(stiff / G, 0.31882, max_relative = 0.02);
}

#[test]
fn bad_periods_and_dampings_are_refused() {
    let record = el_centro();
    assert!(matches!(
        pseudo_acceleration(&record, 0.0, 5.0),
        Err(Error::InvalidParameter { name: "period", .. })
    ));
    assert!(matches!(
        pseudo_acceleration(&record, 1.0, -5.0),
        Err(Error::InvalidParameter { name: "damping", .. })
    ));
    assert!(matches!(
        pseudo_acceleration(&record, 1.0, 100.0),
        Err(Error::InvalidParameter { name: "damping", .. })
    ));
    assert!(matches!(
        PeriodGrid { from: 2.0, to: 1.0, count: 10 }.periods(),
        Err(Error::InvalidParameter { name: "periods", .. })
    ));
    assert!(matches!(
        PeriodGrid { from: 0.1, to: 1.0, count: 1 }.periods(),
        Err(Error::InvalidParameter { name: "periods", .. })
    ));
}
