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

/// A study of the tower on its church over `records` (TOML array items), two levels, one limit state on `field`.
pub fn study(records: &str, field: &str, extra: &str) -> String {
    format!(
        r#"
[tower]
width = 4.0
height = 12.0
mass = 1.5e5
[building]
mass = 2.0e6
mu_static = 1.25
mu_kinetic = 1.0
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
