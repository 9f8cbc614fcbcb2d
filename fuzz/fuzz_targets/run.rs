//! The engine itself on scenarios decoded from the bytes: a tower with 0 to
//! 3 blocks on it (`[[block]]`), an optional building, a harmonic or a pulse
//! of up to 4 g, at most 3 s. A run may refuse the motion with one line
//! naming the file, never panic nor hang; a run that ends holds finite
//! numbers and no block turned past π/2 unless it overturned.
#![no_main]

use libfuzzer_sys::fuzz_target;

// `scenario_text` and `replay`, shared with the stable replay of the kept inputs.
include!("../../crates/rocking-scenario/tests/support/run_fuzz.rs");

fuzz_target!(|data: &[u8]| {
    replay(data);
});
