//! A sweep's cases for its figures: the swept values of each case, its max
//! θ/α, whether the tower overturned, and whether it failed. The command
//! fills it from the rows in memory as they come ([`SweepTable::for_rows`]);
//! the tests also read it from a `sweep.csv` (the swept keys first, then the
//! scalar fields of summary.json, and an `error` column).

use anyhow::bail;
#[cfg(test)]
use anyhow::Context;
use rocking_scenario::Cell;
#[cfg(test)]
use std::path::Path;

/// The column of the plotted value.
pub const VALUE: &str = "max_theta_over_alpha";
/// The column that says whether the tower overturned.
pub const OVERTURNED: &str = "overturned";
/// The column of a case's error message (empty if it ran).
pub const ERROR: &str = "error";

/// One case of a sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    /// Its values of the swept keys, as written, in the order of the axes.
    pub keys: Vec<String>,
    /// Max θ/α (`None`: no tower, or the case failed).
    pub value: Option<f64>,
    /// The tower overturned.
    pub overturned: bool,
    /// The case failed (its `error` is not empty).
    pub failed: bool,
    /// Max θ/α of each block on the tower (`<name>_max_theta_over_alpha`), in
    /// the order of [`SweepTable::blocks`].
    pub blocks: Vec<Option<f64>>,
}

/// The blocks on the tower named by the header's columns
/// `<name>_max_theta_over_alpha`, with those columns.
fn block_columns<'a>(header: impl Iterator<Item = &'a str>) -> Vec<(String, usize)> {
    header
        .enumerate()
        .filter_map(|(c, h)| {
            let name = h.trim().strip_suffix(VALUE)?.strip_suffix('_')?;
            (!name.is_empty()).then(|| (name.to_string(), c))
        })
        .collect()
}

/// The cases of a sweep, in case order.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepTable {
    /// The swept keys, in order.
    pub axes: Vec<String>,
    /// The cases.
    pub cases: Vec<Case>,
    /// The names of the blocks on the tower, if the sweep's scenario has some.
    pub blocks: Vec<String>,
}

/// A [`SweepTable`] being filled from the rows of a sweep in memory.
#[derive(Debug)]
pub struct RowTable {
    table: SweepTable,
    value: usize,
    overturned: Option<usize>,
    error: Option<usize>,
    blocks: Vec<usize>,
}

impl RowTable {
    /// Adds a row (its cells in header order), read as [`SweepTable::read`]
    /// reads the line `sweep.csv` holds for it.
    pub fn push(&mut self, cells: &[Cell]) {
        // The text of a field as written to sweep.csv, then read back by a CSV reader.
        let text = |c: Option<usize>| -> String {
            match c.and_then(|c| cells.get(c)) {
                Some(Cell::Text(t)) => t.trim().to_string(),
                Some(cell) => cell.text().into_owned(),
                None => String::new(),
            }
        };
        let failed = !matches!(text(self.error).as_str(), "" | "null");
        let overturned = matches!(text(self.overturned).to_ascii_lowercase().as_str(), "true" | "1");
        self.table.cases.push(Case {
            keys: (0..self.table.axes.len()).map(|k| text(Some(k))).collect(),
            value: if failed { None } else { number(&text(Some(self.value))) },
            overturned: overturned && !failed,
            failed,
            blocks: self.blocks.iter().map(|&c| if failed { None } else { number(&text(Some(c))) }).collect(),
        });
    }

    /// The table of the rows pushed.
    pub fn finish(self) -> SweepTable {
        self.table
    }
}

/// A value of a swept key as a number, if it is one.
pub fn number(text: &str) -> Option<f64> {
    text.trim().parse::<f64>().ok().filter(|x| x.is_finite())
}

impl SweepTable {
    /// Reads `path`; `axes` are the swept keys (the first columns). The
    /// command draws from the rows in memory ([`SweepTable::for_rows`]); the
    /// tests read files to check it.
    #[cfg(test)]
    pub fn read(path: &Path, axes: &[String]) -> anyhow::Result<Self> {
        let file = std::fs::File::open(path).with_context(|| format!("cannot read {}", path.display()))?;
        Self::from_reader(file, axes).with_context(|| format!("reading {}", path.display()))
    }

    /// Reads a `sweep.csv` from `reader`.
    #[cfg(test)]
    pub fn from_reader(reader: impl std::io::Read, axes: &[String]) -> anyhow::Result<Self> {
        if axes.is_empty() {
            bail!("a sweep needs at least one swept key to plot against");
        }
        let mut csv = csv::Reader::from_reader(reader);
        let header = csv.headers().context("no header line")?.clone();
        let column = |name: &str| header.iter().position(|h| h.trim() == name);
        let mut axis_columns = Vec::new();
        for key in axes {
            match column(key) {
                Some(c) => axis_columns.push(c),
                None => bail!("no column {key} (a swept key) in the header"),
            }
        }
        let Some(value_column) = column(VALUE) else {
            bail!("no column {VALUE} in the header");
        };
        let (overturned_column, error_column) = (column(OVERTURNED), column(ERROR));
        let blocks = block_columns(header.iter());
        let mut cases = Vec::new();
        for (k, record) in csv.records().enumerate() {
            // Line k + 2: the header is line 1.
            let record = record.with_context(|| format!("line {}", k + 2))?;
            let field = |c: Option<usize>| c.and_then(|c| record.get(c)).unwrap_or("").trim();
            let failed = !matches!(field(error_column), "" | "null");
            let overturned = matches!(field(overturned_column).to_ascii_lowercase().as_str(), "true" | "1");
            cases.push(Case {
                keys: axis_columns.iter().map(|&c| field(Some(c)).to_string()).collect(),
                value: if failed { None } else { number(field(Some(value_column))) },
                overturned: overturned && !failed,
                failed,
                blocks: blocks.iter().map(|(_, c)| if failed { None } else { number(field(Some(*c))) }).collect(),
            });
        }
        Ok(Self {
            axes: axes.to_vec(),
            cases,
            blocks: blocks.into_iter().map(|(name, _)| name).collect(),
        })
    }

    /// An empty table for the rows of a sweep whose columns are `header` and
    /// whose swept keys are `axes` (the first columns), filled by [`SweepTable::push`]
    /// as the rows come: the figures need no reading back of `sweep.csv`.
    pub fn for_rows(header: &[String], axes: &[String]) -> anyhow::Result<RowTable> {
        if axes.is_empty() {
            bail!("a sweep needs at least one swept key to plot against");
        }
        let column = |name: &str| header.iter().position(|h| h == name);
        let Some(value) = column(VALUE) else {
            bail!("no column {VALUE} in the header");
        };
        let blocks = block_columns(header.iter().map(String::as_str));
        Ok(RowTable {
            table: Self {
                axes: axes.to_vec(),
                cases: Vec::new(),
                blocks: blocks.iter().map(|(name, _)| name.clone()).collect(),
            },
            value,
            overturned: column(OVERTURNED),
            error: column(ERROR),
            blocks: blocks.into_iter().map(|(_, c)| c).collect(),
        })
    }

    /// The distinct values of axis `k` among `cases`, in order of first appearance.
    pub fn values<'a>(cases: &[&'a Case], k: usize) -> Vec<&'a str> {
        let mut out: Vec<&str> = Vec::new();
        for case in cases {
            if let Some(v) = case.keys.get(k) {
                if !out.contains(&v.as_str()) {
                    out.push(v);
                }
            }
        }
        out
    }

    /// The cases plotted: with more than two axes, those at the first value of
    /// each further axis; and those fixed values as `(key, value)`.
    pub fn selection(&self) -> (Vec<&Case>, Vec<(String, String)>) {
        let all: Vec<&Case> = self.cases.iter().collect();
        let fixed: Vec<(usize, String)> = (2..self.axes.len())
            .filter_map(|k| Self::values(&all, k).first().map(|v| (k, v.to_string())))
            .collect();
        let chosen = all.into_iter().filter(|c| fixed.iter().all(|(k, v)| c.keys.get(*k) == Some(v))).collect();
        let fixed = fixed.into_iter().map(|(k, v)| (self.axes[k].clone(), v)).collect();
        (chosen, fixed)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const CSV: &str = "\
ground.frequency,ground.amplitude,building.mu_static,max_theta_over_alpha,overturned,error
3,0.5,1.25,0.4,false,
3,0.5,1.0,0.5,false,
5,0.5,1.25,,false,\"ground.frequency: bad, really\"
5,0.9,1.25,4.9,true,
";

    fn axes() -> Vec<String> {
        ["ground.frequency", "ground.amplitude", "building.mu_static"].map(String::from).to_vec()
    }

    #[test]
    fn reads_cases_errors_and_overturning() -> anyhow::Result<()> {
        let t = SweepTable::from_reader(CSV.as_bytes(), &axes())?;
        assert_eq!(t.cases.len(), 4);
        assert_eq!(t.cases[0].value, Some(0.4));
        assert!(t.cases[2].failed && t.cases[2].value.is_none());
        assert!(t.cases[3].overturned && !t.cases[0].overturned);
        let (chosen, fixed) = t.selection();
        assert_eq!(chosen.len(), 3, "μs = 1.0 left out");
        assert_eq!(fixed, vec![("building.mu_static".to_string(), "1.25".to_string())]);
        assert_eq!(SweepTable::values(&chosen, 1), vec!["0.5", "0.9"]);
        Ok(())
    }

    #[test]
    fn missing_columns_are_named() {
        let e = SweepTable::from_reader(CSV.as_bytes(), &["tower.height".to_string()]).map(|_| ());
        assert!(format!("{e:?}").contains("no column tower.height"), "{e:?}");
        let e = SweepTable::from_reader("ground.frequency,overturned\n3,false\n".as_bytes(), &axes()[..1]).map(|_| ());
        assert!(format!("{e:?}").contains("no column max_theta_over_alpha"), "{e:?}");
        assert!(SweepTable::from_reader(CSV.as_bytes(), &[]).is_err());
    }

    #[test]
    fn the_rows_in_memory_give_the_table_read_from_their_csv() -> anyhow::Result<()> {
        // A second path to the same table: the cells, and the CSV written from them.
        let header: Vec<String> = ["ground.frequency", "tower.section", "max_theta_over_alpha", "overturned", "error"]
            .map(String::from)
            .to_vec();
        let rows = [
            vec![Cell::Float(3.0), Cell::Text("solid".into()), Cell::Float(0.25), Cell::Bool(false), Cell::Empty],
            vec![Cell::Int(4), Cell::Text("hollow".into()), Cell::Float(4.5), Cell::Bool(true), Cell::Empty],
            vec![
                Cell::Float(5.5),
                Cell::Text("a, b".into()),
                Cell::Empty,
                Cell::Empty,
                Cell::Text("x: \"bad\", really".into()),
            ],
        ];
        let axes = header[..2].to_vec();
        let mut table = SweepTable::for_rows(&header, &axes)?;
        let mut csv = rocking_scenario::csv_line(header.iter().map(String::as_str)) + "\n";
        for row in &rows {
            table.push(row);
            csv.push_str(&rocking_scenario::csv_line(row.iter().map(|cell| cell.text().into_owned())));
            csv.push('\n');
        }
        assert_eq!(table.finish(), SweepTable::from_reader(csv.as_bytes(), &axes)?);
        Ok(())
    }

    /// A block's column `<name>_max_theta_over_alpha` gives its values, by its
    /// name, in the rows and in the file; the tower's column is not a block's.
    #[test]
    fn a_blocks_max_theta_is_read_by_its_name() -> anyhow::Result<()> {
        let header: Vec<String> = ["ground.amplitude", "max_theta_over_alpha", "belfry_max_theta_over_alpha", "error"]
            .map(String::from)
            .to_vec();
        let rows = [
            vec![Cell::Float(0.5), Cell::Float(0.03), Cell::Float(0.0), Cell::Empty],
            vec![Cell::Float(0.8), Cell::Float(0.04), Cell::Float(0.049), Cell::Empty],
            vec![Cell::Float(1.0), Cell::Empty, Cell::Empty, Cell::Text("failed".into())],
        ];
        let axes = header[..1].to_vec();
        let mut table = SweepTable::for_rows(&header, &axes)?;
        for row in &rows {
            table.push(row);
        }
        let table = table.finish();
        assert_eq!(table.blocks, ["belfry"]);
        let blocks: Vec<Vec<Option<f64>>> = table.cases.iter().map(|c| c.blocks.clone()).collect();
        assert_eq!(blocks, [vec![Some(0.0)], vec![Some(0.049)], vec![None]]);
        let csv = "ground.amplitude,max_theta_over_alpha,belfry_max_theta_over_alpha,error\n0.8,0.04,0.049,\n";
        assert_eq!(SweepTable::from_reader(csv.as_bytes(), &axes)?.cases[0].blocks, [Some(0.049)]);
        Ok(())
    }
}
