//! The stack's laws at one instant, against closed forms worked out by hand:
//! the uplift thresholds of a standing stack, the impact of a belfry on a
//! rocking shaft and of a shaft carrying a rocking belfry (angular momentum
//! about the corners, written out independently of the library's Jacobians),
//! the compound restitution of a seated stack and the impulsive moment its
//! seat carries, and horizontal momentum through an impact on a frictionless
//! building.

use rocking::stack::{Block, Interface, Stack, StackRegime, StackState};
use rocking::{Building, BuildingRegime, NormalForce, Pivot};

#[path = "support/stack_two.rs"]
mod two;
use two::{balance, belfry, shaft, Two};

const G: f64 = 9.81;

fn fixed(blocks: &[Block]) -> Stack {
    Stack::new(blocks, None, G).expect("a valid stack")
}

/// A standing stack under a ground acceleration `a_g` moves as one rigid
/// body, `G̈_i = a_g e_x`: interface 2 carries `M_2 = −m_2 (H_2/2) a_g` on
/// `V_2 = m_2 g` and lifts when `|a_g| > g (B_2/2)/(H_2/2)`, the belfry's own
/// `g tan α_2`; interface 1 carries the whole stack, `M_1 = −Σ m_i y_i a_g`,
/// and lifts when `|a_g| > g (B_1/2) Σ m_i / Σ m_i y_i` (`y_i` the heights of
/// the centres of mass: 10 m and 23 m). The corner is `s = sgn M = −sgn a_g`.
#[test]
fn uplift_thresholds_of_a_standing_stack() {
    let stack = fixed(&[shaft(), belfry()]);
    let (m1, m2) = (3.2e5, 4.0e4);
    let thresholds = [G * 2.0 * (m1 + m2) / (m1 * 10.0 + m2 * 23.0), G * 1.5 / 3.0];
    assert!(thresholds[0] < thresholds[1], "the shaft lifts first here");
    // The thresholds the stack reports (for `rocking check`): a few products
    // and one ratio each.
    for (got, want) in stack.uplift_thresholds().iter().zip(thresholds) {
        assert!((got - want).abs() < 1e-14 * want, "{got} vs {want}");
    }
    for (k, threshold) in thresholds.into_iter().enumerate() {
        for sign in [1.0, -1.0] {
            // 1e-9 either side: far above the rounding of a few products (1e-15),
            // far below any error in a term of the threshold.
            for (factor, lifts) in [(1.0 - 1e-9, false), (1.0 + 1e-9, true)] {
                let snap = stack.snapshot(&StackRegime::REST, &StackState::default(), sign * factor * threshold, G);
                let (margin, corner) = stack.uplift_margin(&snap, k);
                assert_eq!(margin > 0.0, lifts, "interface {} at {factor} × {threshold}: margin {margin}", k + 1);
                assert!(corner * sign < 0.0, "corner {corner}");
            }
        }
    }
}

/// One block on a building that slides under it (`Ẍ_p = −μk σ g`, the
/// building's deceleration): it lifts when `μk g > g tan α`, the engine's
/// rule `|Ẍ_p| > g tan α` with the pivot line's acceleration in place of
/// the ground's.
#[test]
fn uplift_of_one_block_on_a_sliding_building() {
    let block = Block::solid(1, 4.0, 12.0, 1.5e5).unwrap();
    for (mu, lifts) in [(0.33, false), (0.34, true)] {
        let building = Building::new(4.0e5, mu, mu, NormalForce::Constant).unwrap();
        let stack = Stack::new(&[block], Some(building), G).unwrap();
        let regime = StackRegime::REST.with_building(BuildingRegime::Slip(rocking::SlipDirection::Positive));
        let state = StackState {
            slip_vel: 0.5,
            ..StackState::default()
        };
        let snap = stack.snapshot(&regime, &state, 0.0, G);
        // ü = −μk g exactly, up to the rounding of one product.
        assert!((snap.slip_acc + mu * G).abs() < 1e-14 * G, "{}", snap.slip_acc);
        let (margin, corner) = stack.uplift_margin(&snap, 0);
        assert_eq!(margin > 0.0, lifts, "μ = {mu}: margin {margin}");
        // Decelerating a building that moves towards +x throws the block towards +x.
        assert!(corner > 0.0);
    }
}

/// Both interfaces rocking on a fixed base; the belfry lands (θ_2 = 0) while
/// the shaft leans at θ_1 = 0.03 on its + corner, then the shaft lands (θ_1 =
/// 0) with the belfry leaning at −0.02 on its − corner. The library's
/// generalised-momentum law gives the velocities of the balances above and
/// loses the energy they lose.
#[test]
fn impacts_of_two_rocking_blocks_by_angular_momentum() {
    let stack = fixed(&[shaft(), belfry()]);
    // (impacting interface, θ_1, s_1, θ_2, s_2, θ̇_1⁻, θ̇_2⁻)
    for (k, theta1, s1, theta2, s2, w1, w2) in [
        (1, 0.03, 1.0, 0.0, 1.0, -0.2, -0.5),
        (0, 0.0, 1.0, -0.02, -1.0, -0.3, 0.4),
        (1, -0.05, -1.0, 0.0, -1.0, 0.1, 0.6),
    ] {
        let regime = StackRegime::REST
            .with(0, Interface::Rocking(Pivot::of_sign(s1)))
            .with(1, Interface::Rocking(Pivot::of_sign(s2)));
        let mut state = StackState::default();
        state.theta[..2].copy_from_slice(&[theta1, theta2]);
        state.theta_dot[..2].copy_from_slice(&[w1, w2]);
        let out = stack.impact(&regime, &state, k);
        let (s1n, s2n) = if k == 0 { (-s1, s2) } else { (s1, -s2) };
        let before = Two::new(shaft(), belfry(), s1, theta1, s2, theta2);
        let after = Two::new(shaft(), belfry(), s1n, theta1, s2n, theta2);
        let (v1, v2) = balance(&after, &before, [true, true], w1, w2);
        // Two 2×2 solves of sums of products of order 1e6–1e8: 1e-12 of the
        // velocities is a thousand roundings.
        let tol = 1e-12 * (w1.abs() + w2.abs());
        assert!(
            (out.state.theta_dot[0] - v1).abs() < tol && (out.state.theta_dot[1] - v2).abs() < tol,
            "{out:?} vs ({v1}, {v2})"
        );
        let expected = [Interface::Rocking(Pivot::of_sign(s1n)), Interface::Rocking(Pivot::of_sign(s2n))];
        // These impacts keep both blocks rocking on (the law's θ̇_k⁺ has the
        // sign of θ̇_k⁻).
        assert_eq!(&out.regime.interfaces[..2], &expected, "{out:?}");
        let ratio = after.kinetic_energy(v1, v2) / before.kinetic_energy(w1, w2);
        assert!(ratio < 1.0 && ratio > 0.5, "{ratio}");
        // The fixed base's vertical momentum balance: the ground pushes up.
        assert!(out.normal_impulse > 0.0, "{out:?}");
    }
}

/// A seated belfry on a landing shaft (fixed base): the two move as one
/// compound block of `I_O' = Σ (J_i + m_i (b_1² + y_i²))` and
/// `θ̇⁺ = r' θ̇⁻`, `r' = 1 − 2 (m_1 + m_2) b_1² / I_O'` (Housner's balance about
/// the new corner: `(G − O)·(G − O') = y² − b_1²` for each centred block).
/// The belfry's velocity jumps by `ΔĠ_2 = (y_2 (θ̇⁺ − θ̇⁻), −s b_1 (θ̇⁺ + θ̇⁻))`
/// and its rotation by `θ̇⁺ − θ̇⁻`, so its seat carries
/// `M_imp = −(m_2 (H_2/2) y_2 + J_2)(θ̇⁺ − θ̇⁻)` on `V_imp = m_2 b_1 (1 + r') |θ̇⁻|`:
///
/// ```text
/// max_seat_impulse_ratio = (m_2 (H_2/2) y_2 + J_2)(1 − r') / (m_2 b_1 b_2 (1 + r'))
/// ```
///
/// independent of `θ̇⁻`. For the slender belfry 1.6 m × 6 m on this shaft it
/// exceeds 1: the model keeps it seated where its base cannot carry the
/// impulse.
#[test]
fn seat_impulse_ratio_of_a_seated_belfry() {
    for upper in [belfry(), Block::solid(2, 1.6, 6.0, 2.0e4).unwrap()] {
        let stack = fixed(&[shaft(), upper]);
        let (m1, m2) = (shaft().mass(), upper.mass());
        let (b1, b2, h2) = (2.0, upper.width() / 2.0, upper.height() / 2.0);
        let (y1, y2) = (10.0, 20.0 + h2);
        let inertia = shaft().inertia_centre() + m1 * (b1 * b1 + y1 * y1) + upper.inertia_centre() + m2 * (b1 * b1 + y2 * y2);
        let r = 1.0 - 2.0 * (m1 + m2) * b1 * b1 / inertia;
        let expected = (m2 * h2 * y2 + upper.inertia_centre()) * (1.0 - r) / (m2 * b1 * b2 * (1.0 + r));
        for (pivot, w) in [(Pivot::Positive, -0.05), (Pivot::Negative, 0.4)] {
            let regime = StackRegime::REST.with(0, Interface::Rocking(pivot));
            let mut state = StackState::default();
            state.theta_dot[0] = w;
            let out = stack.impact(&regime, &state, 0);
            // Sums of a few products, then one ratio: 1e-12 is a thousand roundings.
            assert!((out.state.theta_dot[0] - r * w).abs() < 1e-12 * w.abs(), "{out:?} r' = {r}");
            assert!(
                (out.seat_impulse_ratio - expected).abs() < 1e-12 * expected,
                "{} vs {expected}",
                out.seat_impulse_ratio
            );
            assert_eq!(out.regime.interfaces[1], Interface::Stuck);
        }
        if upper.width() < 2.0 {
            assert!(expected > 1.0, "{expected}");
        } else {
            assert!(expected < 1.0, "{expected}");
        }
    }
}

/// On a frictionless building the foundation gives no horizontal impulse, so
/// the horizontal momentum `m1 u̇ + Σ m_i Ẋ_i` is the same after an impact at
/// either interface as before it (and the building slides, `P = 0`).
#[test]
fn horizontal_momentum_through_impacts_on_a_frictionless_building() {
    let building = Building::new(6.0e5, 0.0, 0.0, NormalForce::Constant).unwrap();
    let stack = Stack::new(&[shaft(), belfry()], Some(building), G).unwrap();
    let momentum = |regime: &StackRegime, state: &StackState| {
        let hand_s1 = regime.interfaces[0].pivot().map_or(1.0, Pivot::sign);
        let hand_s2 = regime.interfaces[1].pivot().map_or(1.0, Pivot::sign);
        let two = Two::new(shaft(), belfry(), hand_s1, state.theta[0], hand_s2, state.theta[1]);
        let v = two.velocities(state.theta_dot[0], state.theta_dot[1]);
        6.0e5 * state.slip_vel + two.m[0] * (v[0][0] + state.slip_vel) + two.m[1] * (v[1][0] + state.slip_vel)
    };
    for (k, theta, w, slip_vel) in [
        (0, [0.0, 0.02], [-0.3, 0.2], 0.1),
        (1, [-0.04, 0.0], [0.25, 0.5], -0.2),
        (1, [0.01, 0.0], [-0.1, -0.3], 0.0),
    ] {
        let regime = StackRegime::REST
            .with(0, Interface::Rocking(Pivot::of_sign(if k == 0 { -w[0] } else { theta[0] })))
            .with(1, Interface::Rocking(Pivot::of_sign(if k == 1 { -w[1] } else { theta[1] })))
            .with_building(BuildingRegime::Slip(rocking::SlipDirection::of_sign(slip_vel)));
        let mut state = StackState::default();
        state.theta[..2].copy_from_slice(&theta);
        state.theta_dot[..2].copy_from_slice(&w);
        state.slip_vel = slip_vel;
        let out = stack.impact(&regime, &state, k);
        let (p0, p1) = (momentum(&regime, &state), momentum(&out.regime, &out.state));
        // Momenta built from products of order 1e6 × velocity: 1e-12 of that is
        // a thousand roundings, and far below any momentum the law could lose
        // (the foundation's impulse would be of order 1e5 × velocity).
        let scale = 1.0e6 * (w[0].abs() + w[1].abs() + slip_vel.abs());
        assert!((p0 - p1).abs() < 1e-12 * scale, "{p0} vs {p1}: {out:?}");
        assert!(out.friction_impulse.abs() < 1e-9 * scale, "{out:?}");
        assert!(matches!(out.regime.building, BuildingRegime::Slip(_)), "{out:?}");
    }
}

/// The table of `validation/results/stack-impacts.csv`: a shaft 4 m × 12 m of
/// 1.5e5 kg landing at −0.05 rad/s from its + corner on a fixed base under a
/// belfry seated or rocking, solved there by Newton–Euler's impulse-momentum
/// balances of each body (SymPy; six equations in the two velocities and the
/// two contact impulses), a method that shares nothing with the generalised
/// momenta here. The velocities after, the kinetic energy kept and the seat
/// impulse ratio agree.
#[test]
fn shaft_landings_of_the_newton_euler_table() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../validation/results/stack-impacts.csv");
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let shaft = Block::solid(1, 4.0, 12.0, 1.5e5).expect("a valid shaft");
    let mut rows = 0;
    for line in text.lines().skip(1) {
        // "configuration, with commas",theta2,w1,w2,w1+,w2+,energy ratio,seat ratio,...
        let (name, rest) = line[1..].split_once("\",").expect("a quoted configuration");
        let v: Vec<f64> = rest.split(',').take(7).map(|x| x.parse().expect("a number")).collect();
        let upper = if name.starts_with("slender") {
            Block::solid(2, 0.8, 4.0, 3.0e4)
        } else {
            Block::solid(2, 2.4, 6.0, 6.0e4)
        }
        .expect("a valid belfry");
        let belfry = if name.contains("corner +1") {
            Interface::Rocking(Pivot::Positive)
        } else if name.contains("corner -1") {
            Interface::Rocking(Pivot::Negative)
        } else {
            Interface::Stuck
        };
        let stack = fixed(&[shaft, upper]);
        let regime = StackRegime::REST.with(0, Interface::Rocking(Pivot::Positive)).with(1, belfry);
        let mut state = StackState::default();
        state.theta[1] = v[0];
        state.theta_dot[..2].copy_from_slice(&[v[1], v[2]]);
        let out = stack.impact(&regime, &state, 0);
        // Both sides are double-precision solutions of small systems of
        // condition ~1e3 (the table says its two methods agree to 5e-14):
        // 1e-11 of the velocities.
        for (got, want) in out.state.theta_dot[..2].iter().zip(&v[3..5]) {
            assert!((got - want).abs() < 1e-11 * 0.05, "{name}: {:?} vs {:?}", &out.state.theta_dot[..2], &v[3..5]);
        }
        let still = |s: &StackState| StackState { theta_dot: [0.0; 6], ..*s };
        let potential = stack.energy(&regime, &still(&state));
        let kept = (stack.energy(&out.regime, &out.state) - potential) / (stack.energy(&regime, &state) - potential);
        // The energies cancel a potential energy of ~2e7 J down to a kinetic
        // energy of ~1e3 J: 1e-16 × 2e4 per term.
        assert!((kept - v[5]).abs() < 1e-10, "{name}: energy kept {kept} vs {}", v[5]);
        if belfry == Interface::Stuck {
            assert!(
                (out.seat_impulse_ratio - v[6]).abs() < 1e-11 * v[6],
                "{name}: {} vs {}",
                out.seat_impulse_ratio,
                v[6]
            );
        }
        rows += 1;
    }
    assert_eq!(rows, 6);
}
