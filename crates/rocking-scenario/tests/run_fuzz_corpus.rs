//! Replays, under stable `cargo test`, the inputs kept from fuzzing the
//! engine (`fuzz/`, target `run`): each input's bytes decode to a scenario
//! (a tower with 0 to 3 blocks, an optional building, a harmonic or a pulse,
//! at most 3 s), which is run as `rocking run` runs it. A run may refuse the
//! motion with one line naming the file, never panic; a run that ends holds
//! finite numbers, and no block that did not overturn turned past π/2.
//! Inputs that found a bug, and the seeds of the corpus (the examples'
//! shapes), are in `tests/data/fuzz/run/`; the fuzzer's corpus,
//! `fuzz/corpus/run/` at the repository root, is replayed too.

use std::collections::BTreeMap;
use std::path::Path;

#[path = "support/run_fuzz.rs"]
mod run_fuzz;
use run_fuzz::{decode, replay, Ran};

#[test]
fn kept_fuzz_inputs_run_or_are_refused_cleanly() {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut tally = BTreeMap::<Ran, usize>::new();
    for dir in [crate_dir.join("tests/data/fuzz/run"), crate_dir.join("../../fuzz/corpus/run")] {
        let mut count = 0;
        for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
            let path = entry.unwrap_or_else(|e| panic!("{e}")).path();
            let data = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            *tally.entry(replay(&data)).or_default() += 1;
            count += 1;
        }
        assert!(count > 0, "no input in {}", dir.display());
    }
    // What the inputs did (`cargo test -- --nocapture` shows it).
    eprintln!("{tally:?}");
    // The corpus exercises the stack: runs with blocks that end.
    let stacked = tally
        .iter()
        .filter(|(ran, _)| matches!(ran, Ran::Ended { blocks, .. } if *blocks > 0))
        .map(|(_, n)| n)
        .sum::<usize>();
    assert!(stacked > 0, "{tally:?}");
}

/// The value of a dotted key of a decoded scenario.
fn number(table: &toml::Table, path: &str) -> f64 {
    let mut value = None;
    let mut inner = table;
    for part in path.split('.') {
        let v = match part.parse::<usize>() {
            Ok(i) => value.and_then(|v: &toml::Value| v.as_array()).and_then(|a| a.get(i)),
            Err(_) => inner.get(part),
        };
        value = v;
        if let Some(t) = v.and_then(toml::Value::as_table) {
            inner = t;
        }
    }
    value.and_then(toml::Value::as_float).unwrap_or_else(|| panic!("{path} in {table}"))
}

/// Asserts each `(key, value)` of an example is decoded from `seed` to within
/// the resolution of the decoder's reads.
fn decodes_to(seed: &str, expected: &[(&str, f64)]) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/fuzz/run").join(seed);
    let data = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let table: toml::Table = decode(&data).0.parse().unwrap_or_else(|e| panic!("{seed}: {e}"));
    for &(key, value) in expected {
        let got = number(&table, key);
        // A 16-bit read on a log scale over at most 6 decades steps by
        // ln(1e6)/65535 = 2.1e-4 of the value (half of it from rounding), and
        // a linear one by 1/65535 of its range: 3e-4 of the value, or 1e-4
        // absolute near 0, covers both.
        assert!((got - value).abs() <= 3e-4 * value.abs() + 1e-4, "{seed}: {key} = {got}, not {value}");
    }
}

#[test]
fn the_seeds_decode_to_the_examples_shapes() {
    // examples/belfry-on-church.toml, its 8 s cut to the fuzzer's 3 s.
    decodes_to(
        "belfry-on-church",
        &[
            ("tower.width", 4.0),
            ("tower.height", 12.0),
            ("tower.mass", 1.5e5),
            ("block.0.width", 3.2),
            ("block.0.height", 4.5),
            ("block.0.mass", 3.0e4),
            ("block.0.wall_thickness", 0.5),
            ("building.mass", 2.0e6),
            ("building.mu_static", 1.25),
            ("building.mu_kinetic", 1.0),
            ("ground.amplitude", 0.8),
            ("ground.frequency", 2.0),
            ("simulation.duration", 3.0),
            ("simulation.rtol", 1e-8),
        ],
    );
    // examples/lantern-on-tower.toml: let go from a lean of 0.002 rad,
    // θ/α = 0.002 / atan(4/12).
    decodes_to(
        "lantern-on-tower",
        &[
            ("tower.width", 4.0),
            ("tower.height", 12.0),
            ("tower.mass", 1.5e5),
            ("block.0.width", 1.2),
            ("block.0.height", 4.5),
            ("block.0.mass", 8.0e3),
            ("initial.theta_over_alpha", 0.002 / (4.0f64 / 12.0).atan()),
            ("simulation.duration", 3.0),
        ],
    );
}
