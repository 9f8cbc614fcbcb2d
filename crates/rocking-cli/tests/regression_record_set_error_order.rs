//! When several records of an assessment's set could not be read, the one
//! line of the error named whichever a thread met first: the records are read
//! in parallel and a parallel collect into a `Result` stops at the first
//! failure in time, not in order. The same file gave kt_01 on one machine and
//! kt_02 on another. The line now names the first failing record in the
//! order of the set, on every run and any number of threads.

use crate::assess::tower_on_b;
use crate::util::{arg, rocking, tempdir, write};

#[test]
fn the_first_failing_record_in_the_set_s_order_is_named() {
    let dir = tempdir();
    std::fs::create_dir_all(dir.path().join("csv")).unwrap_or_else(|e| panic!("{e}"));
    // Twelve one-column CSV records without `dt`: each fails to read, and
    // each thread meets a failure almost at once.
    for k in 1..=12 {
        write(dir.path(), &format!("csv/rec_{k:02}.csv"), "0.0\n0.1\n-0.1\n0.0\n");
    }
    let text = tower_on_b() + "records = [\"csv/*.csv\"]\nunits = \"m/s2\"\nlambda = { from = 0.5, to = 1.0, step = 0.5 }\n";
    let file = write(dir.path(), "assess.toml", &text);
    // Ten runs: with the parallel collect, two threads named rec_01 only when
    // the thread that read it was the first to fail.
    for run in 0..10 {
        let r = rocking(&["assess", arg(&file), "--out", arg(&dir.path().join("out"))]);
        assert_eq!(r.code, Some(1), "run {run}: {}", r.stderr);
        assert_eq!(r.stderr.lines().count(), 1, "run {run}: {}", r.stderr);
        assert!(r.stderr.contains("rec_01.csv"), "run {run}: {}", r.stderr);
    }
}
