//! An output folder owned by one run: the files are written under a hidden
//! staging folder inside it and moved into place only when the run succeeds,
//! so the folder never mixes two runs and a failed run leaves nothing.
//!
//! Two runs writing the same folder at once: each has its own staging folder
//! (a name drawn at random, created only if it does not exist, never one of
//! the process id: two processes in two containers may have the same id), and
//! each commit holds the folder's lock ([`FolderLock`]) from the first removal
//! to the last move, so the folder ends with the complete files of the run
//! that committed last.
//!
//! What a run owns: the files this tool writes ([`KNOWN`]). When a run
//! succeeds, the known files of an earlier run that this one did not write
//! (figures of an earlier `--plot`, a `summary.json` beside a new `sweep.csv`)
//! are removed and the rest replaced; any other file in the folder (the
//! user's own, the scenario itself) is left as it is. When a run fails or is
//! cut short, the staging folder is removed and the folder keeps the earlier
//! run's files untouched; a folder the run created for its output (the
//! output folder, a missing parent of it) is removed too, so that a refused
//! run leaves the disk as it found it ([`CreatedFolders`]).

use super::guard::is_input;
use super::lock::FolderLock;
use crate::signals::Registered;
use anyhow::Context;
use std::path::{Path, PathBuf};
use tempfile::TempDir;

/// Every file name this tool writes into an output folder.
pub const KNOWN: [&str; 41] = [
    "summary.json",
    "history.csv",
    "events.csv",
    "theta.svg",
    "theta.png",
    "slip.svg",
    "slip.png",
    "sweep.csv",
    "sweep_max_theta.svg",
    "sweep_max_theta.png",
    "sweep_map.svg",
    "sweep_map.png",
    "shard.json",
    "stripes.csv",
    "fragility.csv",
    "fractions.csv",
    "ida.svg",
    "ida.png",
    "fragility.svg",
    "fragility.png",
    "spectra.csv",
    "fit.csv",
    "fit.json",
    "spectra.svg",
    "spectra.png",
    "code_spectra.svg",
    "code_spectra.png",
    "fit_SLV.svg",
    "fit_SLV.png",
    "fit_SLC.svg",
    "fit_SLC.png",
    "fit_SD.svg",
    "fit_SD.png",
    "fit_NC.svg",
    "fit_NC.png",
    "assessment.json",
    "capacity.csv",
    "records.csv",
    "report.html",
    "inventory.csv",
    "inventory.geojson",
];

/// The prefix of a staging folder's name (the rest is drawn at random).
pub const STAGING_PREFIX: &str = ".rocking-partial-";

/// A folder being written: files go to [`Staging::path`]; [`Staging::commit`]
/// moves them into place; dropping it without a commit removes them.
#[derive(Debug)]
pub struct Staging {
    dir: PathBuf,
    // Unregistered before the folder is removed (fields drop in order).
    registered: Registered,
    staging: TempDir,
    inputs: Vec<PathBuf>,
    // Removed after the staging folder when there is no commit.
    created: CreatedFolders,
}

impl Staging {
    /// Creates `dir` if needed and an empty staging folder in it. `inputs`
    /// (the scenario, a record) are never removed, even under a known name.
    pub fn new(dir: &Path, inputs: &[PathBuf]) -> anyhow::Result<Self> {
        let created = CreatedFolders::create(dir)?;
        let staging = tempfile::Builder::new()
            .prefix(STAGING_PREFIX)
            .tempdir_in(dir)
            .with_context(|| format!("cannot write into the output folder {}", dir.display()))?;
        Ok(Self {
            dir: dir.to_path_buf(),
            registered: Registered::new(staging.path(), &created.0),
            staging,
            inputs: inputs.to_vec(),
            created,
        })
    }

    /// The staging folder (figures are drawn there under their final names).
    pub fn folder(&self) -> &Path {
        self.staging.path()
    }

    /// Where to write the file `name` until the commit.
    pub fn path(&self, name: &str) -> PathBuf {
        self.staging.path().join(name)
    }

    /// Removes the known files of an earlier run that this one did not write,
    /// then moves this run's files into the folder (each rename is atomic),
    /// holding the folder's lock throughout: another run's commit comes
    /// wholly before or wholly after.
    pub fn commit(mut self) -> anyhow::Result<()> {
        let written: Vec<_> = std::fs::read_dir(self.folder())
            .with_context(|| format!("cannot read {}", self.folder().display()))?
            .filter_map(|e| e.ok().map(|e| e.file_name()))
            .collect();
        // A second Ctrl-C waits for the moves to end.
        let held = self.registered.hold();
        let lock = FolderLock::take(&self.dir)?;
        // A name that a rename cannot replace (a folder) fails before anything moves.
        for name in &written {
            let to = self.dir.join(name);
            if to.is_dir() {
                anyhow::bail!("cannot write {}: it is a folder", to.display());
            }
        }
        for name in KNOWN {
            let old = self.dir.join(name);
            if !written.iter().any(|w| w == name) && old.is_file() && !is_input(&old, &self.inputs) {
                std::fs::remove_file(&old).with_context(|| format!("cannot remove {} of an earlier run", old.display()))?;
            }
        }
        for name in &written {
            let to = self.dir.join(name);
            std::fs::rename(self.folder().join(name), &to).with_context(|| format!("cannot write {}", to.display()))?;
        }
        drop(lock);
        drop(held);
        self.created.keep();
        Ok(())
    }
}

/// The folders made for an output folder: it and its parents that did not
/// exist, the outermost first. Dropped without [`CreatedFolders::keep`] (the
/// run failed before writing anything), each is removed if it is still empty,
/// the innermost first: a folder that was there before, or that holds a file
/// another process put there meanwhile, is never removed.
#[derive(Debug)]
pub struct CreatedFolders(Vec<PathBuf>);

impl CreatedFolders {
    /// Creates the folder `dir` and its missing parents, noting those this call made.
    pub fn create(dir: &Path) -> anyhow::Result<Self> {
        let missing: Vec<&Path> = dir.ancestors().filter(|a| !a.as_os_str().is_empty()).take_while(|a| !a.is_dir()).collect();
        let mut created = Self(Vec::new());
        for folder in missing.into_iter().rev() {
            match std::fs::create_dir(folder) {
                Ok(()) => created.0.push(folder.to_path_buf()),
                // Made by another process meanwhile: not this one's to remove.
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists && folder.is_dir() => {}
                Err(e) => return Err(e).with_context(|| format!("cannot create the output folder {}", dir.display())),
            }
        }
        Ok(created)
    }

    /// Keeps the folders (the run wrote its files there).
    pub fn keep(&mut self) {
        self.0.clear();
    }
}

impl Drop for CreatedFolders {
    fn drop(&mut self) {
        for folder in self.0.iter().rev() {
            // `remove_dir` removes only an empty folder; one that is not stays, and so do its parents.
            if std::fs::remove_dir(folder).is_err() {
                break;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_commit_replaces_the_known_files_and_keeps_the_others() -> anyhow::Result<()> {
        let dir = tempfile::tempdir()?;
        for name in ["summary.json", "theta.svg", "notes.txt"] {
            std::fs::write(dir.path().join(name), "old")?;
        }
        let staging = Staging::new(dir.path(), &[])?;
        std::fs::write(staging.path("summary.json"), "new")?;
        staging.commit()?;
        let mut names: Vec<String> = std::fs::read_dir(dir.path())?
            .map(|e| Ok(e?.file_name().to_string_lossy().into_owned()))
            .collect::<std::io::Result<_>>()?;
        names.sort();
        // The stale figure is gone, the user's file stays, no staging folder is left.
        assert_eq!(names, ["notes.txt", "summary.json"]);
        assert_eq!(std::fs::read_to_string(dir.path().join("summary.json"))?, "new");
        Ok(())
    }

    #[test]
    fn only_the_folders_made_and_still_empty_are_removed() -> anyhow::Result<()> {
        let dir = tempfile::tempdir()?;
        let (outer, inner) = (dir.path().join("a"), dir.path().join("a/b/c"));
        // Made and dropped: a/b/c, a/b and a are gone, the folder that was there stays.
        drop(CreatedFolders::create(&inner)?);
        assert!(!outer.exists() && dir.path().is_dir());
        // A file put in a/ meanwhile keeps a/ (b/ and c/, empty, go).
        let created = CreatedFolders::create(&inner)?;
        std::fs::write(outer.join("notes.txt"), "mine")?;
        drop(created);
        assert!(outer.join("notes.txt").is_file() && !outer.join("b").exists());
        // Kept: all stay; a folder that existed is never noted.
        CreatedFolders::create(&inner)?.keep();
        assert!(inner.is_dir());
        std::fs::remove_dir(&inner)?;
        drop(CreatedFolders::create(&outer.join("b"))?);
        assert!(outer.join("b").is_dir());
        Ok(())
    }

    #[test]
    fn a_dropped_staging_leaves_the_folder_as_it_was() -> anyhow::Result<()> {
        let dir = tempfile::tempdir()?;
        std::fs::write(dir.path().join("summary.json"), "old")?;
        {
            let staging = Staging::new(dir.path(), &[])?;
            std::fs::write(staging.path("summary.json"), "half")?;
        }
        let names: Vec<_> = std::fs::read_dir(dir.path())?.collect::<std::io::Result<_>>()?;
        assert_eq!(names.len(), 1);
        assert_eq!(std::fs::read_to_string(dir.path().join("summary.json"))?, "old");
        Ok(())
    }
}
