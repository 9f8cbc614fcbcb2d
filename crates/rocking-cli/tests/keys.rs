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

/// `--version` prints the name and the version of the package's manifest, exit 0.
#[test]
fn version() {
    let out = rocking(&["--version"]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert_eq!(out.stdout, format!("rocking {}\n", env!("CARGO_PKG_VERSION")));
}
