//! Integration tests of the `rocking` binary: the real executable on real files
//! in temporary folders (one test binary, ripgrep style).

mod util;

mod assess;
mod check;
mod errors;
mod folder;
mod fragility;
mod guard;
mod hardening;
mod keys;
mod run;
mod shard;
mod spectrum;
mod sweep;
mod vertical;
