//! `rocking check`: the derived quantities, without running.

use crate::util::{arg, example, rocking, tempdir, write};

#[test]
fn check_prints_the_derived_quantities_of_the_church() {
    let r = rocking(&["check", "examples/tower-on-church.toml"]);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert!(r.stderr.is_empty(), "{r:?}");
    let out = &r.stdout;
    // α = atan(2/6) = 0.3217506 rad = 18.43495°, R = sqrt(40) = 6.324555 m,
    // p = sqrt(3 g / 4 R) = 1.078574 rad/s, r = 1 − 1.5 sin²α = 0.85.
    for expected in [
        "α = 0.321751 rad = 18.4349°",
        "R = 6.32456 m",
        "p = 1.07857 rad/s",
        "r = 0.85",
        "tan α = 0.333333 g",
        "μs = 1.25 g",
        "harmonic",
        "peak |a_g| = 1.5 g = 14.715 m/s² at t = 0.05 s",
    ] {
        assert!(out.contains(expected), "{expected:?} not in\n{out}");
    }
}

/// The belfry example: each interface's uplift threshold from rest, by hand.
/// The shaft (150 t, centre 6 m up) carries the belfry (30 t, centre
/// 12 + 2.25 m up): the stack tips about the shaft's corner (b = 2 m) when
/// `a (m1 y1 + m2 y2) = g b (m1 + m2)`, a = 3.6e5 / 1.3275e6 g = 0.271186 g;
/// the belfry on a shaft at rest when `a = g tan α₂ = g 3.2/4.5 = 0.711111 g`.
#[test]
fn check_prints_each_interfaces_uplift_threshold() {
    let r = rocking(&["check", "examples/belfry-on-church.toml"]);
    assert_eq!(r.code, Some(0), "{r:?}");
    let out = &r.stdout;
    for expected in [
        "belfry: B = 3.2 m, H = 4.5 m, m = 30000 kg",
        "tower on the building lifts from rest at a_g = 0.271186 g",
        "belfry on the tower lifts from rest at a_g = 0.711111 g",
    ] {
        assert!(out.contains(expected), "{expected:?} not in\n{out}");
    }
}

#[test]
fn check_writes_nothing() {
    let cwd = tempdir();
    let r = crate::util::rocking_in(cwd.path(), &["check", arg(&example("tower-on-church.toml"))]);
    assert_eq!(r.code, Some(0), "{r:?}");
    let entries = std::fs::read_dir(cwd.path()).map(|d| d.count()).unwrap_or(usize::MAX);
    assert_eq!(entries, 0, "check created files");
}

#[test]
fn check_describes_a_record() {
    let dir = tempdir();
    write(dir.path(), "acc.csv", "0.0\n0.1\n-0.3\n0.2\n0.0\n");
    let file = write(
        dir.path(),
        "s.toml",
        "[building]\nmass = 1e6\nmu_static = 0.5\n[ground]\ntype = \"record\"\nfile = \"acc.csv\"\nformat = \"csv\"\ndt = 0.02\nscale = 2.0\n",
    );
    let r = rocking(&["check", arg(&file)]);
    assert_eq!(r.code, Some(0), "{r:?}");
    let out = &r.stdout;
    assert!(out.contains("5 samples, dt = 0.02 s, duration 0.08 s, scale 2"), "{out}");
    assert!(out.contains("acc.csv"), "{out}");
    // Peak 2 × 0.3 g at the third sample.
    assert!(out.contains("peak |a_g| = 0.6 g") && out.contains("at t = 0.04 s"), "{out}");
    assert!(out.contains("tower       none"), "{out}");
}

#[test]
fn check_accepts_the_housner_example() {
    let r = rocking(&["check", arg(&example("housner-block.toml"))]);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert!(r.stdout.contains("building    none (fixed base)"), "{}", r.stdout);
    // amplitude_ratio = 2.5 with tan α = 0.25: 0.625 g.
    assert!(r.stdout.contains("amplitude 0.625 g"), "{}", r.stdout);
}
