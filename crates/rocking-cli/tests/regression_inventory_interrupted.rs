//! Regression (issue 48, item 7): `rocking inventory` stopped by Ctrl-C
//! replaced the town of an earlier run in `--out` with the towers finished
//! so far, and SIGTERM ended it with 130 like Ctrl-C. A signal now ends it at
//! once with one line, `--out` left exactly as it was (the earlier run's
//! files, byte for byte, and nothing else), and the exit status a shell
//! gives a process that signal stopped: 128 + 2 for SIGINT, 128 + 15 for
//! SIGTERM.

#[cfg(unix)]
#[test]
fn a_signal_during_an_inventory_leaves_the_earlier_town_as_it_was() {
    use crate::util::{arg, read, root, tempdir, write};
    use std::time::Duration;
    // Only a guard against a hang: no test waits this long unless the command is stuck.
    let hang = Duration::from_secs(600);
    for (signal, status) in [("-INT", 130), ("-TERM", 143)] {
        let dir = tempdir();
        let grid = root().join("data/hazard/synthetic_grid.txt");
        let records = root().join("data/records/synthetic");
        let assessment = format!(
            "[assessment]\nconfidence_factor = 1.35\nrecords = ['{0}/kt_01.AT2', '{0}/kt_02.AT2', '{0}/kt_03.AT2']\n",
            records.display()
        );
        let base = crate::inventory::base(&grid).replace("[assessment]\nconfidence_factor = 1.35\n", &assessment);
        let assess_file = write(dir.path(), "town.toml", &base);
        // Thirty towers with dynamic checks: far longer than the signal takes to come.
        let rows: String = (0..30).map(|i| format!("T{i:02},,14.{},41.06\n", 34 + i % 10)).collect();
        let towers = write(dir.path(), "towers.csv", &format!("id,name,lon,lat\n{rows}"));
        // An earlier run's town, as its manifest names it.
        let out = dir.path().join("out");
        std::fs::create_dir_all(&out).unwrap_or_else(|e| panic!("{e}"));
        let earlier = [
            ("inventory.csv", "id\nearlier\n"),
            ("report.html", "<p>earlier</p>"),
            (".rocking-manifest", "inventory.csv\nreport.html\n"),
        ];
        for (name, text) in earlier {
            std::fs::write(out.join(name), text).unwrap_or_else(|e| panic!("{e}"));
        }
        let args = [
            "inventory",
            arg(&towers),
            "--assess",
            arg(&assess_file),
            "--out",
            arg(&out),
            "--threads",
            "2",
            "--details",
        ];
        // Signalled once the first tower's own assessment is in the staging folder.
        let first_tower = |staging: &std::path::Path| staging.join("towers").join("T00").join("report.html").exists();
        let r = crate::util::interrupted(&args, &out, signal, hang, first_tower);
        assert_eq!(r.code, Some(status), "{signal}: {}", r.stderr);
        assert_eq!(r.stderr.trim(), "interrupted: nothing written", "{signal}");
        let mut names: Vec<String> = std::fs::read_dir(&out)
            .unwrap_or_else(|e| panic!("{e}"))
            .flatten()
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        assert_eq!(names, [".rocking-manifest", "inventory.csv", "report.html"], "{signal}");
        for (name, text) in earlier {
            assert_eq!(read(&out.join(name)), text, "{signal}: {name}");
        }
    }
}
