//! `rocking sweep --shard K/N` and `rocking merge`: the merge of 1, 3 and 7
//! shards is the unsharded `sweep.csv` byte for byte, each shard holds exactly
//! its block of rows, and every refusal of `merge` (shards of another sweep, a
//! missing shard, a repeated one, a truncated file, an existing output) is one
//! line and exit 1, leaving no merged file behind; the Slurm example with a
//! stand-in for `sbatch`.

use crate::util::{arg, assert_shards_merge_to_whole, merge, read, rocking, tempdir, write, Output, SCENARIO};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// 3 friction values × 4 amplitudes = 12 cases, one friction value failing
/// (mu_kinetic > mu_static): rows of every kind, an error column with text.
const AXES: &str = "\"building.mu_kinetic\" = [0.5, 1.5, 1.0]\n\"ground.amplitude\" = [0.2, 0.6, 1.5, 3.0]";
const CASES: usize = 12;

pub fn sweep_file(dir: &Path, name: &str, extra: &str) -> PathBuf {
    write(dir, name, &format!("{SCENARIO}\n{extra}\n[sweep]\n{AXES}\n"))
}

pub fn ok(r: Output) -> Output {
    assert_eq!(r.code, Some(0), "{r:?}");
    r
}

/// Runs shard `k`/`n` of `file` into `dir/k`; returns that folder.
pub fn shard(file: &Path, dir: &Path, k: usize, n: usize) -> PathBuf {
    let out = dir.join(k.to_string());
    ok(rocking(&[
        "sweep",
        arg(file),
        "--out",
        arg(&out),
        "--shard",
        &format!("{k}/{n}"),
        "--threads",
        "2",
    ]));
    out
}

/// Runs every shard of `n` into `dir/1 … dir/n`.
fn shards(file: &Path, dir: &Path, n: usize) -> Vec<PathBuf> {
    (1..=n).map(|k| shard(file, dir, k, n)).collect()
}

/// A refused merge: exit 1, one line on stderr holding every one of `needles`, no merged file.
pub fn refused(r: &Output, out: &Path, needles: &[&str]) {
    assert_eq!(r.code, Some(1), "{r:?}");
    assert_eq!(r.stderr.trim_end().lines().count(), 1, "one line: {:?}", r.stderr);
    assert!(!r.stderr.contains("panicked"), "{}", r.stderr);
    for n in needles {
        assert!(r.stderr.contains(n), "{n:?} not in {:?}", r.stderr);
    }
    assert!(!out.join("sweep.csv").exists(), "a refused merge writes nothing");
    let leftovers: Vec<_> = std::fs::read_dir(out).map(|d| d.flatten().map(|e| e.file_name()).collect()).unwrap_or_default();
    assert!(leftovers.is_empty(), "no temporary file left: {leftovers:?}");
}

fn manifest(dir: &Path) -> Value {
    serde_json::from_str(&read(&dir.join("shard.json"))).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn merging_1_3_and_7_shards_gives_the_unsharded_file_byte_for_byte() {
    let dir = tempdir();
    let file = sweep_file(dir.path(), "s.toml", "");
    let whole_dir = dir.path().join("whole");
    ok(rocking(&["sweep", arg(&file), "--out", arg(&whole_dir)]));
    let text = read(&whole_dir.join("sweep.csv"));
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 1 + CASES);
    assert!(!whole_dir.join("shard.json").exists(), "an unsharded sweep writes no manifest");
    let counts = [1, 3, 7];
    let check_shard = |k: usize, n: usize, d: &Path| {
        // The block of README, "Studies beyond one machine", computed here from its formula.
        let (first, end) = ((k - 1) * CASES / n, k * CASES / n);
        let m = manifest(d);
        assert_eq!((m["k"].as_u64(), m["n_shards"].as_u64()), (Some(k as u64), Some(n as u64)));
        assert_eq!(
            (m["first_case"].as_u64(), m["cases"].as_u64()),
            (Some(first as u64), Some((end - first) as u64))
        );
        assert_eq!(m["total_cases"].as_u64(), Some(CASES as u64));
        assert_eq!(m["kind"], "sweep");
        // The shard's rows are the unsharded file's rows of its block, with the same header.
        let own = read(&d.join("sweep.csv"));
        let expected: Vec<&str> = std::iter::once(lines[0]).chain(lines[1 + first..1 + end].iter().copied()).collect();
        assert_eq!(own.lines().collect::<Vec<_>>(), expected, "shard {k}/{n}");
    };
    let merges = assert_shards_merge_to_whole(
        dir.path(),
        &whole_dir,
        &["sweep.csv"],
        &counts,
        |k, n, parts| shard(&file, parts, k, n),
        check_shard,
    );
    for (n, r) in counts.iter().zip(merges) {
        assert!(r.stdout.contains(&format!("merged {n} shards ({CASES} cases)")), "{}", r.stdout);
    }
}

#[test]
fn shards_may_be_empty_when_there_are_more_shards_than_cases() {
    let dir = tempdir();
    let file = write(dir.path(), "two.toml", &format!("{SCENARIO}\n[sweep]\n\"ground.amplitude\" = [0.6, 1.5]\n"));
    let whole_dir = dir.path().join("whole");
    ok(rocking(&["sweep", arg(&file), "--out", arg(&whole_dir)]));
    let dirs = shards(&file, &dir.path().join("parts"), 3);
    // floor(0·2/3) = floor(1·2/3) = 0: the first shard has no case, only the header.
    assert_eq!(manifest(&dirs[0])["cases"].as_u64(), Some(0));
    assert_eq!(read(&dirs[0].join("sweep.csv")).lines().count(), 1);
    let out = dir.path().join("merged");
    ok(merge(&dirs.iter().map(PathBuf::as_path).collect::<Vec<_>>(), &out));
    assert_eq!(read(&out.join("sweep.csv")), read(&whole_dir.join("sweep.csv")));
}

#[test]
fn shards_of_different_sweeps_are_refused() {
    let dir = tempdir();
    // The same cases, a different file (a comment): another fingerprint.
    let a = sweep_file(dir.path(), "a.toml", "");
    let b = sweep_file(dir.path(), "b.toml", "# edited\n");
    let one = shard(&a, &dir.path().join("a"), 1, 2);
    let two = shard(&b, &dir.path().join("b"), 2, 2);
    let out = dir.path().join("merged");
    refused(&merge(&[&one, &two], &out), &out, &["shard.json", "another sweep"]);
    // Cut into another number of shards.
    let other_cut = shard(&a, &dir.path().join("a3"), 2, 3);
    refused(&merge(&[&one, &other_cut], &out), &out, &["another cut", "3 shards", "2 shards"]);
}

#[test]
fn a_missing_shard_is_refused() {
    let dir = tempdir();
    let file = sweep_file(dir.path(), "s.toml", "");
    let parts = dir.path().join("parts");
    let (one, three) = (shard(&file, &parts, 1, 3), shard(&file, &parts, 3, 3));
    let out = dir.path().join("merged");
    refused(&merge(&[&one, &three], &out), &out, &["missing shard 2/3"]);
    // A folder that is not a shard at all.
    let plain = dir.path().join("plain");
    ok(rocking(&["sweep", arg(&file), "--out", arg(&plain)]));
    refused(&merge(&[&plain], &out), &out, &["shard.json", "--shard K/N"]);
}

#[test]
fn a_repeated_shard_is_refused() {
    let dir = tempdir();
    let file = sweep_file(dir.path(), "s.toml", "");
    let dirs = shards(&file, &dir.path().join("parts"), 2);
    let out = dir.path().join("merged");
    refused(&merge(&[&dirs[0], &dirs[1], &dirs[0]], &out), &out, &["shard 1/2 is given twice"]);
    // The same shard run twice into two folders.
    let again = shard(&file, &dir.path().join("again"), 2, 2);
    refused(&merge(&[&dirs[0], &dirs[1], &again], &out), &out, &["shard 2/2 is given twice"]);
}

#[test]
fn a_truncated_shard_is_refused() {
    let dir = tempdir();
    let file = sweep_file(dir.path(), "s.toml", "");
    let dirs = shards(&file, &dir.path().join("parts"), 2);
    let csv = dirs[1].join("sweep.csv");
    let full = read(&csv);
    let out = dir.path().join("merged");
    // The last row cut in the middle (an interrupted copy): no final line break.
    let cut = &full[..full.len() - 10];
    std::fs::write(&csv, cut).unwrap_or_else(|e| panic!("{e}"));
    refused(&merge(&[&dirs[0], &dirs[1]], &out), &out, &["2/sweep.csv", "truncated", "no line break"]);
    // The last row gone entirely: whole lines, one fewer than shard.json says.
    let without_last = &full[..full[..full.len() - 1].rfind('\n').map_or(0, |i| i + 1)];
    std::fs::write(&csv, without_last).unwrap_or_else(|e| panic!("{e}"));
    let rows = CASES - CASES / 2;
    refused(
        &merge(&[&dirs[0], &dirs[1]], &out),
        &out,
        &["truncated", &format!("{} rows", rows - 1), &format!("has {rows} cases")],
    );
    // Nothing but part of the header.
    std::fs::write(&csv, "ground").unwrap_or_else(|e| panic!("{e}"));
    refused(&merge(&[&dirs[0], &dirs[1]], &out), &out, &["no complete header line"]);
}

#[test]
fn an_existing_file_is_not_overwritten() {
    let dir = tempdir();
    let file = sweep_file(dir.path(), "s.toml", "");
    let dirs = shards(&file, &dir.path().join("parts"), 2);
    // Merging into a shard's own folder would replace its rows.
    let r = merge(&[&dirs[0], &dirs[1]], &dirs[0]);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert!(r.stderr.contains("exists already"), "{}", r.stderr);
    let out = dir.path().join("mine");
    std::fs::create_dir_all(&out).unwrap_or_else(|e| panic!("{e}"));
    let mine = write(&out, "sweep.csv", "my notes\n");
    let r = merge(&[&dirs[0], &dirs[1]], &out);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert_eq!(read(&mine), "my notes\n");
}

#[test]
fn a_bad_shard_is_a_usage_error() {
    let dir = tempdir();
    let file = sweep_file(dir.path(), "s.toml", "");
    for bad in ["0/3", "4/3", "3", "x/y"] {
        let r = rocking(&["sweep", arg(&file), "--out", arg(&dir.path().join("o")), "--shard", bad]);
        assert_eq!(r.code, Some(2), "{bad}: {r:?}");
        assert!(r.stderr.contains("K/N"), "{bad}: {}", r.stderr);
    }
}

/// A stand-in for Slurm's `sbatch`: runs the script at once, the tasks of an
/// array one after the other with `SLURM_ARRAY_TASK_ID` set, and prints a job id.
const FAKE_SBATCH: &str = r#"#!/usr/bin/env bash
array=""; args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --array=*) array="${1#--array=}" ;;
    --parsable|--export=*|--dependency=*|--cpus-per-task=*) ;;
    *) args+=("$1") ;;
  esac
  shift
done
if [ -n "$array" ]; then
  for k in $(seq "${array%-*}" "${array#*-}"); do
    SLURM_ARRAY_TASK_ID=$k SLURM_CPUS_PER_TASK=1 bash "${args[@]}" >&2 || exit 1
  done
else
  bash "${args[@]}" >&2 || exit 1
fi
echo "1$RANDOM;cluster"
"#;

#[cfg(unix)]
#[test]
fn the_slurm_example_runs_the_shards_and_merges_them() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempdir();
    let file = sweep_file(dir.path(), "s.toml", "");
    let whole_dir = dir.path().join("whole");
    ok(rocking(&["sweep", arg(&file), "--out", arg(&whole_dir)]));
    let bin = dir.path().join("bin");
    std::fs::create_dir_all(&bin).unwrap_or_else(|e| panic!("{e}"));
    let sbatch = write(&bin, "sbatch", FAKE_SBATCH);
    std::fs::set_permissions(&sbatch, std::fs::Permissions::from_mode(0o755)).unwrap_or_else(|e| panic!("{e}"));
    let path = format!("{}:{}", bin.display(), std::env::var("PATH").unwrap_or_default());
    let script = crate::util::example("cluster/slurm-sweep.sh");
    let out = dir.path().join("study");
    let r = std::process::Command::new("bash")
        .args([arg(&script), arg(&file), "5", arg(&out)])
        .env("PATH", path)
        .env("ROCKING", env!("CARGO_BIN_EXE_rocking"))
        .output()
        .unwrap_or_else(|e| panic!("cannot run bash: {e}"));
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    for k in 1..=5 {
        assert!(out.join(format!("shards/{k}/shard.json")).exists(), "shard {k}");
    }
    assert_eq!(read(&out.join("sweep.csv")), read(&whole_dir.join("sweep.csv")));
}
