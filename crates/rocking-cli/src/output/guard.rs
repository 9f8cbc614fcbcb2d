//! Never overwrite an input: an output path that is the scenario file or the
//! record file (the same file by canonical path, or by device and inode) is
//! refused before anything is written; so is a file of an output's name that
//! no earlier run wrote (`folder::refuse_foreign`).

use anyhow::bail;
use std::path::{Path, PathBuf};

/// The canonical form of `path`, which may not exist yet (its folder must).
fn canonical(path: &Path) -> Option<PathBuf> {
    if let Ok(c) = std::fs::canonicalize(path) {
        return Some(c);
    }
    let parent = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    Some(std::fs::canonicalize(parent).ok()?.join(path.file_name()?))
}

#[cfg(unix)]
fn same_file(a: &Path, b: &Path) -> bool {
    use std::os::unix::fs::MetadataExt;
    match (std::fs::metadata(a), std::fs::metadata(b)) {
        (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
        _ => false,
    }
}

#[cfg(not(unix))]
fn same_file(_: &Path, _: &Path) -> bool {
    false
}

/// The input `path` is, if it is one of `inputs`.
fn matching_input<'a>(path: &Path, inputs: &'a [PathBuf]) -> Option<&'a PathBuf> {
    let target = canonical(path);
    inputs
        .iter()
        .find(|input| target.is_some() && target == canonical(input) || same_file(path, input))
}

/// Whether `path` is one of `inputs`.
pub fn is_input(path: &Path, inputs: &[PathBuf]) -> bool {
    matching_input(path, inputs).is_some()
}

/// Fails if any of `outputs` is one of `inputs`, or is a file there already
/// that no earlier run of this tool wrote (not in its folder's manifest):
/// both refused before the run starts.
pub fn refuse_to_overwrite_inputs(outputs: &[PathBuf], inputs: &[PathBuf]) -> anyhow::Result<()> {
    for output in outputs {
        if let Some(input) = matching_input(output, inputs) {
            bail!(
                "refusing to write {}: it is the input file {} (choose another --out)",
                output.display(),
                input.display()
            );
        }
    }
    super::folder::refuse_foreign(outputs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_file_by_another_path_is_refused() -> anyhow::Result<()> {
        let dir = tempfile::tempdir()?;
        let input = dir.path().join("history.csv");
        std::fs::write(&input, "x")?;
        let sub = dir.path().join("sub");
        std::fs::create_dir(&sub)?;
        let roundabout = sub.join("..").join("history.csv");
        assert!(refuse_to_overwrite_inputs(&[roundabout], std::slice::from_ref(&input)).is_err());
        assert!(refuse_to_overwrite_inputs(&[sub.join("history.csv")], &[input]).is_ok());
        Ok(())
    }
}
