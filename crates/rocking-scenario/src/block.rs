//! `[[block]]`: the blocks stacked on the tower (a belfry on its shaft, the
//! drums of a column), each standing centred on the one before it, the first
//! on `[tower]`. A block is described as the tower is by its outer
//! dimensions (`width`, `height`, `mass` or `density`, `section`, …), with an
//! optional `name` that prefixes its outputs and its sweep keys, and its
//! moment of inertia about its own centre of mass (`inertia_centre`).

use crate::error::{ErrorKind, Fault};
use crate::read::{with_article, Section};
use arrayvec::{ArrayString, ArrayVec};
use rocking::stack::{Block, MAX_BLOCKS};
use rocking::{Tower, TowerGeometry};
use toml::{Table, Value};

/// The key of the blocks' array of tables.
pub const BLOCK: &str = "block";
/// The most blocks on a tower.
pub const MAX_ABOVE: usize = MAX_BLOCKS - 1;
/// The longest name of a block (characters).
pub const MAX_NAME: usize = 32;

/// The names of the blocks above the tower, the lowest first: what the
/// outputs' names are made of. Copied with a run's layout.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct BlockNames {
    names: [ArrayString<MAX_NAME>; MAX_ABOVE],
    len: usize,
}

impl BlockNames {
    /// The names, the lowest block first.
    pub fn iter(&self) -> impl Iterator<Item = &str> {
        self.names[..self.len].iter().map(ArrayString::as_str)
    }
    /// The number of blocks above the tower.
    pub fn len(&self) -> usize {
        self.len
    }
    /// Whether the tower carries no block.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
    /// The name of the `k`-th block above the tower (`k` from 1, as
    /// [`rocking::Event::block`]); `"tower"` for 0.
    pub fn name(&self, k: usize) -> &str {
        match k {
            0 => "tower",
            k => self.names.get(k - 1).filter(|_| k <= self.len).map_or("", ArrayString::as_str),
        }
    }
    /// The position (from 1) of the block named `name`, if there is one.
    pub fn position(&self, name: &str) -> Option<usize> {
        self.iter().position(|n| n == name).map(|i| i + 1)
    }
}

/// The default name of the `k`-th block above the tower (`k` from 1): `block2`
/// for the first (the tower being block 1), `block3`, …
fn default_name(k: usize) -> String {
    format!("block{}", k + 1)
}

/// Names no block may take: the sections of a scenario file and of the files
/// built on it, and the tower's, which `overturned_block` uses.
const RESERVED: &[&str] = &[
    "tower",
    "building",
    "ground",
    "initial",
    "simulation",
    "block",
    "sweep",
    "site",
    "assessment",
    "fragility",
    "name",
];

/// The tables of `[[block]]` in `table`, in order (none if absent).
fn tables(value: Option<&Value>) -> Result<Vec<&Table>, Fault> {
    match value {
        None => Ok(Vec::new()),
        Some(Value::Array(items)) => items
            .iter()
            .enumerate()
            .map(|(i, item)| {
                item.as_table().ok_or_else(|| {
                    Fault::new(
                        format!("{BLOCK}[{}]", i + 1),
                        ErrorKind::WrongType {
                            expected: "a table: write each block as [[block]] with its keys",
                            got: with_article(item),
                        },
                    )
                })
            })
            .collect(),
        Some(other) => Err(Fault::new(
            BLOCK,
            ErrorKind::WrongType {
                expected: "an array of tables: write each block as [[block]] with its keys",
                got: with_article(other),
            },
        )),
    }
}

/// The name of the `k`-th block (from 1) given by `table`, checked: a plain
/// identifier of at most [`MAX_NAME`] characters, not reserved.
fn name_of(table: &Table, k: usize) -> Result<String, Fault> {
    let key = format!("{BLOCK}[{k}].name");
    let name = match table.get("name") {
        None => return Ok(default_name(k)),
        Some(Value::String(s)) => s.clone(),
        Some(other) => {
            return Err(Fault::new(
                key,
                ErrorKind::WrongType {
                    expected: "a string",
                    got: with_article(other),
                },
            ))
        }
    };
    let identifier = name.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_') && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !identifier || name.len() > MAX_NAME {
        return Err(Fault::invalid(
            key,
            format!("{name:?} is not a plain name: letters, digits and _ (not first a digit), at most {MAX_NAME} characters, as it prefixes the block's outputs (\"belfry\" gives belfry_max_abs_theta_rad)"),
        ));
    }
    if RESERVED.contains(&name.as_str()) {
        return Err(Fault::invalid(
            key,
            format!("\"{name}\" is the name of a section or of the tower: choose another"),
        ));
    }
    Ok(name)
}

/// The names of the blocks of a scenario table, checked (unique), the lowest first.
pub fn names(table: &Table) -> Result<BlockNames, Fault> {
    let tables = tables(table.get(BLOCK))?;
    if tables.len() > MAX_ABOVE {
        return Err(Fault::invalid(
            BLOCK,
            format!("at most {MAX_ABOVE} blocks stand on the tower, got {}", tables.len()),
        ));
    }
    let mut out = BlockNames::default();
    let mut seen: ArrayVec<String, MAX_ABOVE> = ArrayVec::new();
    for (i, t) in tables.iter().enumerate() {
        let name = name_of(t, i + 1)?;
        if seen.contains(&name) {
            return Err(Fault::invalid(
                format!("{BLOCK}[{}].name", i + 1),
                format!("\"{name}\" names an earlier block too: each block needs its own name"),
            ));
        }
        out.names[i] = ArrayString::from(&name).unwrap_or_default();
        seen.push(name);
    }
    out.len = tables.len();
    Ok(out)
}

/// Sets the sweep key `key` of a block named in `names` (`belfry.width`) to
/// `value` in `table`, in that block's `[[block]]`; false (nothing set) if
/// `key` is not a block's.
pub(crate) fn set_key(table: &mut Table, names: &BlockNames, key: &str, value: Value) -> bool {
    let Some((position, rest)) = key.split_once('.').and_then(|(name, rest)| Some((names.position(name)?, rest))) else {
        return false;
    };
    match table
        .get_mut(BLOCK)
        .and_then(Value::as_array_mut)
        .and_then(|a| a.get_mut(position - 1))
        .and_then(Value::as_table_mut)
    {
        Some(block) => {
            block.insert(rest.to_string(), value);
            true
        }
        None => false,
    }
}

/// Sets the key `key` of a block of `table` named by its name (`belfry.width`,
/// as a sweep's axis or an inventory's column gives it) to `value`; false
/// (nothing set) if `key` names no block of `table`, or `table`'s blocks are
/// not well formed (their parse says what is wrong).
pub fn set_named_key(table: &mut Table, key: &str, value: Value) -> bool {
    names(table).is_ok_and(|names| set_key(table, &names, key, value))
}

/// The blocks of a scenario table, the lowest first, with their names; each
/// no wider than the one below it (the first than `tower`). Errors name the
/// block's key as a sweep writes it (`belfry.width`).
pub(crate) fn parse(table: &Table, tower: Option<&Tower>) -> Result<(Vec<Block>, BlockNames), Fault> {
    let names = names(table)?;
    let tables = tables(table.get(BLOCK))?;
    if tables.is_empty() {
        return Ok((Vec::new(), names));
    }
    let Some(tower) = tower else {
        return Err(Fault::new(BLOCK, ErrorKind::Missing("blocks stand on a tower: give a [tower]".into())));
    };
    let mut blocks = Vec::with_capacity(tables.len());
    // The tower's width as given (its width from R and α otherwise).
    let tower_width = table.get("tower").and_then(|t| t.get("width")).and_then(crate::read::as_number);
    let mut below = (tower_width.unwrap_or_else(|| Block::from_tower(tower).width()), "the tower".to_string());
    for (i, (t, name)) in tables.iter().zip(names.iter()).enumerate() {
        let value = Value::Table((*t).clone());
        let block = one(&Section::new(BLOCK, &value)?, i + 2).map_err(|f| rename(f, name))?;
        if block.width() > below.0 {
            return Err(Fault::invalid(
                format!("{name}.width"),
                format!(
                    "{} m is wider than the {} m of {} below it: a block stands on the one below, no wider",
                    block.width(),
                    below.0,
                    below.1
                ),
            ));
        }
        below = (block.width(), format!("block \"{name}\""));
        blocks.push(block);
    }
    Ok((blocks, names))
}

/// An error about a key of `[[block]]`, or about the tower's parameter a
/// block's geometry went through, named as the block's key (`belfry.width`).
fn rename(mut fault: Fault, name: &str) -> Fault {
    if let Some(key) = fault.key.take() {
        let rest = key.strip_prefix("block.").or_else(|| key.strip_prefix("tower.")).unwrap_or(&key);
        fault.key = Some(format!("{name}.{rest}"));
    }
    fault
}

/// One block from its keys; `index` its place in the stack (2 for the first
/// above the tower). The section formulas are the tower's (a block is
/// described as a tower is); its own inertia is about its centre of mass.
fn one(s: &Section<'_>, index: usize) -> Result<Block, Fault> {
    s.only_scenario_keys()?;
    let width = s.required_number("width", "the block's width in m")?;
    let height = s.required_number("height", "the block's height in m")?;
    let (mass, section) = crate::tower::mass_and_section(s, "block")?;
    let as_tower = Tower::from_geometry(&TowerGeometry {
        width,
        height,
        depth: s.number("depth")?,
        section,
        mass,
        inertia_pivot: None,
        // Not used by a block (its impacts follow the stack's law); given so
        // that a squat block, whose Housner value is negative, is accepted.
        restitution: Some(0.0),
    })
    .map_err(Fault::from)?;
    // The section's inertia about a base corner, moved to the centre of mass
    // (parallel axes, R² = (B² + H²)/4), unless given.
    let mass = as_tower.mass();
    let inertia = match s.number("inertia_centre")? {
        Some(j) => j,
        None => as_tower.inertia_pivot() - mass * (width * width + height * height) / 4.0,
    };
    Block::new(index, width, height, mass, inertia).map_err(|e| Fault::invalid(s.key("inertia_centre"), e.to_string()))
}
