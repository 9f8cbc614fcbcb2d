//! Regression: a fragility study of a tower carrying blocks wrote stripes.csv
//! with the one-block header (36 columns) over rows of the stack's fields (44
//! cells: the stack's and each block's), and refused a limit state on a
//! block's field (`belfry_max_theta_over_alpha`) as "not a field of
//! summary.json". The study's fields are now those of its stack.

use crate::util::{arg, csv_table, rocking, root, tempdir, write};

#[test]
fn a_study_of_a_stack_writes_its_fields_and_counts_a_blocks_limit_state() {
    let dir = tempdir();
    let records = root().join("data/records/synthetic");
    let study = format!(
        "[tower]\nwidth = 4.0\nheight = 12.0\nmass = 1.5e5\n[[block]]\nname = \"belfry\"\nwidth = 1.0\nheight = 2.0\nmass = 1.0e3\n\
         [study]\nrecords = [\"{0}/kt_01.AT2\", \"{0}/kt_02.AT2\"]\nmeasure = \"pga\"\nlevels = {{ from = 0.2, to = 1.0, steps = 3 }}\nfree_after = 1.0\n\
         [[study.limit_state]]\nname = \"belfry-half\"\nfield = \"belfry_max_theta_over_alpha\"\nabove = 0.5\n",
        records.display()
    );
    let file = write(dir.path(), "study.toml", &study);
    let out = dir.path().join("out");
    let r = rocking(&["fragility", arg(&file), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    // csv_table reads with the csv crate, which refuses rows longer than the header.
    let (header, rows) = csv_table(&out.join("stripes.csv"));
    assert_eq!(rows.len(), 6, "2 records × 3 levels");
    for name in ["max_seat_impulse_ratio", "belfry_max_theta_over_alpha", "belfry_overturned"] {
        assert!(header.iter().any(|h| h == name), "no column {name}: {header:?}");
    }
    let column = |name: &str| header.iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name}"));
    // The exceedances counted from the rows, level by level, against fractions.csv's.
    let (level, ratio) = (column("level"), column("belfry_max_theta_over_alpha"));
    let (_, fractions) = csv_table(&out.join("fractions.csv"));
    assert_eq!(fractions.len(), 3);
    for f in &fractions {
        let exceeded = rows
            .iter()
            .filter(|r| r[level] == f[1] && r[ratio].parse::<f64>().unwrap_or_else(|e| panic!("{e}")) > 0.5)
            .count();
        assert_eq!(f[3], exceeded.to_string(), "{f:?}");
    }
    // Some level exceeds and some does not: the count is not trivially all or none.
    assert!(fractions.iter().any(|f| f[3] == "0") && fractions.iter().any(|f| f[3] != "0"), "{fractions:?}");
}
