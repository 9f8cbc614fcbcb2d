//! The files of a town's inventory: `inventory.csv` and `inventory.geojson`,
//! the latter written from the rows of the former by
//! [`rocking_assess::Town`]. `rocking inventory` feeds it each row as it is
//! written and `rocking merge` the rows of the merged file ([`from_csv`]), so
//! the two write the same bytes.

use anyhow::Context;
use rocking_assess::{Ranked, Town};
use std::fs::File;
use std::io::BufWriter;
use std::path::Path;

/// One row per tower: each check's ag capacity and ζ_E, the governing one, the error.
pub const INVENTORY_CSV: &str = "inventory.csv";
/// The same as RFC 7946 points.
pub const INVENTORY_GEOJSON: &str = "inventory.geojson";

/// Reads `inventory.csv` at `path` and writes `inventory.geojson` at `geojson` (`shown` names it in errors) from its rows: the towers.
pub fn from_csv(path: &Path, geojson: &Path, shown: &Path) -> anyhow::Result<Vec<Ranked>> {
    let context = || format!("cannot read {}", path.display());
    let written = || format!("cannot write {}", shown.display());
    let mut reader = csv::ReaderBuilder::new().from_path(path).with_context(context)?;
    let header: Vec<String> = reader.headers().with_context(context)?.iter().map(String::from).collect();
    let mut town = Town::new(&header, BufWriter::new(File::create(geojson).with_context(written)?)).with_context(written)?;
    for record in reader.records() {
        let record = record.with_context(context)?;
        town.push(&record.iter().collect::<Vec<_>>()).with_context(written)?;
    }
    Ok(town.finish().with_context(written)?.0)
}
