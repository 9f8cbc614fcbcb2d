//! The assessment file on arbitrary text: `rocking assess`'s path short of
//! the record set (parse and validate, the capacity and the kinematic checks
//! of the tower and of each block on it). It may refuse the text with one line
//! naming the file, never panic; what it accepts gives finite numbers.
#![no_main]

use libfuzzer_sys::fuzz_target;

// `replay`, shared with the stable replay of the kept inputs.
include!("../../crates/rocking-assess/tests/support/assessment_fuzz.rs");

fuzz_target!(|data: &[u8]| replay(data));
