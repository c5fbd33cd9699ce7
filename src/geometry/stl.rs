//! STL files (ASCII and binary): reading into a [`TriMesh`] and writing.

use std::io::{self, Write};
use std::path::Path;

use glam::DVec3;

use super::mesh::{MeshError, TriMesh};

/// Why an STL file could not be read. Every message starts with the file name.
#[derive(Debug, thiserror::Error)]
pub enum StlError {
    /// The file could not be read.
    #[error("{file}: cannot read: {source}")]
    Io {
        file: String,
        #[source]
        source: io::Error,
    },
    /// Syntax error in an ASCII file, at `line` (counted from 1).
    #[error("{file}: line {line}: {reason}")]
    Ascii { file: String, line: usize, reason: String },
    /// Error in a binary file, at triangle `triangle` (counted from 0).
    #[error("{file}: binary STL, triangle {triangle} (from 0): {reason}")]
    Binary { file: String, triangle: usize, reason: String },
    /// Neither a valid binary nor an ASCII file.
    #[error("{file}: {reason}")]
    Format { file: String, reason: String },
    /// The triangles do not make a mesh (e.g. there are none).
    #[error("{file}: {source}")]
    Mesh {
        file: String,
        #[source]
        source: MeshError,
    },
}

/// Triangle corners [m] of an STL file's bytes; `file` names it in errors.
///
/// Binary is recognised first by its exact size, 84 + 50 n bytes for the n triangles its header
/// announces (some binary files start with "solid", like ASCII ones); otherwise a file starting
/// with "solid" is ASCII. Facet normals are ignored (corner order defines orientation).
pub fn parse_stl(bytes: &[u8], file: &str) -> Result<Vec<[DVec3; 3]>, StlError> {
    let exact_binary = binary_size(bytes) == Some(bytes.len() as u64);
    let text_start = bytes.iter().position(|b| !b.is_ascii_whitespace()).unwrap_or(bytes.len());
    let ascii = bytes[text_start..].get(..5).is_some_and(|s| s.eq_ignore_ascii_case(b"solid"));
    if !exact_binary && ascii {
        parse_ascii(bytes, file)
    } else {
        parse_binary(bytes, file)
    }
}

/// Size in bytes that a binary STL with this header should have.
fn binary_size(bytes: &[u8]) -> Option<u64> {
    let n = u32::from_le_bytes(bytes.get(80..84)?.try_into().ok()?);
    Some(84 + 50 * u64::from(n))
}

fn parse_binary(bytes: &[u8], file: &str) -> Result<Vec<[DVec3; 3]>, StlError> {
    let Some(size) = binary_size(bytes) else {
        let reason = if bytes.is_empty() { "empty file".into() } else {
            format!("{} bytes: too short for a binary STL (84-byte header) and not ASCII (no leading 'solid')", bytes.len())
        };
        return Err(StlError::Format { file: file.into(), reason });
    };
    let n = ((size - 84) / 50) as usize;
    if (bytes.len() as u64) < size {
        return Err(StlError::Binary {
            file: file.into(),
            triangle: (bytes.len() - 84) / 50,
            reason: format!("file truncated: the header announces {n} triangles ({size} bytes) but the file has {} bytes", bytes.len()),
        });
    }
    // Trailing bytes after the announced triangles are tolerated (some exporters pad).
    let f = |b: &[u8], k: usize| f64::from(f32::from_le_bytes(b[4 * k..4 * k + 4].try_into().unwrap()));
    let mut tris = Vec::with_capacity(n);
    for (triangle, rec) in bytes[84..size as usize].chunks_exact(50).enumerate() {
        // Skip the 12-byte normal; the 2-byte attribute count at the end is unused.
        let t: [DVec3; 3] = std::array::from_fn(|v| DVec3::new(f(rec, 3 + 3 * v), f(rec, 4 + 3 * v), f(rec, 5 + 3 * v)));
        if let Some(v) = t.iter().position(|p| !p.is_finite()) {
            let reason = format!("vertex {} has a non-finite coordinate {}", v + 1, t[v]);
            return Err(StlError::Binary { file: file.into(), triangle, reason });
        }
        tris.push(t);
    }
    Ok(tris)
}

/// Where the ASCII parser is, and what it expects next.
#[derive(Clone, Copy, PartialEq)]
enum State {
    Outside,
    Solid,
    Facet,
    Loop(usize),
    EndFacet,
}

fn parse_ascii(bytes: &[u8], file: &str) -> Result<Vec<[DVec3; 3]>, StlError> {
    let text = String::from_utf8_lossy(bytes);
    let err = |line: usize, reason: String| StlError::Ascii { file: file.into(), line, reason };
    let mut state = State::Outside;
    let mut corners = [DVec3::ZERO; 3];
    let mut tris = Vec::new();
    let mut last = 0;
    for (i, line) in text.lines().enumerate() {
        let line_no = i + 1;
        let mut tok = line.split_whitespace();
        let Some(word) = tok.next() else { continue };
        last = line_no;
        state = match (state, word.to_ascii_lowercase().as_str()) {
            (State::Outside, "solid") => State::Solid,
            // The facet normal is ignored: the corner order defines the orientation.
            (State::Solid, "facet") => State::Facet,
            (State::Solid, "endsolid") => State::Outside,
            (State::Facet, "outer") if tok.next().is_some_and(|w| w.eq_ignore_ascii_case("loop")) => State::Loop(0),
            (State::Loop(k), "vertex") if k < 3 => {
                let words: Vec<&str> = tok.collect();
                if words.len() != 3 {
                    return Err(err(line_no, format!("expected 3 coordinates after 'vertex', found {}", words.len())));
                }
                let mut xyz = [0.0f64; 3];
                for (x, w) in xyz.iter_mut().zip(&words) {
                    *x = w.parse().map_err(|_| err(line_no, format!("invalid number '{w}'")))?;
                    if !x.is_finite() {
                        return Err(err(line_no, format!("non-finite coordinate '{w}'")));
                    }
                }
                corners[k] = DVec3::from_array(xyz);
                State::Loop(k + 1)
            }
            (State::Loop(3), "endloop") => State::EndFacet,
            (State::EndFacet, "endfacet") => {
                tris.push(corners);
                State::Solid
            }
            (s, _) => return Err(err(line_no, format!("expected {}, found '{}'", expected(s), line.trim()))),
        };
    }
    if matches!(state, State::Facet | State::Loop(_) | State::EndFacet) {
        return Err(err(last, format!("file ends inside a facet, expected {}", expected(state))));
    }
    Ok(tris)
}

fn expected(s: State) -> String {
    match s {
        State::Outside => "'solid'".into(),
        State::Solid => "'facet' or 'endsolid'".into(),
        State::Facet => "'outer loop'".into(),
        State::Loop(k) if k < 3 => format!("'vertex' (corner {} of 3)", k + 1),
        State::Loop(_) => "'endloop' (a facet has exactly 3 vertices)".into(),
        State::EndFacet => "'endfacet'".into(),
    }
}

/// Writes triangles (corners [m]) as ASCII STL named `name`; numbers are written so that they
/// read back exactly.
pub fn write_stl_ascii(w: &mut impl Write, name: &str, triangles: &[[DVec3; 3]]) -> io::Result<()> {
    writeln!(w, "solid {name}")?;
    for [a, b, c] in triangles {
        let n = (*b - *a).cross(*c - *a).normalize_or_zero();
        writeln!(w, "  facet normal {:e} {:e} {:e}\n    outer loop", n.x, n.y, n.z)?;
        for p in [a, b, c] {
            writeln!(w, "      vertex {:e} {:e} {:e}", p.x, p.y, p.z)?;
        }
        writeln!(w, "    endloop\n  endfacet")?;
    }
    writeln!(w, "endsolid {name}")
}

/// Writes triangles (corners [m]) as binary STL (single precision), with a header that does
/// not start with "solid".
pub fn write_stl_binary(w: &mut impl Write, triangles: &[[DVec3; 3]]) -> io::Result<()> {
    let mut header = [b' '; 80];
    header[..23].copy_from_slice(b"binary STL from riprap.");
    w.write_all(&header)?;
    let n = u32::try_from(triangles.len()).map_err(|_| io::Error::other("too many triangles for STL"))?;
    w.write_all(&n.to_le_bytes())?;
    for [a, b, c] in triangles {
        let n = (*b - *a).cross(*c - *a).normalize_or_zero();
        for p in [n, *a, *b, *c] {
            for x in p.to_array() {
                w.write_all(&(x as f32).to_le_bytes())?;
            }
        }
        w.write_all(&[0, 0])?;
    }
    Ok(())
}

impl TriMesh {
    /// Reads an STL file (ASCII or binary), merging duplicate vertices.
    pub fn from_stl(path: &Path) -> Result<TriMesh, StlError> {
        let file = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|source| StlError::Io { file: file.clone(), source })?;
        Self::from_named_stl_bytes(&bytes, &file)
    }

    /// Reads STL bytes (ASCII or binary); errors name the file "<memory>".
    pub fn from_stl_bytes(bytes: &[u8]) -> Result<TriMesh, StlError> {
        Self::from_named_stl_bytes(bytes, "<memory>")
    }

    /// Reads STL bytes, naming them `file` in errors.
    pub fn from_named_stl_bytes(bytes: &[u8], file: &str) -> Result<TriMesh, StlError> {
        let soup = parse_stl(bytes, file)?;
        TriMesh::from_triangle_soup(&soup).map_err(|source| StlError::Mesh { file: file.into(), source })
    }

    /// The corners [m] of every triangle, in order (e.g. for [`write_stl_ascii`]).
    pub fn triangle_soup(&self) -> Vec<[DVec3; 3]> {
        (0..self.triangles().len()).map(|i| self.corners(i)).collect()
    }
}
