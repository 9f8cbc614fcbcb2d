//! Running the binary and writing scenario files.

use std::path::{Path, PathBuf};
use std::process::Command;

/// What a run of the binary gave.
#[derive(Debug)]
pub struct Output {
    /// Exit code (`None` if killed by a signal).
    pub code: Option<i32>,
    pub stdout: String,
    pub stderr: String,
}

/// Runs `rocking args…` in `cwd` with backtraces on, so that a panic would show.
pub fn rocking_in(cwd: &Path, args: &[&str]) -> Output {
    let out = Command::new(env!("CARGO_BIN_EXE_rocking"))
        .args(args)
        .current_dir(cwd)
        .env("RUST_BACKTRACE", "1")
        .output()
        .unwrap_or_else(|e| panic!("cannot start rocking: {e}"));
    Output {
        code: out.status.code(),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

/// Runs `rocking args…` in the repository root (where `examples/` is).
pub fn rocking(args: &[&str]) -> Output {
    rocking_in(&root(), args)
}

/// The repository root.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// An example scenario of the repository.
pub fn example(name: &str) -> PathBuf {
    root().join("examples").join(name)
}

/// A fresh temporary folder.
pub fn tempdir() -> tempfile::TempDir {
    tempfile::tempdir().unwrap_or_else(|e| panic!("cannot create a temporary folder: {e}"))
}

/// Writes `text` to `dir/name` and returns the path.
pub fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap_or_else(|e| panic!("cannot write {}: {e}", path.display()));
    path
}

/// Reads a file the binary wrote.
pub fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()))
}

/// The staging folder of the run writing into `out` (`.rocking-partial-` and
/// a random name), once it exists; `None` after `limit`.
pub fn staging_folder(out: &Path, limit: std::time::Duration) -> Option<PathBuf> {
    let start = std::time::Instant::now();
    while start.elapsed() < limit {
        let found = std::fs::read_dir(out)
            .into_iter()
            .flatten()
            .flatten()
            .find(|e| e.file_name().to_string_lossy().starts_with(".rocking-partial-"));
        if let Some(entry) = found {
            return Some(entry.path());
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    None
}

/// `path` as a `&str` argument.
pub fn arg(path: &Path) -> &str {
    path.to_str().unwrap_or_else(|| panic!("non-UTF-8 path {}", path.display()))
}

/// A small scenario of the tower on its church: 1 s of a 0.6 g, 5 Hz harmonic.
pub const SCENARIO: &str = concat!(
    "name = \"small\"\n",
    include_str!("../../rocking-scenario/tests/data/church.toml"),
    r#"
[ground]
type = "harmonic"
amplitude = 0.6
frequency = 5.0

[simulation]
duration = 1.0
output_dt = 0.003
"#
);

/// `SCENARIO` with `from` replaced by `to` (which must occur).
pub fn scenario_with(from: &str, to: &str) -> String {
    assert!(SCENARIO.contains(from), "{from:?} is not in the scenario");
    SCENARIO.replacen(from, to, 1)
}

/// `rocking merge DIRS… --out OUT`.
pub fn merge(dirs: &[&Path], out: &Path) -> Output {
    let mut args = vec!["merge"];
    args.extend(dirs.iter().map(|d| arg(d)));
    args.extend(["--out", arg(out)]);
    rocking(&args)
}

/// The check of a sharded command against its unsharded run in `whole`: for
/// each N of `counts`, runs shard K/N for K = 1 … N with `shard(k, n, parts)`
/// (which writes it into a folder under `parts`, `dir/shards-N`, and returns
/// that folder), hands each to `check_shard(k, n, folder)`, merges them given
/// in reverse order (the merge puts them back in the order of K), and asserts
/// that each of `files` of the merge is the same file of `whole`, byte for
/// byte. Returns each merge's output, in the order of `counts`.
pub fn assert_shards_merge_to_whole(
    dir: &Path,
    whole: &Path,
    files: &[&str],
    counts: &[usize],
    shard: impl Fn(usize, usize, &Path) -> PathBuf,
    mut check_shard: impl FnMut(usize, usize, &Path),
) -> Vec<Output> {
    let bytes = |p: &Path| std::fs::read(p).unwrap_or_else(|e| panic!("cannot read {}: {e}", p.display()));
    let mut merges = Vec::new();
    for &n in counts {
        let parts = dir.join(format!("shards-{n}"));
        let folders: Vec<PathBuf> = (1..=n).map(|k| shard(k, n, &parts)).collect();
        for (k, folder) in (1..=n).zip(&folders) {
            check_shard(k, n, folder);
        }
        let reversed: Vec<&Path> = folders.iter().rev().map(PathBuf::as_path).collect();
        let merged = dir.join(format!("merged-{n}"));
        let r = merge(&reversed, &merged);
        assert_eq!(r.code, Some(0), "the merge of {n} shards: {r:?}");
        for file in files {
            assert!(
                bytes(&merged.join(file)) == bytes(&whole.join(file)),
                "{file} of {n} shards differs from the unsharded one"
            );
        }
        merges.push(r);
    }
    merges
}

/// The header and rows of a CSV file the binary wrote, quoted fields unquoted.
pub fn csv_table(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let mut reader = csv::Reader::from_path(path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    let header = reader
        .headers()
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .iter()
        .map(String::from)
        .collect();
    let rows = reader
        .records()
        .map(|r| r.unwrap_or_else(|e| panic!("{}: {e}", path.display())).iter().map(String::from).collect())
        .collect();
    (header, rows)
}

/// What [`interrupted`] saw: the exit code, stderr, and the staging folder
/// the run wrote into until the signal.
#[cfg(unix)]
pub struct Interrupted {
    /// Exit code (`None` if killed by a signal).
    pub code: Option<i32>,
    pub stderr: String,
    /// The run's `.rocking-partial-…` folder in `out`.
    pub staging: PathBuf,
}

/// Starts `rocking args…` (writing into `out`), waits until `under_way` holds
/// of its staging folder (what it writes there has begun), sends it `signal`
/// (`-INT` as Ctrl-C does, `-TERM`) and waits for it to end. Each wait is at
/// most `limit`: a run that the signal did not stop would go on far longer,
/// and is killed and fails the test.
#[cfg(unix)]
pub fn interrupted(args: &[&str], out: &Path, signal: &str, limit: std::time::Duration, under_way: impl Fn(&Path) -> bool) -> Interrupted {
    use std::time::{Duration, Instant};
    let mut child = Command::new(env!("CARGO_BIN_EXE_rocking"))
        .args(args)
        .current_dir(root())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("cannot start rocking: {e}"));
    let staging = staging_folder(out, limit).unwrap_or_else(|| panic!("no staging folder in {:?}", limit));
    let start = Instant::now();
    while !under_way(&staging) {
        assert!(start.elapsed() < limit, "the run's output did not begin in {limit:?}");
        std::thread::sleep(Duration::from_millis(10));
    }
    let kill = Command::new("kill").args([signal, &child.id().to_string()]).status();
    assert!(kill.is_ok_and(|s| s.success()), "cannot send {signal}");
    let (code, stderr) = wait_exit(&mut child, limit, signal);
    Interrupted { code, stderr, staging }
}

/// Waits at most `limit` for `child` to end (else kills it and fails the
/// test, naming `what` was sent): its exit code (`None` if killed by a
/// signal) and what it wrote on its standard error.
#[cfg(unix)]
pub fn wait_exit(child: &mut std::process::Child, limit: std::time::Duration, what: &str) -> (Option<i32>, String) {
    use std::time::{Duration, Instant};
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap_or_else(|e| panic!("{e}")) {
            break status;
        }
        if start.elapsed() > limit {
            child.kill().unwrap_or_default();
            panic!("{what}: the run did not stop in {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let mut stderr = String::new();
    if let Some(mut pipe) = child.stderr.take() {
        std::io::Read::read_to_string(&mut pipe, &mut stderr).unwrap_or_default();
    }
    (status.code(), stderr)
}
