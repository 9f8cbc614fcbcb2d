//! Replays, under stable `cargo test`, the inputs kept from fuzzing the
//! inventory (`fuzz/`, target `inventory`): the first byte of each picks the
//! assessment file, the rest is the towers' CSV; it must be refused with one
//! line naming the towers' file, or each tower assessed or refused with one
//! line naming its row, never a panic. New crashing inputs go to
//! `tests/data/fuzz/inventory/`; the fuzzer's corpus, `fuzz/corpus/inventory/`
//! at the repository root, is replayed too.

use std::path::Path;

#[path = "support/inventory_fuzz.rs"]
mod inventory_fuzz;

#[test]
fn kept_fuzz_inputs_never_panic() {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    for dir in [crate_dir.join("tests/data/fuzz/inventory"), crate_dir.join("../../fuzz/corpus/inventory")] {
        let mut count = 0;
        for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
            let path = entry.unwrap_or_else(|e| panic!("{e}")).path();
            let data = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            inventory_fuzz::replay(&data);
            count += 1;
        }
        assert!(count > 0, "no input in {}", dir.display());
    }
}
