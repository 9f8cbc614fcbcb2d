//! Speed of a belfry on its shaft against the shaft alone, on the user's
//! path: `examples/belfry-on-church.toml` (a 4 m × 12 m tower on a church
//! that may slide, the belfry 3.2 m × 4.5 m on it, 8 s of 0.8 g at 2 Hz: the
//! shaft and the belfry both rock) run as `rocking run` computes it (history
//! every 5 ms and the events kept) and as a sweep does (the summary alone),
//! and the same file with its `[[block]]` table cut, the tower alone, in the
//! same run of the bench. In this process: no process start, no file written.
//!
//! `cargo bench -p rocking-scenario --bench belfry`; the ratio of a belfry's
//! time to its tower's alone is what docs/src/performance.md reports.

// criterion_group! generates an undocumented function.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use rocking_scenario::{Case, RunOptions, Scenario};
use std::hint::black_box;
use std::path::Path;

const BELFRY: &str = include_str!("../../../examples/belfry-on-church.toml");

/// The example without its `[[block]]` table: the tower alone on the same church.
fn tower_alone() -> String {
    match (BELFRY.find("[[block]]"), BELFRY.find("[building]")) {
        (Some(from), Some(to)) if from < to => format!("{}{}", &BELFRY[..from], &BELFRY[to..]),
        _ => panic!("belfry-on-church.toml has no [[block]] before its [building]"),
    }
}

/// The case of a scenario's text, built once (its inputs read and checked).
fn case(text: &str) -> Case {
    Scenario::from_toml_str(text, Path::new("belfry-on-church.toml"))
        .and_then(|s| s.build())
        .unwrap_or_else(|e| panic!("{e}"))
}

fn belfry(c: &mut Criterion) {
    let cases = [("tower_alone", case(&tower_alone())), ("with_belfry", case(BELFRY))];
    for (what, options) in [("run", RunOptions::ALL), ("summary", RunOptions::SUMMARY)] {
        for (name, case) in &cases {
            c.bench_function(&format!("{what}_{name}"), |b| {
                b.iter(|| black_box(case).run(options).map(|o| o.summary.max_abs_theta()).ok())
            });
        }
    }
}

criterion_group!(benches, belfry);
criterion_main!(benches);
