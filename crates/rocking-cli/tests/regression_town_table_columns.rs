//! Regression (issue 47, item 3): the table of the town's `report.html` had
//! `lon` and `lat` in its header and not in its rows, so every ζ_E stood two
//! columns left of its heading (the example's worst linear check, 0.49, read
//! as a pass of 2.37 under "SLV linear"), and an error row spanned two
//! columns fewer than the header. The table's cells are read back here and
//! compared with `inventory.csv`, column by column, tower by tower.

use crate::util::{arg, csv_table, read, rocking, tempdir};

/// The cells of each row of the first table of `html` whose header starts
/// with `rank`: (text, colspan). Read by hand: the page is this tool's own
/// (no script, no nested table, one `<tr>` per row), and the test needs only
/// the cells' text, not an HTML parser's tree.
fn table_rows(html: &str) -> Vec<Vec<(String, usize)>> {
    let start = html.find("<tr><th>rank</th>").unwrap_or_else(|| panic!("no table of towers in the page"));
    let end = start + html[start..].find("</table>").unwrap_or_else(|| panic!("the table does not end"));
    html[start..end]
        .split("<tr")
        .skip(1)
        .map(|row| {
            let mut cells = Vec::new();
            for piece in row.split("<t").skip(1) {
                let Some(open_end) = piece.find('>') else { continue };
                let (open, rest) = piece.split_at(open_end);
                if !(open.starts_with('d') || open.starts_with('h')) {
                    continue;
                }
                let span = open
                    .split("colspan=\"")
                    .nth(1)
                    .and_then(|s| s.split('"').next())
                    .map_or(1, |s| s.parse().unwrap_or_else(|_| panic!("colspan {s:?}")));
                let body = &rest[1..];
                let body = &body[..body.find("</t").unwrap_or(body.len())];
                cells.push((text_of(body), span));
            }
            cells
        })
        .collect()
}

/// The text of a cell: its tags dropped, the page's entities decoded.
fn text_of(html: &str) -> String {
    let mut out = String::new();
    let mut in_tag = false;
    for c in html.chars() {
        match c {
            '<' => in_tag = true,
            '>' => in_tag = false,
            _ if !in_tag => out.push(c),
            _ => {}
        }
    }
    out.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&amp;", "&")
        .trim()
        .to_string()
}

/// The heading the page gives the column `name` of inventory.csv, if it shows it.
fn heading(name: &str) -> Option<String> {
    match name {
        "id" | "name" | "lon" | "lat" | "governing" => Some(name.to_string()),
        "zeta_E" => Some("ζE".into()),
        _ => name.strip_suffix("_zeta_E").map(|check| format!("ζE {}", check.replace('_', " "))),
    }
}

/// `text` rounded to `decimals` as the page must show it (ζ_E to 3 decimals, coordinates to 6).
fn rounded(text: &str, decimals: usize) -> f64 {
    let x: f64 = text.parse().unwrap_or_else(|_| panic!("not a number: {text:?}"));
    format!("{x:.decimals$}").parse().unwrap_or_else(|_| panic!("{x}"))
}

#[test]
fn every_cell_of_the_town_table_is_the_column_of_inventory_csv_it_stands_under() {
    let dir = tempdir();
    let out = dir.path().join("out");
    let r = rocking(&[
        "inventory",
        "examples/town/towers.csv",
        "--assess",
        "examples/town/assess.toml",
        "--out",
        arg(&out),
    ]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let (header, rows) = csv_table(&out.join("inventory.csv"));
    let table = table_rows(&read(&out.join("report.html")));
    let (head, body) = table.split_first().unwrap_or_else(|| panic!("an empty table"));
    let width: usize = head.iter().map(|c| c.1).sum();
    let headings: Vec<&str> = head.iter().map(|c| c.0.as_str()).collect();
    // Every ζ_E column of the CSV, the identity and the governing check have their heading.
    let shown: Vec<(usize, usize)> = header
        .iter()
        .enumerate()
        .filter_map(|(i, name)| {
            let h = heading(name)?;
            let column = headings
                .iter()
                .position(|t| *t == h)
                .unwrap_or_else(|| panic!("no heading {h:?} in {headings:?}"));
            Some((i, column))
        })
        .collect();
    assert_eq!(shown.len(), header.iter().filter(|h| heading(h).is_some()).count());
    let id_column = headings.iter().position(|t| *t == "id").unwrap_or_else(|| panic!("no id heading"));
    let mut seen = 0;
    for cells in body {
        // Every row spans the header's columns, an error's row too.
        assert_eq!(cells.iter().map(|c| c.1).sum::<usize>(), width, "{cells:?} under {headings:?}");
        if cells.len() != head.len() {
            continue;
        }
        let id = &cells[id_column].0;
        let row = rows
            .iter()
            .find(|r| r[0] == *id)
            .unwrap_or_else(|| panic!("tower {id} of the page not in inventory.csv"));
        for &(i, column) in &shown {
            let (name, given, cell) = (&header[i], &row[i], &cells[column].0);
            match name.as_str() {
                "id" | "name" => assert_eq!(cell, given, "{name} of {id}"),
                "governing" => assert_eq!(*cell, given.replace('_', " "), "{name} of {id}"),
                // A coordinate to 6 decimals (a tenth of a metre), a ζ_E to 3:
                // the cell's text is the CSV's number so rounded, exactly.
                "lon" | "lat" => assert_eq!(
                    rounded(cell, 6).to_bits(),
                    rounded(given, 6).to_bits(),
                    "{name} of {id}: {cell} against {given}"
                ),
                _ if given.is_empty() => assert_eq!(cell, "—", "{name} of {id}"),
                // The governing ζ_E marked `≥` exactly when inventory.csv says it is a lower bound.
                "zeta_E" => {
                    let bound = row[header
                        .iter()
                        .position(|h| h == "zeta_E_is_lower_bound")
                        .unwrap_or_else(|| panic!("no lower-bound column"))]
                        == "true";
                    let value = cell.strip_prefix("≥ ");
                    assert_eq!(value.is_some(), bound, "{name} of {id}: {cell}");
                    assert_eq!(
                        rounded(value.unwrap_or(cell), 3).to_bits(),
                        rounded(given, 3).to_bits(),
                        "{name} of {id}: {cell} against {given}"
                    );
                }
                _ => assert_eq!(
                    rounded(cell, 3).to_bits(),
                    rounded(given, 3).to_bits(),
                    "{name} of {id}: {cell} against {given}"
                ),
            }
        }
        seen += 1;
    }
    assert_eq!(seen, rows.len(), "every tower of the example is assessed and in the table");
}
