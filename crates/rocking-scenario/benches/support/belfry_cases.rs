//! The cases of the `belfry` bench, shared with the `stack_ratios` example:
//! `examples/belfry-on-church.toml`, and the same file with its `[[block]]`
//! table cut, the tower alone on the same church; and the bodies of
//! `examples/belfry-assess/assess.toml` under a record, with and without
//! the belfry.

use rocking_scenario::{Case, Scenario};
use std::path::Path;

const BELFRY: &str = include_str!("../../../../examples/belfry-on-church.toml");
const ASSESS: &str = include_str!("../../../../examples/belfry-assess/assess.toml");

/// The case of a scenario's text, its paths relative to `origin`, built once
/// (its inputs read and checked).
fn case(text: &str, origin: &Path) -> Result<Case, String> {
    Scenario::from_toml_str(text, origin).and_then(|s| s.build()).map_err(|e| e.to_string())
}

/// `text` without its `[[block]]` tables (those before its `[building]`).
fn tower_alone(text: &str, what: &str) -> Result<String, String> {
    match (text.find("[[block]]"), text.find("[building]")) {
        (Some(from), Some(to)) if from < to => Ok(format!("{}{}", &text[..from], &text[to..])),
        _ => Err(format!("{what} has no [[block]] before its [building]")),
    }
}

/// The tower alone and the tower with its belfry, named.
pub fn belfry_cases() -> Result<[(&'static str, Case); 2], String> {
    let origin = Path::new("belfry-on-church.toml");
    let alone = tower_alone(BELFRY, "belfry-on-church.toml")?;
    Ok([("tower_alone", case(&alone, origin)?), ("with_belfry", case(BELFRY, origin)?)])
}

/// The tower, belfry and church of `examples/belfry-assess/assess.toml`
/// (its `[tower]`, `[[block]]` and `[building]` tables) under El Centro
/// 1940 N-S (`data/records`) scaled by `scale`, for 41 s: the tower alone
/// and with its belfry, named. The cases of the record table of
/// docs/src/performance.md.
pub fn record_cases(scale: f64) -> Result<[(&'static str, Case); 2], String> {
    let bodies = match (ASSESS.find("[tower]"), ASSESS.find("[site]")) {
        (Some(from), Some(to)) if from < to => &ASSESS[from..to],
        _ => return Err("belfry-assess/assess.toml has no [tower] before its [site]".into()),
    };
    let text = format!(
        "{bodies}\n[ground]\ntype = \"record\"\nfile = \"../../data/records/elcentro_1940_ns.AT2\"\nscale = {scale:?}\n\n[simulation]\nduration = 41.0\n"
    );
    let origin = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/belfry-assess/assess.toml"));
    let alone = tower_alone(&text, "belfry-assess/assess.toml")?;
    Ok([("tower_alone", case(&alone, origin)?), ("with_belfry", case(&text, origin)?)])
}
