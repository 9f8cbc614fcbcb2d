//! The engine against a second integration of the model written plainly here
//! from docs/src/model.md, sharing no code with it: a fixed-step classical
//! Runge–Kutta scheme (RK4) on the equations (T)–(B) of each regime, every
//! transition found by a sign change of its condition at a step's end and
//! located by bisection (each trial a fresh RK4 step from the step's start),
//! and the impact law, the impact that ends at rest and Coulomb's decision
//! at `u̇ = 0` written out again. Constant normal force, harmonic input.
//!
//! The cases are the two that the engine got wrong: the tower on its church
//! with `μk = μs` (the default when `mu_kinetic` is left out; the engine
//! stopped with "regime switches do not settle") and with a low restitution on
//! the sliding church (it never finished).
//!
//! Accuracy of the second integration, with steps of `H` = 1e-5 s: RK4's
//! global error is of order `(H ω)⁴` per unit time for motions of angular
//! frequency `ω` (31 rad/s for 5 Hz): 1e-14; the bisection locates each
//! transition to 1e-18 s; the peaks are read at step ends, where a peak of a
//! smooth quantity is missed by at most `max|q̈| (H/2)² / 2`: 1e-10 rad of θ
//! (`|θ̈|` < 10 rad/s²) and 1e-9 m of slip (`|ü|` < 40 m/s²), 3e-8 and 7e-7
//! of the smallest peaks here (3 mrad, 1.5 mm). The engine runs at rtol
//! 1e-11. The bound on the peaks and the final slip, 1e-6 relative, covers
//! these; measured, the two agree to 1.2e-9 (θ) and 7.7e-10 (slip), with the
//! same number of impacts (11, 29, 25).
#![allow(clippy::unwrap_used)]

mod common;
use common::G;
use rocking::{
    simulate, Building, EventKind, EventLog, GroundMotion, Harmonic, Initial, MassInput, Model, NormalForce, Section, Settings, Tower, TowerGeometry,
};

/// Step of the second integration (s).
const H: f64 = 1e-5;
/// `|θ̇⁺|` below which an impact leaves the tower standing (rad/s), as the model says.
const REST: f64 = 1e-9;

/// The bodies, the friction and the input `a_g = A sin(ω t)`.
#[derive(Clone, Copy)]
struct Case {
    m2: f64,
    inertia: f64,
    radius: f64,
    alpha: f64,
    /// Sliding mass `M = m1 + m2`.
    total: f64,
    mu_s: f64,
    mu_k: f64,
    r: f64,
    amplitude: f64,
    omega: f64,
}

#[derive(Clone, Copy, PartialEq, Debug)]
enum TowerState {
    Rest,
    /// On the pivot `s = ±1`.
    Rocking(f64),
}

#[derive(Clone, Copy, PartialEq, Debug)]
enum BuildingState {
    Stick,
    /// Sliding towards `σ = ±1`.
    Slip(f64),
}

/// `(θ, θ̇, u, u̇)`.
type Y = [f64; 4];

/// What the second integration reports.
#[derive(Debug, Default)]
struct Outcome {
    max_abs_theta: f64,
    max_abs_slip: f64,
    final_slip: f64,
    impacts: u32,
    first_uplift: Option<f64>,
    first_slip: Option<f64>,
}

impl Case {
    fn b(&self) -> f64 {
        self.radius * self.alpha.sin()
    }
    fn h(&self) -> f64 {
        self.radius * self.alpha.cos()
    }
    fn a_g(&self, t: f64) -> f64 {
        self.amplitude * (self.omega * t).sin()
    }

    /// `(θ̈, ü)` of (T)–(B) in the regime, `N = M g`.
    fn accelerations(&self, tower: TowerState, building: BuildingState, t: f64, y: &Y) -> (f64, f64) {
        let a_g = self.a_g(t);
        match (tower, building) {
            (TowerState::Rest, BuildingState::Stick) => (0.0, 0.0),
            (TowerState::Rest, BuildingState::Slip(sigma)) => (0.0, -self.mu_k * sigma * G - a_g),
            (TowerState::Rocking(s), BuildingState::Stick) => (self.stuck_theta_ddot(s, a_g, y[0]), 0.0),
            (TowerState::Rocking(s), BuildingState::Slip(sigma)) => {
                // I θ̈ + m2 R cos φ X = −s m2 g R sin φ
                // m2 R cos φ θ̈ + M X = −μk σ M g − s m2 R sin φ θ̇²
                let phi = self.alpha - s * y[0];
                let c = self.m2 * self.radius * phi.cos();
                let r1 = -s * self.m2 * G * self.radius * phi.sin();
                let r2 = -self.mu_k * sigma * self.total * G - s * self.m2 * self.radius * phi.sin() * y[1] * y[1];
                let det = self.inertia * self.total - c * c;
                let theta_ddot = (r1 * self.total - c * r2) / det;
                let x_p = (self.inertia * r2 - c * r1) / det;
                (theta_ddot, x_p - a_g)
            }
        }
    }

    /// Housner's equation with the pivot line moving with the ground.
    fn stuck_theta_ddot(&self, s: f64, a_g: f64, theta: f64) -> f64 {
        let phi = self.alpha - s * theta;
        -self.m2 * self.radius / self.inertia * (s * G * phi.sin() + a_g * phi.cos())
    }

    /// The friction force that keeps the building stuck, (B) with `ü = 0`.
    fn stick_force(&self, tower: TowerState, t: f64, y: &Y) -> f64 {
        let a_g = self.a_g(t);
        match tower {
            TowerState::Rest => self.total * a_g,
            TowerState::Rocking(s) => {
                let phi = self.alpha - s * y[0];
                let theta_ddot = self.stuck_theta_ddot(s, a_g, y[0]);
                self.total * a_g + self.m2 * self.radius * (phi.cos() * theta_ddot + s * phi.sin() * y[1] * y[1])
            }
        }
    }

    /// Whether a standing tower lifts on pivot `s`: the pivot line's
    /// acceleration beyond `g tan α` away from `s`.
    fn lifts(&self, building: BuildingState, t: f64, s: f64) -> bool {
        let x_p = match building {
            BuildingState::Stick => self.a_g(t),
            BuildingState::Slip(sigma) => -self.mu_k * sigma * G,
        };
        -s * x_p > G * self.alpha.tan()
    }

    fn rk4(&self, tower: TowerState, building: BuildingState, t: f64, y: &Y, h: f64) -> Y {
        let f = |t: f64, y: &Y| {
            let (a, b) = self.accelerations(tower, building, t, y);
            [y[1], a, y[3], b]
        };
        let add = |y: &Y, k: &Y, c: f64| -> Y { std::array::from_fn(|i| y[i] + c * k[i]) };
        let k1 = f(t, y);
        let k2 = f(t + h / 2.0, &add(y, &k1, h / 2.0));
        let k3 = f(t + h / 2.0, &add(y, &k2, h / 2.0));
        let k4 = f(t + h, &add(y, &k3, h));
        std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
    }

    /// The impact on pivot `s` (docs/src/model.md, "Impact on a building that
    /// can slide"): `(θ̇⁺, u̇⁺, building after)`.
    fn impact(&self, s: f64, w: f64, v: f64) -> (f64, f64, BuildingState) {
        let (m2b, m2h, inertia, total) = (self.m2 * self.b(), self.m2 * self.h(), self.inertia, self.total);
        let angular = self.r * inertia * w + m2h * v;
        // Stuck through it.
        let w_stick = angular / inertia;
        let p_stick = -total * v + m2h * (w_stick - w);
        let n = -s * m2b * (w_stick + w);
        let mut after = (w_stick, 0.0, BuildingState::Stick);
        if p_stick.abs() > self.mu_s * n.max(0.0) {
            // Sliding: P = −μk σ N = μk σ s m2 b (θ̇⁺ + θ̇⁻).
            let sigma = -p_stick.signum();
            let c = self.mu_k * sigma * s * m2b;
            // I θ̇⁺ + m2 h u̇⁺ = angular;  (m2 h − c) θ̇⁺ + M u̇⁺ = M v + (m2 h + c) w.
            let rhs = total * v + (m2h + c) * w;
            let det = inertia * total - m2h * (m2h - c);
            let w_slide = (angular * total - m2h * rhs) / det;
            let v_slide = (inertia * rhs - (m2h - c) * angular) / det;
            if v_slide * sigma > 0.0 {
                after = (w_slide, v_slide, BuildingState::Slip(sigma));
            }
        }
        if after.0 * w < 0.0 {
            // It ends at rest: θ̇⁺ = 0, N = −s m2 b θ̇⁻, the friction decided again.
            let n = -s * m2b * w;
            let p_stick = -total * v - m2h * w;
            after = if p_stick.abs() <= self.mu_s * n {
                (0.0, 0.0, BuildingState::Stick)
            } else {
                let sigma = -p_stick.signum();
                (0.0, v + (m2h * w - self.mu_k * sigma * n) / total, BuildingState::Slip(sigma))
            };
        }
        if after.0.abs() < REST && after.1.abs() < REST * self.radius {
            after = (after.0, 0.0, BuildingState::Stick);
        }
        after
    }
}

/// The conditions of a regime, negative while it holds.
#[derive(Clone, Copy, PartialEq, Debug)]
enum Cond {
    Uplift,
    Impact,
    Overturn,
    SlipStart,
    SlipStop,
}

/// Integrates `case` for `duration` seconds from rest.
fn integrate(case: &Case, duration: f64) -> Outcome {
    let mut out = Outcome::default();
    let (mut tower, mut building) = (TowerState::Rest, BuildingState::Stick);
    let mut t = 0.0;
    let mut y: Y = [0.0; 4];
    // Impact and slip stop start on zero: armed once they have been negative.
    let mut armed = false;
    let value = |tower: TowerState, building: BuildingState, c: Cond, t: f64, y: &Y| -> f64 {
        match (c, tower, building) {
            (Cond::Uplift, TowerState::Rest, BuildingState::Stick) => case.a_g(t).abs() - G * case.alpha.tan(),
            (Cond::Impact, TowerState::Rocking(s), _) => -s * y[0],
            (Cond::Overturn, TowerState::Rocking(s), _) => s * y[0] - std::f64::consts::FRAC_PI_2,
            (Cond::SlipStart, _, BuildingState::Stick) => case.stick_force(tower, t, y).abs() - case.mu_s * case.total * G,
            (Cond::SlipStop, _, BuildingState::Slip(sigma)) => -sigma * y[3],
            _ => -1.0,
        }
    };
    let settle = |t: f64, y: &mut Y, tower: &mut TowerState, building: &mut BuildingState, armed: &mut bool, out: &mut Outcome| {
        for _ in 0..16 {
            let slip_demand = case.stick_force(*tower, t, y);
            let slips = *building == BuildingState::Stick && slip_demand.abs() > case.mu_s * case.total * G;
            match *tower {
                TowerState::Rest => {
                    // Both hold at a jump: the lower threshold is passed first.
                    let slip_first = slips && case.mu_s < case.alpha.tan();
                    let lift = [-1.0, 1.0].into_iter().find(|&s| case.lifts(*building, t, s));
                    if let (Some(s), false) = (lift, slip_first) {
                        *tower = TowerState::Rocking(s);
                        out.first_uplift.get_or_insert(t);
                        *armed = false;
                        continue;
                    }
                }
                TowerState::Rocking(s) => {
                    // Just lifted, and the building as it now moves no longer lifts it.
                    if y[0] == 0.0 && y[1] == 0.0 && !case.lifts(*building, t, s) {
                        *tower = TowerState::Rest;
                        continue;
                    }
                }
            }
            if slips {
                *building = BuildingState::Slip(-slip_demand.signum());
                out.first_slip.get_or_insert(t);
                *armed = false;
                continue;
            }
            return;
        }
        panic!("no regime settles at t = {t}");
    };
    settle(t, &mut y, &mut tower, &mut building, &mut armed, &mut out);
    while t < duration {
        let h = H.min(duration - t);
        let y1 = case.rk4(tower, building, t, &y, h);
        let conds = [Cond::Uplift, Cond::Impact, Cond::Overturn, Cond::SlipStart, Cond::SlipStop];
        // The earliest condition that crosses zero in the step, located by bisection.
        let mut first: Option<(f64, Cond)> = None;
        for c in conds {
            let v0 = value(tower, building, c, t, &y);
            let v1 = value(tower, building, c, t + h, &y1);
            let starts_on_zero = matches!(c, Cond::Impact | Cond::SlipStop);
            let crosses = v1 > 0.0 && (v0 <= 0.0 || (starts_on_zero && !armed));
            if !crosses {
                continue;
            }
            assert!(!starts_on_zero || armed, "{c:?} at t = {t}: the motion did not leave zero");
            let (mut lo, mut hi) = (0.0, h);
            for _ in 0..64 {
                let mid = 0.5 * (lo + hi);
                if value(tower, building, c, t + mid, &case.rk4(tower, building, t, &y, mid)) > 0.0 {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            if first.is_none_or(|(tf, _)| hi < tf) {
                first = Some((hi, c));
            }
        }
        let Some((tau, c)) = first else {
            t += h;
            y = y1;
            if value(tower, building, Cond::Impact, t, &y) < 0.0 || value(tower, building, Cond::SlipStop, t, &y) < 0.0 {
                armed = true;
            }
            out.max_abs_theta = out.max_abs_theta.max(y[0].abs());
            out.max_abs_slip = out.max_abs_slip.max(y[2].abs());
            continue;
        };
        y = case.rk4(tower, building, t, &y, tau);
        t += tau;
        out.max_abs_slip = out.max_abs_slip.max(y[2].abs());
        armed = false;
        match c {
            // `settle` lifts it (the pivot line's acceleration on a sliding
            // building is constant: that uplift holds at once or never).
            Cond::Uplift => {}
            Cond::Overturn => panic!("the tower overturned at t = {t}"),
            Cond::SlipStart => {
                let f = case.stick_force(tower, t, &y);
                building = BuildingState::Slip(-f.signum());
                out.first_slip.get_or_insert(t);
            }
            Cond::SlipStop => {
                // Coulomb at u̇ = 0.
                y[3] = 0.0;
                let f = case.stick_force(tower, t, &y);
                building = if f.abs() <= case.mu_s * case.total * G {
                    BuildingState::Stick
                } else {
                    BuildingState::Slip(-f.signum())
                };
            }
            Cond::Impact => {
                let TowerState::Rocking(s) = tower else { unreachable!() };
                out.impacts += 1;
                let (w, v, after) = case.impact(s, y[1], y[3]);
                y[0] = 0.0;
                y[1] = w;
                y[3] = v;
                building = after;
                tower = if w.abs() < REST { TowerState::Rest } else { TowerState::Rocking(-s) };
                if tower == TowerState::Rest {
                    y[1] = 0.0;
                }
            }
        }
        settle(t, &mut y, &mut tower, &mut building, &mut armed, &mut out);
    }
    out.final_slip = y[2];
    out
}

/// The tower on its church (4 m × 12 m, 150 t, solid; 2,000 t of church)
/// under 1.5 g at 5 Hz, as the engine and as the second integration.
fn compare(mu_s: f64, mu_k: f64, restitution: Option<f64>, duration: f64) -> (rocking::Summary, Outcome, EventLog) {
    let tower = Tower::from_geometry(&TowerGeometry {
        width: 4.0,
        height: 12.0,
        depth: None,
        section: Section::Solid,
        mass: MassInput::Mass(1.5e5),
        inertia_pivot: None,
        restitution,
    })
    .unwrap();
    let model = Model::new(Some(tower), Some(Building::new(2.0e6, mu_s, mu_k, NormalForce::Constant).unwrap()), G).unwrap();
    let (amplitude, frequency) = (1.5 * G, 5.0);
    let ground = GroundMotion::Harmonic(Harmonic::new(amplitude, frequency, 10.0, 0.0).unwrap());
    // The engine far tighter than its default, so that the comparison
    // measures the second integration and the model, not the tolerance.
    let settings = Settings {
        duration,
        rtol: 1e-11,
        atol: 1e-13,
    };
    let mut log = EventLog::default();
    let summary = simulate(&model, &ground, Initial::default(), &settings, &mut log).unwrap();
    let case = Case {
        m2: tower.mass(),
        inertia: tower.inertia_pivot(),
        radius: tower.radius(),
        alpha: tower.alpha(),
        total: 2.0e6 + tower.mass(),
        mu_s,
        mu_k,
        r: tower.restitution(),
        amplitude,
        omega: std::f64::consts::TAU * frequency,
    };
    (summary, integrate(&case, duration), log)
}

fn report(summary: &rocking::Summary, outcome: &Outcome) -> String {
    format!("engine {summary:?}\nsecond {outcome:?}")
}

/// Relative differences of the peaks and the final slip.
fn differences(summary: &rocking::Summary, outcome: &Outcome) -> [f64; 3] {
    let theta = summary.theta_range.0.abs().max(summary.theta_range.1.abs());
    [
        (theta - outcome.max_abs_theta).abs() / theta,
        (summary.max_abs_slip - outcome.max_abs_slip).abs() / summary.max_abs_slip,
        (summary.final_slip - outcome.final_slip).abs() / summary.max_abs_slip,
    ]
}

/// `mu_kinetic` left out: μk = μs = 1.25. Over 3 s the church slides in
/// every cycle of the shaking and the tower rocks through a dozen impacts.
#[test]
fn default_kinetic_friction_on_the_tower_on_church() {
    let (summary, outcome, _) = compare(1.25, 1.25, None, 3.0);
    let text = report(&summary, &outcome);
    assert_eq!(u64::from(outcome.impacts), summary.impacts, "{text}");
    assert!(summary.impacts >= 5 && summary.max_abs_slip > 1e-3, "{text}");
    // The transitions are located to 1e-12 s by both: their instants agree to 1e-9 s.
    assert!((summary.first_slip_time.unwrap() - outcome.first_slip.unwrap()).abs() < 1e-9, "{text}");
    assert!((summary.first_uplift_time.unwrap() - outcome.first_uplift.unwrap()).abs() < 1e-9, "{text}");
    for d in differences(&summary, &outcome) {
        assert!(d < 1e-6, "{d:e}\n{text}");
    }
}

/// A low restitution on the sliding church: r = 0.2 and r = 0, where
/// impacts end at rest on the church.
#[test]
fn low_restitution_on_the_sliding_church() {
    for r in [0.2, 0.0] {
        let (summary, outcome, log) = compare(1.25, 1.0, Some(r), 3.0);
        let text = report(&summary, &outcome);
        assert_eq!(u64::from(outcome.impacts), summary.impacts, "r = {r}\n{text}");
        let at_rest = log.events.iter().filter(|e| e.kind == EventKind::Impact && e.after.theta_dot == 0.0).count();
        assert!(r > 0.0 || at_rest > 0, "r = 0: some impacts must end at rest\n{text}");
        for d in differences(&summary, &outcome) {
            assert!(d < 1e-6, "r = {r}: {d:e}\n{text}");
        }
    }
}
