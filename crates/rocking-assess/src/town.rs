//! A town's towers read from the rows of `inventory.csv` (the text of their
//! fields, as written): their GeoJSON (RFC 7946 points, for QGIS or a web
//! map), and the towers ranked for the figures, the report, the terminal and
//! the page. `rocking inventory` feeds [`Town`] each row as it is written and
//! `rocking merge` the rows of the merged file, so the two write the same bytes.

use std::io::Write;

/// The columns of a tower's identity and place, first in `inventory.csv`.
pub const IDENTITY: [&str; 4] = ["id", "name", "lon", "lat"];

/// Whether a column of `inventory.csv` holds numbers (an ag capacity or a ζ_E).
fn is_number_column(name: &str) -> bool {
    name.ends_with("_ag_capacity_g") || name.ends_with("zeta_E")
}

/// A coordinate's text as degrees within ±`limit`, if it is one.
pub fn degrees(text: &str, limit: f64) -> Option<f64> {
    text.trim().parse::<f64>().ok().filter(|x| x.is_finite() && x.abs() <= limit)
}

/// One tower as the ranking, the map and the report show it.
#[derive(Debug, Clone, PartialEq)]
pub struct Ranked {
    /// Its place in the file's rows (0 the first).
    pub index: usize,
    /// Its `id`.
    pub id: String,
    /// Its `name`.
    pub name: String,
    /// Its place (lon, lat degrees), when both are numbers.
    pub point: Option<(f64, f64)>,
    /// The governing ζ_E, if any check was completed.
    pub zeta: Option<f64>,
    /// The governing check (`SLV linear_kinematic`), or empty.
    pub governing: String,
    /// Every check's ζ_E, in the order of [`Town::checks`] (`None`: not completed).
    pub check_zetas: Vec<Option<f64>>,
    /// The row's error, or empty.
    pub error: String,
}

/// The towers of an inventory, read from its rows as they come; writes their GeoJSON to `W` on the way.
#[derive(Debug)]
pub struct Town<W: Write> {
    header: Vec<String>,
    /// The column of each check's ζ_E and its check's name (`SLV_nonlinear_kinematic`).
    checks: Vec<(usize, String)>,
    geojson: W,
    first: bool,
    /// Every tower, in input order.
    pub towers: Vec<Ranked>,
}

impl<W: Write> Town<W> {
    /// Starts the GeoJSON FeatureCollection on `geojson` for rows of `header`.
    pub fn new(header: &[String], mut geojson: W) -> std::io::Result<Self> {
        geojson.write_all(b"{\"type\":\"FeatureCollection\",\"features\":[")?;
        let checks = header
            .iter()
            .enumerate()
            .filter_map(|(i, h)| h.strip_suffix("_zeta_E").map(|check| (i, check.to_string())))
            .collect();
        Ok(Self {
            header: header.to_vec(),
            checks,
            geojson,
            first: true,
            towers: Vec::new(),
        })
    }

    /// The checks' names (`SLD_activation`…), in the order of [`Ranked::check_zetas`].
    pub fn checks(&self) -> Vec<String> {
        self.checks.iter().map(|(_, n)| n.clone()).collect()
    }

    /// Takes one row (its fields' text, in the header's order).
    pub fn push(&mut self, fields: &[&str]) -> std::io::Result<()> {
        use serde_json::Value as J;
        let field = |name: &str| self.header.iter().position(|h| h == name).and_then(|i| fields.get(i)).copied().unwrap_or("");
        let number = |text: &str| text.parse::<f64>().ok();
        let point = degrees(field("lon"), 180.0).zip(degrees(field("lat"), 90.0));
        let mut p = geojson::JsonObject::new();
        for (name, text) in self.header.iter().zip(fields) {
            let value = match name.as_str() {
                "lon" | "lat" => continue,
                "id" | "name" => J::from(*text),
                n if is_number_column(n) => number(text).map_or(J::Null, J::from),
                _ if text.is_empty() => J::Null,
                _ => J::from(*text),
            };
            p.insert(name.clone(), value);
        }
        let id = field("id");
        let feature = geojson::Feature {
            bbox: None,
            geometry: point.map(|(lon, lat)| geojson::Geometry::new(geojson::Value::Point(vec![lon, lat]))),
            id: (!id.is_empty()).then(|| geojson::feature::Id::String(id.to_string())),
            properties: Some(p),
            foreign_members: None,
        };
        self.geojson.write_all(if self.first { b"\n" } else { b",\n" })?;
        serde_json::to_writer(&mut self.geojson, &feature)?;
        self.first = false;
        self.towers.push(Ranked {
            index: self.towers.len(),
            id: id.to_string(),
            name: field("name").to_string(),
            point,
            zeta: number(field("zeta_E")),
            governing: field("governing").to_string(),
            check_zetas: self.checks.iter().map(|(i, _)| fields.get(*i).and_then(|t| number(t))).collect(),
            error: field("error").to_string(),
        });
        Ok(())
    }

    /// Ends the GeoJSON: the towers in input order, and the writer.
    pub fn finish(mut self) -> std::io::Result<(Vec<Ranked>, W)> {
        self.geojson.write_all(b"\n]}\n")?;
        self.geojson.flush()?;
        Ok((self.towers, self.geojson))
    }
}

/// The towers with a governing ζ_E, least first (input order among equals).
pub fn ranking(towers: &[Ranked]) -> Vec<&Ranked> {
    let mut ranked: Vec<&Ranked> = towers.iter().filter(|t| t.zeta.is_some()).collect();
    ranked.sort_by(|a, b| a.zeta.unwrap_or(f64::INFINITY).total_cmp(&b.zeta.unwrap_or(f64::INFINITY)));
    ranked
}
