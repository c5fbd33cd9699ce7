//! Output files: VTK for ParaView, CSV time series, and PNG/SVG line plots.
//!
//! Everything a long run writes is either replaced atomically (VTK, PVD, SVG,
//! PNG) or appended row by row (CSV), so that a run killed at any moment
//! leaves readable files behind.

// Module declarations.
pub mod blocks;
pub mod checkpoint;
pub mod csv;
pub mod debris;
pub mod plot;
pub mod pvd;
pub mod shallow;
pub mod vtk;

use std::fs::{self, File};
use std::io::Write;
use std::path::{Path, PathBuf};

/// Writes `bytes` to `path` so that readers see either the old file or the
/// complete new one, never a partial file, and the new file survives a power
/// cut once this returns (used for checkpoints).
///
/// The data goes to `<path>.tmp` in the same directory (a rename is only
/// atomic within one file system), is fsynced, and is then renamed over
/// `path`. On failure the temporary file is removed and `path` is untouched.
pub(crate) fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    write_via_tmp(path, bytes, true)
}

/// Like [`write_atomically`] but without forcing the data to disk: a crashed
/// process still leaves the old or the new file, never a partial one. For
/// output that is rewritten often (VTK frames, `.pvd`, plots), where an fsync
/// per file would dominate the run time of small cases.
pub(crate) fn write_replacing(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    write_via_tmp(path, bytes, false)
}

fn write_via_tmp(path: &Path, bytes: &[u8], durable: bool) -> std::io::Result<()> {
    let tmp = tmp_path(path, ".tmp");
    let result = (|| -> std::io::Result<()> {
        let mut file = File::create(&tmp)?;
        file.write_all(bytes)?;
        if durable {
            file.sync_all()?;
        }
        drop(file);
        fs::rename(&tmp, path)
    })();
    if let Err(e) = result {
        // Best effort: the original error is the one worth reporting.
        let _ = fs::remove_file(&tmp);
        return Err(naming(path)(e));
    }
    if durable {
        sync_parent_dir(path);
    }
    result
}

/// Puts `path` into an I/O error's message, keeping its kind: the OS's message names no file
/// ("Permission denied (os error 13)"), and an output folder holds many.
pub(crate) fn naming(path: &Path) -> impl Fn(std::io::Error) -> std::io::Error + '_ {
    move |e| std::io::Error::new(e.kind(), format!("{}: {e}", path.display()))
}

/// `path` with `suffix` appended to its file name (`a/b.vtu` -> `a/b.vtu.tmp`).
pub(crate) fn tmp_path(path: &Path, suffix: &str) -> PathBuf {
    let mut name = path.file_name().unwrap_or_default().to_os_string();
    name.push(suffix);
    path.with_file_name(name)
}

/// Makes a finished rename durable across a power cut. Best effort: some
/// file systems refuse to open or sync a directory, and the data itself is
/// already safe, so errors are ignored.
pub(crate) fn sync_parent_dir(path: &Path) {
    #[cfg(unix)]
    {
        let dir = match path.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        if let Ok(d) = File::open(dir) {
            let _ = d.sync_all();
        }
    }
    #[cfg(not(unix))]
    let _ = path;
}

/// An `InvalidInput` error with a message, for argument checks.
pub(crate) fn invalid_input(msg: impl Into<String>) -> std::io::Error {
    std::io::Error::new(std::io::ErrorKind::InvalidInput, msg.into())
}

/// An `InvalidData` error with a message, for files that do not parse.
pub(crate) fn invalid_data(msg: impl Into<String>) -> std::io::Error {
    std::io::Error::new(std::io::ErrorKind::InvalidData, msg.into())
}

/// Escapes text for use inside a double-quoted XML attribute.
pub(crate) fn xml_escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            _ => out.push(c),
        }
    }
    out
}

/// A fresh, empty directory under the system temp dir for one test,
/// removed when the test passes and kept for inspection when it fails.
#[cfg(test)]
pub(crate) fn test_dir(name: &str) -> TestDir {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    let pid = std::process::id();
    let dir = std::env::temp_dir().join(format!("riprap_io_test_{pid}_{n}_{name}"));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).expect("create test dir");
    TestDir(dir)
}

/// See [`test_dir`]; derefs to the directory's path.
#[cfg(test)]
pub(crate) struct TestDir(PathBuf);

#[cfg(test)]
impl std::ops::Deref for TestDir {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

#[cfg(test)]
impl AsRef<Path> for TestDir {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

#[cfg(test)]
impl Drop for TestDir {
    fn drop(&mut self) {
        if !std::thread::panicking() {
            let _ = fs::remove_dir_all(&self.0);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn write_atomically_replaces_and_leaves_no_tmp() {
        let dir = test_dir("atomic");
        let path = dir.join("a.txt");
        write_atomically(&path, b"first").unwrap();
        write_atomically(&path, b"second").unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"second");
        assert!(!dir.join("a.txt.tmp").exists());
        assert_eq!(fs::read_dir(&dir).unwrap().count(), 1);
    }

    #[test]
    fn write_atomically_fails_cleanly_in_missing_dir() {
        let dir = test_dir("atomic_missing");
        let path = dir.join("no_such_dir").join("a.txt");
        let e = write_atomically(&path, b"x").unwrap_err();
        assert!(!path.exists());
        assert!(e.to_string().contains("no_such_dir"), "{e}");
    }

    #[test]
    fn tmp_path_appends_to_file_name() {
        assert_eq!(
            tmp_path(Path::new("out/p.vtu"), ".tmp"),
            Path::new("out/p.vtu.tmp")
        );
    }

    #[test]
    fn xml_escape_escapes_markup() {
        assert_eq!(xml_escape(r#"a<b>&"c'"#), "a&lt;b&gt;&amp;&quot;c&apos;");
    }
}
