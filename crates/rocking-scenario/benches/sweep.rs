//! Speed of a sweep on the grid of `bench/scipy_peer.py`: the 0.5 m × 2 m
//! block on a fixed base, 10 s of harmonic shaking at rtol 1e-8 (atol 1e-10,
//! the peer's `rtol · 1e-2`), amplitudes 0.3, 0.5, 0.7, 0.9 g × frequencies
//! 1, 1.25, …, 7 Hz (100 cases), on 1 and on 2 threads, in this process (no
//! process start, no file written).
//!
//! `cargo bench -p rocking-scenario --bench sweep`; criterion prints the rate
//! in cases per second. Compare with the peer on the same grid
//! (`python3 scripts/peer/scipy_peer.py 0.5 2.0 10 1e-8 "0.3,0.5,0.7,0.9" "1,1.25,…,7"`),
//! or run both, the whole command against the peer, with `scripts/sweep-vs-peer.sh`.

// criterion_group! generates an undocumented function.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use rocking_scenario::Sweep;
use std::convert::Infallible;
use std::path::Path;
use std::sync::atomic::AtomicBool;

/// The peer's block and grid (the performance chapter's 100 cases).
const PEER_GRID: &str = include_str!("peer-grid.toml");

fn sweep(c: &mut Criterion) {
    let sweep = match Sweep::from_toml_str(PEER_GRID, Path::new("peer-grid.toml")) {
        Ok(s) => s,
        Err(e) => panic!("{e}"),
    };
    let mut group = c.benchmark_group("sweep_peer_grid_100_cases_10s");
    group.sample_size(10);
    group.throughput(Throughput::Elements(sweep.len() as u64));
    for threads in [1usize, 2] {
        group.bench_with_input(BenchmarkId::new("threads", threads), &threads, |b, &threads| {
            let cancel = AtomicBool::new(false);
            b.iter(|| {
                let mut sum = 0.0;
                let done = sweep.run(Some(threads), &cancel, |row| {
                    sum += row.cells.iter().filter_map(|c| c.as_f64()).sum::<f64>();
                    Ok::<(), Infallible>(())
                });
                (done.map(|d| d.written).ok(), sum)
            })
        });
    }
    group.finish();
}

criterion_group!(benches, sweep);
criterion_main!(benches);
