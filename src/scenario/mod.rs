//! Scenario files: TOML in SI units, read, checked and turned into a `Simulation`.
//!
//! Every error names the file, the line, the key and the reason. Unknown keys are errors.

mod build;
pub mod default;
pub mod schema;

use std::path::{Path, PathBuf};

pub use build::{build, Built, Derived};
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
    #[error("{file}:{line}: {message}")]
    Parse {
        /// The file.
        file: String,
        /// 1-based line.
        line: usize,
        /// toml's message (names the key).
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
}

impl Source {
    /// Reads and parses a scenario file.
    pub fn from_file(path: &Path) -> Result<Source, ScenarioError> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path)
            .map_err(|e| ScenarioError::Io { file: file.clone(), reason: e.to_string() })?;
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        Source::from_str(&text, &file, dir)
    }

    /// Parses scenario text; `file` names it in messages.
    pub fn from_str(text: &str, file: &str, dir: PathBuf) -> Result<Source, ScenarioError> {
        let scenario: Scenario = toml::from_str(text).map_err(|e| {
            let line = e.span().map_or(0, |s| text[..s.start.min(text.len())].lines().count().max(1));
            let line = if e.span().is_some_and(|s| text[..s.start.min(text.len())].ends_with('\n')) {
                line + 1
            } else {
                line
            };
            ScenarioError::Parse { file: file.to_string(), line, message: e.message().to_string() }
        })?;
        Ok(Source { scenario, text: text.to_string(), file: file.to_string(), dir })
    }

    /// An `Invalid` error for `key` (a dotted path such as `spheres[1].diameter`).
    pub fn invalid(&self, key: &str, reason: impl Into<String>) -> ScenarioError {
        ScenarioError::Invalid {
            file: self.file.clone(),
            line: line_of(&self.text, key),
            key: key.to_string(),
            reason: reason.into(),
        }
    }
}

/// Best-effort line of a dotted key path in TOML text: finds the table (the n-th `[[name]]` for
/// `name[n]`, or `[name]`), then the first line after it that sets the last key.
fn line_of(text: &str, key: &str) -> usize {
    let parts: Vec<&str> = key.split('.').collect();
    let lines: Vec<&str> = text.lines().collect();
    let mut from = 0;
    if let Some(first) = parts.first() {
        let (name, index) = match first.split_once('[') {
            Some((n, rest)) => (n, rest.trim_end_matches(']').parse::<usize>().ok()),
            None => (*first, None),
        };
        let header = match index {
            Some(_) => format!("[[{name}]]"),
            None => format!("[{name}]"),
        };
        let mut seen = 0;
        for (k, l) in lines.iter().enumerate() {
            if l.trim() == header {
                if index.is_none_or(|i| i == seen) {
                    from = k;
                    break;
                }
                seen += 1;
            }
        }
    }
    let last = parts.last().map(|p| p.split('[').next().unwrap_or(p)).unwrap_or("");
    for (k, l) in lines.iter().enumerate().skip(from) {
        if k > from && l.trim_start().starts_with('[') && !l.trim_start().starts_with("[[spheres.") {
            break;
        }
        let t = l.trim_start();
        if t.starts_with(last) && t[last.len()..].trim_start().starts_with('=')
            || l.contains(&format!(" {last} ="))
            || l.contains(&format!("{{{last} ="))
            || l.contains(&format!("{{ {last} ="))
        {
            return k + 1;
        }
    }
    from + 1
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unknown_key_names_line_and_key() {
        let text = "[run]\nname = \"x\"\nend_time = 1.0\nend_tme = 2.0\n[domain]\nmin=[0,0,0]\nmax=[1,1,1]\n";
        let e = Source::from_str(text, "case.toml", PathBuf::new()).unwrap_err().to_string();
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
