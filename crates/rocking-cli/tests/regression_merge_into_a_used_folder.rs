//! Regression: `rocking merge` into an existing folder wrote sweep.csv beside
//! another run's files (a summary.json, a stale shard.json), where they read
//! as one result. A merge now writes into a new or empty folder only.

use crate::shard::{ok, shard, sweep_file};
use crate::util::{arg, merge, read, rocking, tempdir, write, SCENARIO};

#[test]
fn a_merge_into_a_folder_holding_other_files_is_refused() {
    let dir = tempdir();
    let file = sweep_file(dir.path(), "s.toml", "");
    let parts = dir.path().join("parts");
    let (one, two) = (shard(&file, &parts, 1, 2), shard(&file, &parts, 2, 2));

    // A run's folder.
    let run = dir.path().join("run");
    let scenario = write(dir.path(), "run.toml", SCENARIO);
    ok(rocking(&["run", arg(&scenario), "--out", arg(&run)]));
    let r = merge(&[&one, &two], &run);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert!(r.stderr.contains("refusing to merge into"), "{}", r.stderr);
    assert!(
        ["events.csv", "history.csv", "summary.json"].iter().any(|f| r.stderr.contains(f)),
        "{}",
        r.stderr
    );
    assert!(!run.join("sweep.csv").exists());

    // A shard's own folder: its shard.json would stay beside the merged rows.
    let r = merge(&[&one, &two], &two);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert!(r.stderr.contains("refusing to"), "{}", r.stderr);

    // Any file of the user's: kept, nothing written.
    let mine = dir.path().join("mine");
    std::fs::create_dir_all(&mine).unwrap_or_else(|e| panic!("{e}"));
    let notes = write(&mine, "notes.txt", "mine\n");
    let r = merge(&[&one, &two], &mine);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert!(r.stderr.contains("notes.txt"), "{}", r.stderr);
    assert_eq!(read(&notes), "mine\n");
    assert!(!mine.join("sweep.csv").exists());

    // An empty folder and a new one are fine.
    let empty = dir.path().join("empty");
    std::fs::create_dir_all(&empty).unwrap_or_else(|e| panic!("{e}"));
    ok(merge(&[&one, &two], &empty));
    let new = dir.path().join("new");
    ok(merge(&[&one, &two], &new));
    assert_eq!(read(&empty.join("sweep.csv")), read(&new.join("sweep.csv")));
    // The folder holding the shards' folders (a batch job's OUT/shards/K) is fine too.
    ok(merge(&[&one, &two], &parts));
    // An empty subfolder is something too.
    let nested = dir.path().join("nested");
    std::fs::create_dir_all(nested.join("sub")).unwrap_or_else(|e| panic!("{e}"));
    let r = merge(&[&one, &two], &nested);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert!(r.stderr.contains("sub"), "{}", r.stderr);
}
