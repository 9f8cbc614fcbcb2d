//! Replays, under stable `cargo test`, the inputs kept from fuzzing the
//! record readers (`fuzz/`, target `records`): each file is the fuzz input,
//! its first byte picking the format as the fuzz target does. Every reader
//! must refuse or accept without panicking, and an accepted record must hold
//! finite values at strictly increasing times. New crashing inputs go to
//! `tests/data/fuzz/records/`; the fuzzer's corpus, `fuzz/corpus/records/` at
//! the repository root, is replayed too.

use std::path::Path;

#[path = "support/records_fuzz.rs"]
mod records_fuzz;
use records_fuzz::replay;

#[test]
fn kept_fuzz_inputs_never_panic() {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    for dir in [crate_dir.join("tests/data/fuzz/records"), crate_dir.join("../../fuzz/corpus/records")] {
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
