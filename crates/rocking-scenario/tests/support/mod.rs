#![allow(dead_code)]
// Shared by the regression tests of a study's records (included, not a test of its own).

/// A PEER AT2 file of 10 samples every 0.01 s, rising to `peak` g.
pub fn at2(peak: f64) -> String {
    let values: Vec<String> = (1..=10).map(|i| format!("{:.7E}", peak * f64::from(i) / 10.0)).collect();
    format!(
        "TEST\ntest\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=   10, DT=   .0100 SEC,\n  {}\n",
        values.join("  ")
    )
}

/// The bodies of the tests of every crate: the bell tower on its church.
pub const CHURCH: &str = include_str!("../data/church.toml");

/// A study of the tower on its church over `records` (TOML array items), two levels, one limit state on `field`.
pub fn study(records: &str, field: &str, extra: &str) -> String {
    format!(
        r#"{CHURCH}
[study]
records = [{records}]
measure = "pga"
levels = [0.2, 0.4]
free_after = 0.1
{extra}
[[study.limit_state]]
name = "state"
field = "{field}"
above = 0.5
"#
    )
}
