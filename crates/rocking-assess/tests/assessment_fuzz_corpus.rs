//! Replays, under stable `cargo test`, the inputs kept from fuzzing the
//! assessment file (`fuzz/`, target `assessment`): each is parsed and
//! validated, its capacities and kinematic checks computed; it must be
//! refused with one line naming the file, or give finite numbers, never a
//! panic. New crashing inputs go to `tests/data/fuzz/assessment/`; the
//! fuzzer's corpus, `fuzz/corpus/assessment/` at the repository root, is
//! replayed too.

use std::path::Path;

#[path = "support/assessment_fuzz.rs"]
mod assessment_fuzz;

#[test]
fn kept_fuzz_inputs_never_panic() {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    for dir in [crate_dir.join("tests/data/fuzz/assessment"), crate_dir.join("../../fuzz/corpus/assessment")] {
        let mut count = 0;
        for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
            let path = entry.unwrap_or_else(|e| panic!("{e}")).path();
            let data = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            assessment_fuzz::replay(&data);
            count += 1;
        }
        assert!(count > 0, "no input in {}", dir.display());
    }
}
