//! The towers' CSV of `rocking inventory` on arbitrary bytes: the first byte
//! picks the assessment file (a tower with a belfry and its site's parameters
//! given, or the town's file on the synthetic hazard grid), the rest is the
//! CSV. It may refuse the file with one line naming it, and each tower with
//! one line naming its row, never panic; every number of a row is finite.
#![no_main]

use libfuzzer_sys::fuzz_target;

// `replay`, shared with the stable replay of the kept inputs.
include!("../../crates/rocking-assess/tests/support/inventory_fuzz.rs");

fuzz_target!(|data: &[u8]| replay(data));
