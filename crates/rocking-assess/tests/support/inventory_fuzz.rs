// What the `inventory` fuzz target does with one input, shared by the target
// (`fuzz/fuzz_targets/inventory.rs`, through `include!`) and the stable
// replay of the kept inputs (`tests/fuzz_corpora.rs`): the first
// byte picks the assessment file the towers start from, the rest is the
// towers' CSV. An even byte: the tests' tower on subsoil B
// (`tests/data/tower_on_b.toml`, its site's parameters given) with a belfry
// on it; an odd one: the town's file (`examples/town/assess.toml`), its site
// at each tower's lon, lat on the synthetic hazard grid, given as text.
// `Inventory::new` may refuse the towers' file with one line naming it; each
// tower is assessed (the first 5) and may fail with one line naming the file
// and its row; never a panic, and every number of a row is finite.
//
// Nothing is read from disk and nothing is simulated: an input that names
// `records` (a column `assessment.records` gives a tower a record set, whose
// records are files or are run through the model) is skipped.

/// The towers assessed of one input: rows enough for a repeated id and the
/// faults of several rows, few enough that an input of many valid towers
/// (each some milliseconds of kinematic checks, of the tower and the belfry)
/// does not slow the fuzzing down to a few inputs a second.
pub const MOST_TOWERS: usize = 5;

/// Checks one fuzz input as a towers' CSV.
pub fn replay(data: &[u8]) {
    use rocking_assess::{Inventory, InventoryError};
    use rocking_scenario::{parse_toml, Cases, Cell, GridCache};
    use std::path::Path;
    use toml::Value;

    let Some((&selector, towers)) = data.split_first() else { return };
    if towers.windows(b"records".len()).any(|w| w == b"records") {
        return;
    }
    let (origin, file) = (Path::new("fuzz.toml"), Path::new("fuzz.csv"));
    let grid = Path::new("grid.txt");
    let (assess, grids) = if selector % 2 == 0 {
        let tower = include_str!("../data/tower_on_b.toml");
        (
            format!("{tower}\n[[block]]\nname = \"belfry\"\nwidth = 1.6\nheight = 8.0\nmass = 2.0e4\n"),
            GridCache::default(),
        )
    } else {
        let town = include_str!("../../../../examples/town/assess.toml");
        let grids = GridCache::holding(grid, include_str!("../../../../data/hazard/synthetic_grid.txt")).expect("the synthetic grid reads");
        (town.to_string(), grids)
    };
    let mut base = parse_toml(&assess, origin).expect("the assessment file parses");
    if let Some(Value::Table(site)) = base.get_mut("site") {
        if site.contains_key("grid") {
            site.insert("grid".into(), Value::String(grid.display().to_string()));
        }
    }
    let inventory = match Inventory::from_table(base, origin, towers, file, grids) {
        Ok(inventory) => inventory,
        Err(InventoryError::Towers(line)) => {
            assert!(
                line.contains("fuzz.csv") && !line.contains('\n'),
                "not one line naming the towers' file: {line:?}"
            );
            return;
        }
        Err(e) => panic!("the assessment file is valid, refused: {e}"),
    };
    let header = inventory.header();
    for index in 0..inventory.len().min(MOST_TOWERS) {
        // The row of the tower (`row` assesses it: an error is its last cell).
        let row = inventory.row(index);
        assert_eq!(row.cells.len(), header.len(), "a row's cells are the header's");
        for cell in &row.cells {
            if let Cell::Float(x) = cell {
                assert!(x.is_finite(), "a number not finite in row {}: {:?}", index + 1, row.cells);
            }
        }
        if let Some(Cell::Text(error)) = row.cells.last() {
            let named = format!("fuzz.csv row {}", index + 1);
            assert!(error.starts_with(&named) && !error.contains('\n'), "not one line naming the row: {error:?}");
        }
    }
}
