//! Replays, under stable `cargo test`, the inputs kept from fuzzing the
//! assessment file and the towers' CSV (`fuzz/`, targets `assessment` and
//! `inventory`), each as its target does (`support/assessment_fuzz.rs`,
//! `support/inventory_fuzz.rs`): an assessment file must be refused with one
//! line naming it, or give finite capacities and checks; a towers' file must
//! be refused with one line naming it, or each tower assessed or refused with
//! one line naming its row; never a panic. New crashing inputs go to
//! `tests/data/fuzz/<target>/`; the fuzzer's corpus, `fuzz/corpus/<target>/`
//! at the repository root, is replayed too.

use std::path::Path;

#[path = "support/assessment_fuzz.rs"]
mod assessment_fuzz;
#[path = "support/inventory_fuzz.rs"]
mod inventory_fuzz;

/// Replays every input kept for the fuzz target `target` through `replay`.
fn replay_kept(target: &str, replay: fn(&[u8])) {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    for dir in [crate_dir.join("tests/data/fuzz").join(target), crate_dir.join("../../fuzz/corpus").join(target)] {
        let mut count = 0;
        for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
            let path = entry.unwrap_or_else(|e| panic!("{e}")).path();
            let data = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            replay(&data);
            count += 1;
        }
        assert!(count > 0, "no input in {}", dir.display());
    }
}

#[test]
fn kept_assessment_files_never_panic() {
    replay_kept("assessment", assessment_fuzz::replay);
}

#[test]
fn kept_towers_files_never_panic() {
    replay_kept("inventory", inventory_fuzz::replay);
}
