//! The state at the end of a run: a tower past its stability limit when the
//! run ends (`|θ| > α`, still rotating) was reported as `overturned: false`
//! and nothing else. The summary now says where the tower ends
//! (`end_state`) and what its free motion will do (`will_overturn`), in
//! closed form ([`free_motion_overturns`]); both are checked here against
//! integrating that free motion to its end.
#![allow(missing_docs, clippy::unwrap_used)]

mod common;

use common::{fixed, run, tight, G};
use rocking::reference::solid_block;
use rocking::{free_motion_overturns, EndState, GroundMotion, Harmonic, Initial};

/// The closed form against integration: from each start of a grid of leans
/// (inside and beyond α, both ways) and speeds, a tower rocking freely on a
/// fixed base overturns within 30 s exactly when the verdict says it will.
/// Starts within 1e-3 of a boundary of the verdict (the energy at the
/// barrier, before or after the next impact) are left out of the grid: there
/// the run's tolerance, not the law, would decide.
#[test]
fn the_verdict_of_the_free_motion_is_what_integration_finds() {
    let model = fixed(solid_block(1.0, 6.0));
    let d = model.derived();
    let (alpha, p, r) = (d.alpha.unwrap(), d.p.unwrap(), d.restitution.unwrap());
    let (mut falls, mut stays) = (0, 0);
    for lean in [-1.4, -1.1, -0.9, -0.5, 0.0, 0.3, 0.7, 0.95, 1.05, 1.2, 1.5] {
        for speed in [-0.5, -0.3, -0.15, -0.05, 0.0, 0.05, 0.15, 0.3, 0.5] {
            let (theta, theta_dot) = (lean * alpha, speed * p);
            let e = theta_dot * theta_dot / (2.0 * p * p) + (alpha - theta.abs()).cos();
            let after_impact = r * r * (e - alpha.cos()) - (1.0 - alpha.cos());
            if (e - 1.0).abs() < 1e-3 || after_impact.abs() < 1e-3 * (1.0 - alpha.cos()) {
                continue;
            }
            let verdict = free_motion_overturns(alpha, p, r, theta, theta_dot);
            let s = run(&model, &GroundMotion::None, Initial { theta, theta_dot }, &tight(30.0));
            assert_eq!(s.overturned(), verdict, "θ/α = {lean}, θ̇/p = {speed}: e = {e}");
            if verdict {
                falls += 1;
            } else {
                stays += 1;
            }
        }
    }
    // Both verdicts are exercised, many times each.
    assert!(falls >= 20 && stays >= 10, "{falls} fall, {stays} stay");
}

/// A 2 m × 20 m tower (tan α = 0.1) under 0.5 g at 1 Hz for the whole run
/// ends past its stability limit, still rotating, without having overturned:
/// the summary says so, and that it will overturn (no input remains after
/// the harmonic's end, the run's). Integrating on shows it does.
#[test]
fn a_tower_past_its_limit_at_the_end_is_said_to_be_and_falls() {
    let model = fixed(solid_block(2.0, 20.0));
    let ground = GroundMotion::Harmonic(Harmonic::new(0.5 * G, 1.0, 20.0, 0.0).unwrap());
    let at_rest = Initial { theta: 0.0, theta_dot: 0.0 };
    let s = run(&model, &ground, at_rest, &tight(20.0));
    assert!(!s.overturned());
    assert_eq!(s.end_state, EndState::BeyondStabilityLimit);
    assert!(s.theta_range.1.max(-s.theta_range.0) > model.derived().alpha.unwrap());
    assert_eq!(s.will_overturn, Some(true));
    let on = run(&model, &ground, at_rest, &tight(60.0));
    assert!(on.overturned() && on.overturn_time.unwrap() > 20.0);
}

/// The verdict at the end of shaking against the run continued: under
/// harmonic shaking of 3 s at several amplitudes, a run stopped at 3.5 s
/// says `will_overturn`, and the same run to 60 s overturns exactly when it
/// said so. While shaking remains (a run stopped at 2.5 s) it says nothing,
/// and a tower that never lifted off ends at rest.
#[test]
fn the_verdict_at_the_end_of_shaking_is_what_the_run_continued_finds() {
    let model = fixed(solid_block(1.0, 6.0));
    let at_rest = Initial { theta: 0.0, theta_dot: 0.0 };
    let mut seen = [false, false];
    for amplitude in [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0] {
        let ground = GroundMotion::Harmonic(Harmonic::new(amplitude * G, 1.5, 3.0, 0.0).unwrap());
        let during = run(&model, &ground, at_rest, &tight(2.5));
        assert_eq!(during.will_overturn, None, "{amplitude} g");
        let short = run(&model, &ground, at_rest, &tight(3.5));
        let long = run(&model, &ground, at_rest, &tight(60.0));
        if short.overturned() {
            assert_eq!((short.end_state, short.will_overturn), (EndState::Overturned, Some(true)));
            continue;
        }
        let verdict = short.will_overturn.unwrap();
        assert_eq!(long.overturned(), verdict, "{amplitude} g: ends {:?}", short.end_state);
        seen[usize::from(verdict)] = true;
        if amplitude * G < G * model.derived().uplift_acceleration_g.unwrap() {
            assert_eq!(short.end_state, EndState::Rest, "{amplitude} g");
        }
    }
    assert!(seen[0], "no case stayed up");
}
