//! Regression: the dynamic checks' progress was counted by one atomic and told
//! outside it, so two runs ending at once could tell their counts out of order
//! (CI saw 60 told before 59): a progress bar stepped back. The counts are now
//! told in order, 1, 2, 3, … up to the number of runs, whatever the threads.
//!
//! The progress function here is slow on every odd count (5 ms, a hundred
//! times a run of this tower), so that on four threads the next run ends while
//! it is still being told: before the fix that reordered the counts.

#![allow(clippy::unwrap_used)]

use rocking_assess::{Assessment, AssessmentInput};
use rocking_scenario::RecordCache;
use std::path::Path;
use std::sync::Mutex;
use std::time::Duration;

#[test]
fn progress_counts_are_told_in_order_on_four_threads() {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR"));
    let file = std::fs::read_to_string(folder.join("tests/data/tower_on_b.toml")).unwrap();
    let from = "width = 4.0\nheight = 12.0\nmass = 1.5e5\n";
    assert!(file.contains(from), "tower_on_b.toml has no {from:?}");
    // A slender block that rocks under the synthetic records; [assessment] is the file's last table.
    let text = file.replace(from, "width = 1.0\nheight = 5.0\nmass = 1.0e4\n")
        + "records = [\"records/synthetic/kt_01.AT2\", \"records/synthetic/kt_02.AT2\", \"records/synthetic/kt_03.AT2\"]\n\
           free_after = 2.0\nlambda = { from = 0.5, to = 4.0, step = 0.5 }\n";
    let input = AssessmentInput::from_toml_str(&text, &folder.join("../../data/assess.toml")).unwrap();

    let told = Mutex::new(Vec::new());
    let progress = |done: usize, most: usize| {
        if done % 2 == 1 {
            std::thread::sleep(Duration::from_millis(5));
        }
        told.lock().unwrap().push((done, most));
    };
    let pool = rayon::ThreadPoolBuilder::new().num_threads(4).build().unwrap();
    let outcome = pool
        .install(|| Assessment::run_observed(&input, &RecordCache::with_capacity(3), &progress))
        .unwrap();

    // The runs made, counted from the outcome: the set at λ = 1 and each λ of
    // the scan (the bisection's included), for each check.
    let runs: usize = outcome.dynamic.iter().map(|d| 3 * (1 + d.scan.len())).sum();
    let told = told.into_inner().unwrap();
    let counts: Vec<usize> = told.iter().map(|&(done, _)| done).collect();
    assert_eq!(counts, (1..=runs).collect::<Vec<_>>());
    assert!(told.iter().all(|&(done, most)| done <= most), "{told:?}");
}
