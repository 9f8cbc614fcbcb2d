//! Regression (issue 47, item 4): in the report of a tower with a belfry, the
//! belfry's capacity table said of d0 "the tower overturns". Each mechanism's
//! row now names the block it turns: the tower's says the tower, the belfry's
//! the belfry.

use crate::assess::tower_on_b;
use crate::util::{arg, read, rocking, tempdir, write};

/// The tests' tower with a solid belfry 2 m wide and 4 m tall on it (b = 1 m,
/// h = 2 m: α0 = 1/2), kinematic checks only.
pub fn belfry_on_b() -> String {
    tower_on_b() + "\n[[block]]\nname = \"belfry\"\nwidth = 2.0\nheight = 4.0\nmass = 2.0e4\n"
}

/// `rocking assess` of the belfry on the tests' tower into `dir/out`, with `extra` arguments: its report.
pub fn belfry_report(dir: &std::path::Path, extra: &[&str]) -> String {
    let file = write(dir, "belfry.toml", &belfry_on_b());
    let out = dir.join("out");
    let mut args = vec!["assess", arg(&file), "--out", arg(&out)];
    args.extend(extra);
    let r = rocking(&args);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    read(&out.join("report.html"))
}

#[test]
fn the_belfrys_d0_row_names_the_belfry() {
    let dir = tempdir();
    let report = belfry_report(dir.path(), &[]);
    let rows: Vec<&str> = report.lines().filter(|l| l.contains("displacement at which a* vanishes")).collect();
    // One capacity table per mechanism, the tower's (with the belfry on it) first.
    assert_eq!(rows.len(), 2, "{rows:?}");
    assert!(rows[0].contains("the tower overturns"), "{}", rows[0]);
    assert!(rows[1].contains("the belfry overturns"), "{}", rows[1]);
    assert!(!rows[1].contains("tower"), "{}", rows[1]);
}
