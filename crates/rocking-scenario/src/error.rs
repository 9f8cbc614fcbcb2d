//! Errors of a scenario: each names the file, the dotted key and what is wrong,
//! on one line (`examples/tower.toml: tower.width: must be a finite number > 0, got -4`).

use std::borrow::Cow;
use std::fmt;
use std::path::{Path, PathBuf};

/// A scenario that cannot be read, built or run.
#[derive(Debug, thiserror::Error)]
#[error("{}: {fault}", one_line(&.file.display().to_string()))]
pub struct Error {
    /// The scenario file (or the origin given for a table or a JSON value).
    pub file: PathBuf,
    /// The key and what is wrong with it.
    pub fault: Fault,
}

impl Error {
    /// The dotted key at fault (`tower.width`), if there is one.
    pub fn key(&self) -> Option<&str> {
        self.fault.key.as_deref()
    }
    /// What is wrong.
    pub fn kind(&self) -> &ErrorKind {
        &self.fault.kind
    }
}

/// What is wrong with which key, before the file is known.
#[derive(Debug, thiserror::Error)]
pub struct Fault {
    /// The dotted key (`ground.frequency`), `None` for a fault of the whole file (a syntax error).
    pub key: Option<String>,
    /// What is wrong.
    pub kind: ErrorKind,
}

/// On one line whatever the key and the values it quotes hold ([`one_line`]).
impl fmt::Display for Fault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = match &self.key {
            Some(key) => format!("{key}: {}", self.kind),
            None => self.kind.to_string(),
        };
        f.write_str(&one_line(&text))
    }
}

/// `text` on one line: each control character in it (a line break, a tab,
/// an escape) and the line and paragraph separators written as a Rust
/// string writes them (`\n`, `\t`, `\u{1b}`, `\u{2028}`), the rest as it
/// is. An error quotes what the user wrote (a key, a value, a file's name),
/// which may hold a line break; its message stays one line.
pub fn one_line(text: &str) -> Cow<'_, str> {
    let breaks = |c: char| c.is_control() || matches!(c, '\u{2028}' | '\u{2029}');
    if !text.chars().any(breaks) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        if breaks(c) {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    Cow::Owned(out)
}

impl Fault {
    /// A fault of `key`.
    pub fn new(key: impl Into<String>, kind: ErrorKind) -> Self {
        Self { key: Some(key.into()), kind }
    }
    /// `key` has a value out of its range.
    pub fn invalid(key: impl Into<String>, reason: impl Into<String>) -> Self {
        Self::new(key, ErrorKind::Invalid(reason.into()))
    }
    /// The error of this fault in `file`.
    pub fn in_file(self, file: &Path) -> Error {
        Error {
            file: file.to_path_buf(),
            fault: self,
        }
    }
}

/// The classes of scenario errors.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The file is not valid TOML (or the JSON value not an object).
    #[error("line {line}, column {column}: {message}")]
    Syntax {
        /// 1-based line.
        line: usize,
        /// 1-based column (in characters).
        column: usize,
        /// What the parser found, on one line.
        message: String,
    },
    /// A value of the wrong TOML type.
    #[error("expected {expected}, got {got}")]
    WrongType {
        /// What the key takes ("a number").
        expected: &'static str,
        /// What it was given ("a string").
        got: &'static str,
    },
    /// A key that no section of this kind has (a typo).
    #[error("unknown key{}; valid keys: {}", did_you_mean(.suggestion), .valid.join(", "))]
    UnknownKey {
        /// The closest valid key, if one is close.
        suggestion: Option<String>,
        /// The keys the section takes (a block's by its name: `belfry.width`).
        valid: Vec<String>,
    },
    /// A section the scenario does not have.
    #[error("unknown section{}; valid sections: {}", did_you_mean(.suggestion), .valid.join(", "))]
    UnknownSection {
        /// The closest valid section, if one is close.
        suggestion: Option<String>,
        /// The sections a scenario takes.
        valid: Vec<String>,
    },
    /// A required key or section is absent.
    #[error("{0}")]
    Missing(String),
    /// A key that exists but does not apply here (`frequency` with `type = "record"`),
    /// or two keys that exclude each other.
    #[error("{0}")]
    NotApplicable(String),
    /// A value outside its valid range.
    #[error("{0}")]
    Invalid(String),
    /// An input file (a ground-motion record) cannot be read.
    #[error("cannot read {}: {reason}", .path.display())]
    Read {
        /// The file, resolved against the scenario's folder.
        path: PathBuf,
        /// Why (the operating system's message).
        reason: String,
        /// The operating system's error number, if there is one (`ENOENT`: the
        /// Python package raises `FileNotFoundError`).
        os_error: Option<i32>,
    },
    /// A ground-motion record is malformed.
    #[error("{}: {source}", .path.display())]
    Record {
        /// The file, resolved against the scenario's folder.
        path: PathBuf,
        /// What is wrong, with the line where there is one.
        source: rocking::RecordError,
    },
    /// The simulation failed (a numerical failure, not an input error).
    #[error(transparent)]
    Simulation(rocking::Error),
}

impl ErrorKind {
    /// `word` is none of the keys `valid`: the closest of them suggested, if one is close.
    pub fn unknown_key<S: AsRef<str>>(word: &str, valid: &[S]) -> Self {
        let (suggestion, valid) = suggested(word, valid);
        Self::UnknownKey { suggestion, valid }
    }
    /// `word` is none of the sections `valid`: the closest of them suggested, if one is close.
    pub fn unknown_section<S: AsRef<str>>(word: &str, valid: &[S]) -> Self {
        let (suggestion, valid) = suggested(word, valid);
        Self::UnknownSection { suggestion, valid }
    }
}

/// The closest of `valid` to `word`, and `valid`, owned.
fn suggested<S: AsRef<str>>(word: &str, valid: &[S]) -> (Option<String>, Vec<String>) {
    let valid: Vec<&str> = valid.iter().map(AsRef::as_ref).collect();
    (closest(word, &valid).map(str::to_string), valid.iter().map(|s| s.to_string()).collect())
}

fn did_you_mean(s: &Option<String>) -> String {
    s.as_ref().map(|s| format!(" (did you mean `{s}`?)")).unwrap_or_default()
}

/// The scenario key of each parameter of the library: the key whose
/// description ([`crate::SCENARIO_KEYS`]) says it sets the parameter; the
/// bodies of the model are the `[tower]` (with or without a building).
pub fn key_of(parameter: rocking::Parameter) -> &'static str {
    if parameter == rocking::Parameter::Bodies {
        return "tower";
    }
    if parameter == rocking::Parameter::Blocks {
        return "block";
    }
    crate::SCENARIO_KEYS
        .iter()
        .find(|k| k.parameter == Some(parameter))
        // A parameter added to the library without a key: named in words.
        .map_or("(parameter)", |k| k.key)
}

impl From<rocking::Error> for Fault {
    /// A library error: its parameter mapped to the scenario key by [`key_of`].
    fn from(e: rocking::Error) -> Self {
        match e {
            rocking::Error::InvalidParameter { parameter, reason } => Fault::invalid(key_of(parameter), reason),
            // Only the vertical motion can take g + a_v to zero.
            free_fall @ rocking::Error::FreeFall { .. } => Fault {
                key: Some("ground.vertical".into()),
                kind: ErrorKind::Simulation(free_fall),
            },
            other => Fault {
                key: None,
                kind: ErrorKind::Simulation(other),
            },
        }
    }
}

/// The message of an I/O error without Rust's ` (os error 2)` suffix.
pub(crate) fn io_reason(e: &std::io::Error) -> String {
    let text = e.to_string();
    match text.find(" (os error ") {
        Some(i) => text[..i].to_string(),
        None => text,
    }
}

/// The closest of `candidates` to `word` within two edits (and fewer than the
/// candidate's length), for "did you mean"; the first of the closest on a tie.
pub fn closest<'a>(word: &str, candidates: &[&'a str]) -> Option<&'a str> {
    candidates
        .iter()
        .map(|&c| (edit_distance(word, c), c))
        .filter(|&(d, c)| d <= 2 && d < c.chars().count())
        .min_by_key(|&(d, _)| d)
        .map(|(_, c)| c)
}

/// Levenshtein distance with adjacent transpositions counted as one edit (`hieght` → `height`).
fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    let mut d = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for (i, row) in d.iter_mut().enumerate() {
        row[0] = i;
    }
    for (j, cell) in d[0].iter_mut().enumerate() {
        *cell = j;
    }
    for i in 1..=a.len() {
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut best = (d[i - 1][j] + 1).min(d[i][j - 1] + 1).min(d[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                best = best.min(d[i - 2][j - 2] + 1);
            }
            d[i][j] = best;
        }
    }
    d[a.len()][b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transposition_is_one_edit() {
        assert_eq!(edit_distance("hieght", "height"), 1);
        assert_eq!(edit_distance("widht", "width"), 1);
        assert_eq!(edit_distance("mass", "mass"), 0);
        assert_eq!(edit_distance("", "abc"), 3);
    }

    #[test]
    fn closest_only_when_close() {
        assert_eq!(closest("hieght", &["width", "height"]), Some("height"));
        assert_eq!(closest("colour", &["width", "height"]), None);
    }

    /// Every parameter of the library has its own scenario key, set by one
    /// key of the description; a hand-checked sample.
    #[test]
    fn every_parameter_has_a_distinct_key() {
        use rocking::Parameter as P;
        let keys: std::collections::BTreeSet<&str> = P::ALL.iter().map(|&p| key_of(p)).collect();
        assert_eq!(keys.len(), P::ALL.len());
        assert!(!keys.contains("(parameter)"));
        let setting: Vec<P> = crate::SCENARIO_KEYS.iter().filter_map(|k| k.parameter).collect();
        // All but the bodies and the blocks (sections, not keys), each once.
        assert_eq!(setting.len(), P::ALL.len() - 2);
        assert!(P::ALL.iter().all(|p| *p == P::Bodies || *p == P::Blocks || setting.contains(p)));
        assert_eq!(key_of(P::Blocks), "block");
        assert_eq!(key_of(P::TowerWidth), "tower.width");
        assert_eq!(key_of(P::GroundRickerCentre), "ground.t0");
        assert_eq!(key_of(P::Gravity), "simulation.g");
        assert_eq!(key_of(P::InitialThetaDot), "initial.theta_dot");
        assert_eq!(key_of(P::Bodies), "tower");
    }

    #[test]
    fn io_reason_drops_os_error_suffix() {
        let e = std::io::Error::from_raw_os_error(2);
        assert_eq!(io_reason(&e), "No such file or directory");
    }
}
