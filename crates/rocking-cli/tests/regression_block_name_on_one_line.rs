//! Regression: a block's name that is not a plain name was quoted raw in its
//! error, so a name holding a line break (`"bel\nfry"`) split the one error
//! line in two. The name is now written escaped, as TOML would write it.

use crate::util::{arg, rocking, tempdir, write};

#[test]
fn a_block_name_with_a_line_break_is_refused_on_one_line() {
    let dir = tempdir();
    let file = write(
        dir.path(),
        "stack.toml",
        "[tower]\nwidth = 4.0\nheight = 12.0\nmass = 1.5e5\n[[block]]\nname = \"bel\\nfry\"\nwidth = 1.0\nheight = 2.0\nmass = 1.0e3\n\
         [ground]\ntype = \"harmonic\"\namplitude = 0.5\nfrequency = 2.0\nduration = 1.0\n",
    );
    let out = dir.path().join("out");
    let r = rocking(&["run", arg(&file), "--out", arg(&out)]);
    assert_eq!(r.code, Some(1), "{}", r.stderr);
    assert_eq!(r.stderr.lines().count(), 1, "{}", r.stderr);
    assert!(
        r.stderr.contains("stack.toml: block[1].name: \"bel\\nfry\" is not a plain name"),
        "{}",
        r.stderr
    );
    assert!(!r.stderr.contains("panicked"), "{}", r.stderr);
    assert!(!out.exists(), "nothing written for a refused file");
}
