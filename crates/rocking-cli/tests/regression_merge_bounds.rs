//! Regression: `rocking merge` allocated what a manifest claimed. Shard
//! `1/18446744073709551615` panicked ("capacity overflow"), `1/100000000`
//! took 6.7 GB and aborted, and a shard whose sweep.csv or shard.json is a
//! link to /dev/zero aborted (its header was read without a limit). Each is
//! now one line and exit 1, under a limit of 1 GB of address space (the
//! merge of a few rows needs a few MB).

use crate::shard::{ok, shard, sweep_file};
use crate::util::{arg, tempdir};
use serde_json::{json, Value};
use std::path::Path;
use std::process::Command;

/// `rocking merge dirs… --out out` with its address space limited to 1 GB:
/// exit code (`None`: killed by a signal, an abort) and stderr.
fn merge_limited(dirs: &[&Path], out: &Path) -> (Option<i32>, String) {
    let mut script = format!("ulimit -v 1000000 && exec '{}' merge", env!("CARGO_BIN_EXE_rocking"));
    for d in dirs {
        script.push_str(&format!(" '{}'", arg(d)));
    }
    script.push_str(&format!(" --out '{}'", arg(out)));
    let r = Command::new("sh")
        .args(["-c", &script])
        .output()
        .unwrap_or_else(|e| panic!("cannot start sh: {e}"));
    (r.status.code(), String::from_utf8_lossy(&r.stderr).into_owned())
}

/// A refusal: exit 1 and one line holding every one of `needles`.
fn refused((code, stderr): (Option<i32>, String), needles: &[&str]) {
    assert_eq!(code, Some(1), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    for n in needles {
        assert!(stderr.contains(n), "{n:?} not in {stderr:?}");
    }
}

/// Rewrites `dir/shard.json` as shard `k` of `n` of `total` cases (a hand edit that stays consistent).
fn edit_manifest(dir: &Path, k: u64, n: u64, total: u64) {
    let path = dir.join("shard.json");
    let mut m: Value = serde_json::from_str(&crate::util::read(&path)).unwrap_or_else(|e| panic!("{e}"));
    // floor((k−1)·total/n) .. floor(k·total/n), in 128 bits as the tool computes it.
    let start = |i: u64| (u128::from(i) * u128::from(total) / u128::from(n)) as u64;
    m["k"] = json!(k);
    m["n_shards"] = json!(n);
    m["total_cases"] = json!(total);
    m["first_case"] = json!(start(k - 1));
    m["cases"] = json!(start(k) - start(k - 1));
    std::fs::write(&path, m.to_string()).unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn a_huge_number_of_shards_is_counted_not_allocated() {
    let dir = tempdir();
    let file = sweep_file(dir.path(), "s.toml", "");
    let one = shard(&file, &dir.path().join("parts"), 1, 2);
    let out = dir.path().join("merged");
    for n in [u64::MAX, 100_000_000, 1_000_000_000_000_000] {
        edit_manifest(&one, 1, n, 12);
        // Ten shards named, the others counted: n − 1 missing in all.
        refused(
            merge_limited(&[&one], &out),
            &[&format!("missing shards 2/{n}, 3/{n}"), &format!("11/{n}, and {} more", n - 11)],
        );
    }
    assert!(!out.join("sweep.csv").exists());
}

#[cfg(unix)]
#[test]
fn a_device_in_place_of_a_shard_file_is_not_read() {
    let dir = tempdir();
    let file = sweep_file(dir.path(), "s.toml", "");
    let parts = dir.path().join("parts");
    let (one, two) = (shard(&file, &parts, 1, 2), shard(&file, &parts, 2, 2));
    let out = dir.path().join("merged");
    let rows = two.join("sweep.csv");
    std::fs::remove_file(&rows).unwrap_or_else(|e| panic!("{e}"));
    std::os::unix::fs::symlink("/dev/zero", &rows).unwrap_or_else(|e| panic!("{e}"));
    refused(merge_limited(&[&one, &two], &out), &["2/sweep.csv", "not a regular file"]);
    // A header of 2 MiB without a line break: read no further than 1 MiB.
    std::fs::remove_file(&rows).unwrap_or_else(|e| panic!("{e}"));
    std::fs::write(&rows, vec![b'a'; 2 << 20]).unwrap_or_else(|e| panic!("{e}"));
    refused(merge_limited(&[&one, &two], &out), &["2/sweep.csv", "no header line in its first 1 MiB"]);
    // The manifest itself.
    let json = one.join("shard.json");
    std::fs::remove_file(&json).unwrap_or_else(|e| panic!("{e}"));
    std::os::unix::fs::symlink("/dev/zero", &json).unwrap_or_else(|e| panic!("{e}"));
    refused(merge_limited(&[&one, &two], &out), &["1/shard.json", "not a regular file"]);
    assert!(!out.join("sweep.csv").exists());
    // The folders made whole again merge.
    ok(crate::util::rocking(&["sweep", arg(&file), "--out", arg(&one), "--shard", "1/2"]));
    std::fs::remove_file(&rows).unwrap_or_else(|e| panic!("{e}"));
    ok(crate::util::rocking(&["sweep", arg(&file), "--out", arg(&two), "--shard", "2/2"]));
    ok(crate::util::merge(&[&one, &two], &out));
}
