//! Regression: a sweep's axis misspelling a block's key (`belfry.widht`) was
//! refused with the list of the tower's keys alone and no "did you mean": the
//! blocks' keys were not among the keys a sweep knows. They now are, for the
//! blocks the scenario has (by their names, as an axis gives them), both in
//! the list and in the suggestion; a misspelt tower key still gets its own.

use rocking_scenario::Sweep;
use std::path::Path;

/// The tests' tower on its church carrying `blocks` (TOML `[[block]]` tables),
/// swept over `axis`.
fn sweep(blocks: &str, axis: &str) -> Result<Sweep, String> {
    let text = format!(
        "{}\n{blocks}\n[ground]\ntype = \"harmonic\"\namplitude = 0.6\nfrequency = 2.0\nduration = 1.0\n\n[sweep]\n\"{axis}\" = [1.0, 1.5]\n",
        include_str!("data/church.toml")
    );
    Sweep::from_toml_str(&text, Path::new("s.toml")).map_err(|e| e.to_string())
}

const BELFRY: &str = "[[block]]\nname = \"belfry\"\nwidth = 3.2\nheight = 4.5\nmass = 3.0e4\n";
const LANTERN: &str = "[[block]]\nname = \"lantern\"\nwidth = 1.0\nheight = 2.0\nmass = 2.0e3\n";

/// The one-line error of an axis on `key`.
fn refused(blocks: &str, key: &str) -> String {
    let e = sweep(blocks, key).map(|_| ()).expect_err("the axis should be refused");
    assert_eq!(e.lines().count(), 1, "{e}");
    e
}

/// The valid keys a refusal lists, in its order.
fn listed(e: &str) -> Vec<&str> {
    e.split_once("; valid keys: ").map_or(Vec::new(), |(_, keys)| keys.split(", ").collect())
}

/// A block's keys as an axis gives them, in the key reference's order: every
/// key of `[[block]]` but its name, each after `name.`.
fn block_keys(name: &str) -> Vec<String> {
    ["width", "height", "mass", "density", "depth", "section", "wall_thickness", "inertia_centre"]
        .iter()
        .map(|k| format!("{name}.{k}"))
        .collect()
}

#[test]
fn a_misspelt_block_key_is_suggested_among_its_blocks_keys() {
    let stack = format!("{BELFRY}{LANTERN}");
    // `widht` is one transposition from `width`: suggested under the block it names.
    let e = refused(&stack, "belfry.widht");
    assert!(
        e.starts_with("s.toml: sweep.\"belfry.widht\": unknown key (did you mean `belfry.width`?); valid keys: "),
        "{e}"
    );
    assert_eq!(listed(&e), block_keys("belfry"));
    let e = refused(&stack, "lantern.hieght");
    assert!(e.contains("(did you mean `lantern.height`?)"), "{e}");
    assert_eq!(listed(&e), block_keys("lantern"));

    // A misspelt block name (one deletion from `belfry`): every key is listed,
    // the blocks' after the tower's, and the block's key suggested.
    let e = refused(&stack, "belfr.width");
    assert!(e.contains("unknown key (did you mean `belfry.width`?)"), "{e}");
    let keys = listed(&e);
    let at = |k: &str| keys.iter().position(|x| *x == k).unwrap_or_else(|| panic!("{k} not listed in {e}"));
    assert!(
        at("tower.alpha") < at("belfry.width") && at("lantern.inertia_centre") < at("building.mass"),
        "{e}"
    );
    for k in block_keys("belfry").iter().chain(&block_keys("lantern")) {
        at(k);
    }
    // `block.width` would be every block's and none: refused with the blocks' keys.
    let e = refused(&stack, "block.width");
    assert!(e.contains("sweep.\"block.width\": unknown key;"), "{e}");
    assert_eq!(listed(&e).len(), 2 * block_keys("").len(), "{e}");

    // The tower's own misspelling keeps its suggestion and its list.
    let e = refused(&stack, "tower.widht");
    assert!(e.contains("(did you mean `tower.width`?)"), "{e}");
    assert!(listed(&e).iter().all(|k| k.starts_with("tower.")), "{e}");

    // The keys of the blocks the scenario has, no other: without a belfry,
    // `belfry.width` is suggested nowhere and listed nowhere.
    let e = refused(LANTERN, "belfry.widht");
    assert!(!e.contains("did you mean") && !e.contains("belfry.width"), "{e}");
    assert!(listed(&e).contains(&"lantern.width"), "{e}");
    // A tower alone: `block.width` lists every key, none of a block.
    let e = refused("", "block.width");
    assert!(listed(&e).contains(&"tower.width") && !e.contains("block.width,"), "{e}");

    // The key spelt right is swept.
    assert_eq!(sweep(&stack, "belfry.width").map(|s| s.len()), Ok(2));
}
