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
//! What a run owns: the files it wrote, named in the folder's manifest
//! ([`MANIFEST`], one name a line, written with the files). When a run
//! succeeds, the files of the earlier run's manifest that this one did not
//! write (figures of an earlier `--plot`, a `summary.json` beside a new
//! `sweep.csv`) are removed and the rest replaced; any other file in the
//! folder, whatever its name (the user's own `report.html`, the scenario
//! itself), is left as it is, and a run that would replace one is refused
//! before it starts ([`refuse_foreign`]) and again, under the lock, at the
//! commit. When a run fails or is
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

/// Every file name this tool writes into an output folder: a manifest's
/// entry is removed only if it is one of these (a manifest edited by hand
/// cannot make a run remove another file).
pub const KNOWN: [&str; 48] = [
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
    "hazard.csv",
    "risk.csv",
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
    "fields.csv",
    "town_map.svg",
    "town_map.png",
    "town_ranking.svg",
    "town_ranking.png",
];

/// Whether this tool writes a file of this name: one of [`KNOWN`], or a
/// figure of `rocking assess --plot` (`report_*.svg`, `report_*.png`, named
/// for the limit states and the blocks of its file).
pub fn is_known(name: &str) -> bool {
    KNOWN.contains(&name) || (name.starts_with("report_") && (name.ends_with(".svg") || name.ends_with(".png")) && !name.contains(['/', '\\']))
}

/// The manifest of an output folder: the names of the files the last run
/// that committed there wrote.
pub const MANIFEST: &str = ".rocking-manifest";

/// The first line of a manifest.
const MANIFEST_HEADER: &str = "# the files rocking wrote in this folder, one a line (the next run replaces or removes these and no other)";

/// The names a folder's manifest lists (none if it has none); lines that
/// are not a plain file name (a path, `..`, a comment) are skipped.
pub fn manifest(dir: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(dir.join(MANIFEST)).unwrap_or_default();
    text.lines()
        .filter(|l| !l.is_empty() && !l.starts_with('#') && *l != "." && *l != ".." && !l.contains(['/', '\\']))
        .map(str::to_string)
        .collect()
}

/// Whether `name` in `dir` may be replaced: absent, or written by an earlier run (in `listed`, its manifest).
fn replaceable(dir: &Path, name: &str, listed: &[String]) -> bool {
    std::fs::symlink_metadata(dir.join(name)).is_err() || listed.iter().any(|l| l == name)
}

/// The line refusing to replace `path`, a file no run of this tool wrote.
fn foreign(path: &Path) -> anyhow::Error {
    anyhow::anyhow!(
        "refusing to replace {}: it was not written by an earlier run of rocking (it is not in {}; move it, or choose another --out)",
        path.display(),
        path.with_file_name(MANIFEST).display()
    )
}

/// Fails if any of `outputs` is there already and no earlier run of this
/// tool wrote it (it is not in its folder's manifest).
pub fn refuse_foreign(outputs: &[PathBuf]) -> anyhow::Result<()> {
    for output in outputs {
        let (Some(dir), Some(name)) = (output.parent(), output.file_name()) else {
            continue;
        };
        let dir = if dir.as_os_str().is_empty() { Path::new(".") } else { dir };
        if !replaceable(dir, &name.to_string_lossy(), &manifest(dir)) {
            return Err(foreign(output));
        }
    }
    Ok(())
}

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

    /// Removes the files of the earlier run's manifest that this run did not
    /// write, then moves this run's files and its manifest into the folder
    /// (each rename is atomic), holding the folder's lock throughout: another
    /// run's commit comes wholly before or wholly after. A file of this run's
    /// names that no earlier run wrote fails the commit before anything moves.
    pub fn commit(mut self) -> anyhow::Result<()> {
        let written: Vec<String> = std::fs::read_dir(self.folder())
            .with_context(|| format!("cannot read {}", self.folder().display()))?
            .filter_map(|e| e.ok().map(|e| e.file_name().to_string_lossy().into_owned()))
            .collect();
        let mut list = String::from(MANIFEST_HEADER);
        for name in &written {
            list.push('\n');
            list.push_str(name);
        }
        list.push('\n');
        // Written in the staging folder after its listing, so that it is not one of its own names.
        let staged_manifest = self.path(MANIFEST);
        std::fs::write(&staged_manifest, list).with_context(|| format!("cannot write {}", self.dir.join(MANIFEST).display()))?;
        // A second Ctrl-C waits for the moves to end.
        let held = self.registered.hold();
        let lock = FolderLock::take(&self.dir)?;
        let listed = manifest(&self.dir);
        // A name that a rename cannot replace (a folder), or that is not an
        // earlier run's, fails before anything moves.
        for name in &written {
            let to = self.dir.join(name);
            if to.is_dir() {
                anyhow::bail!("cannot write {}: it is a folder", to.display());
            }
            if !replaceable(&self.dir, name, &listed) {
                return Err(foreign(&to));
            }
        }
        for name in &listed {
            let old = self.dir.join(name);
            if is_known(name) && !written.contains(name) && old.is_file() && !is_input(&old, &self.inputs) {
                std::fs::remove_file(&old).with_context(|| format!("cannot remove {} of an earlier run", old.display()))?;
            }
        }
        // The manifest before the files: a run checking the folder without
        // the lock ([`refuse_foreign`]) never sees a file of this run unlisted.
        let manifest_path = self.dir.join(MANIFEST);
        std::fs::rename(&staged_manifest, &manifest_path).with_context(|| format!("cannot write {}", manifest_path.display()))?;
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
    fn a_commit_replaces_the_files_of_the_manifest_and_keeps_the_others() -> anyhow::Result<()> {
        let dir = tempfile::tempdir()?;
        for name in ["summary.json", "theta.svg", "notes.txt", "events.csv"] {
            std::fs::write(dir.path().join(name), "old")?;
        }
        // An earlier run wrote summary.json and theta.svg; events.csv is the user's, and so is notes.txt
        // (listed by hand, but not a name of this tool's).
        std::fs::write(dir.path().join(MANIFEST), "# header\nsummary.json\ntheta.svg\nnotes.txt\n../x\n")?;
        let staging = Staging::new(dir.path(), &[])?;
        std::fs::write(staging.path("summary.json"), "new")?;
        staging.commit()?;
        let mut names: Vec<String> = std::fs::read_dir(dir.path())?
            .map(|e| Ok(e?.file_name().to_string_lossy().into_owned()))
            .collect::<std::io::Result<_>>()?;
        names.sort();
        // The stale figure is gone, the user's files stay, no staging folder is left.
        assert_eq!(names, [MANIFEST, "events.csv", "notes.txt", "summary.json"]);
        assert_eq!(std::fs::read_to_string(dir.path().join("summary.json"))?, "new");
        assert_eq!(std::fs::read_to_string(dir.path().join("events.csv"))?, "old");
        assert_eq!(manifest(dir.path()), ["summary.json"]);
        Ok(())
    }

    #[test]
    fn a_commit_never_replaces_a_file_no_run_wrote() -> anyhow::Result<()> {
        let dir = tempfile::tempdir()?;
        std::fs::write(dir.path().join("summary.json"), "mine")?;
        let staging = Staging::new(dir.path(), &[])?;
        std::fs::write(staging.path("summary.json"), "new")?;
        let e = format!("{:#}", staging.commit().err().ok_or_else(|| anyhow::anyhow!("committed over the user's file"))?);
        assert!(e.contains("summary.json") && e.contains("not written by an earlier run"), "{e}");
        assert_eq!(std::fs::read_to_string(dir.path().join("summary.json"))?, "mine");
        assert!(refuse_foreign(&[dir.path().join("summary.json")]).is_err());
        assert!(refuse_foreign(&[dir.path().join("history.csv")]).is_ok());
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
