//! A town's towers read from the rows of `inventory.csv` (the text of their
//! fields, as written): their GeoJSON (RFC 7946 points, for QGIS or a web
//! map), and the towers ranked for the figures, the report, the terminal and
//! the page. `rocking inventory` feeds [`Town`] each row as it is written and
//! `rocking merge` the rows of the merged file, so the two write the same bytes.

use std::io::Write;

/// The columns of a tower's identity and place, first in `inventory.csv`.
pub const IDENTITY: [&str; 4] = ["id", "name", "lon", "lat"];

/// The column of `inventory.csv` that says whether the governing ζ_E is a lower bound.
pub const LOWER_BOUND: &str = "zeta_E_is_lower_bound";

/// The decimals a column's numbers mean in the GeoJSON, if it holds computed
/// numbers: an acceleration in g to 4 (a ten-thousandth of g, 0.001 m/s²,
/// below any hazard map's precision), a ζ_E to 3 (the verdict turns at 1, and
/// a thousandth is below the spread of any input).
pub fn decimals(name: &str) -> Option<usize> {
    if name.ends_with("_ag_capacity_g") || (name.starts_with("ag_") && name.ends_with("_g")) {
        Some(AG_DECIMALS)
    } else if name.ends_with("zeta_E") {
        Some(ZETA_DECIMALS)
    } else {
        None
    }
}

/// The decimals of a ζ_E in the GeoJSON and on the town's page.
pub const ZETA_DECIMALS: usize = 3;
/// The decimals of an acceleration in g.
pub const AG_DECIMALS: usize = 4;
/// The decimals of a coordinate in degrees (a tenth of a metre on the ground).
pub const DEGREE_DECIMALS: usize = 6;

/// `x` rounded to `decimals`: the double nearest its decimal text so rounded
/// (which the JSON writer then prints with no more digits than those).
pub fn rounded(x: f64, decimals: usize) -> f64 {
    if !x.is_finite() {
        return x;
    }
    format!("{x:.decimals$}").parse().unwrap_or(x)
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
    /// Whether the governing ζ_E is only a lower bound (its ag capacity the top of the search or of the λ scan).
    pub lower_bound: bool,
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
                LOWER_BOUND => match *text {
                    "true" => J::Bool(true),
                    "false" => J::Bool(false),
                    _ => J::Null,
                },
                n => match decimals(n) {
                    Some(d) => number(text).map_or(J::Null, |x| J::from(rounded(x, d))),
                    // "governing", "error" and the inputs: a number as one, as the tower was assessed with it.
                    None if text.is_empty() => J::Null,
                    None if !matches!(n, "governing" | "error") => number(text).filter(|x| x.is_finite()).map_or_else(|| J::from(*text), J::from),
                    None => J::from(*text),
                },
            };
            p.insert(name.clone(), value);
        }
        let id = field("id");
        let feature = geojson::Feature {
            bbox: None,
            geometry: point.map(|(lon, lat)| geojson::Geometry::new(geojson::Value::Point(vec![rounded(lon, DEGREE_DECIMALS), rounded(lat, DEGREE_DECIMALS)]))),
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
            lower_bound: field(LOWER_BOUND) == "true",
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

/// The longest field name of a Shapefile (its dBase table: 10 bytes).
pub const SHAPEFILE_NAME_MAX: usize = 10;

/// The short name of a check's method in a Shapefile's field.
fn method_alias(method: &str) -> Option<&'static str> {
    Some(match method {
        "activation" => "act",
        "linear_kinematic" => "lk",
        "nonlinear_kinematic" => "nk",
        "nonlinear_dynamic" => "nd",
        _ => return None,
    })
}

/// Whether `alias` is a field name a Shapefile keeps: 1 to 10 ASCII letters, digits and `_`, a letter first.
pub fn shapefile_safe(alias: &str) -> bool {
    (1..=SHAPEFILE_NAME_MAX).contains(&alias.len())
        && alias.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_')
        && alias.bytes().next().is_some_and(|b| b.is_ascii_alphabetic())
}

/// The alias a property would like: a check's column as `<LS>_<m>_ag` or
/// `<LS>_<m>_z` (`SLV_lk_z`), the lower bound `zeta_E_lb`, a dotted key by its
/// last part (`tower.width` → `width`), and a long name its words' initials
/// but the last's (`confidence_factor` → `c_factor`), cut to 10 characters.
fn wished_alias(name: &str) -> String {
    if name == LOWER_BOUND {
        return "zeta_E_lb".into();
    }
    for (suffix, short) in [("_ag_capacity_g", "ag"), ("_zeta_E", "z")] {
        let check = name.strip_suffix(suffix).and_then(|check| {
            let (state, method) = check.split_once('_')?;
            Some(format!("{state}_{}_{short}", method_alias(method)?))
        });
        if let Some(alias) = check {
            return alias;
        }
    }
    let last = name.rsplit('.').next().unwrap_or(name);
    let mut alias: String = last.chars().map(|c| if c.is_ascii_alphanumeric() { c } else { '_' }).collect();
    if alias.len() > SHAPEFILE_NAME_MAX {
        let words: Vec<&str> = alias.split('_').filter(|w| !w.is_empty()).collect();
        if let Some((tail, head)) = words.split_last() {
            let mut short: Vec<String> = head.iter().map(|w| w[..1].to_string()).collect();
            short.push((*tail).to_string());
            alias = short.join("_");
        }
    }
    if !alias.bytes().next().is_some_and(|b| b.is_ascii_alphabetic()) {
        alias.insert(0, 'f');
    }
    alias.truncate(SHAPEFILE_NAME_MAX);
    alias
}

/// The Shapefile alias of each property of `inventory.geojson` (every
/// column of `header` but `lon`, `lat`, which are the point): a name of at
/// most 10 ASCII letters, digits and `_` ([`shapefile_safe`]), distinct from
/// the others without regard to case (dBase's names are not), a repeated one
/// cut to 8 and numbered (`width_2`). `fields.csv` lists them.
pub fn shapefile_aliases(header: &[String]) -> Vec<(String, String)> {
    let mut taken: Vec<String> = Vec::new();
    let mut out = Vec::new();
    for name in header.iter().filter(|h| !matches!(h.as_str(), "lon" | "lat")) {
        let wished = wished_alias(name);
        let mut alias = wished.clone();
        let mut n = 2;
        while taken.contains(&alias.to_ascii_lowercase()) {
            let mut cut = wished.clone();
            cut.truncate(SHAPEFILE_NAME_MAX - 1 - n.to_string().len());
            alias = format!("{cut}_{n}");
            n += 1;
        }
        taken.push(alias.to_ascii_lowercase());
        out.push((name.clone(), alias));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_aliases_of_the_example_town_are_short_distinct_and_as_written_by_hand() {
        let header: Vec<String> = [
            "id",
            "name",
            "lon",
            "lat",
            "tower.width",
            "tower.height",
            "soil",
            "topography",
            "tower.mass",
            "assessment.confidence_factor",
            "ag_SLD_g",
            "SLD_activation_ag_capacity_g",
            "SLV_nonlinear_dynamic_zeta_E",
            "zeta_E",
            LOWER_BOUND,
            "governing",
            "error",
            "belfry.width",
            "block.2nd",
        ]
        .map(String::from)
        .to_vec();
        let aliases: Vec<String> = shapefile_aliases(&header).into_iter().map(|(_, a)| a).collect();
        assert_eq!(
            aliases,
            [
                "id",
                "name",
                "width",
                "height",
                "soil",
                "topography",
                "mass",
                "c_factor",
                "ag_SLD_g",
                "SLD_act_ag",
                "SLV_nd_z",
                "zeta_E",
                "zeta_E_lb",
                "governing",
                "error",
                "width_2",
                "f2nd"
            ]
        );
        assert!(aliases.iter().all(|a| shapefile_safe(a)), "{aliases:?}");
    }

    #[test]
    fn names_equal_but_for_case_get_distinct_aliases() {
        let header: Vec<String> = ["a.Width", "b.width", "c.WIDTH"].map(String::from).to_vec();
        let aliases: Vec<String> = shapefile_aliases(&header).into_iter().map(|(_, a)| a).collect();
        assert_eq!(aliases, ["Width", "width_2", "WIDTH_3"]);
    }

    #[test]
    fn rounding_keeps_the_digits_meant() {
        // The decimal texts, rounded by hand.
        assert_eq!(rounded(0.48951, 3).to_bits(), 0.49_f64.to_bits());
        assert_eq!(rounded(2.370_849_1, 3).to_bits(), 2.371_f64.to_bits());
        assert_eq!(rounded(0.247_54, 4).to_bits(), 0.2475_f64.to_bits());
        assert_eq!(rounded(14.332_000_1, 6).to_bits(), 14.332_f64.to_bits());
        assert!(rounded(f64::INFINITY, 3).is_infinite());
        assert_eq!(decimals("SLV_linear_kinematic_zeta_E"), Some(3));
        assert_eq!(decimals("ag_SLV_g"), Some(4));
        assert_eq!(decimals("SLD_activation_ag_capacity_g"), Some(4));
        assert_eq!(decimals(LOWER_BOUND), None);
        assert_eq!(decimals("tower.height"), None);
    }
}
