//! The scenario parser on arbitrary text: `check`'s path (parse and
//! validate). It may refuse the text with an error naming the file, never panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rocking_scenario::Scenario;
use std::path::Path;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let origin = Path::new("fuzz.toml");
    if let Err(e) = Scenario::from_toml_str(text, origin) {
        assert!(e.to_string().starts_with("fuzz.toml: "));
    }
});
