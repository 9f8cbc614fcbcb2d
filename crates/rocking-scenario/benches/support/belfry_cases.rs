//! The two cases of the `belfry` bench, shared with the `stack_ratios`
//! example: `examples/belfry-on-church.toml`, and the same file with its
//! `[[block]]` table cut, the tower alone on the same church.

use rocking_scenario::{Case, Scenario};
use std::path::Path;

const BELFRY: &str = include_str!("../../../../examples/belfry-on-church.toml");

/// The case of a scenario's text, built once (its inputs read and checked).
fn case(text: &str) -> Result<Case, String> {
    Scenario::from_toml_str(text, Path::new("belfry-on-church.toml"))
        .and_then(|s| s.build())
        .map_err(|e| e.to_string())
}

/// The tower alone and the tower with its belfry, named.
pub fn belfry_cases() -> Result<[(&'static str, Case); 2], String> {
    let alone = match (BELFRY.find("[[block]]"), BELFRY.find("[building]")) {
        (Some(from), Some(to)) if from < to => format!("{}{}", &BELFRY[..from], &BELFRY[to..]),
        _ => return Err("belfry-on-church.toml has no [[block]] before its [building]".into()),
    };
    Ok([("tower_alone", case(&alone)?), ("with_belfry", case(BELFRY)?)])
}
