//! The benchmark case of `scripts/peer/scipy_peer.py`: prints max θ/α, impacts, time per case.
//!
//!     peer_case [B H A F T [D]]    (m, m, g, Hz, s, s of shaking: default T)
use rocking::{reference::solid_block, simulate, GroundMotion, Harmonic, Initial, Model, Settings};

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
    let settings = Settings {
        duration: t,
        rtol: 1e-8,
        atol: 1e-10,
    };
    let n: usize = std::env::var("REPEAT").ok().and_then(|v| v.parse().ok()).unwrap_or(200);
    let start = std::time::Instant::now();
    let mut s = simulate(&model, &ground, Initial::default(), &settings, &mut ())?;
    for _ in 1..n {
        s = simulate(&model, &ground, Initial::default(), &settings, &mut ())?;
    }
    let per = start.elapsed().as_secs_f64() / n as f64;
    println!(
        "max_theta_over_alpha {:.16} impacts {} overturned {} evals {} per_case {:.3e} s",
        s.max_abs_theta() / tower.alpha(),
        s.impacts,
        s.overturned(),
        s.evaluations,
        per
    );
    Ok(())
}
