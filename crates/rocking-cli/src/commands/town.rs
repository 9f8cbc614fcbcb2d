//! The files of a town's inventory: `inventory.csv`, `inventory.geojson` and
//! `fields.csv` (the GeoJSON's properties' Shapefile aliases), the latter two
//! written from the rows and the header of the first by
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
/// Each property of the GeoJSON and its alias of at most 10 characters, the name a Shapefile's field can have.
pub const FIELDS_CSV: &str = "fields.csv";

/// The text of `fields.csv` for the columns `header` of `inventory.csv`:
/// `property,alias`, one line per property ([`rocking_assess::shapefile_aliases`]).
pub fn fields_csv(header: &[String]) -> String {
    let mut out = rocking_scenario::csv_line(["property", "alias"]) + "\n";
    for (name, alias) in rocking_assess::shapefile_aliases(header) {
        out.push_str(&rocking_scenario::csv_line([name, alias]));
        out.push('\n');
    }
    out
}

/// Reads `inventory.csv` at `path` and writes `inventory.geojson` at `geojson` (`shown` names it in errors) from its rows: the towers, and the header.
pub fn from_csv(path: &Path, geojson: &Path, shown: &Path) -> anyhow::Result<(Vec<Ranked>, Vec<String>)> {
    let context = || format!("cannot read {}", path.display());
    let written = || format!("cannot write {}", shown.display());
    let mut reader = csv::ReaderBuilder::new().from_path(path).with_context(context)?;
    let header: Vec<String> = reader.headers().with_context(context)?.iter().map(String::from).collect();
    let mut town = Town::new(&header, BufWriter::new(File::create(geojson).with_context(written)?)).with_context(written)?;
    for record in reader.records() {
        let record = record.with_context(context)?;
        town.push(&record.iter().collect::<Vec<_>>()).with_context(written)?;
    }
    Ok((town.finish().with_context(written)?.0, header))
}
