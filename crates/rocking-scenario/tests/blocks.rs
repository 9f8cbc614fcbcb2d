//! `[[block]]`: blocks stacked on the tower in a scenario file: their keys and
//! errors, their outputs (summary fields, history columns, events named by the
//! block), and a sweep over a block's key.

use rocking_scenario::columns::{event_kind, history_header, HISTORY, HISTORY_POINTS};
use rocking_scenario::{summary_json, Cell, RunOptions, Scenario, Sweep};
use std::path::Path;
use std::sync::atomic::AtomicBool;

const ORIGIN: &str = "dir/belfry.toml";

/// The bell tower on its church carrying a belfry 2 m × 5 m of 30 t, shaken
/// at 0.6 g and 2 Hz for 4 s.
fn text(block: &str) -> String {
    format!(
        "name = \"belfry\"\n{}\n[[block]]\n{block}\n[ground]\ntype = \"harmonic\"\namplitude = 0.6\nfrequency = 2.0\nduration = 4.0\n\n[simulation]\nduration = 5.0\noutput_dt = 0.01\n",
        include_str!("data/church.toml")
    )
}

const BELFRY: &str = "name = \"belfry\"\nwidth = 2.0\nheight = 5.0\nmass = 3.0e4\n";

fn scenario(text: &str) -> Result<Scenario, String> {
    Scenario::from_toml_str(text, Path::new(ORIGIN)).map_err(|e| e.to_string())
}

/// The one-line error of `text`, which must name `key`.
fn fails(text: &str, key: &str) -> String {
    let e = scenario(text).map(|_| ()).expect_err("the scenario should fail");
    let prefix = format!("{ORIGIN}: {key}: ");
    assert!(e.starts_with(&prefix) && !e.contains('\n'), "{e:?} should start with {prefix:?}");
    e[prefix.len()..].to_string()
}

#[test]
fn the_contracts_errors_name_the_key() {
    let wide = fails(&text(&BELFRY.replace("width = 2.0", "width = 4.5")), "belfry.width");
    assert!(wide.contains("4.5 m is wider than the 4 m of the tower below it"), "{wide}");
    let second = format!("{BELFRY}\n[[block]]\nname = \"cross\"\nwidth = 2.5\nheight = 1.0\nmass = 1.0e3\n");
    let wider = fails(&text(&second), "cross.width");
    assert!(wider.contains("wider than the 2 m of block \"belfry\" below it"), "{wider}");
    let restitution = fails(&text(BELFRY).replace("mass = 1.5e5", "mass = 1.5e5\nrestitution = 0.8"), "tower.restitution");
    assert!(restitution.contains("applies to a tower alone"), "{restitution}");
    for bad in ["2bells", "bell tower", "tower", "block", ""] {
        let message = fails(&text(&BELFRY.replace("\"belfry\"", &format!("\"{bad}\""))), "block[1].name");
        assert!(message.contains(&format!("\"{bad}\"")), "{message}");
    }
    let twice = fails(
        &text(&format!("{BELFRY}\n[[block]]\n{}", BELFRY.replace("width = 2.0", "width = 1.0"))),
        "block[2].name",
    );
    assert!(twice.contains("names an earlier block too"), "{twice}");
    let typo = fails(&text(&format!("{BELFRY}heigth = 2.0\n")), "belfry.heigth");
    assert!(typo.contains("did you mean `height`?"), "{typo}");
    let missing = fails(&text("width = 2.0\nheight = 5.0\n"), "block2.mass");
    assert!(missing.starts_with("required"), "{missing}");
    let vertical = text(BELFRY).replace(
        "[simulation]",
        "[ground.vertical]\ntype = \"harmonic\"\namplitude = 0.1\nfrequency = 3.0\n\n[simulation]",
    );
    fails(&vertical, "ground.vertical");
}

/// The outputs of a belfry that rocks: its own fields, columns and events,
/// each read back from the run. Its slenderness is atan(2/5), by hand.
#[test]
fn a_belfrys_outputs_are_named_by_it() {
    let case = scenario(&text(BELFRY)).and_then(|s| s.build().map_err(|e| e.to_string())).expect("the case");
    let outcome = case.run(RunOptions::ALL).expect("the run");
    let summary = summary_json(&outcome, 0.0);
    let peak = summary["belfry_max_abs_theta_rad"].as_f64().expect("a peak");
    assert!(peak > 0.0, "the belfry did not rock: {summary}");
    let ratio = summary["belfry_max_theta_over_alpha"].as_f64().expect("a ratio");
    // One division: to the last bit or one rounding of it.
    assert!((ratio - peak / (2.0f64 / 5.0).atan()).abs() <= 2.0 * f64::EPSILON * ratio, "{ratio}");
    let history = outcome.history.as_ref().expect("a history");
    let header = history_header(HISTORY, HISTORY_POINTS, &outcome.layout);
    assert_eq!(header[header.len() - 2..], ["belfry_theta", "belfry_theta_dot"]);
    let sampled = history.samples.iter().map(|s| s.stack.expect("the stack").theta[1].abs()).fold(0.0, f64::max);
    assert!(sampled <= peak && sampled > 0.5 * peak, "{sampled} against {peak}");
    let kinds: Vec<String> = outcome.events.iter().map(|e| event_kind(&outcome.layout, e).into_owned()).collect();
    let impacts = kinds.iter().filter(|k| *k == "belfry_impact").count();
    assert_eq!(summary["belfry_impacts"].as_u64(), Some(impacts as u64));
    assert!(kinds.iter().any(|k| k == "belfry_uplift") && kinds.iter().any(|k| k == "uplift"), "{kinds:?}");
    assert_eq!(summary["events"].as_u64(), Some(kinds.len() as u64));
    assert_eq!(summary["overturned_block"], serde_json::Value::Null);
    assert_eq!(summary["belfry_overturned"], serde_json::Value::Bool(false));
    assert!(summary["max_seat_impulse_ratio"].as_f64().is_some());
}

/// The quantities the summary reports of every body, for the tower and for
/// the belfry, read back from the event log (not from the summary's
/// tracker): the impacts and the first uplift are counted and found among
/// each body's events, the peak over α divided by the slenderness by hand
/// (atan(4/12) for the tower, atan(2/5) for the belfry), and the overturning
/// flags are false with no `overturn` event.
#[test]
fn every_bodys_fields_agree_with_its_events() {
    let case = scenario(&text(BELFRY)).and_then(|s| s.build().map_err(|e| e.to_string())).expect("the case");
    let outcome = case.run(RunOptions::ALL).expect("the run");
    let summary = summary_json(&outcome, 0.0);
    let kinds: Vec<String> = outcome.events.iter().map(|e| event_kind(&outcome.layout, e).into_owned()).collect();
    assert!(!kinds.iter().any(|k| k.ends_with("overturn")), "{kinds:?}");
    for (prefix, alpha) in [("", (4.0f64 / 12.0).atan()), ("belfry_", (2.0f64 / 5.0).atan())] {
        let field = |name: &str| summary[format!("{prefix}{name}")].clone();
        let impacts = kinds.iter().filter(|k| **k == format!("{prefix}impact")).count();
        assert!(impacts > 0, "{prefix}: no impact");
        assert_eq!(field("impacts").as_u64(), Some(impacts as u64), "{prefix}impacts");
        let uplift = kinds.iter().position(|k| *k == format!("{prefix}uplift")).map(|i| outcome.events[i].time);
        assert_eq!(field("first_uplift_time_s").as_f64(), uplift, "{prefix}first_uplift_time_s");
        let peak = field("max_abs_theta_rad").as_f64().expect("a peak");
        let ratio = field("max_theta_over_alpha").as_f64().expect("a ratio");
        // One division, and atan by hand against the library's: a few roundings.
        assert!(
            (ratio - peak / alpha).abs() <= 4.0 * f64::EPSILON * ratio,
            "{prefix}: {ratio} against {}",
            peak / alpha
        );
        assert_eq!(field("overturned"), serde_json::Value::Bool(false), "{prefix}overturned");
    }
    // The friction demands: the tower's at its pivot, the belfry's on the shaft, each a ratio > 0.
    for name in ["max_pivot_friction_demand", "belfry_max_friction_demand"] {
        assert!(summary[name].as_f64().is_some_and(|d| d > 0.0 && d.is_finite()), "{name}: {}", summary[name]);
    }
}

/// A sweep over `belfry.width` sets the width of the block so named (its
/// uplift threshold, and so its first uplift, moves with it), refuses a
/// block's name and a name no block has, has the block's fields as columns,
/// and gives the same rows on one thread and on two.
#[test]
fn a_sweep_over_a_blocks_width() {
    let file = |axes: &str| format!("{}\n[sweep]\n{axes}\n", text(BELFRY));
    let sweep = Sweep::from_toml_str(&file("\"belfry.width\" = [1.0, 2.0]"), Path::new(ORIGIN)).expect("the sweep");
    for (i, width) in [1.0, 2.0].into_iter().enumerate() {
        let table = sweep.case_table(i).expect("the case");
        let block = &table["block"].as_array().expect("the blocks")[0];
        assert_eq!(block["width"].as_float(), Some(width));
    }
    let header = sweep.header();
    let column = |name: &str| header.iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name}"));
    let rows_with = |threads: usize| {
        let mut rows = Vec::new();
        sweep
            .run(Some(threads), &AtomicBool::new(false), |row| {
                rows.push(row);
                Ok::<(), std::convert::Infallible>(())
            })
            .expect("the sweep's run");
        rows
    };
    let rows = rows_with(1);
    // Every cell (the work counts too) the same on two threads.
    assert_eq!(rows, rows_with(2));
    let uplift = |row: usize| match &rows[row].cells[column("belfry_first_uplift_time_s")] {
        Cell::Float(t) => *t,
        other => panic!("{other:?}"),
    };
    // The narrower belfry (tan α = 0.2 against 0.4) lifts first.
    assert!(uplift(0) < uplift(1), "{} {}", uplift(0), uplift(1));
    for (axes, key) in [
        ("\"belfry.name\" = [\"a\"]", "sweep.\"belfry.name\""),
        ("\"belfy.width\" = [1.0]", "sweep.\"belfy.width\""),
    ] {
        let e = Sweep::from_toml_str(&file(axes), Path::new(ORIGIN))
            .map(|_| ())
            .expect_err("refused")
            .to_string();
        assert!(e.starts_with(&format!("{ORIGIN}: {key}: ")), "{e}");
    }
}

/// A slender lantern (1.2 m × 4.5 m, 8 t) on the tower, both released from
/// a small lean of the tower with no ground motion: once the tower rests,
/// each landing of the lantern on its other corner passes through the seated
/// tower's base. That is Housner's impact of the lantern on a fixed base,
/// `ω⁺ = r₂ ω⁻` about the new corner, `r₂ = 1 − 2 m b² / I_O`; the lantern's
/// momentum changes by `m (−h (ω⁺ − ω⁻), s b (ω⁺ + ω⁻))` and its angular
/// momentum about the tower's base centre by `(m y h + J)(ω⁺ − ω⁻)` (`y` the
/// height of its centre above that base, `h` its half height, `b` its half
/// width), so the tower's base carries the ratio
///
/// ```text
/// (m y h + J)(1 − r₂) / (m b (1 + r₂) B₁/2)  = 1.4790…
/// ```
///
/// independent of the lantern's speed: above 1, the model keeps the tower
/// seated where the impulse would tip it.
#[test]
fn a_lantern_landing_on_a_seated_tower_exceeds_the_seat() {
    // The example that shows it (examples/lantern-on-tower.toml): this lantern
    // on the tests' tower, on a fixed base, let go from θ = 0.002 with no ground motion.
    let text = include_str!("../../../examples/lantern-on-tower.toml");
    let outcome = scenario(text)
        .and_then(|s| s.build().map_err(|e| e.to_string()))
        .and_then(|c| c.run(RunOptions::SUMMARY).map_err(|e| e.to_string()))
        .expect("the run");
    let (m, b, h, y, half_tower) = (8.0e3, 0.6, 2.25, 12.0 + 2.25, 2.0);
    let j = m * (1.2f64 * 1.2 + 4.5 * 4.5) / 12.0;
    let r = 1.0 - 2.0 * m * b * b / (j + m * (b * b + h * h));
    let expected = (m * y * h + j) * (1.0 - r) / (m * b * (1.0 + r) * half_tower);
    let ratio = outcome.summary.stack.expect("a stack").max_seat_impulse_ratio;
    // A few products and one solve of Kane's equations: 1e-12 is thousands of roundings.
    assert!((ratio - expected).abs() < 1e-12 * expected, "{ratio} vs {expected}");
    assert!(expected > 1.0);
}
