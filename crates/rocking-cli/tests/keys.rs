//! `rocking keys` and `rocking --version`.

use crate::util::*;

/// The committed reference page is what `rocking keys --markdown` prints: a
/// key added to the parser's table but not to the page (or the reverse) fails
/// here. To update the page: `rocking keys --markdown > docs/src/reference/keys.md`.
#[test]
fn the_keys_page_is_the_generated_one() {
    let out = rocking(&["keys", "--markdown"]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let page = read(&root().join("docs/src/reference/keys.md"));
    // Compared line by line so that a failure names the first line that differs.
    for (i, (generated, committed)) in out.stdout.lines().zip(page.lines()).enumerate() {
        assert_eq!(
            committed,
            generated,
            "docs/src/reference/keys.md line {} differs from `rocking keys --markdown`; regenerate the page",
            i + 1
        );
    }
    assert_eq!(
        page.lines().count(),
        out.stdout.lines().count(),
        "docs/src/reference/keys.md and `rocking keys --markdown` differ in length; regenerate the page"
    );
}

/// Without `--markdown`, one line per key of the scenario reference: as many
/// lines as rows in the page's key tables (those whose first cell is a key).
#[test]
fn one_line_per_key() {
    let out = rocking(&["keys"]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let page = read(&root().join("docs/src/reference/keys.md"));
    let rows: Vec<&str> = page
        .lines()
        .filter_map(|l| l.strip_prefix("| `"))
        .filter_map(|l| l.split('`').next())
        .filter(|k| !k.starts_with('{') && !k.starts_with('['))
        .collect();
    let listed: Vec<&str> = out.stdout.lines().filter_map(|l| l.split_whitespace().next()).collect();
    assert_eq!(listed, rows);
    assert!(listed.contains(&"tower.width") && listed.contains(&"simulation.atol"), "{listed:?}");
}

/// `--json` describes the keys `rocking keys` lists, in the same order, with
/// the symbols and units of a hand-checked sample (those of the key
/// reference and of the figures' legends).
#[test]
fn json_describes_every_listed_key() {
    let json = rocking(&["keys", "--json"]);
    assert_eq!(json.code, Some(0), "{}", json.stderr);
    let value: serde_json::Value = serde_json::from_str(&json.stdout).unwrap_or_else(|e| panic!("{e}: {}", json.stdout));
    let described: Vec<&serde_json::Value> = ["scenario", "assessment"]
        .iter()
        .flat_map(|part| value[part].as_array().into_iter().flatten())
        .collect();
    let keys: Vec<&str> = described.iter().filter_map(|k| k["key"].as_str()).collect();
    let lines = rocking(&["keys"]);
    let listed: Vec<&str> = lines.stdout.lines().filter_map(|l| l.split_whitespace().next()).collect();
    assert_eq!(keys, listed);
    let of = |key: &str| {
        described
            .iter()
            .find(|k| k["key"] == key)
            .map(|k| (k["symbol"].clone(), k["unit"].clone(), k["sweepable"].clone()))
    };
    let expect = |symbol: &str, unit: &str, sweepable: bool| Some((symbol.into(), unit.into(), sweepable.into()));
    assert_eq!(of("tower.height"), expect("H", "m", true));
    assert_eq!(of("ground.frequency"), expect("f", "Hz", true));
    assert_eq!(of("building.mu_kinetic"), expect("μk", "", true));
    assert_eq!(of("initial.theta_dot"), expect("θ̇0", "rad/s", true));
    assert_eq!(of("tower.points"), expect("points", "m", false));
    let units = described.iter().find(|k| k["key"] == "ground.units").map(|k| k["choices"].clone());
    assert_eq!(units, Some(serde_json::json!(["g", "m/s2", "cm/s2"])));
}

/// `--version` prints the name and the version of the package's manifest, exit 0.
#[test]
fn version() {
    let out = rocking(&["--version"]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert_eq!(out.stdout, format!("rocking {}\n", env!("CARGO_PKG_VERSION")));
}
