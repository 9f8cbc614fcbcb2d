//! The manifest of a shard, `shard.json` (README, "Studies beyond one
//! machine"): which block of which study the folder's rows are.
//!
//! ```json
//! { "kind": "sweep", "file": "sweep.csv", "k": 2, "n_shards": 3,
//!   "first_case": 3, "cases": 3, "total_cases": 10,
//!   "fingerprint": "sha256:…", "rocking_version": "0.1.0" }
//! ```
//!
//! `kind` says what the rows are and how a merge finishes (`sweep`: the rows
//! are the result; `inventory`: its `inventory.geojson` is made from the
//! merged rows; `fragility`: the merged `stripes.csv` is fitted, the study
//! read again from the file named by `study`); `file` is the file of rows in
//! the folder. The fingerprint is the
//! SHA-256 of the bytes of the study file (the sweep file) as read: shards
//! merge only when they came from the same text. What that file reads (a
//! ground-motion record) is not in it: a record changed between shards is not
//! seen, which keeps a shard from hashing hundreds of records; the version of
//! `rocking` that ran the shard is recorded, and merged only with its own.

use anyhow::{bail, Context};
use rocking_scenario::Shard;
use serde_json::{json, Value};
use sha2::{Digest, Sha256};
use std::ops::Range;
use std::path::Path;

/// The manifest's file name in a shard's folder.
pub const SHARD_JSON: &str = "shard.json";

/// Largest `shard.json` read (bytes): the manifest this tool writes has a few hundred.
pub const MAX_MANIFEST_BYTES: u64 = 64 << 10;

/// What `shard.json` says.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Manifest {
    /// What the rows are: `"sweep"` (or a study's stripes).
    pub kind: String,
    /// The file of rows in the shard's folder (`sweep.csv`).
    pub file: String,
    /// Which block of how many.
    pub shard: Shard,
    /// The cases of the block, as indices in the whole study.
    pub cases: Range<usize>,
    /// The cases of the whole study.
    pub total_cases: usize,
    /// `sha256:` and the hex digest of the study file's bytes.
    pub fingerprint: String,
    /// The version of `rocking` that ran the shard.
    pub rocking_version: String,
    /// The study file (absolute), whose fits a merge makes (a fragility study's); its
    /// bytes must still have the fingerprint.
    pub study: Option<String>,
}

impl Manifest {
    /// The manifest of shard `shard` of a study of `total_cases` cases read from `study_bytes`.
    pub fn new(kind: &str, file: &str, shard: Shard, total_cases: usize, study_bytes: &[u8]) -> Self {
        Self {
            kind: kind.to_string(),
            file: file.to_string(),
            shard,
            cases: shard.cases(total_cases),
            total_cases,
            fingerprint: fingerprint(study_bytes),
            rocking_version: env!("CARGO_PKG_VERSION").to_string(),
            study: None,
        }
    }

    /// The manifest as pretty JSON with a final line break.
    pub fn to_json(&self) -> String {
        let mut value = json!({
            "kind": self.kind,
            "file": self.file,
            "k": self.shard.k(),
            "n_shards": self.shard.n(),
            "first_case": self.cases.start,
            "cases": self.cases.len(),
            "total_cases": self.total_cases,
            "fingerprint": self.fingerprint,
            "rocking_version": self.rocking_version,
        });
        if let (Some(study), Some(map)) = (&self.study, value.as_object_mut()) {
            map.insert("study".into(), Value::String(study.clone()));
        }
        let mut text = serde_json::to_string_pretty(&value).unwrap_or_default();
        text.push('\n');
        text
    }

    /// Reads and checks `dir/shard.json`; errors name the file and the key.
    pub fn read(dir: &Path) -> anyhow::Result<Self> {
        let path = dir.join(SHARD_JSON);
        let text = rocking_scenario::file::read_text(&path, MAX_MANIFEST_BYTES).with_context(|| {
            format!(
                "cannot read {} (is {} a folder written by `rocking sweep --shard K/N` or `rocking inventory --shard K/N`?)",
                path.display(),
                dir.display()
            )
        })?;
        let value: Value = serde_json::from_str(&text).with_context(|| format!("{}: not valid JSON", path.display()))?;
        let text_field = |key: &str| -> anyhow::Result<String> {
            match value.get(key) {
                Some(Value::String(s)) => Ok(s.clone()),
                _ => bail!("{}: {key}: missing or not a string", path.display()),
            }
        };
        let count = |key: &str| -> anyhow::Result<usize> {
            value
                .get(key)
                .and_then(Value::as_u64)
                .and_then(|n| usize::try_from(n).ok())
                .with_context(|| format!("{}: {key}: missing or not a whole number", path.display()))
        };
        let shard = Shard::new(count("k")?, count("n_shards")?).map_err(|e| anyhow::anyhow!("{}: k, n_shards: {e}", path.display()))?;
        let total_cases = count("total_cases")?;
        let (first, cases) = (count("first_case")?, count("cases")?);
        let expected = shard.cases(total_cases);
        if first != expected.start || cases != expected.len() {
            bail!(
                "{}: first_case {first} and cases {cases} are not shard {shard} of {total_cases} cases (first_case {}, cases {})",
                path.display(),
                expected.start,
                expected.len()
            );
        }
        let file = text_field("file")?;
        if file.is_empty() || file.contains(['/', '\\']) || file == ".." {
            bail!("{}: file: {file:?} is not a file name in the shard's folder", path.display());
        }
        Ok(Self {
            kind: text_field("kind")?,
            file,
            shard,
            cases: expected,
            total_cases,
            fingerprint: text_field("fingerprint")?,
            rocking_version: text_field("rocking_version")?,
            study: match value.get("study") {
                None => None,
                Some(Value::String(s)) => Some(s.clone()),
                Some(_) => bail!("{}: study: not a string", path.display()),
            },
        })
    }
}

/// `sha256:` and the lowercase hex SHA-256 of `bytes`.
pub fn fingerprint(bytes: &[u8]) -> String {
    let digest = Sha256::digest(bytes);
    let hex: String = digest.iter().map(|b| format!("{b:02x}")).collect();
    format!("sha256:{hex}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fingerprint_is_the_sha256_of_the_bytes() {
        // FIPS 180-2, appendix B.1: SHA-256("abc").
        assert_eq!(fingerprint(b"abc"), "sha256:ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    }

    #[test]
    fn a_manifest_reads_back_as_written() -> anyhow::Result<()> {
        let dir = tempfile::tempdir()?;
        let shard = Shard::new(2, 3).map_err(anyhow::Error::msg)?;
        let mut m = Manifest::new("fragility", "stripes.csv", shard, 10, b"x = 1\n");
        m.study = Some("/data/study.toml".into());
        std::fs::write(dir.path().join(SHARD_JSON), m.to_json())?;
        let back = Manifest::read(dir.path())?;
        assert_eq!(back, m);
        assert_eq!(back.cases, 3..6, "floor(10/3) .. floor(20/3)");
        Ok(())
    }
}
