//! `[ground.vertical]` through the command: the outputs it adds, the closed
//! form of a constant vertical acceleration (the motion under gravity
//! `g + c`), free fall reported on one line with its instant, and a sweep of
//! its keys.

use crate::util::{arg, read, rocking, tempdir, write};
use std::path::{Path, PathBuf};

/// The tower on a church that can slide (μs = 0.45, dynamic normal force), 3 s of
/// a horizontal harmonic, and `vertical` (a `[ground.vertical]` table or
/// nothing); `g` and the horizontal amplitude in g are given.
fn scenario(g: f64, amplitude_g: f64, vertical: &str) -> String {
    format!(
        r#"[tower]
width = 4.0
height = 12.0
mass = 1.5e5

[building]
mass = 2.0e6
mu_static = 0.45
mu_kinetic = 0.4
normal_force = "dynamic"

[ground]
type = "harmonic"
amplitude = {amplitude_g:?}
frequency = 2.0
{vertical}
[simulation]
duration = 3.0
output_dt = 0.01
g = {g:?}
"#
    )
}

/// The columns of a history.csv: header and rows of numbers (text → NaN).
fn history(dir: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = read(&dir.join("history.csv"));
    let mut lines = text.lines();
    let header = lines.next().unwrap_or_default().split(',').map(String::from).collect();
    let rows = lines.map(|l| l.split(',').map(|f| f.parse().unwrap_or(f64::NAN)).collect()).collect();
    (header, rows)
}

fn summary(dir: &Path) -> serde_json::Value {
    serde_json::from_str(&read(&dir.join("summary.json"))).unwrap_or_else(|e| panic!("{e}"))
}

/// Writes `text` as `dir/name.toml` and runs it into `dir/name`, which must succeed.
fn run_ok(dir: &Path, name: &str, text: &str) -> PathBuf {
    let file = write(dir, &format!("{name}.toml"), text);
    let out = dir.join(name);
    let r = rocking(&["run", arg(&file), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{r:?}");
    out
}

/// Writes `text` as `dir/name.toml` and runs it, which must fail with exit
/// code 1 and one line: the file and that line.
fn run_fails(dir: &Path, name: &str, text: &str) -> (PathBuf, String) {
    let file = write(dir, &format!("{name}.toml"), text);
    let r = rocking(&["run", arg(&file), "--out", arg(&dir.join("o"))]);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert_eq!(r.stderr.lines().count(), 1, "{r:?}");
    let line = r.stderr.trim_end().to_string();
    (file, line)
}

/// Runs the sweep file `text` and returns its column of the least effective gravity.
fn least_gravity_of_sweep(dir: &Path, text: &str) -> Vec<f64> {
    let file = write(dir, "sweep.toml", text);
    let out = dir.join("o");
    let r = rocking(&["sweep", arg(&file), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{r:?}");
    let csv = read(&out.join("sweep.csv"));
    let header: Vec<&str> = csv.lines().next().unwrap_or_default().split(',').collect();
    let column = header
        .iter()
        .position(|c| *c == "min_effective_gravity_m_s2")
        .unwrap_or_else(|| panic!("{header:?}"));
    csv.lines()
        .skip(1)
        .map(|line| line.split(',').nth(column).and_then(|v| v.parse().ok()).unwrap_or(f64::NAN))
        .collect()
}

/// `g (1 − A)`, the least of `g + A g sin(…)` over whole periods, against
/// each value of `found`: to 1e-14 m/s², a few ulps of g, the rounding of
/// `A g` and of the sine at its trough.
fn assert_least_gravity(found: &[f64], amplitudes: &[f64]) {
    assert_eq!(found.len(), amplitudes.len());
    for (g_min, a) in found.iter().zip(amplitudes) {
        assert!((g_min - 9.81 * (1.0 - a)).abs() < 1e-14, "{g_min} for A = {a}");
    }
}

/// A constant `a_v = c` (a rectangular pulse longer than the run) gives the
/// motion of a run with gravity `g + c` under the same horizontal
/// acceleration in m/s² (docs/src/model.md's closed form): θ and the slip agree at
/// every output instant to 1e-7 of their peaks. 0.7 g with c = 0.2 g lifts
/// the tower (0.7 > 1.2 tan α) and slides the church (0.7 > 1.2 μs). The
/// horizontal amplitude in g of the second run is 0.7 · 9.81 / (9.81 + c),
/// which rounds, and the two
/// runs step differently (their right-hand sides differ by rounding), so
/// they agree to the integration tolerance (rtol 1e-8), not to the bit.
#[test]
fn a_constant_vertical_acceleration_is_gravity_plus_it() {
    let dir = tempdir();
    let c_g = 0.2;
    let g = 9.81;
    let vertical = format!("[ground.vertical]\ntype = \"rectangular-pulse\"\namplitude = {c_g}\nduration = 10.0\n");
    let lifted = run_ok(dir.path(), "lifted", &scenario(g, 0.7, &vertical));
    let heavier = run_ok(dir.path(), "heavier", &scenario(g + c_g * g, 0.7 * g / (g + c_g * g), ""));
    let (header_a, a) = history(&lifted);
    let (header_b, b) = history(&heavier);
    assert_eq!(header_a.last().map(String::as_str), Some("ground_acc_v"));
    assert_eq!(header_a[..header_a.len() - 1], header_b[..], "the vertical column is the only one added");
    assert_eq!(a.len(), b.len());
    let column = |h: &[String], name: &str| h.iter().position(|c| c == name).unwrap_or_else(|| panic!("no {name}"));
    for name in ["theta", "slip", "ground_acc"] {
        let (ia, ib) = (column(&header_a, name), column(&header_b, name));
        let peak = b.iter().map(|r| r[ib].abs()).fold(0.0, f64::max);
        assert!(peak > 0.0, "{name} moves");
        for (ra, rb) in a.iter().zip(&b) {
            assert!((ra[ia] - rb[ib]).abs() <= 1e-7 * peak, "{name} at t = {}: {} against {}", ra[0], ra[ia], rb[ib]);
        }
    }
    let v = column(&header_a, "ground_acc_v");
    assert!(a.iter().all(|r| (r[v] - c_g * g).abs() < 1e-15), "a_v = c throughout");
    assert_eq!(summary(&lifted)["min_effective_gravity_m_s2"].as_f64(), Some(g + c_g * g));
    assert!(summary(&heavier).get("min_effective_gravity_m_s2").is_none());
}

/// `a_v = 1.2 g sin(2π t)` takes `g + a_v` to zero where `sin(2π t) = −1/1.2`:
/// `t = (π + asin(1/1.2)) / (2π)`. The run stops there with exit code 1 and
/// one line naming the file, the table and that instant (to 1e-9 s: it is
/// located by root finding on the input).
#[test]
fn free_fall_is_one_line_with_its_instant() {
    let dir = tempdir();
    let text = scenario(9.81, 0.1, "[ground.vertical]\ntype = \"harmonic\"\namplitude = 1.2\nfrequency = 1.0\n");
    let (file, line) = run_fails(dir.path(), "falls", &text);
    assert!(
        line.starts_with(&format!("error: {}: ground.vertical: the ground falls faster than gravity at t = ", arg(&file))),
        "{line}"
    );
    let exact = (std::f64::consts::PI + (1.0f64 / 1.2).asin()) / (2.0 * std::f64::consts::PI);
    let t: f64 = line
        .split("at t = ")
        .nth(1)
        .and_then(|rest| rest.split(' ').next())
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("no instant in {line}"));
    assert!((t - exact).abs() < 1e-9, "{t} against {exact}");
}

/// The vertical amplitude as a sweep axis: the column of the least effective
/// gravity is there, and for a harmonic that completes its trough it is
/// `g (1 − A)` (to rounding of the sine at its trough).
#[test]
fn the_vertical_keys_sweep() {
    let dir = tempdir();
    let text = scenario(9.81, 0.3, "[ground.vertical]\ntype = \"harmonic\"\namplitude = 0.1\nfrequency = 5.0\n")
        + "\n[sweep]\n\"ground.vertical.amplitude\" = [0.1, 0.3, 0.5]\n";
    assert_least_gravity(&least_gravity_of_sweep(dir.path(), &text), &[0.1, 0.3, 0.5]);
}

/// A vertical record that cannot be read names `ground.vertical.file`.
#[test]
fn a_missing_vertical_record_names_its_key() {
    let dir = tempdir();
    let (_, line) = run_fails(
        dir.path(),
        "missing",
        &scenario(9.81, 0.3, "[ground.vertical]\ntype = \"record\"\nfile = \"nowhere.AT2\"\n"),
    );
    assert!(line.contains(": ground.vertical.file: "), "{line}");
    // And a key of another type, inside the table, names the table's key.
    let wrong = "[ground.vertical]\ntype = \"sine-pulse\"\namplitude = 0.2\nfrequency = 3.0\nduration = 1.0\n";
    let (_, line) = run_fails(dir.path(), "wrong", &scenario(9.81, 0.3, wrong));
    assert!(line.contains(": ground.vertical.duration: does not apply to type = \"sine-pulse\""), "{line}");
}

/// `[ground.vertical]` of type "none" is a vertical motion of zero: the
/// column is there (all zeros), the least effective gravity is g itself, and
/// the motion is that of no vertical table at all, to the bit.
#[test]
fn a_vertical_of_type_none_is_gravity_alone() {
    let dir = tempdir();
    let none = run_ok(dir.path(), "none", &scenario(9.81, 0.7, "[ground.vertical]\ntype = \"none\"\n"));
    let plain = run_ok(dir.path(), "plain", &scenario(9.81, 0.7, ""));
    let (header, rows) = history(&none);
    let (_, plain_rows) = history(&plain);
    assert_eq!(header.last().map(String::as_str), Some("ground_acc_v"));
    for (a, b) in rows.iter().zip(&plain_rows) {
        assert_eq!(a[a.len() - 1].to_bits(), 0.0f64.to_bits());
        assert_eq!(
            a[..a.len() - 1].iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
            b.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
        );
    }
    assert_eq!(summary(&none)["min_effective_gravity_m_s2"].as_f64(), Some(9.81));
}

/// Axes on `ground.vertical` keys add the vertical motion to a base scenario
/// without one: the sweep's column is there, `g (1 − A)` for each amplitude.
#[test]
fn axes_can_add_the_vertical_motion() {
    let dir = tempdir();
    let text = scenario(9.81, 0.3, "")
        + "\n[sweep]\n\"ground.vertical.type\" = [\"harmonic\"]\n\"ground.vertical.frequency\" = [8.0]\n\"ground.vertical.amplitude\" = [0.1, 0.3]\n";
    assert!(!text.contains("[ground.vertical]"));
    assert_least_gravity(&least_gravity_of_sweep(dir.path(), &text), &[0.1, 0.3]);
}
