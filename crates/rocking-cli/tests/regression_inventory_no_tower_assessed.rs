//! Regression: when every tower of an inventory failed, `rocking inventory`
//! ended with "2 of 2 towers with an error …; the others are assessed",
//! though no other was. The last line now says "the others are assessed"
//! only when there are others.

use crate::assess::tower_on_b;
use crate::util::{arg, rocking, tempdir, write};

#[test]
fn no_other_tower_is_said_to_be_assessed_when_every_one_failed() {
    let dir = tempdir();
    let assess = write(dir.path(), "assess.toml", &tower_on_b());
    let towers = write(dir.path(), "towers.csv", "id,lon,lat,tower.width\nA,14.4,41.0,-4.0\nB,14.4,41.0,-3.0\n");
    let out = dir.path().join("out");
    let r = rocking(&["inventory", arg(&towers), "--assess", arg(&assess), "--out", arg(&out)]);
    assert_eq!(r.code, Some(1), "{}", r.stderr);
    let last = r.stderr.trim_end().lines().last().unwrap_or_default();
    assert!(last.contains("2 of 2 towers with an error (in the error column of "), "{}", r.stderr);
    assert!(!last.contains("the others are assessed"), "{}", r.stderr);
}
