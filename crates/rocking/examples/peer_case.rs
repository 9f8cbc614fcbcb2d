//! The benchmark case of `scripts/peer/scipy_peer.py`: prints max θ/α, impacts,
//! the time of the 10th impact and the time per case.
//!
//!     [REPEAT=n] [RTOL=x] peer_case [B H A F T [D]]    (m, m, g, Hz, s, s of shaking: default T)
//!
//! RTOL defaults to 1e-8, with atol = rtol / 100 as the peer takes it.
use rocking::{reference::solid_block, simulate, EventKind, EventLog, GroundMotion, Harmonic, Initial, Model, Settings};

fn main() -> Result<(), rocking::Error> {
    let args: Vec<f64> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let (b, h, a, f, t, d) = match args[..] {
        [b, h, a, f, t] => (b, h, a, f, t, t),
        [b, h, a, f, t, d] => (b, h, a, f, t, d),
        _ => (0.5, 2.0, 0.5, 2.0, 20.0, 20.0),
    };
    let g = 9.81;
    let tower = solid_block(b, h);
    let model = Model::new(Some(tower), None, g)?;
    let ground = GroundMotion::Harmonic(Harmonic::new(a * g, f, d, 0.0)?);
    let rtol: f64 = std::env::var("RTOL").ok().and_then(|v| v.parse().ok()).unwrap_or(1e-8);
    let settings = Settings {
        duration: t,
        rtol,
        atol: 1e-2 * rtol,
    };
    let mut log = EventLog::default();
    simulate(&model, &ground, Initial::default(), &settings, &mut log)?;
    let tenth = log.events.iter().filter(|e| e.kind == EventKind::Impact).nth(9).map_or(f64::NAN, |e| e.time);
    let n: usize = std::env::var("REPEAT").ok().and_then(|v| v.parse().ok()).unwrap_or(200);
    let start = std::time::Instant::now();
    let mut s = simulate(&model, &ground, Initial::default(), &settings, &mut ())?;
    for _ in 1..n {
        s = simulate(&model, &ground, Initial::default(), &settings, &mut ())?;
    }
    let per = start.elapsed().as_secs_f64() / n as f64;
    println!(
        "max_theta_over_alpha {:.16} impacts {} impact10 {:.16} overturned {} evals {} per_case {:.3e} s",
        s.max_abs_theta() / tower.alpha(),
        s.impacts,
        tenth,
        s.overturned(),
        s.evaluations,
        per
    );
    Ok(())
}
