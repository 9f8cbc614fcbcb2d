//! The lock of an output folder: whoever changes the files of a folder (a
//! run's commit, a merge) holds it, so that two processes writing the same
//! folder at once never interleave their files. It is an advisory lock of
//! the operating system on the folder itself (`flock` on Unix), released when
//! the process ends however it ends, and independent of process ids (two
//! processes of two containers may have the same one). Where a folder cannot
//! be locked (a file system that only locks files opened for writing, as NFS
//! does), the lock is taken on a file `.rocking.lock` in it, which is left
//! there (removing a lock file would let a third process lock a new file
//! while a second waits on the old one).

use anyhow::Context;
use std::fs::{File, OpenOptions};
use std::path::Path;

/// The lock file, where the folder itself cannot be locked.
pub const LOCK_FILE: &str = ".rocking.lock";

/// An exclusive lock on a folder, held until dropped.
#[derive(Debug)]
pub struct FolderLock {
    _file: File,
}

impl FolderLock {
    /// Waits for the lock of the folder `dir` (which must exist) and takes it.
    pub fn take(dir: &Path) -> anyhow::Result<Self> {
        #[cfg(unix)]
        if let Ok(file) = File::open(dir) {
            if file.lock().is_ok() {
                return Ok(Self { _file: file });
            }
        }
        let path = dir.join(LOCK_FILE);
        let file = OpenOptions::new()
            .create(true)
            .truncate(false)
            .write(true)
            .open(&path)
            .with_context(|| format!("cannot lock the output folder {}", dir.display()))?;
        file.lock().with_context(|| format!("cannot lock the output folder {}", dir.display()))?;
        Ok(Self { _file: file })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[cfg(unix)]
    #[test]
    fn a_second_lock_waits_for_the_first() -> anyhow::Result<()> {
        let dir = tempfile::tempdir()?;
        let first = FolderLock::take(dir.path())?;
        // The lock is on the open folder: another open of it cannot take it meanwhile.
        let other = File::open(dir.path())?;
        assert!(matches!(other.try_lock(), Err(std::fs::TryLockError::WouldBlock)));
        drop(first);
        assert!(other.try_lock().is_ok());
        // No lock file where the folder itself can be locked.
        assert_eq!(std::fs::read_dir(dir.path())?.count(), 0);
        Ok(())
    }
}
