//! Regression: two `rocking` processes writing the same `--out` at once left
//! a mix (summary.json and events.csv of one run, history.csv of the other;
//! sweep.csv beside a run's files), and two processes with the same process
//! id (two containers, two PID namespaces) shared one staging folder, named
//! after the id, and left a summary.json holding two JSON documents. A
//! staging folder now has a random name, and a commit holds the folder's lock.
//!
//! 100 pairs of processes, each pair started together into a fresh folder:
//! half of them with distinct process ids, half with the same one (each
//! process is the first of a PID namespace of its own, by `unshare`); in each
//! half, pairs of two runs and pairs of a run and a sweep. Every folder must
//! hold exactly the files of one of the two, each equal to what that command
//! writes alone (summary.json but for its wall time).

use crate::util::{arg, read, rocking, tempdir, write, SCENARIO};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};

/// Pairs of each half.
const PAIRS: usize = 50;

/// What a folder holds: its names, sorted, and their contents (summary.json without its wall time).
fn contents(dir: &Path) -> Vec<(String, String)> {
    crate::folder::names(dir)
        .into_iter()
        .map(|name| {
            let text = read(&dir.join(&name));
            let text = if name == "summary.json" {
                let mut value: Value = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}: {text:?}", dir.display()));
                value.as_object_mut().map(|o| o.remove("wall_time_s"));
                value.to_string()
            } else {
                text
            };
            (name, text)
        })
        .collect()
}

/// Whether `unshare` can start a process as the first of a PID namespace of its own.
fn unshare_works() -> bool {
    Command::new("unshare")
        .args(["--user", "--pid", "--fork", "--map-root-user", "true"])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

/// Starts `rocking args…`, alone in a PID namespace when `same_pid` (its id is then 1).
fn start(args: &[&str], same_pid: bool) -> Child {
    let bin = env!("CARGO_BIN_EXE_rocking");
    let mut command = if same_pid {
        let mut c = Command::new("unshare");
        c.args(["--user", "--pid", "--fork", "--map-root-user", "--", bin]);
        c
    } else {
        Command::new(bin)
    };
    command
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("cannot start rocking: {e}"))
}

fn wait(child: Child) {
    let out = child.wait_with_output().unwrap_or_else(|e| panic!("{e}"));
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
}

#[test]
fn two_processes_into_one_folder_leave_the_files_of_one() {
    let dir = tempdir();
    let a = write(dir.path(), "a.toml", &SCENARIO.replace("duration = 1.0", "duration = 0.3"));
    let b = write(
        dir.path(),
        "b.toml",
        &SCENARIO
            .replace("name = \"small\"", "name = \"other\"")
            .replace("amplitude = 0.6", "amplitude = 0.7")
            .replace("duration = 1.0", "duration = 0.2"),
    );
    let s = write(
        dir.path(),
        "s.toml",
        &format!(
            "{}\n[sweep]\n\"ground.frequency\" = [4.0, 5.0]\n",
            SCENARIO.replace("duration = 1.0", "duration = 0.2")
        ),
    );
    // Each command alone: the only contents a folder may end with.
    let commands: [(&str, &PathBuf); 3] = [("run", &a), ("run", &b), ("sweep", &s)];
    let alone: Vec<Vec<(String, String)>> = commands
        .iter()
        .enumerate()
        .map(|(i, (command, file))| {
            let out = dir.path().join(format!("alone-{i}"));
            let r = rocking(&[command, arg(file), "--out", arg(&out)]);
            assert_eq!(r.code, Some(0), "{r:?}");
            contents(&out)
        })
        .collect();
    assert_ne!(alone[0], alone[1], "the two runs must be told apart");

    let same_pid = unshare_works();
    if !same_pid {
        eprintln!("unshare cannot make PID namespaces here: the second half runs with distinct process ids too");
    }
    let mut mixed = Vec::new();
    for half in [false, true] {
        for pair in 0..PAIRS {
            let out = dir.path().join(format!("pair-{half}-{pair}"));
            let second = if pair % 2 == 0 { 1 } else { 2 };
            let children = [0, second].map(|i| {
                let (command, file) = commands[i];
                start(&[command, arg(file), "--out", arg(&out)], half && same_pid)
            });
            children.into_iter().for_each(wait);
            let found = contents(&out);
            if found != alone[0] && found != alone[second] {
                mixed.push((out.display().to_string(), found.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>()));
            }
        }
    }
    assert!(mixed.is_empty(), "{} of {} folders hold a mix: {mixed:?}", mixed.len(), 2 * PAIRS);
}
