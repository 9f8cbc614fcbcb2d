//! What a second block costs, as ratios measured in one run: the cases of
//! the `stack` bench (crates/rocking/benches/stack.rs: the 0.5 m × 2 m block,
//! 20 s of 0.5 g at 2 Hz, alone through the engine and carrying a 0.3 m ×
//! 0.6 m block through `simulate`, on a fixed base and on a sliding building)
//! and of the `belfry` bench (benches/belfry.rs: examples/belfry-on-church.toml
//! with and without its `[[block]]`, as `rocking run` and as a sweep compute
//! it; and the bodies of examples/belfry-assess under El Centro 1940 N-S at
//! scales 1 and 2, with and without the belfry).
//!
//!     cargo run --release -p rocking-scenario --example stack_ratios [ROUNDS]
//!
//! The two cases of each pair run one after the other, `ROUNDS` times (200
//! by default), and each pair's ratio is that of their median times: on a
//! shared machine whose speed drifts by a factor of two from one minute to
//! the next, the pair sees the same drift, and two runs of criterion do not.

use rocking::reference::stack_bench;
use rocking::stack::run::run;
use rocking::stack::{Block, Stack, StackState};
use rocking::{simulate, Initial, Model};
use rocking_scenario::{Case, RunOptions};
use std::hint::black_box;
use std::time::Instant;

#[path = "../benches/support/belfry_cases.rs"]
mod support;

/// The median of `times` (s).
fn median(mut times: Vec<f64>) -> f64 {
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

/// The median times of `a` and `b`, run in turn `rounds` times.
fn pair(rounds: usize, mut a: impl FnMut(), mut b: impl FnMut()) -> (f64, f64) {
    let (mut ta, mut tb) = (Vec::with_capacity(rounds), Vec::with_capacity(rounds));
    for _ in 0..rounds {
        let start = Instant::now();
        a();
        ta.push(start.elapsed().as_secs_f64());
        let start = Instant::now();
        b();
        tb.push(start.elapsed().as_secs_f64());
    }
    (median(ta), median(tb))
}

fn report(what: &str, (one, two): (f64, f64)) {
    println!("{what:<58} {:>9.1} µs {:>9.1} µs {:>6.2}×", one * 1e6, two * 1e6, two / one);
}

fn main() -> Result<(), String> {
    let rounds = match std::env::args().nth(1) {
        Some(r) => r
            .parse::<usize>()
            .ok()
            .filter(|&r| r > 0)
            .ok_or(format!("ROUNDS: expected a positive integer, got {r:?}"))?,
        None => 200,
    };
    println!("{:<58} {:>12} {:>12} {:>7}", "pair (medians of the rounds)", "first", "second", "ratio");
    let bench = stack_bench();
    let (ground, settings, stack_settings) = (&bench.ground, &bench.settings, &bench.stack_settings);
    let (tower, upper, gravity) = (bench.tower, bench.upper, bench.gravity);
    for (name, building) in bench.bases {
        let name = name.replace('_', " ");
        let one = Model::new(Some(tower), building, gravity).map_err(|e| e.to_string())?;
        let two = one.clone().with_blocks(&[upper]).map_err(|e| e.to_string())?;
        let engine = || {
            black_box(simulate(&one, ground, Initial::default(), settings, &mut ()).ok());
        };
        let stacked = || {
            black_box(simulate(&two, ground, Initial::default(), settings, &mut ()).ok());
        };
        report(&format!("{name}: engine, one block / simulate, two"), pair(rounds, engine, stacked));
        let (stack_one, stack_two) = (
            Stack::new(&[Block::from_tower(&tower)], building, gravity).map_err(|e| e.to_string())?,
            Stack::new(&[Block::from_tower(&tower), upper], building, gravity).map_err(|e| e.to_string())?,
        );
        let by_stack = |s: &Stack| {
            black_box(run(s, ground, &StackState::default(), stack_settings).ok());
        };
        report(
            &format!("{name}: stack's stepper, one block / two"),
            pair(rounds, || by_stack(&stack_one), || by_stack(&stack_two)),
        );
    }
    let [(_, alone), (_, belfry)] = support::belfry_cases()?;
    for (what, options) in [("as rocking run", RunOptions::ALL), ("as a sweep (summary)", RunOptions::SUMMARY)] {
        let go = |c: &Case| drop(black_box(c.run(options).ok()));
        report(
            &format!("belfry-on-church {what}: alone / with belfry"),
            pair(rounds, || go(&alone), || go(&belfry)),
        );
    }
    // Each of these runs 41 s of record: a tenth of the rounds.
    let rounds = rounds.div_ceil(10);
    for scale in [1.0, 2.0] {
        let [(_, alone), (_, belfry)] = support::record_cases(scale)?;
        for (what, options) in [("run", RunOptions::ALL), ("sweep", RunOptions::SUMMARY)] {
            let go = |c: &Case| drop(black_box(c.run(options).ok()));
            report(
                &format!("belfry-assess, El Centro x{scale}, as a {what}: alone / with"),
                pair(rounds, || go(&alone), || go(&belfry)),
            );
        }
    }
    Ok(())
}
