//! Scenario files: TOML in SI units, read, checked and turned into a `Simulation`.
//!
//! Every error names the file, the line, the key and the reason. Unknown keys are errors.

pub mod armour;
mod blocks;
pub mod breakwater;
mod build;
mod checks;
mod contact;
pub mod coupling;
pub mod default;
mod derived;
pub mod fluid;
pub mod memory;
pub mod mound;
pub mod output_size;
mod pairings;
pub mod schema;
mod settings;
pub mod shallow;
mod spheres;
pub mod text;
mod wall_overlaps;
mod walls;

use std::ops::Range;
use std::path::{Path, PathBuf};

use toml::de::{DeTable, DeValue, ValueDeserializer};
use toml::Spanned;

pub use build::{build, check, Built};
pub use derived::Derived;
pub use fluid::FluidDerived;
pub use schema::Scenario;

/// What is wrong with a scenario.
#[derive(Debug, thiserror::Error)]
pub enum ScenarioError {
    /// The file could not be read.
    #[error("{file}: cannot read the scenario: {reason}")]
    Io {
        /// The file.
        file: String,
        /// The reason.
        reason: String,
    },
    /// TOML syntax, an unknown key or a value of the wrong type.
    #[error("{file}:{line}: {}{message}", key_prefix(.key))]
    Parse {
        /// The file.
        file: String,
        /// 1-based line (0 when unknown).
        line: usize,
        /// Dotted path of the offending key, e.g. `wall[2].motion.stop` (empty when unknown).
        key: String,
        /// toml's message (for a syntax error, followed by the offending line).
        message: String,
    },
    /// A value that parses but makes no physical sense.
    #[error("{file}:{line}: key `{key}`: {reason}")]
    Invalid {
        /// The file.
        file: String,
        /// 1-based line (best effort: the line of the key, or of its table).
        line: usize,
        /// Dotted path of the key, e.g. `spheres[1].sizes[0].diameter`.
        key: String,
        /// Why it is refused.
        reason: String,
    },
}

fn key_prefix(key: &str) -> String {
    if key.is_empty() {
        String::new()
    } else {
        format!("key `{key}`: ")
    }
}

/// A scenario with its source text and where it came from.
#[derive(Clone, Debug)]
pub struct Source {
    /// The parsed scenario.
    pub scenario: Scenario,
    /// The TOML text.
    pub text: String,
    /// File name for messages (`<built-in>` for the default scenario).
    pub file: String,
    /// Folder against which relative paths (STL files) are resolved.
    pub dir: PathBuf,
    /// What `[breakwater]` expanded into, for `riprap check` (its walls, blocks, porous zones
    /// and `[armour]` are in `scenario`).
    pub breakwater: Option<breakwater::BreakwaterSummary>,
}

impl Source {
    /// Reads and parses a scenario file.
    pub fn from_file(path: &Path) -> Result<Source, ScenarioError> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| ScenarioError::Io {
            file: file.clone(),
            reason: e.to_string(),
        })?;
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        Source::from_str(&text, &file, dir)
    }

    /// Parses scenario text; `file` names it in messages.
    pub fn from_str(text: &str, file: &str, dir: PathBuf) -> Result<Source, ScenarioError> {
        let scenario: Scenario = toml::from_str(text).map_err(|e| parse_error(text, file, e))?;
        let mut src = Source {
            scenario,
            text: text.to_string(),
            file: file.to_string(),
            dir,
            breakwater: None,
        };
        src.breakwater = breakwater::expand(&mut src)?;
        Ok(src)
    }

    /// An `Invalid` error for `key` (a dotted path such as `spheres[1].diameter`), at its line.
    pub fn invalid(&self, key: &str, reason: impl Into<String>) -> ScenarioError {
        self.invalid_at(key, key, reason)
    }

    /// An `Invalid` error for `key`, at the line of the key path `at` (for a key that is missing,
    /// point at the one that makes it needed).
    pub fn invalid_at(&self, key: &str, at: &str, reason: impl Into<String>) -> ScenarioError {
        ScenarioError::Invalid {
            file: self.file.clone(),
            line: line_of(&self.text, at),
            key: key.to_string(),
            reason: reason.into(),
        }
    }
}

/// One step of a key path: a key, or an index into an array.
#[derive(Clone, Debug, PartialEq)]
enum Seg {
    Key(String),
    Index(usize),
}

fn path_string(segs: &[Seg]) -> String {
    let mut s = String::new();
    for seg in segs {
        match seg {
            Seg::Key(k) => {
                if !s.is_empty() {
                    s.push('.');
                }
                s.push_str(k);
            }
            Seg::Index(i) => s.push_str(&format!("[{i}]")),
        }
    }
    s
}

/// `spheres[1].sizes[0].diameter` → [spheres, 1, sizes, 0, diameter].
fn parse_path(key: &str) -> Vec<Seg> {
    let mut segs = Vec::new();
    for part in key.split('.').filter(|p| !p.is_empty()) {
        let mut pieces = part.split('[');
        if let Some(name) = pieces.next().filter(|n| !n.is_empty()) {
            segs.push(Seg::Key(name.to_string()));
        }
        for idx in pieces {
            if let Ok(i) = idx.trim_end_matches(']').parse() {
                segs.push(Seg::Index(i));
            }
        }
    }
    segs
}

/// 1-based line of a byte offset.
fn line_at(text: &str, pos: usize) -> usize {
    let pos = pos.min(text.len());
    text.as_bytes()[..pos]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

/// Follows `segs` down the tree as far as it exists: (segments found, span of the deepest key
/// or array element found).
fn walk_path(root: &Spanned<DeValue<'_>>, segs: &[Seg]) -> (usize, Option<Range<usize>>) {
    let mut node = root;
    let mut span = None;
    for (n, seg) in segs.iter().enumerate() {
        let next = match (seg, node.get_ref()) {
            (Seg::Key(k), DeValue::Table(t)) => {
                t.get_key_value(k.as_str()).map(|(k, v)| (k.span(), v))
            }
            (Seg::Index(i), DeValue::Array(a)) => a.get(*i).map(|v| (v.span(), v)),
            _ => None,
        };
        match next {
            Some((s, v)) => {
                span = Some(s);
                node = v;
            }
            None => return (n, span),
        }
    }
    (segs.len(), span)
}

/// Line of a dotted key path in TOML text (`wall[2].motion.stop`, `spheres[0].spheres[3]`,
/// `spheres[1].sizes[0].diameter`): the line of the key itself, or of the array entry (the
/// `[[wall]]` header, or the `{ ... }` of an inline array of tables), or, when the key is not
/// written, of the deepest table on its path that is. Works with any TOML layout: it follows
/// toml's own spans.
fn line_of(text: &str, key: &str) -> usize {
    let Ok(root) = DeTable::parse(text) else {
        return 1;
    };
    let root = Spanned::new(root.span(), DeValue::Table(root.into_inner()));
    match walk_path(&root, &parse_path(key)) {
        (_, Some(span)) => line_at(text, span.start),
        (_, None) => 1,
    }
}

/// The deepest key or value in the tree whose span contains `pos`: its path, the node (the
/// value), and whether `pos` lies on the key rather than the value.
fn locate<'a, 'i>(
    node: &'a Spanned<DeValue<'i>>,
    pos: usize,
    path: &mut Vec<Seg>,
) -> Option<(&'a Spanned<DeValue<'i>>, bool)> {
    let contains = |s: Range<usize>| s.start <= pos && pos < s.end.max(s.start + 1);
    match node.get_ref() {
        DeValue::Table(t) => {
            for (k, v) in t.iter() {
                path.push(Seg::Key(k.get_ref().to_string()));
                if contains(k.span()) {
                    return Some((v, true));
                }
                if let Some(found) = locate(v, pos, path) {
                    return Some(found);
                }
                if contains(v.span()) {
                    return Some((v, false));
                }
                path.pop();
            }
            None
        }
        DeValue::Array(a) => {
            for (i, v) in a.iter().enumerate() {
                path.push(Seg::Index(i));
                if let Some(found) = locate(v, pos, path) {
                    return Some(found);
                }
                if contains(v.span()) {
                    return Some((v, false));
                }
                path.pop();
            }
            None
        }
        _ => None,
    }
}

/// Which `kind`-tagged table sits at `path`, if any.
fn tagged_at(path: &[Seg]) -> Option<&'static str> {
    match path {
        [Seg::Key(k), Seg::Index(_)] if k == "wall" => Some("wall"),
        [Seg::Key(k), Seg::Index(_)] if k == "spheres" => Some("spheres"),
        [Seg::Key(k), Seg::Index(_)] if k == "blocks" => Some("blocks"),
        [.., Seg::Key(k)] if k == "motion" => Some("motion"),
        _ => None,
    }
}

/// Re-reads a `kind`-tagged table as the struct of its kind, straight from toml's tree so that
/// the error keeps its span; `None` when that gives no (new) error.
fn payload_error(what: &str, node: &Spanned<DeValue<'_>>) -> Option<toml::de::Error> {
    let DeValue::Table(t) = node.get_ref() else {
        return None;
    };
    let kind = t.get("kind")?.get_ref().as_str()?.to_string();
    let t: DeTable<'_> = t
        .iter()
        .filter(|(k, _)| k.get_ref() != "kind")
        .map(|(k, v)| (k.clone(), v.clone()))
        .collect();
    let de = || ValueDeserializer::from(Spanned::new(node.span(), DeValue::Table(t.clone())));
    fn check<'de, T: serde::Deserialize<'de>>(
        de: ValueDeserializer<'de>,
    ) -> Option<toml::de::Error> {
        T::deserialize(de).err()
    }
    match (what, kind.as_str()) {
        ("wall", "plane") => check::<schema::PlaneWall>(de()),
        ("wall", "box") => check::<schema::BoxWall>(de()),
        ("wall", "cylinder") => check::<schema::CylinderWall>(de()),
        ("wall", "mesh") => check::<schema::MeshWall>(de()),
        ("spheres", "list") => check::<schema::ListSet>(de()),
        ("spheres", "lattice") => check::<schema::LatticeSet>(de()),
        ("spheres", "random") => check::<schema::RandomSet>(de()),
        ("spheres", "feed") => check::<schema::FeedSet>(de()),
        ("spheres", "file") => check::<schema::FileSet>(de()),
        ("blocks", "list") => check::<schema::ListBlocks>(de()),
        ("blocks", "lattice") => check::<schema::LatticeBlocks>(de()),
        ("blocks", "random") => check::<schema::RandomBlocks>(de()),
        ("motion", "fixed") => check::<schema::FixedMotion>(de()),
        ("motion", "linear") => check::<schema::LinearMotion>(de()),
        ("motion", "oscillation") => check::<schema::OscillationMotion>(de()),
        _ => None,
    }
}

/// Turns toml's error into one that names the line and the key path.
///
/// serde's internally tagged enums (`kind = ...`) buffer their table and lose toml's spans: an
/// error inside `[[wall]]`, `[[spheres]]` or `motion = { ... }` comes back pointing at the whole
/// table. Such a table is then read again as the struct of its kind, directly from toml's tree,
/// which gives the exact key (repeated for a `motion` inside a wall).
fn parse_error(text: &str, file: &str, e: toml::de::Error) -> ScenarioError {
    let Ok(root) = DeTable::parse(text) else {
        // A syntax error: name the line and show it.
        let line = e.span().map_or(0, |s| line_at(text, s.start));
        let shown = text
            .lines()
            .nth(line.wrapping_sub(1))
            .unwrap_or("")
            .trim_end();
        let key = e
            .span()
            .map(|s| syntax_key(text, s.start))
            .unwrap_or_default();
        return ScenarioError::Parse {
            file: file.to_string(),
            line,
            key,
            message: format!(
                "TOML syntax error: {}\n  {line:>4} | {shown}",
                e.message().trim_end()
            ),
        };
    };
    let root = Spanned::new(root.span(), DeValue::Table(root.into_inner()));
    let mut err = e;
    for _ in 0..4 {
        let Some(span) = err.span() else { break };
        let mut inner = None;
        // An array of tagged tables with the error's span: serde lost which entry failed (the
        // span of an array of tables is that of its first header), so try them in order.
        if let DeValue::Table(t) = root.get_ref() {
            for name in ["wall", "spheres"] {
                if let Some(arr) = t.get(name) {
                    if let DeValue::Array(a) = arr.get_ref() {
                        if arr.span() == span || a.first().is_some_and(|v| v.span() == span) {
                            inner = a.iter().find_map(|v| payload_error(name, v));
                        }
                    }
                }
            }
        }
        // A tagged table (or a `motion` inside one) with the error's span.
        if inner.is_none() {
            let mut path = Vec::new();
            if let Some((node, false)) = locate(&root, span.start, &mut path) {
                if node.span() == span {
                    inner = tagged_at(&path).and_then(|what| payload_error(what, node));
                }
            }
        }
        match inner {
            Some(inner)
                if inner.span() != Some(span.clone()) || inner.message() != err.message() =>
            {
                err = inner
            }
            _ => break,
        }
    }
    let mut path = Vec::new();
    // (An error about the whole document, such as a missing [run], has the root's span.)
    if let Some(span) = err.span().filter(|s| *s != root.span()) {
        locate(&root, span.start, &mut path);
    }
    let message = err.message().trim_end().to_string();
    // "missing field `x`" names a key below the table that was located.
    if let Some(missing) = message
        .strip_prefix("missing field `")
        .and_then(|m| m.split('`').next())
    {
        path.push(Seg::Key(missing.to_string()));
    }
    ScenarioError::Parse {
        file: file.to_string(),
        line: err.span().map_or(0, |s| line_at(text, s.start)),
        key: path_string(&path),
        message,
    }
}

/// For a syntax error at `pos`: the key being written there, prefixed by the table header above
/// it (best effort; empty when there is no `key =` on that line).
fn syntax_key(text: &str, pos: usize) -> String {
    let pos = pos.min(text.len());
    let start = text[..pos].rfind('\n').map_or(0, |i| i + 1);
    let line = text[start..].lines().next().unwrap_or("");
    let Some((key, _)) = line.split_once('=') else {
        return String::new();
    };
    let key = key.trim();
    if key.is_empty()
        || !key
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "_-.\"' ".contains(c))
    {
        return String::new();
    }
    let header = text[..start]
        .lines()
        .rev()
        .map(str::trim)
        .find(|l| l.starts_with('['))
        // The name between the brackets, without a comment after the header.
        .map(|h| {
            let name = h.trim_start_matches('[').split(']').next().unwrap_or("");
            name.trim().to_string()
        });
    match header {
        Some(h) if !h.is_empty() => format!("{h}.{key}"),
        _ => key.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Regression: a syntax error under a header with a comment named the key
    /// `breakwater]   # the mound ….material`.
    #[test]
    fn a_syntax_error_under_a_commented_header_names_the_table() {
        let text = "[breakwater]   # the mound\nslope = 2.0\nslope = 3.0\n";
        let pos = text.rfind("slope").unwrap();
        assert_eq!(syntax_key(text, pos), "breakwater.slope");
        let text = "[[blocks]] # a list\nkind = \"list\"\nkind = \"x\"\n";
        assert_eq!(syntax_key(text, text.rfind("kind").unwrap()), "blocks.kind");
    }

    #[test]
    fn unknown_key_names_line_and_key() {
        let text = "[run]\nname = \"x\"\nend_time = 1.0\nend_tme = 2.0\n[domain]\nmin=[0,0,0]\nmax=[1,1,1]\n";
        let e = Source::from_str(text, "case.toml", PathBuf::new())
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("case.toml:4:"), "{e}");
        assert!(e.contains("end_tme"), "{e}");
    }

    #[test]
    fn line_of_finds_array_entries() {
        let text = "[run]\nname='a'\n[[material]]\nname='a'\ndensity=1\n[[material]]\nname='b'\ndensity = -1\n";
        assert_eq!(line_of(text, "material[1].density"), 8);
        assert_eq!(line_of(text, "run.name"), 2);
    }
}
