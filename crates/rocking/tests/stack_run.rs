//! Runs of a two-block stack against conservation laws, closed forms and the
//! one-block engine: energy between impacts and its loss at each impact,
//! Housner's ratio for a belfry on a seated shaft, horizontal momentum on a
//! frictionless building, mirror symmetry, independence of the sampling, and a
//! belfry that cannot rock equal to one block of the combined shape.

#[path = "support/stack_two.rs"]
mod two;

use rocking::stack::run::{run, RunSettings, StackEventKind, StackRun};
use rocking::stack::{Block, Interface, Stack, StackState, MAX_BLOCKS};
use rocking::{simulate, Building, GroundMotion, Harmonic, History, Initial, Model, NormalForce, Pivot, Settings, Tower};
use two::{balance, belfry, shaft, Two};

const G: f64 = 9.81;

fn tight(duration: f64) -> RunSettings {
    RunSettings {
        duration,
        rtol: 1e-11,
        atol: 1e-13,
        sample_interval: 0.01,
    }
}

fn released(theta: [f64; 2]) -> StackState {
    let mut s = StackState::default();
    s.theta[..2].copy_from_slice(&theta);
    s
}

fn sign(i: Interface) -> f64 {
    i.pivot().map_or(1.0, Pivot::sign)
}

/// Energy after the last event before each sample equals the energy at the
/// sample (no input, fixed base: nothing works on the stack between events).
fn check_energy_between_events(stack: &Stack, run: &StackRun, tol: f64) {
    let mut e = stack.energy(&run.samples[0].regime, &run.samples[0].state);
    let mut events = run.events.iter().peekable();
    for sample in &run.samples {
        while let Some(ev) = events.next_if(|ev| ev.time < sample.time) {
            e = stack.energy(&ev.regime, &ev.after);
        }
        let now = stack.energy(&sample.regime, &sample.state);
        assert!((now - e).abs() <= tol, "t = {}: {now} vs {e}", sample.time);
    }
}

/// Shaft and belfry both released leaning (θ_1 = 0.05, θ_2 = −0.1) on a
/// fixed base with no input. Between events the energy is constant; at each
/// impact the velocities after it are those of the angular-momentum balances
/// about the corners (`support/stack_two.rs`, hand kinematics), and so is the
/// energy kept, `E⁺/E⁻ = T(θ̇⁺)/T(θ̇⁻)` (the potential energy does not jump).
#[test]
fn energy_of_a_free_two_block_stack() {
    let stack = Stack::new(&[shaft(), belfry()], None, G).expect("a valid stack");
    let run = run(&stack, &GroundMotion::None, &released([0.05, -0.1]), &tight(6.0)).expect("the run");
    assert!(run.overturned.is_none());
    // rtol 1e-11 on states of order 0.1 rad and 1 rad/s, over ~600 steps:
    // energy drifts by far less than 1e-8 of the potential energy scale
    // (m g H ~ 6e7 J), i.e. 0.6 J.
    let scale = stack.total_mass() * G * 20.0;
    check_energy_between_events(&stack, &run, 1e-8 * scale);
    let mut checked = [0usize; 2];
    for ev in &run.events {
        let StackEventKind::Impact(k) = ev.kind else { continue };
        let b = &ev.before;
        let a = &ev.after;
        let before = Two::new(
            shaft(),
            belfry(),
            sign(ev.regime_before.interfaces[0]),
            b.theta[0],
            sign(ev.regime_before.interfaces[1]),
            b.theta[1],
        );
        let after = Two::new(
            shaft(),
            belfry(),
            sign(ev.regime.interfaces[0]),
            a.theta[0],
            sign(ev.regime.interfaces[1]),
            a.theta[1],
        );
        let rocking = [ev.regime.interfaces[0] != Interface::Stuck, ev.regime.interfaces[1] != Interface::Stuck];
        let (v1, v2) = balance(&after, &before, rocking, b.theta_dot[0], b.theta_dot[1]);
        let w = b.theta_dot[0].abs() + b.theta_dot[1].abs();
        // One small linear solve each way: 1e-12 of the velocities.
        assert!(
            (a.theta_dot[0] - v1).abs() < 1e-12 * w && (a.theta_dot[1] - v2).abs() < 1e-12 * w,
            "t = {}: {a:?} vs ({v1}, {v2})",
            ev.time
        );
        let kept = after.kinetic_energy(v1, v2) / before.kinetic_energy(b.theta_dot[0], b.theta_dot[1]);
        let e0 = stack.energy(&ev.regime_before, b);
        let e1 = stack.energy(&ev.regime, a);
        let potential = e0 - before.kinetic_energy(b.theta_dot[0], b.theta_dot[1]);
        // The energies differ from the hand ones by rounding of sums of order 1e7 J.
        assert!(
            (e1 - (potential + kept * (e0 - potential))).abs() < 1e-9 * scale,
            "t = {}: {e1} vs kept {kept}",
            ev.time
        );
        assert!(kept < 1.0);
        checked[k] += 1;
    }
    assert!(checked[0] >= 3 && checked[1] >= 3, "impacts checked per interface: {checked:?}");
}

/// A column of `n` drums, 1 m × 1.5 m of 3.6 t each, for every size the
/// run is built for (one to [`MAX_BLOCKS`]: it is sized to the stack),
/// released with every drum leaning 0.04 rad on alternate sides on a fixed
/// base with no input. Between events the energy is constant; the drums
/// lift, rock and land (every interface impacts) and the run loses energy
/// only there. rtol 1e-11 over 1.5 s: the energy drifts by about 1e-12 of
/// the column's `m g H` scale (measured); 1e-10 leaves a hundredfold margin
/// for rounding, while a wrong term of the equations moves it by far more.
#[test]
fn a_column_of_every_size_keeps_its_energy_between_impacts() {
    for n in 1..=MAX_BLOCKS {
        let drums: Vec<Block> = (1..=n).map(|k| Block::solid(k, 1.0, 1.5, 3.6e3).expect("a valid drum")).collect();
        let stack = Stack::new(&drums, None, G).expect("a valid column");
        let mut start = StackState::default();
        for k in 0..n {
            start.theta[k] = if k % 2 == 0 { 0.04 } else { -0.04 };
        }
        let out = run(&stack, &GroundMotion::None, &start, &tight(1.5)).expect("the run");
        assert!(out.overturned.is_none(), "{n} drums: none overturns");
        let scale = stack.total_mass() * G * 1.5 * n as f64;
        check_energy_between_events(&stack, &out, 1e-10 * scale);
        let (first, last) = (stack.energy(&out.samples[0].regime, &out.samples[0].state), {
            let s = out.samples.last().expect("samples");
            stack.energy(&s.regime, &s.state)
        });
        assert!(last < first, "{n} drums: the impacts take energy ({last} J of {first} J left)");
        for k in 0..n {
            assert!(
                out.events.iter().any(|e| e.kind == StackEventKind::Impact(k)),
                "{n} drums: interface {k} impacts"
            );
        }
    }
}

/// A belfry 3 m × 6 m rocking freely on a squat shaft 8 m × 4 m that never
/// lifts: every impact is Housner's with the belfry's own
/// `r = 1 − 1.5 sin²α_2`, `tan α_2 = 1.5/3`, so `sin²α_2 = 0.2`, `r = 0.7` and
/// the impact keeps `r² = 0.49` of the kinetic energy.
#[test]
fn belfry_on_a_seated_shaft_loses_housners_energy() {
    let base = Block::solid(1, 8.0, 4.0, 5.0e5).expect("a valid base");
    let stack = Stack::new(&[base, belfry()], None, G).expect("a valid stack");
    let run = run(&stack, &GroundMotion::None, &released([0.0, 0.2]), &tight(4.0)).expect("the run");
    let (mut impacts, mut energies) = (0, 0);
    for ev in &run.events {
        assert!(
            !matches!(ev.kind, StackEventKind::Uplift(0) | StackEventKind::Impact(0)),
            "the base moved: {ev:?}"
        );
        if let StackEventKind::Impact(1) = ev.kind {
            let ratio = ev.after.theta_dot[1] / ev.before.theta_dot[1];
            // A 1×1 balance of a few products.
            assert!((ratio - 0.7).abs() < 1e-13, "{ratio}");
            // The library's energy less the potential energy of the pose
            // (the same before and after): the kinetic energy kept.
            let at_rest = |state: &StackState| StackState { theta_dot: [0.0; 6], ..*state };
            let kinetic = |regime, state: &StackState| stack.energy(regime, state) - stack.energy(regime, &at_rest(state));
            let kept = kinetic(&ev.regime, &ev.after) / kinetic(&ev.regime_before, &ev.before);
            // The difference cancels a potential energy of 2e7 J down to the
            // kinetic energy: 1e-16 × 2e7 J per term, 1e-14 × 2e7 J relative to
            // it leaves a margin of a hundred. The last, tiny rebounds (the
            // accumulation that seats the belfry) fall below that rounding.
            let kinetic_before = kinetic(&ev.regime_before, &ev.before);
            if kinetic_before > 1e3 {
                assert!(
                    (kept - 0.49).abs() < 1e-14 * 2.0e7 / kinetic_before,
                    "{kept} (kinetic energy {kinetic_before} J)"
                );
                energies += 1;
            }
            impacts += 1;
        }
    }
    assert!(impacts >= 5 && energies >= 3, "{impacts} impacts, {energies} energies checked");
    assert!(run.events.iter().any(|e| e.kind == StackEventKind::Rest(1)), "the belfry comes to rest");
}

/// On a frictionless building with no input the horizontal momentum
/// `m1 u̇ + Σ m_i Ẋ_i` starts at 0 and stays 0, through the impacts of either
/// interface and the building's reversals.
#[test]
fn horizontal_momentum_on_a_frictionless_building() {
    let building = Building::new(6.0e5, 0.0, 0.0, NormalForce::Constant).expect("a valid building");
    let stack = Stack::new(&[shaft(), belfry()], Some(building), G).expect("a valid stack");
    let run = run(&stack, &GroundMotion::None, &released([0.06, -0.15]), &tight(5.0)).expect("the run");
    // The momentum's scale: the masses times speeds of order 1 m/s, 4e5 kg·m/s;
    // the integration keeps it to rtol-sized fractions of that.
    let scale = stack.total_mass();
    for s in &run.samples {
        let p = stack.horizontal_momentum(&s.regime, &s.state);
        assert!(p.abs() < 1e-8 * scale, "t = {}: {p}", s.time);
    }
    let mut impacts = [0usize; 2];
    for ev in &run.events {
        if let StackEventKind::Impact(k) = ev.kind {
            let (p0, p1) = (
                stack.horizontal_momentum(&ev.regime_before, &ev.before),
                stack.horizontal_momentum(&ev.regime, &ev.after),
            );
            assert!((p1 - p0).abs() < 1e-10 * scale, "t = {}: {p0} → {p1}", ev.time);
            impacts[k] += 1;
        }
    }
    assert!(impacts[0] >= 2 && impacts[1] >= 2, "{impacts:?}");
}

/// `a_g → −a_g` and `θ(0) → −θ(0)` mirror the whole run: `θ_k → −θ_k`,
/// `u → −u`, at every sample and event.
#[test]
fn mirror_symmetry() {
    let building = Building::new(6.0e5, 0.3, 0.25, NormalForce::Dynamic).expect("a valid building");
    let stack = Stack::new(&[shaft(), belfry()], Some(building), G).expect("a valid stack");
    let shake = |a: f64| GroundMotion::Harmonic(Harmonic::new(a, 1.2, 3.0, 0.0).expect("a valid input"));
    let plus = run(&stack, &shake(0.35 * G), &released([0.0, 0.01]), &tight(4.0)).expect("the run");
    let minus = run(&stack, &shake(-0.35 * G), &released([0.0, -0.01]), &tight(4.0)).expect("the run");
    assert!(plus.events.iter().any(|e| e.kind == StackEventKind::Slip), "the building slips");
    assert!(plus.events.iter().any(|e| e.kind == StackEventKind::Impact(0)), "the shaft rocks");
    assert_eq!(plus.events.len(), minus.events.len());
    for (a, b) in plus.events.iter().zip(&minus.events) {
        assert_eq!(a.kind, b.kind);
        // Event times: the mirrored functions cross at the mirrored instant,
        // found to a few ulps by the root finder.
        assert!((a.time - b.time).abs() < 1e-9, "{} vs {}", a.time, b.time);
    }
    for (a, b) in plus.samples.iter().zip(&minus.samples) {
        // Integration tolerance on states of order 0.1, kept through the events.
        for k in 0..2 {
            assert!(
                (a.state.theta[k] + b.state.theta[k]).abs() < 1e-8,
                "t = {}: θ_{} {} vs {}",
                a.time,
                k + 1,
                a.state.theta[k],
                b.state.theta[k]
            );
        }
        assert!((a.state.slip + b.state.slip).abs() < 1e-8, "t = {}", a.time);
    }
}

/// The samples are read from the dense output between steps that do not
/// depend on them: another spacing gives the same events, bit for bit.
#[test]
fn events_do_not_depend_on_the_sampling() {
    let stack = Stack::new(&[shaft(), belfry()], None, G).expect("a valid stack");
    let input = GroundMotion::Harmonic(Harmonic::new(0.4 * G, 1.5, 3.0, 0.0).expect("a valid input"));
    let a = run(&stack, &input, &StackState::default(), &tight(4.0)).expect("the run");
    let b = run(
        &stack,
        &input,
        &StackState::default(),
        &RunSettings {
            sample_interval: 0.0037,
            ..tight(4.0)
        },
    )
    .expect("the run");
    assert!(a.events.len() > 4);
    assert_eq!(a.events, b.events);
}

/// A belfry 4 m wide and 1 m tall on the 4 m × 20 m shaft cannot rock (its
/// uplift needs a horizontal acceleration of `g (B/2)/(H/2) = 4 g`): the stack
/// moves as one block of the combined shape, computed by hand:
///
/// ```text
/// m = 3.2e5 + 4e4 = 3.6e5 kg,  y_G = (3.2e5 · 10 + 4e4 · 20.5) / m = 11.1667 m
/// I_O = Σ [m_i (B_i² + H_i²)/12 + m_i (b² + y_i²)],  b = 2 m
///     = 3.2e5 (16 + 400)/12 + 3.2e5 (4 + 100) + 4e4 (16 + 1)/12 + 4e4 (4 + 420.25)
/// R = sqrt(b² + y_G²),  α = atan(b / y_G)
/// ```
///
/// Its θ under a harmonic input equals the engine's for that tower, on a
/// fixed base and on a sliding building.
#[test]
fn a_belfry_that_cannot_rock_is_one_block_of_the_combined_shape() {
    let cap = Block::solid(2, 4.0, 1.0, 4.0e4).expect("a valid cap");
    let m = 3.6e5;
    let y_g = (3.2e5 * 10.0 + 4.0e4 * 20.5) / m;
    let inertia = 3.2e5 * 416.0 / 12.0 + 3.2e5 * 104.0 + 4.0e4 * 17.0 / 12.0 + 4.0e4 * 424.25;
    let tower = Tower::from_properties(m, inertia, 2.0f64.hypot(y_g), (2.0 / y_g).atan(), None).expect("a valid tower");
    let input = GroundMotion::Harmonic(Harmonic::new(0.3 * G, 1.0, 3.0, 0.0).expect("a valid input"));
    for building in [None, Some(Building::new(8.0e5, 0.35, 0.3, NormalForce::Constant).expect("a valid building"))] {
        let stack = Stack::new(&[shaft(), cap], building, G).expect("a valid stack");
        let stacked = run(&stack, &input, &StackState::default(), &tight(5.0)).expect("the run");
        assert!(stacked.events.iter().all(|e| !matches!(e.kind, StackEventKind::Uplift(1))), "the cap lifted");
        let impacts = stacked.events.iter().filter(|e| e.kind == StackEventKind::Impact(0)).count();
        assert!(impacts >= 2, "{impacts} impacts");
        let model = Model::new(Some(tower), building, G).expect("a valid model");
        let mut history = History::new(0.01, vec![]);
        let settings = Settings {
            duration: 5.0,
            rtol: 1e-11,
            atol: 1e-13,
        };
        simulate(&model, &input, Initial::default(), &settings, &mut history).expect("the engine's run");
        let mut compared = 0;
        for s in &stacked.samples {
            let Some(e) = history.samples.iter().find(|e| (e.t - s.time).abs() < 1e-12) else {
                continue;
            };
            // Two integrations to rtol 1e-11 with events located to ~1e-15 s:
            // they agree to 1e-7 rad after a few impacts (the angles are 1e-2).
            assert!(
                (s.state.theta[0] - e.state.theta).abs() < 1e-7,
                "t = {}: {} vs {}",
                s.time,
                s.state.theta[0],
                e.state.theta
            );
            assert!(
                (s.state.slip - e.state.slip).abs() < 1e-7,
                "t = {}: u {} vs {}",
                s.time,
                s.state.slip,
                e.state.slip
            );
            compared += 1;
        }
        assert!(compared > 400, "{compared} samples compared");
    }
}

/// A building sliding under a rocking shaft and belfry with no input: the
/// foundation's friction `F = −μk σ N` is the only horizontal force, and the
/// dynamic normal force is the weight plus the rate of the vertical momentum,
/// `N = Σ m g + d/dt Σ m_i ẏ_i`. Between two instants `t1 < t2` of one slip
/// with no event between them, therefore,
///
/// ```text
/// Δ(m1 u̇ + Σ m_i Ẋ_i) = −μk σ [g Σ m (t2 − t1) + Δ(Σ m_i ẏ_i)]     (dynamic)
/// Δ(m1 u̇ + Σ m_i Ẋ_i) = −μk σ  g Σ m (t2 − t1)                      (constant)
/// ```
///
/// with the momenta from the hand kinematics of `support/stack_two.rs`.
#[test]
fn friction_of_a_sliding_building_under_a_rocking_stack() {
    for normal in [NormalForce::Dynamic, NormalForce::Constant] {
        let (m1, mu) = (6.0e5, 0.15);
        let building = Building::new(m1, mu, mu, normal).expect("a valid building");
        let stack = Stack::new(&[shaft(), belfry()], Some(building), G).expect("a valid stack");
        let mut initial = released([0.05, -0.1]);
        initial.slip_vel = 3.0;
        let out = run(&stack, &GroundMotion::None, &initial, &tight(3.0)).expect("the run");
        let total = stack.total_mass();
        let momenta = |s: &rocking::stack::run::StackSample| {
            let i = s.regime.interfaces;
            let two = Two::new(shaft(), belfry(), sign(i[0]), s.state.theta[0], sign(i[1]), s.state.theta[1]);
            let v = two.velocities(s.state.theta_dot[0], s.state.theta_dot[1]);
            let u = s.state.slip_vel;
            (
                m1 * u + two.m[0] * (v[0][0] + u) + two.m[1] * (v[1][0] + u),
                two.m[0] * v[0][1] + two.m[1] * v[1][1],
            )
        };
        let mut checked = 0;
        for pair in out.samples.windows(2) {
            let (a, b) = (&pair[0], &pair[1]);
            let rocking = b.regime.interfaces[..2].iter().all(|i| *i != Interface::Stuck);
            let slipping = b.regime.building == rocking::BuildingRegime::Slip(rocking::SlipDirection::Positive);
            if a.regime != b.regime || !rocking || !slipping || out.events.iter().any(|e| e.time > a.time && e.time <= b.time) {
                continue;
            }
            let ((h0, v0), (h1, v1)) = (momenta(a), momenta(b));
            let normal_impulse = G * total * (b.time - a.time) + if normal == NormalForce::Dynamic { v1 - v0 } else { 0.0 };
            // Momenta of order 3e6 kg·m/s integrated to rtol 1e-11: 1e-9 of
            // that is a hundred times the integration error, and a hundred
            // times below the dynamic part of the normal impulse checked.
            assert!(
                (h1 - h0 + mu * normal_impulse).abs() < 1e-9 * total * 3.0,
                "{normal:?} t = {}: {} vs {}",
                a.time,
                h1 - h0,
                -mu * normal_impulse
            );
            checked += 1;
        }
        assert!(checked > 20, "{normal:?}: {checked} intervals checked");
    }
}
