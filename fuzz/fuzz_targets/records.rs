//! Every record reader on arbitrary text: the first byte picks the format
//! (AT2, ESM, CSV with or without `dt`, or guessed), the rest is the file.
//! A reader may refuse the text, never panic; a record it accepts holds
//! finite values at strictly increasing times.
#![no_main]

use libfuzzer_sys::fuzz_target;

// `replay`, shared with the stable replay of the kept inputs.
include!("../../crates/rocking/tests/support/records_fuzz.rs");

fuzz_target!(|data: &[u8]| replay(data));
