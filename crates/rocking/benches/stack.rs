//! Speed of the stack's stepper against the engine: the 0.5 m × 2 m block of
//! `housner.rs` (20 s of 0.5 g at 2 Hz, rtol 1e-8, atol 1e-10) run by the
//! engine and as a one-block stack, and the same block carrying a 0.3 m ×
//! 0.6 m block of the same density, on a fixed base and on a sliding building
//! (2 × 10⁴ kg, μs = 0.4, μk = 0.35, dynamic normal force), by the stack's
//! stepper and through `simulate` (which keeps the summary).
//!
//! Both blocks rock in both cases (through `simulate`, the largest |θ| of the
//! lower block and of the upper: 0.0729 and 0.282 rad on the fixed base,
//! 0.0549 and 0.227 rad on the sliding building, which slips 11.7 mm at most),
//! so the two-block cases time two rocking interfaces. (With μs = 0.3 the
//! building slips before the upper block's uplift: it never rocks.)
//!
//! `cargo bench -p rocking --bench stack`.

// criterion_group! generates an undocumented function.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use rocking::reference::{stack_bench, StackBench};
use rocking::stack::run::run;
use rocking::stack::{Block, Stack, StackState};
use rocking::{simulate, Initial, Model};
use std::hint::black_box;

fn ok<T, E: std::fmt::Display>(r: Result<T, E>) -> T {
    match r {
        Ok(v) => v,
        Err(e) => panic!("{e}"),
    }
}

fn stacks(c: &mut Criterion) {
    let StackBench {
        ground,
        settings,
        stack_settings,
        tower,
        upper,
        bases,
        gravity,
    } = stack_bench();
    let lower = Block::from_tower(&tower);
    for (name, building) in bases {
        let model = ok(Model::new(Some(tower), building, gravity));
        c.bench_function(&format!("engine_one_block_{name}"), |b| {
            b.iter(|| simulate(black_box(&model), black_box(&ground), Initial::default(), &settings, &mut ()).map(|s| s.max_abs_theta()))
        });
        let one = ok(Stack::new(&[lower], building, gravity));
        c.bench_function(&format!("stack_one_block_{name}"), |b| {
            b.iter(|| run(black_box(&one), black_box(&ground), &StackState::default(), &stack_settings).map(|r| r.events.len()))
        });
        let two = ok(Stack::new(&[lower, upper], building, gravity));
        c.bench_function(&format!("stack_two_blocks_{name}"), |b| {
            b.iter(|| run(black_box(&two), black_box(&ground), &StackState::default(), &stack_settings).map(|r| r.events.len()))
        });
        // The user's path: the same two blocks through `simulate`, with the summary kept.
        let stacked = ok(ok(Model::new(Some(tower), building, gravity)).with_blocks(&[upper]));
        c.bench_function(&format!("simulate_two_blocks_{name}"), |b| {
            b.iter(|| simulate(black_box(&stacked), black_box(&ground), Initial::default(), &settings, &mut ()).map(|s| s.max_abs_theta()))
        });
    }
}

criterion_group!(benches, stacks);
criterion_main!(benches);
