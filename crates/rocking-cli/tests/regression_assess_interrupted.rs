//! Regression (issue 48, item 7): `rocking assess` stopped by SIGINT or
//! SIGTERM died by the signal, leaving its hidden `.rocking-partial-*`
//! folder in `--out` and an `--out` it had created. The first signal now
//! ends it at once with one line and exit status 128 plus the signal's
//! number (130 for SIGINT, 143 for SIGTERM), the staging folder and the
//! folders it created removed.

#[cfg(unix)]
#[test]
fn a_signal_during_an_assessment_leaves_the_disk_as_it_was() {
    use crate::util::{arg, tempdir, write};
    use std::time::Duration;
    for (signal, status) in [("-INT", 130), ("-TERM", 143)] {
        let dir = tempdir();
        crate::assess::synthetic_records(dir.path(), "records");
        // A fine scan (600 values of λ × 3 records): far longer than the test waits.
        let text = crate::assess::tower_on_b() + "records = [\"records/*.AT2\"]\nfree_after = 5.0\nlambda = { from = 0.01, to = 6.0, step = 0.01 }\n";
        let file = write(dir.path(), "assess.toml", &text);
        let out = dir.path().join("new").join("out");
        // Signalled once its staging folder exists (the records are being run).
        let r = crate::util::interrupted(&["assess", arg(&file), "--out", arg(&out)], &out, signal, Duration::from_secs(120), |_| true);
        assert_eq!(r.code, Some(status), "{signal}: {}", r.stderr);
        assert_eq!(r.stderr.trim(), "interrupted: nothing written", "{signal}");
        // Neither the staging folder nor the folders made for it are left.
        assert!(!dir.path().join("new").exists(), "{signal}");
    }
}
