//! Speed of a belfry on its shaft against the shaft alone, on the user's
//! path: `examples/belfry-on-church.toml` (a 4 m × 12 m tower on a church
//! that may slide, the belfry 3.2 m × 4.5 m on it, 8 s of 0.8 g at 2 Hz: the
//! shaft and the belfry both rock) run as `rocking run` computes it (history
//! every 5 ms and the events kept) and as a sweep does (the summary alone),
//! and the same file with its `[[block]]` table cut, the tower alone, in the
//! same run of the bench. In this process: no process start, no file written.
//!
//! Also the bodies of `examples/belfry-assess/assess.toml` under El Centro
//! 1940 N-S at scales 1 and 2 (41 s), as a sweep computes them, with and
//! without the belfry.
//!
//! `cargo bench -p rocking-scenario --bench belfry`; the ratio of a belfry's
//! time to its tower's alone is what docs/src/performance.md reports.

// criterion_group! generates an undocumented function.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use rocking_scenario::RunOptions;
use std::hint::black_box;

#[path = "support/belfry_cases.rs"]
mod support;

fn belfry(c: &mut Criterion) {
    let cases = support::belfry_cases().unwrap_or_else(|e| panic!("{e}"));
    for (what, options) in [("run", RunOptions::ALL), ("summary", RunOptions::SUMMARY)] {
        for (name, case) in &cases {
            c.bench_function(&format!("{what}_{name}"), |b| {
                b.iter(|| black_box(case).run(options).map(|o| o.summary.max_abs_theta()).ok())
            });
        }
    }
    // The belfry assessment's bodies under El Centro: 41 s each, a few samples.
    let mut group = c.benchmark_group("record");
    group.sample_size(10);
    for scale in [1.0, 2.0] {
        for (name, case) in support::record_cases(scale).unwrap_or_else(|e| panic!("{e}")) {
            group.bench_function(format!("summary_scale_{scale}_{name}"), |b| {
                b.iter(|| black_box(&case).run(RunOptions::SUMMARY).map(|o| o.summary.max_abs_theta()).ok())
            });
        }
    }
    group.finish();
}

criterion_group!(benches, belfry);
criterion_main!(benches);
