//! Replays, under stable `cargo test`, the inputs kept from fuzzing the
//! scenario parser (`fuzz/`, target `scenario`): each must be accepted, or
//! refused with an error that names the file, never a panic. New crashing
//! inputs go to `tests/data/fuzz/scenario/`; the fuzzer's corpus,
//! `fuzz/corpus/scenario/` at the repository root, is replayed too.

use rocking_scenario::Scenario;
use std::path::Path;

#[test]
fn kept_fuzz_inputs_never_panic() {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    for dir in [crate_dir.join("tests/data/fuzz/scenario"), crate_dir.join("../../fuzz/corpus/scenario")] {
        let mut count = 0;
        for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
            let path = entry.unwrap_or_else(|e| panic!("{e}")).path();
            let data = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            count += 1;
            let Ok(text) = std::str::from_utf8(&data) else { continue };
            if let Err(e) = Scenario::from_toml_str(text, Path::new("fuzz.toml")) {
                let line = e.to_string();
                assert!(line.starts_with("fuzz.toml: "), "{}: {line}", path.display());
            }
        }
        assert!(count > 0, "no input in {}", dir.display());
    }
}
