//! The commit the `rocking` command is built from, for the reports' closing
//! section: `ROCKING_COMMIT`, the output of `git rev-parse HEAD` in the
//! checkout, or "unknown" outside one (a crate downloaded from a registry).
//! A dozen lines of `git` rather than a build-info crate: this is the one
//! fact needed.

use std::process::Command;

fn main() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let git = |args: &[&str]| {
        Command::new("git")
            .args(args)
            .current_dir(&root)
            .output()
            .ok()
            .filter(|o| o.status.success())
            .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
    };
    let commit = git(&["rev-parse", "HEAD"]).unwrap_or_else(|| "unknown".into());
    println!("cargo:rustc-env=ROCKING_COMMIT={commit}");
    // Built again when HEAD moves: the file HEAD (a worktree's own), and the
    // branch's ref it names (in the repository's common folder).
    if let Some(dir) = git(&["rev-parse", "--absolute-git-dir"]) {
        println!("cargo:rerun-if-changed={dir}/HEAD");
    }
    if let Some(common) = git(&["rev-parse", "--path-format=absolute", "--git-common-dir"]) {
        if let Some(reference) = git(&["symbolic-ref", "-q", "HEAD"]) {
            println!("cargo:rerun-if-changed={common}/{reference}");
        }
        println!("cargo:rerun-if-changed={common}/packed-refs");
    }
}
