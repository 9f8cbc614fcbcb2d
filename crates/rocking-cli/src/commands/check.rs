//! `rocking check SCENARIO.toml`: validates a scenario (reading its record, if
//! any) and prints the derived quantities, without running it.

use crate::format::sig;
use rocking::{GroundMotion, NormalForce};
use rocking_scenario::{record_format_name, Case, GroundInfo, GroundKind};
use std::fmt::Write;
use std::path::PathBuf;

/// Arguments of `rocking check`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The scenario file (TOML).
    pub scenario: PathBuf,
}

/// Validates and prints.
pub fn execute(args: &Args) -> anyhow::Result<()> {
    let scenario = super::load_scenario(&args.scenario)?;
    let case = scenario.build()?;
    super::print(&describe(&case))
}

/// The derived quantities of a case, one topic per paragraph.
fn describe(case: &Case) -> String {
    let mut out = String::new();
    let g = case.model.gravity();
    // Writing to a String cannot fail.
    let _ = writeln!(out, "scenario    {} ({})", case.name, case.file.display());
    // Every quantity of the model comes from its one computation,
    // `Model::derived` (the page's `check` reads the same); only the
    // formatting is here.
    let d = case.model.derived();
    match (d.tower_mass, d.inertia_pivot, d.alpha, d.radius, d.p, d.restitution, d.uplift_acceleration_g) {
        (Some(mass), Some(inertia), Some(alpha), Some(radius), Some(p), Some(r), Some(tan)) => {
            let _ = writeln!(out, "tower       m2 = {} kg, I_O = {} kg·m²", sig(mass, 6), sig(inertia, 6));
            let _ = writeln!(
                out,
                "            α = {} rad = {}°, R = {} m, p = {} rad/s, r = {}",
                sig(alpha, 6),
                sig(alpha.to_degrees(), 6),
                sig(radius, 6),
                sig(p, 6),
                sig(r, 6)
            );
            let _ = writeln!(out, "            uplift acceleration tan α = {} g = {} m/s²", sig(tan, 6), sig(tan * g, 6));
            for (k, (x, y)) in case.points.iter().enumerate() {
                let _ = writeln!(out, "            point p{} = ({}, {}) m", k + 1, sig(*x, 6), sig(*y, 6));
            }
        }
        _ => {
            let _ = writeln!(out, "tower       none");
        }
    }
    if let Some(stack) = case.model.stack() {
        describe_stack(&mut out, case, &stack, g);
    }
    match (case.model.building(), d.sliding_mass, d.slip_acceleration_g) {
        (Some(b), Some(sliding_mass), Some(slip)) => {
            let normal = match b.normal_force() {
                NormalForce::Constant => "constant",
                NormalForce::Dynamic => "dynamic",
            };
            let _ = writeln!(
                out,
                "building    m1 = {} kg, M = {} kg, μs = {}, μk = {}, normal force {normal}",
                sig(b.mass(), 6),
                sig(sliding_mass, 6),
                sig(b.mu_static(), 6),
                sig(b.mu_kinetic(), 6)
            );
            let _ = writeln!(out, "            slip acceleration μs = {} g = {} m/s²", sig(slip, 6), sig(slip * g, 6));
        }
        _ => {
            let _ = writeln!(out, "building    none (fixed base)");
        }
    }
    describe_motion(&mut out, "ground     ", "a_g", &case.ground_info, &case.ground, g);
    if let (Some(info), Some(motion)) = (&case.vertical_info, &case.vertical) {
        describe_motion(&mut out, "vertical   ", "a_v", info, motion, g);
        let bound = g - motion.peak().0;
        let _ = writeln!(
            out,
            "            effective gravity g + a_v >= g - max |a_v| = {} m/s²{}",
            sig(bound, 6),
            if bound > 0.0 { "" } else { " (the run stops where g + a_v reaches 0)" }
        );
    }
    let _ = writeln!(
        out,
        "initial     θ = {} rad, θ̇ = {} rad/s",
        sig(case.initial.theta, 6),
        sig(case.initial.theta_dot, 6)
    );
    let s = &case.settings;
    let rows = (s.duration / case.output_dt + 1e-9).floor() + 1.0;
    let _ = writeln!(
        out,
        "simulation  duration {} s, g = {} m/s², output every {} s ({} history rows), rtol {}, atol {}",
        sig(s.duration, 6),
        sig(g, 6),
        sig(case.output_dt, 6),
        rows,
        sig(s.rtol, 3),
        sig(s.atol, 3)
    );
    out
}

/// The blocks on the tower and the ground acceleration that lifts each
/// interface from rest (everything else at rest, the building stuck).
fn describe_stack(out: &mut String, case: &Case, stack: &rocking::stack::Stack, g: f64) {
    for (k, block) in stack.blocks().iter().enumerate().skip(1) {
        let _ = writeln!(
            out,
            "{}{}: B = {} m, H = {} m, m = {} kg, J = {} kg·m², α = {} rad = {}°",
            if k == 1 { "blocks      " } else { "            " },
            case.blocks.name(k),
            sig(block.width(), 6),
            sig(block.height(), 6),
            sig(block.mass(), 6),
            sig(block.inertia_centre(), 6),
            sig(block.alpha(), 6),
            sig(block.alpha().to_degrees(), 6)
        );
    }
    for (k, threshold) in stack.uplift_thresholds().iter().enumerate() {
        let below = if k == 0 {
            if case.model.building().is_some() { "the building" } else { "the ground" }.to_string()
        } else {
            format!("the {}", case.blocks.name(k - 1))
        };
        let _ = writeln!(
            out,
            "{}{} on {below} lifts from rest at a_g = {} g = {} m/s²",
            if k == 0 { "uplift      " } else { "            " },
            case.blocks.name(k),
            sig(threshold / g, 6),
            sig(*threshold, 6)
        );
    }
}

/// The lines of `rocking check` for one ground motion (`label` is the first
/// column, `symbol` the acceleration's name in the peak line).
fn describe_motion(out: &mut String, label: &str, symbol: &str, info: &GroundInfo, motion: &GroundMotion, g: f64) {
    let mut parts = vec![info.kind.as_str().to_string()];
    if let Some(a) = info.amplitude_g {
        parts.push(format!("amplitude {} g = {} m/s²", sig(a, 6), sig(a * g, 6)));
    }
    if let Some(f) = info.frequency_hz {
        parts.push(format!("frequency {} Hz", sig(f, 6)));
    }
    if let Some(phase) = info.phase_rad {
        parts.push(format!("phase {} rad", sig(phase, 6)));
    }
    if let Some(t0) = info.t0_s {
        parts.push(format!("t0 = {} s", sig(t0, 6)));
    }
    if let Some(end) = info.end_time_s {
        parts.push(format!("until t = {} s", sig(end, 6)));
    }
    let _ = writeln!(out, "{label} {}", parts.join(", "));
    if let Some(r) = &info.record {
        let step = r
            .time_step_s
            .map_or_else(|| "uneven time step".to_string(), |dt| format!("dt = {} s", sig(dt, 6)));
        let _ = writeln!(
            out,
            "            record {} ({}): {} samples, {step}, duration {} s, scale {}",
            r.file.display(),
            record_format_name(r.format),
            r.samples,
            sig(r.duration_s, 6),
            sig(r.scale, 6)
        );
    }
    if info.kind != GroundKind::None {
        let (peak, at) = motion.peak();
        let _ = writeln!(
            out,
            "            peak |{symbol}| = {} g = {} m/s² at t = {} s",
            sig(peak / g, 6),
            sig(peak, 6),
            sig(at, 6)
        );
    }
}
