//! Regression: `rocking spectrum` (records and `--site`) took a record
//! peaking at 1e300 g and wrote its spectra, while `rocking assess` refused
//! the same record (a peak above 100 g: wrong units or scale). The reader of
//! both now refuses it the same way: one line naming the file, exit 1.

use crate::util::{arg, rocking_in, tempdir, write};

/// What the refusal says of `huge.csv` (1e300 g, printed with 3 decimals).
const PEAK: &str = "huge.csv peaks at 1.000e300 g, above 100 g";

#[test]
fn a_record_beyond_any_ground_motion_is_refused() {
    let dir = tempdir();
    let huge = write(dir.path(), "huge.csv", "time,acceleration\n0,0\n0.01,1e300\n0.02,0\n0.03,0\n");
    let fine = "time,acceleration\n0,0\n0.01,0.1\n0.02,-0.2\n0.03,0.05\n0.04,0\n";
    write(dir.path(), "b.csv", fine);
    write(dir.path(), "c.csv", fine);
    let site = write(
        dir.path(),
        "site.toml",
        r#"name = "tower"
[tower]
width = 4.0
height = 12.0
mass = 1.5e5
[site]
code = "ntc2018"
soil = "B"
topography = "T1"
[site.SLD]
ag = 0.06
F0 = 2.5
Tc_star = 0.3
[site.SLV]
ag = 0.155
F0 = 2.4
Tc_star = 0.3
[site.SLC]
ag = 0.2
F0 = 2.4
Tc_star = 0.3
[assessment]
records = ["huge.csv", "b.csv", "c.csv"]
"#,
    );

    let r = rocking_in(dir.path(), &["spectrum", arg(&huge), "--out", "records"]);
    assert_eq!(r.code, Some(1), "{}", r.stderr);
    assert_eq!(r.stderr.lines().count(), 1, "{}", r.stderr);
    assert!(r.stderr.contains(PEAK), "{}", r.stderr);

    let spectrum = rocking_in(dir.path(), &["spectrum", "--site", arg(&site), "--out", "site"]);
    assert_eq!(spectrum.code, Some(1), "{}", spectrum.stderr);
    assert_eq!(spectrum.stderr.lines().count(), 1, "{}", spectrum.stderr);
    assert!(
        spectrum.stderr.contains(PEAK) && spectrum.stderr.contains("assessment.records"),
        "{}",
        spectrum.stderr
    );
    // The same words as `rocking assess` on the same file.
    let assess = rocking_in(dir.path(), &["assess", arg(&site), "--out", "assess"]);
    assert_eq!(assess.code, Some(1), "{}", assess.stderr);
    assert_eq!(spectrum.stderr, assess.stderr);

    for out in ["records", "site"] {
        assert!(!dir.path().join(out).exists(), "{out}: nothing written for a refused record");
    }
}
