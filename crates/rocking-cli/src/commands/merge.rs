//! `rocking merge DIR... --out DIR`: the shards of a study (folders written by
//! `rocking sweep --shard K/N` or `rocking inventory --shard K/N`) put back
//! into one file, in case order, byte-identical to the file of the unsharded
//! run (README, "Studies beyond one machine"); an inventory's
//! `inventory.geojson` is then made from the merged rows.
//!
//! Everything is checked before a byte is kept: every folder's `shard.json`
//! (same kind, same study fingerprint, same `rocking` version, same number of
//! shards and cases), every shard from 1 to N exactly once, the same header in
//! every file, and in each file as many rows as its shard has cases, the last
//! one ended by a line break. The rows are copied as bytes (never parsed and
//! written again, so nothing of them can change) into a temporary file in the
//! output folder, renamed into place once complete: an interrupted or refused
//! merge leaves no partial file, and an existing file is never replaced.
//!
//! The output folder must be new or empty (but for the shards' own folders):
//! a merge's file beside another run's files (a `summary.json`, a stale
//! `shard.json`) would read as one result. The folder's lock is held from that check to the rename, so a run
//! writing the same folder at once comes wholly before or after.
//!
//! Nothing grows with what a manifest claims: the number of shards is checked
//! against the folders given before anything is counted or listed, a header
//! is read no further than [`MAX_HEADER_BYTES`], and a file of rows must be a
//! regular file (a link to `/dev/zero` is refused, not read for ever).

use crate::output::FolderLock;
use crate::shard::{Manifest, SHARD_JSON};
use anyhow::{bail, Context};
use std::fs::File;
use std::io::{BufRead, BufReader, BufWriter, Read, Write};
use std::path::{Path, PathBuf};

/// Longest header line read (bytes): a sweep's has a few kB.
pub const MAX_HEADER_BYTES: u64 = 1 << 20;

/// Missing shards listed by name at most (the rest are counted).
const MISSING_LISTED: usize = 10;

/// Arguments of `rocking merge`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The shards' folders (each with its shard.json), in any order.
    #[arg(required = true, value_name = "DIR")]
    pub shards: Vec<PathBuf>,
    /// Output folder, created if needed; it must be empty but for the shards' folders.
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
}

/// The file of the merged rows of each kind of shard this version can merge.
fn merged_file(kind: &str) -> Option<&'static str> {
    match kind {
        "sweep" => Some(super::sweep::SWEEP_CSV),
        "inventory" => Some(super::town::INVENTORY_CSV),
        "fragility" => Some(super::fragility::STRIPES_CSV),
        _ => None,
    }
}

/// Checks the shards and writes the merged file.
pub fn execute(args: &Args) -> anyhow::Result<()> {
    let shards: Vec<(PathBuf, Manifest)> = args.shards.iter().map(|d| Ok((d.clone(), Manifest::read(d)?))).collect::<anyhow::Result<_>>()?;
    let ordered = check_set(&shards)?;
    let (first_dir, first) = ordered[0];
    let name = merged_file(&first.kind).with_context(|| {
        format!(
            "{}: kind: {:?} is not a kind of shard this rocking can merge (it merges \"sweep\", \"inventory\" and \"fragility\")",
            first_dir.join(SHARD_JSON).display(),
            first.kind
        )
    })?;
    if first.file != name {
        bail!(
            "{}: file: {:?}, expected {name:?} for kind {:?}",
            first_dir.join(SHARD_JSON).display(),
            first.file,
            first.kind
        );
    }

    // Removed again (if this made it and it is still empty) when the merge fails.
    let mut created = crate::output::CreatedFolders::create(&args.out)?;
    let _lock = FolderLock::take(&args.out)?;
    let target = args.out.join(name);
    if target.exists() {
        bail!("refusing to write {}: it exists already (remove it, or choose another --out)", target.display());
    }
    refuse_a_used_folder(&args.out, &args.shards)?;
    let mut temp = tempfile::Builder::new()
        .prefix(&format!(".{name}."))
        .tempfile_in(&args.out)
        .with_context(|| format!("cannot write in {}", args.out.display()))?;
    {
        let mut out = BufWriter::new(temp.as_file_mut());
        let mut header: Option<(Vec<u8>, &Path)> = None;
        for (dir, manifest) in &ordered {
            let path = dir.join(&manifest.file);
            let file = File::open(&path).with_context(|| format!("cannot read {}", path.display()))?;
            if !file.metadata().with_context(|| format!("cannot read {}", path.display()))?.is_file() {
                bail!("{}: not a regular file", path.display());
            }
            let mut reader = BufReader::with_capacity(1 << 16, file);
            let mut line = Vec::new();
            let mut scan = Records::default();
            scan.read_record(&mut (&mut reader).take(MAX_HEADER_BYTES), &mut line)
                .with_context(|| format!("cannot read {}", path.display()))?;
            if line.len() as u64 >= MAX_HEADER_BYTES && !scan.complete() {
                bail!("{}: no header line in its first {} MiB", path.display(), MAX_HEADER_BYTES >> 20);
            }
            if line.is_empty() || !scan.complete() {
                bail!("{}: truncated: no complete header line", path.display());
            }
            match &header {
                None => {
                    out.write_all(&line).with_context(|| format!("cannot write {}", target.display()))?;
                    header = Some((line.clone(), dir));
                }
                Some((h, other)) if *h != line => bail!(
                    "{}: its columns differ from those of {} (shards of different sweeps?)",
                    path.display(),
                    other.join(&manifest.file).display()
                ),
                Some(_) => {}
            }
            let rows = copy_records(&mut reader, &mut out, &mut scan).with_context(|| format!("merging {} into {}", path.display(), target.display()))?;
            if !scan.complete() {
                bail!("{}: truncated: its last row has no line break (an interrupted or cut copy?)", path.display());
            }
            if rows != manifest.cases.len() {
                bail!(
                    "{}: truncated or altered: {rows} rows, but {} says shard {} has {} cases",
                    path.display(),
                    dir.join(SHARD_JSON).display(),
                    manifest.shard,
                    manifest.cases.len()
                );
            }
        }
        out.flush().with_context(|| format!("cannot write {}", target.display()))?;
    }
    temp.as_file().sync_all().with_context(|| format!("cannot write {}", target.display()))?;
    // `persist_noclobber`: a file that appeared meanwhile is not replaced either.
    temp.persist_noclobber(&target)
        .map_err(|e| e.error)
        .with_context(|| format!("cannot write {}", target.display()))?;
    created.keep();
    let mut written = vec![target.clone()];
    if first.kind == "inventory" {
        written.extend(finish_inventory(&args.out, &target)?);
    }
    if first.kind == "fragility" {
        written.extend(finish_fragility(&first_dir.join(SHARD_JSON), first, &args.out, &target)?);
    }
    let written: Vec<String> = written.iter().map(|p| p.display().to_string()).collect();
    super::print(&format!(
        "merged {} shards ({} {}) into {}\n",
        ordered.len(),
        first.total_cases,
        if first.kind == "inventory" { "towers" } else { "cases" },
        written.join(", ")
    ))
}

/// The fits of a merged fragility study: its study file read again (refused
/// if its bytes changed since the shards ran), its stripes counted from the
/// merged `stripes.csv`.
fn finish_fragility(json: &Path, manifest: &Manifest, out: &Path, stripes: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let study_file = PathBuf::from(
        manifest
            .study
            .as_deref()
            .with_context(|| format!("{}: study: missing (the study file of a fragility shard)", json.display()))?,
    );
    let text = rocking_scenario::file::read_text(&study_file, rocking_scenario::file::MAX_INPUT_BYTES)
        .with_context(|| format!("cannot read {} (the study of {})", study_file.display(), json.display()))?;
    if crate::shard::fingerprint(text.as_bytes()) != manifest.fingerprint {
        bail!(
            "{}: changed since the shards ran (its fingerprint is not that of {}): the stripes are merged, not fitted",
            study_file.display(),
            json.display()
        );
    }
    let study = rocking_scenario::Study::from_toml_str(&text, &study_file)?;
    super::fragility::fit_merged(&study, stripes, out)
}

/// The merged towers' `inventory.geojson` and `fields.csv`, made from the merged `inventory.csv` as `rocking inventory` makes them.
fn finish_inventory(out: &Path, csv: &Path) -> anyhow::Result<[PathBuf; 2]> {
    use super::town::{fields_csv, from_csv, FIELDS_CSV, INVENTORY_GEOJSON};
    let temp_for = |name: &str| {
        tempfile::Builder::new()
            .prefix(&format!(".{name}."))
            .tempfile_in(out)
            .with_context(|| format!("cannot write in {}", out.display()))
    };
    let target = out.join(INVENTORY_GEOJSON);
    let temp = temp_for(INVENTORY_GEOJSON)?;
    let (_, header) = from_csv(csv, temp.path(), &target)?;
    let fields = out.join(FIELDS_CSV);
    let fields_temp = temp_for(FIELDS_CSV)?;
    std::fs::write(fields_temp.path(), fields_csv(&header)).with_context(|| format!("cannot write {}", fields.display()))?;
    for (temp, target) in [(temp, &target), (fields_temp, &fields)] {
        temp.persist_noclobber(target)
            .map_err(|e| e.error)
            .with_context(|| format!("cannot write {}", target.display()))?;
    }
    Ok([target, fields])
}

/// The shards in order 1..=N, after checking they are all the shards of one study, each once.
fn check_set(shards: &[(PathBuf, Manifest)]) -> anyhow::Result<Vec<&(PathBuf, Manifest)>> {
    let (first_dir, first) = &shards[0];
    let first_json = first_dir.join(SHARD_JSON);
    for (dir, m) in &shards[1..] {
        let json = dir.join(SHARD_JSON);
        let differs = |what: &str, a: &dyn std::fmt::Display, b: &dyn std::fmt::Display| {
            anyhow::anyhow!("{}: shard of another {what}: {a}, but {} has {b}", json.display(), first_json.display())
        };
        if m.kind != first.kind {
            return Err(differs("kind of study", &m.kind, &first.kind));
        }
        if m.fingerprint != first.fingerprint {
            return Err(differs("sweep (the sweep files differ)", &m.fingerprint, &first.fingerprint));
        }
        if m.rocking_version != first.rocking_version {
            return Err(differs("version of rocking", &m.rocking_version, &first.rocking_version));
        }
        if m.shard.n() != first.shard.n() {
            return Err(differs(
                "cut (another number of shards)",
                &format!("{} shards", m.shard.n()),
                &format!("{} shards", first.shard.n()),
            ));
        }
        if m.total_cases != first.total_cases || m.file != first.file {
            return Err(differs(
                "sweep",
                &format!("{} cases in {}", m.total_cases, m.file),
                &format!("{} cases in {}", first.total_cases, first.file),
            ));
        }
    }
    // Every shard once, in order: n folders at least. A count of shards above
    // the folders given is refused by counting, never by a table of n slots.
    let n = first.shard.n();
    let mut ordered: Vec<&(PathBuf, Manifest)> = shards.iter().collect();
    ordered.sort_by_key(|(_, m)| m.shard.k());
    for pair in ordered.windows(2) {
        if pair[0].1.shard.k() == pair[1].1.shard.k() {
            bail!(
                "{}: shard {} is given twice (also {})",
                pair[1].0.join(SHARD_JSON).display(),
                pair[1].1.shard,
                pair[0].0.join(SHARD_JSON).display()
            );
        }
    }
    // Distinct numbers in 1..=n: the missing ones are n − (folders given).
    let missing = n - ordered.len();
    if missing > 0 {
        let mut given = ordered.iter().map(|(_, m)| m.shard.k()).peekable();
        let mut listed = Vec::new();
        for k in 1..=n {
            if given.next_if_eq(&k).is_none() {
                listed.push(format!("{k}/{n}"));
                if listed.len() == MISSING_LISTED.min(missing) {
                    break;
                }
            }
        }
        if missing > listed.len() {
            listed.push(format!("and {} more", missing - listed.len()));
        }
        bail!(
            "missing shard{} {} (the sweep of {} is cut in {n}: give every shard's folder)",
            if missing > 1 { "s" } else { "" },
            listed.join(", "),
            first_json.display()
        );
    }
    Ok(ordered)
}

/// Refuses an output folder that holds anything but the shards' folders (a
/// batch job's `OUT/shards/K`) and its lock file: a merged file beside
/// another run's files would read as one result with them.
fn refuse_a_used_folder(dir: &Path, shards: &[PathBuf]) -> anyhow::Result<()> {
    let shards: Vec<PathBuf> = shards.iter().filter_map(|s| std::fs::canonicalize(s).ok()).collect();
    let entries = std::fs::read_dir(dir).with_context(|| format!("cannot read {}", dir.display()))?;
    for entry in entries {
        let entry = entry.with_context(|| format!("cannot read {}", dir.display()))?;
        let name = entry.file_name();
        let holds_a_shard = || std::fs::canonicalize(entry.path()).is_ok_and(|e| shards.iter().any(|s| s.starts_with(&e)));
        if name != crate::output::LOCK_FILE && !holds_a_shard() {
            bail!(
                "refusing to merge into {}: it holds {} (a merge writes into a new or empty folder: choose another --out)",
                dir.display(),
                dir.join(name).display()
            );
        }
    }
    Ok(())
}

/// Where a CSV scan stands: inside a quoted field or not, at the start of a record or not.
///
/// Written by hand: the merge copies the rows as bytes and only needs to know
/// where each record ends (a line break outside quotes, RFC 4180); the csv
/// crate would parse every field and write it again.
#[derive(Debug, Default)]
struct Records {
    quoted: bool,
    /// A record has begun and not ended yet.
    open: bool,
}

impl Records {
    /// Whether the bytes seen so far end with a complete record.
    fn complete(&self) -> bool {
        !self.open
    }

    /// Scans `bytes`, returning the number of records they end.
    fn scan(&mut self, bytes: &[u8]) -> usize {
        let mut ended = 0;
        for &b in bytes {
            match b {
                b'"' => {
                    self.quoted = !self.quoted;
                    self.open = true;
                }
                b'\n' if !self.quoted => {
                    ended += 1;
                    self.open = false;
                }
                _ => self.open = true,
            }
        }
        ended
    }

    /// Reads one record (the header) into `line`, its line break included.
    fn read_record(&mut self, reader: &mut impl BufRead, line: &mut Vec<u8>) -> std::io::Result<()> {
        loop {
            let start = line.len();
            if reader.read_until(b'\n', line)? == 0 {
                return Ok(());
            }
            if self.scan(&line[start..]) > 0 || !line.ends_with(b"\n") {
                return Ok(());
            }
        }
    }
}

/// Copies the rest of `reader` into `out`, returning the number of records it ends.
fn copy_records(reader: &mut impl Read, out: &mut impl Write, scan: &mut Records) -> std::io::Result<usize> {
    let mut buffer = vec![0u8; 1 << 16];
    let mut rows = 0;
    loop {
        let n = match reader.read(&mut buffer) {
            Ok(0) => return Ok(rows),
            Ok(n) => n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        rows += scan.scan(&buffer[..n]);
        out.write_all(&buffer[..n])?;
    }
}

#[cfg(test)]
mod tests {
    use super::Records;

    #[test]
    fn records_end_at_line_breaks_outside_quotes() {
        let mut scan = Records::default();
        // Three records, one holding a quoted line break and an escaped quote.
        assert_eq!(scan.scan(b"a,b\n\"x\ny\",\"say \"\"hi\"\"\"\n1,2\n"), 3);
        assert!(scan.complete());
        assert_eq!(scan.scan(b"3,4"), 0);
        assert!(!scan.complete(), "a last row without its line break");
    }
}
