//! One block on a building: the stack's generic equations against the
//! engine's own (T)–(B), stick demand and impact law.
//!
//! Tolerances. The engine evaluates `sin φ, cos φ` of `φ = α − s θ` and
//! combines them with `m2 R`; the stack rotates the vectors `(∓b, 0)` and
//! `(0, h)` by `θ` and takes dot products. Both are a handful of roundings
//! away from the exact value, so they agree to some 1e-15 of the largest
//! term of each equation; `1e-13` of it leaves a margin of a hundred ulps and
//! would still catch a wrong term (the smallest term checked, the dynamic
//! normal force's `μk m2 R θ̇²` part, is above 1e-4 of the scale here).

use super::dynamics::Snapshot;
use super::*;
use crate::body::{Building, NormalForce, Tower};
use crate::equations::Kernel;
use crate::model::Model;
use crate::regime::{Regime, SlipDirection, TowerRegime};

const G: f64 = 9.81;

fn tower() -> Tower {
    // Width 4 m, height 12 m, 1.5e5 kg, solid.
    let (b, h, m) = (2.0f64, 6.0f64, 1.5e5);
    let radius = b.hypot(h);
    Tower::from_properties(m, 4.0 / 3.0 * m * radius * radius, radius, libm::atan2(b, h), None).unwrap()
}

fn building(mu_s: f64, mu_k: f64, normal: NormalForce) -> Building {
    Building::new(4.0e5, mu_s, mu_k, normal).unwrap()
}

fn pair(normal: NormalForce, mu_s: f64, mu_k: f64) -> (Kernel, Stack) {
    let t = tower();
    let b = building(mu_s, mu_k, normal);
    let kernel = Kernel::new(&Model::new(Some(t), Some(b), G).unwrap());
    let stack = Stack::new(&[Block::from_tower(&t)], Some(b), G).unwrap();
    (kernel, stack)
}

fn close(a: f64, b: f64, scale: f64, what: &str) {
    assert!((a - b).abs() <= 1e-13 * scale, "{what}: {a} vs {b} (scale {scale})");
}

fn one_block_regime(tower: TowerRegime, building: BuildingRegime) -> StackRegime {
    let interface = match tower {
        TowerRegime::Rest => Interface::Stuck,
        TowerRegime::Rocking(p) => Interface::Rocking(p),
    };
    StackRegime::REST.with(0, interface).with_building(building)
}

fn state(theta: f64, theta_dot: f64, slip_vel: f64) -> StackState {
    let mut s = StackState::default();
    s.theta[0] = theta;
    s.theta_dot[0] = theta_dot;
    s.slip_vel = slip_vel;
    s
}

const STATES: [(f64, f64); 6] = [(0.05, -0.3), (-0.12, 0.7), (0.2, 1.1), (-0.01, -0.05), (0.3, 0.0), (-0.25, -0.9)];
const GROUND: [f64; 3] = [0.0, 3.7, -6.2];

/// (T)–(B) in every regime, both normal-force laws, with and without a
/// vertical ground motion: θ̈ and ü of the stack equal the engine's.
#[test]
fn one_block_accelerations_are_the_engines() {
    for normal in [NormalForce::Constant, NormalForce::Dynamic] {
        let (kernel, stack) = pair(normal, 0.5, 0.4);
        for &(theta, theta_dot) in &STATES {
            for &a_g in &GROUND {
                for g_e in [G, G + 2.5] {
                    for building_regime in [
                        BuildingRegime::Stick,
                        BuildingRegime::Slip(SlipDirection::Positive),
                        BuildingRegime::Slip(SlipDirection::Negative),
                    ] {
                        let pivot = crate::regime::Pivot::of_sign(theta);
                        for tower_regime in [TowerRegime::Rest, TowerRegime::Rocking(pivot)] {
                            let engine = kernel.accelerations(
                                Regime {
                                    tower: tower_regime,
                                    building: building_regime,
                                },
                                a_g,
                                g_e,
                                theta,
                                theta_dot,
                            );
                            let regime = one_block_regime(tower_regime, building_regime);
                            let snap = stack.snapshot(&regime, &state(theta, theta_dot, 0.0), a_g, g_e);
                            // Scale of (T) over I_O: k (g_e + |a_g| + R θ̇²).
                            let scale = kernel.k * (g_e + a_g.abs() + kernel.radius * theta_dot * theta_dot) + g_e + a_g.abs();
                            let what = format!("{normal:?} {tower_regime:?} {building_regime:?} θ={theta} θ̇={theta_dot} a_g={a_g} g_e={g_e}");
                            close(snap.theta_ddot[0], engine.theta, scale, &format!("θ̈ {what}"));
                            close(snap.slip_acc, engine.slip, scale, &format!("ü {what}"));
                        }
                    }
                }
            }
        }
    }
}

/// The friction a sticking building needs and the normal force, against the
/// engine's stick demand.
#[test]
fn one_block_stick_demand_is_the_engines() {
    for normal in [NormalForce::Constant, NormalForce::Dynamic] {
        let (kernel, stack) = pair(normal, 0.5, 0.4);
        for &(theta, theta_dot) in &STATES {
            for &a_g in &GROUND {
                let g_e = G;
                let pivot = crate::regime::Pivot::of_sign(theta);
                for tower_regime in [TowerRegime::Rest, TowerRegime::Rocking(pivot)] {
                    let (f_req, n) = kernel.stick_demand(tower_regime, a_g, g_e, theta, theta_dot);
                    let snap: Snapshot = stack.snapshot(&one_block_regime(tower_regime, BuildingRegime::Stick), &state(theta, theta_dot, 0.0), a_g, g_e);
                    let scale = kernel.total * (g_e + a_g.abs()) + kernel.m2r * theta_dot * theta_dot;
                    close(stack.friction_force(&snap), f_req, scale, "F_req");
                    close(stack.normal_force(&snap), n, scale, "N");
                }
            }
        }
    }
}

/// The load on interface 1 (the tower on the building) is the tower's pivot
/// reaction: `(T, V) = m2 (f_x, f_y)` of the engine, and its friction demand
/// Shenton's `|f_x| / f_y`.
#[test]
fn one_block_interface_load_is_the_pivot_reaction() {
    let (kernel, stack) = pair(NormalForce::Dynamic, 0.5, 0.4);
    for &(theta, theta_dot) in &STATES {
        for &a_g in &GROUND {
            let pivot = crate::regime::Pivot::of_sign(theta);
            let lean = kernel.lean(pivot.sign(), theta);
            for building_regime in [BuildingRegime::Stick, BuildingRegime::Slip(SlipDirection::Negative)] {
                let engine = kernel.accelerations(
                    Regime {
                        tower: TowerRegime::Rocking(pivot),
                        building: building_regime,
                    },
                    a_g,
                    G,
                    theta,
                    theta_dot,
                );
                let (fx, fy) = kernel.pivot_reactions(Some(lean), theta_dot, engine.theta, a_g + engine.slip, G);
                let snap = stack.snapshot(
                    &one_block_regime(TowerRegime::Rocking(pivot), building_regime),
                    &state(theta, theta_dot, 0.0),
                    a_g,
                    G,
                );
                let load = stack.interface_load(&snap, 0);
                let scale = G + a_g.abs() + kernel.radius * (theta_dot * theta_dot + engine.theta.abs());
                close(load.tangential / kernel.m2, fx, scale, "f_x");
                close(load.normal / kernel.m2, fy, scale, "f_y");
                close(load.friction_demand(), fx.abs() / fy, scale / fy, "demand");
            }
        }
    }
}

/// The impact law: the stack's generalised-momentum balance against the
/// engine's one-tower law, on a building sticking or sliding before the
/// impact, with friction that lets it stick, slide, or (a sliding building
/// that sticks) end the impact at rest.
#[test]
fn one_block_impact_is_the_engines() {
    let mut cases = std::collections::BTreeSet::new();
    for (mu_s, mu_k) in [(0.5, 0.4), (0.05, 0.03), (0.0, 0.0), (2.0, 1.5), (20.0, 20.0)] {
        let (kernel, stack) = pair(NormalForce::Constant, mu_s, mu_k);
        for (s, theta_dot) in [(1.0, -0.8), (-1.0, 0.5), (1.0, -0.02)] {
            for (building_regime, slip_vel) in [
                (BuildingRegime::Stick, 0.0),
                (BuildingRegime::Slip(SlipDirection::Positive), 0.3),
                (BuildingRegime::Slip(SlipDirection::Negative), -0.05),
                (BuildingRegime::Slip(SlipDirection::Negative), -2.0),
                (BuildingRegime::Slip(SlipDirection::Positive), 0.2),
                (BuildingRegime::Slip(SlipDirection::Negative), -0.2),
            ] {
                let engine = kernel.impact_law(s, theta_dot, slip_vel, building_regime);
                cases.insert(format!("{:?} {}", engine.building, engine.theta_dot == 0.0));
                let pivot = crate::regime::Pivot::of_sign(s);
                let regime = one_block_regime(TowerRegime::Rocking(pivot), building_regime);
                let out = stack.impact(&regime, &state(0.0, theta_dot, slip_vel), 0);
                let what = format!("μ=({mu_s},{mu_k}) s={s} θ̇⁻={theta_dot} {building_regime:?} u̇⁻={slip_vel}: {engine:?} vs {out:?}");
                // Velocities: a few roundings of terms of size |θ̇⁻| and |u̇⁻|/R.
                let scale = theta_dot.abs() + slip_vel.abs() / kernel.radius;
                close(out.state.theta_dot[0], engine.theta_dot, scale, &what);
                close(out.state.slip_vel, engine.slip_vel, scale * kernel.radius, &what);
                assert_eq!(out.regime.building, engine.building, "{what}");
                let seated = engine.theta_dot == 0.0;
                assert_eq!(out.regime.interfaces[0] == Interface::Stuck, seated, "{what}");
                if !seated {
                    assert_eq!(out.regime.interfaces[0], Interface::Rocking(pivot.flipped()), "{what}");
                }
            }
        }
    }
    // Every branch of the law was met: stick and slide in both directions,
    // rocking on or ended at rest.
    for case in ["Stick false", "Stick true", "Slip(Positive) false", "Slip(Negative) false"] {
        assert!(cases.contains(case), "{case} not met: {cases:?}");
    }
    assert!(
        cases.contains("Slip(Positive) true") || cases.contains("Slip(Negative) true"),
        "no impact ended at rest on a sliding building: {cases:?}"
    );
}

/// On a fixed base the balance about the new corner is Housner's:
/// `θ̇⁺ = r θ̇⁻`, `r = 1 − 2 m R² sin²α / I_O` (the tower's own restitution).
#[test]
fn one_block_on_a_fixed_base_is_housner() {
    let t = tower();
    let stack = Stack::new(&[Block::from_tower(&t)], None, G).unwrap();
    let r = 1.0 - 2.0 * t.mass() * t.radius().powi(2) * t.alpha().sin().powi(2) / t.inertia_pivot();
    for (pivot, theta_dot) in [(crate::regime::Pivot::Positive, -0.4), (crate::regime::Pivot::Negative, 1.3)] {
        let regime = StackRegime::REST.with(0, Interface::Rocking(pivot));
        let out = stack.impact(&regime, &state(0.0, theta_dot, 0.0), 0);
        // A 1×1 system of a few products: a few ulps of θ̇⁻.
        assert!((out.state.theta_dot[0] - r * theta_dot).abs() < 1e-14 * theta_dot.abs(), "{out:?} r={r}");
        assert_eq!(out.regime.interfaces[0], Interface::Rocking(pivot.flipped()));
        assert!((r - t.restitution()).abs() < 1e-15);
    }
}

/// Painlevé's paradox of the dynamic normal force: on a light building under
/// high friction (1 kg under the 1.5e5 kg tower, μ = 5) the system of (T)–(B)
/// with `F = −μk σ N` has no solution where its determinant is not positive.
/// The stack's Kane system is singular at exactly the same states (the
/// determinant of a permuted matrix is the same), and agrees elsewhere.
#[test]
fn one_block_painleve_domain_is_the_engines() {
    let t = tower();
    let b = Building::new(1.0, 5.0, 5.0, NormalForce::Dynamic).unwrap();
    let kernel = Kernel::new(&Model::new(Some(t), Some(b), G).unwrap());
    let stack = Stack::new(&[Block::from_tower(&t)], Some(b), G).unwrap();
    let (mut singular, mut regular) = (0, 0);
    for i in -20..=20 {
        let theta = 0.015 * f64::from(i);
        if theta == 0.0 {
            continue;
        }
        for theta_dot in [-1.0, -0.1, 0.0, 0.3] {
            for dir in [SlipDirection::Positive, SlipDirection::Negative] {
                let pivot = crate::regime::Pivot::of_sign(theta);
                let building_regime = BuildingRegime::Slip(dir);
                let engine = kernel.accelerations(
                    Regime {
                        tower: TowerRegime::Rocking(pivot),
                        building: building_regime,
                    },
                    0.0,
                    G,
                    theta,
                    theta_dot,
                );
                let snap = stack.snapshot(
                    &one_block_regime(TowerRegime::Rocking(pivot), building_regime),
                    &state(theta, theta_dot, 0.0),
                    0.0,
                    G,
                );
                assert_eq!(
                    engine.theta.is_nan(),
                    snap.theta_ddot[0].is_nan(),
                    "θ = {theta}, θ̇ = {theta_dot}, {dir:?}: {engine:?} vs {}",
                    snap.theta_ddot[0]
                );
                if engine.theta.is_nan() {
                    singular += 1;
                } else {
                    regular += 1;
                }
            }
        }
    }
    assert!(singular > 10 && regular > 10, "{singular} singular, {regular} regular states");
}

/// The column's centre of mass, worked by hand: a shaft 3 m × 15 m of 400 t
/// under a belfry 1.5 m × 5 m of 30 t has `h = (400 · 7.5 + 30 · 17.5) / 430
/// = 3525 / 430` m above the shaft's base; the stack's body above interface
/// 1 is that column, above interface 2 the belfry alone (`h = 2.5` m). Each
/// is a few roundings from the exact value: 4 ulps.
#[test]
fn column_centre_by_hand() {
    let shaft = Block::solid(1, 3.0, 15.0, 4.0e5).unwrap();
    let belfry = Block::solid(2, 1.5, 5.0, 3.0e4).unwrap();
    let (mass, h) = column_centre(&[shaft, belfry]);
    let bits = |x: f64, y: f64| (x.to_bits(), y.to_bits());
    assert_eq!(bits(mass, 0.0), bits(4.3e5, 0.0));
    assert!((h - 3525.0 / 430.0).abs() <= 4.0 * f64::EPSILON * h, "{h}");
    let stack = Stack::new(&[shaft, belfry], None, G).unwrap();
    let bodies = [dynamics::Body::above(&stack.blocks, 0), dynamics::Body::above(&stack.blocks, 1)];
    assert_eq!(bits(bodies[0].mass, bodies[0].centre_height), bits(mass, h));
    assert_eq!(bits(bodies[1].mass, bodies[1].centre_height), bits(3.0e4, 2.5));
}
