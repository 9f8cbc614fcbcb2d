//! Regression: `rocking spectrum --periods FROM,TO,N` took any N, so a count
//! typed with a few zeros too many (0.02,4,1000000000) ran for hours and
//! filled the memory (8 GB after 9 minutes) instead of being refused. N is
//! now at most 10,000 (rocking_codes::MAX_PERIODS): one line, exit 1.

use crate::util::{arg, rocking_in, root, tempdir};

#[test]
fn a_huge_period_count_is_refused_on_one_line() {
    let dir = tempdir();
    let elcentro = root().join("data/records/elcentro_1940_ns.AT2");
    for count in ["10001", "1000000000"] {
        let periods = format!("0.02,4,{count}");
        let r = rocking_in(dir.path(), &["spectrum", arg(&elcentro), "--periods", &periods, "--out", "out"]);
        assert_eq!(r.code, Some(1), "{count}: {}", r.stderr);
        assert_eq!(r.stderr.lines().count(), 1, "{}", r.stderr);
        assert!(r.stderr.contains(&format!("--periods: at most 10000 periods, got {count}")), "{}", r.stderr);
        assert!(!dir.path().join("out").exists(), "nothing written for a refused count");
    }
    // The largest count allowed runs: one row of spectra.csv per period.
    let r = rocking_in(dir.path(), &["spectrum", arg(&elcentro), "--periods", "0.02,4,10000", "--out", "out"]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let rows = std::fs::read_to_string(dir.path().join("out/spectra.csv"))
        .unwrap_or_else(|e| panic!("{e}"))
        .lines()
        .count();
    assert_eq!(rows, 10_001, "the header and 10,000 periods");
}
