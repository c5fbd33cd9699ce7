//! STL files (ASCII and binary): reading into a [`TriMesh`] and writing.

use std::io::{self, Write};
use std::path::Path;

use crate::math::Vec3;

use super::mesh::{MeshError, TriMesh};

/// Why an STL file could not be read. Every message starts with the file name.
#[derive(Debug, thiserror::Error)]
pub enum StlError {
    /// The file could not be read.
    #[error("{file}: cannot read: {source}")]
    Io {
        /// The file.
        file: String,
        /// The system's reason.
        #[source]
        source: io::Error,
    },
    /// Syntax error in an ASCII file.
    #[error("{file}: line {line}: {reason}")]
    Ascii {
        /// The file.
        file: String,
        /// Line number, counted from 1.
        line: usize,
        /// What is wrong.
        reason: String,
    },
    /// Error in a binary file.
    #[error("{file}: binary STL, triangle {triangle} (from 0): {reason}")]
    Binary {
        /// The file.
        file: String,
        /// Triangle index, counted from 0.
        triangle: usize,
        /// What is wrong.
        reason: String,
    },
    /// Neither a valid binary nor an ASCII file.
    #[error("{file}: {reason}")]
    Format {
        /// The file.
        file: String,
        /// What is wrong.
        reason: String,
    },
    /// The triangles do not make a mesh (e.g. there are none).
    #[error("{file}: {source}")]
    Mesh {
        /// The file.
        file: String,
        /// What is wrong.
        #[source]
        source: MeshError,
    },
}

/// Triangle corners [m] of an STL file's bytes; `file` names it in errors.
///
/// Binary is recognised first by its exact size, 84 + 50 n bytes for the n triangles its header
/// announces (some binary files start with "solid", like ASCII ones); otherwise a file starting
/// with "solid" is ASCII unless it holds NUL bytes. Facet normals are ignored (the corner order
/// defines the orientation).
pub fn parse_stl(bytes: &[u8], file: &str) -> Result<Vec<[Vec3; 3]>, StlError> {
    let exact_binary = binary_size(bytes) == Some(bytes.len() as u64);
    let text_start = bytes
        .iter()
        .position(|b| !b.is_ascii_whitespace())
        .unwrap_or(bytes.len());
    let ascii = bytes[text_start..]
        .get(..5)
        .is_some_and(|s| s.eq_ignore_ascii_case(b"solid"));
    // Text never holds NUL bytes (binary files nearly always do, in their numbers).
    if ascii && !exact_binary && !bytes.contains(&0) {
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

fn parse_binary(bytes: &[u8], file: &str) -> Result<Vec<[Vec3; 3]>, StlError> {
    let Some(size) = binary_size(bytes) else {
        let reason = if bytes.is_empty() {
            "empty file".into()
        } else {
            format!("{} bytes: too short for a binary STL (84-byte header) and not ASCII (no leading 'solid')", bytes.len())
        };
        return Err(StlError::Format {
            file: file.into(),
            reason,
        });
    };
    let n = ((size - 84) / 50) as usize;
    if (bytes.len() as u64) < size {
        return Err(StlError::Binary {
            file: file.into(),
            triangle: (bytes.len() - 84) / 50,
            reason: format!("file truncated: the header announces {n} triangles ({size} bytes) but the file has {} bytes", bytes.len()),
        });
    }
    // A few trailing bytes after the announced triangles are tolerated (some exporters pad);
    // a whole record or more means the header's count is wrong and triangles would be lost.
    let extra = bytes.len() as u64 - size;
    if extra >= 50 {
        return Err(StlError::Binary {
            file: file.into(),
            triangle: n,
            reason: format!("the header announces {n} triangles ({size} bytes) but the file has {} bytes, room for {} more: a wrong triangle count in the header", bytes.len(), extra / 50),
        });
    }
    let f =
        |b: &[u8], k: usize| f64::from(f32::from_le_bytes(b[4 * k..4 * k + 4].try_into().unwrap()));
    let mut tris = Vec::with_capacity(n);
    for (triangle, rec) in bytes[84..size as usize].chunks_exact(50).enumerate() {
        // Skip the 12-byte normal; the 2-byte attribute count at the end is unused.
        let t: [Vec3; 3] = std::array::from_fn(|v| {
            Vec3::new(f(rec, 3 + 3 * v), f(rec, 4 + 3 * v), f(rec, 5 + 3 * v))
        });
        if let Some(v) = t.iter().position(|p| !p.is_finite()) {
            let reason = format!("vertex {} has a non-finite coordinate {}", v + 1, t[v]);
            return Err(StlError::Binary {
                file: file.into(),
                triangle,
                reason,
            });
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

fn parse_ascii(bytes: &[u8], file: &str) -> Result<Vec<[Vec3; 3]>, StlError> {
    let text = String::from_utf8_lossy(bytes);
    let err = |line, reason| StlError::Ascii {
        file: file.into(),
        line,
        reason,
    };
    let (mut state, mut corners, mut tris, mut last) =
        (State::Outside, [Vec3::ZERO; 3], Vec::new(), 0);
    for (i, line) in text.lines().enumerate() {
        if !line.trim().is_empty() {
            last = i + 1;
            state = step(state, line, &mut corners, &mut tris).map_err(|r| err(last, r))?;
        }
    }
    if matches!(state, State::Facet | State::Loop(_) | State::EndFacet) {
        let reason = format!("file ends inside a facet, expected {}", expected(state));
        return Err(err(last, reason));
    }
    // A file cut between two facets parses up to its end: only the missing `endsolid` tells.
    if state == State::Solid {
        let reason = format!(
            "file ends after {} facets without 'endsolid': it looks truncated (triangles missing)",
            tris.len()
        );
        return Err(err(last, reason));
    }
    Ok(tris)
}

/// One non-blank line of an ASCII STL: the next state, or what is wrong.
fn step(
    state: State,
    line: &str,
    corners: &mut [Vec3; 3],
    tris: &mut Vec<[Vec3; 3]>,
) -> Result<State, String> {
    let mut tok = line.split_whitespace();
    let word = tok.next().unwrap_or_default().to_ascii_lowercase();
    Ok(match (state, word.as_str()) {
        (State::Outside, "solid") => State::Solid,
        // The facet normal is ignored: the corner order defines the orientation.
        (State::Solid, "facet") => State::Facet,
        (State::Solid, "endsolid") => State::Outside,
        (State::Facet, "outer") if tok.next().is_some_and(|w| w.eq_ignore_ascii_case("loop")) => {
            State::Loop(0)
        }
        (State::Loop(k), "vertex") if k < 3 => {
            let words: Vec<&str> = tok.collect();
            if words.len() != 3 {
                return Err(format!(
                    "expected 3 coordinates after 'vertex', found {}",
                    words.len()
                ));
            }
            for (j, w) in words.iter().enumerate() {
                let x: f64 = w.parse().map_err(|_| format!("invalid number '{w}'"))?;
                if !x.is_finite() {
                    return Err(format!("non-finite coordinate '{w}'"));
                }
                corners[k][j] = x;
            }
            State::Loop(k + 1)
        }
        (State::Loop(3), "endloop") => State::EndFacet,
        (State::Loop(_), "vertex") => return Err("more than 3 vertices in a facet".into()),
        (State::EndFacet, "endfacet") => {
            tris.push(*corners);
            State::Solid
        }
        (s, _) => return Err(format!("expected {}, found '{}'", expected(s), line.trim())),
    })
}

fn expected(s: State) -> String {
    match s {
        State::Outside => "'solid'".into(),
        State::Solid => "'facet' or 'endsolid'".into(),
        State::Facet => "'outer loop'".into(),
        State::Loop(k) if k < 3 => format!("'vertex' (corner {} of 3)", k + 1),
        State::Loop(_) => "'endloop'".into(),
        State::EndFacet => "'endfacet'".into(),
    }
}

/// Writes triangles (corners [m]) as ASCII STL named `name`; numbers are written so that they
/// read back exactly.
pub fn write_stl_ascii(w: &mut impl Write, name: &str, triangles: &[[Vec3; 3]]) -> io::Result<()> {
    writeln!(w, "solid {name}")?;
    for [a, b, c] in triangles {
        let n = (*b - *a).cross(*c - *a).normalize_or_zero();
        writeln!(
            w,
            "  facet normal {:e} {:e} {:e}\n    outer loop",
            n.x, n.y, n.z
        )?;
        for p in [a, b, c] {
            writeln!(w, "      vertex {:e} {:e} {:e}", p.x, p.y, p.z)?;
        }
        writeln!(w, "    endloop\n  endfacet")?;
    }
    writeln!(w, "endsolid {name}")
}

/// Writes triangles (corners [m]) as binary STL (single precision), with a header that does
/// not start with "solid".
pub fn write_stl_binary(w: &mut impl Write, triangles: &[[Vec3; 3]]) -> io::Result<()> {
    let mut header = [b' '; 80];
    header[..23].copy_from_slice(b"binary STL from riprap.");
    w.write_all(&header)?;
    let n = u32::try_from(triangles.len())
        .map_err(|_| io::Error::other("too many triangles for STL"))?;
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
        let bytes = std::fs::read(path).map_err(|source| StlError::Io {
            file: file.clone(),
            source,
        })?;
        Self::from_named_stl_bytes(&bytes, &file)
    }

    /// Reads STL bytes (ASCII or binary); errors name the file `<memory>`.
    pub fn from_stl_bytes(bytes: &[u8]) -> Result<TriMesh, StlError> {
        Self::from_named_stl_bytes(bytes, "<memory>")
    }

    /// Reads STL bytes, naming them `file` in errors.
    pub fn from_named_stl_bytes(bytes: &[u8], file: &str) -> Result<TriMesh, StlError> {
        let soup = parse_stl(bytes, file)?;
        TriMesh::from_triangle_soup(&soup).map_err(|source| StlError::Mesh {
            file: file.into(),
            source,
        })
    }

    /// The corners [m] of every triangle, in order (e.g. for [`write_stl_ascii`]).
    pub fn triangle_soup(&self) -> Vec<[Vec3; 3]> {
        (0..self.triangles().len())
            .map(|i| self.corners(i))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::plane::assert_like_plane;
    use crate::geometry::test_util::{square_grid, Rng};

    /// Writes `bytes` to a temporary file, reads it with [`TriMesh::from_stl`], removes it.
    fn via_file(name: &str, bytes: &[u8]) -> TriMesh {
        let path = std::env::temp_dir().join(format!("riprap_stl_{}_{name}", std::process::id()));
        std::fs::write(&path, bytes).unwrap();
        let mesh = TriMesh::from_stl(&path);
        std::fs::remove_file(&path).unwrap();
        mesh.unwrap()
    }

    fn ascii(tris: &[[Vec3; 3]]) -> Vec<u8> {
        let mut b = Vec::new();
        write_stl_ascii(&mut b, "test", tris).unwrap();
        b
    }

    fn binary(tris: &[[Vec3; 3]]) -> Vec<u8> {
        let mut b = Vec::new();
        write_stl_binary(&mut b, tris).unwrap();
        b
    }

    fn random_soup(n: usize) -> Vec<[Vec3; 3]> {
        let mut rng = Rng(99);
        (0..n)
            .map(|_| [rng.vec(3.0), rng.vec(3.0), rng.vec(3.0)])
            .collect()
    }

    fn err(bytes: &[u8]) -> String {
        TriMesh::from_named_stl_bytes(bytes, "bad.stl")
            .unwrap_err()
            .to_string()
    }

    #[test]
    fn ascii_round_trip_is_exact() {
        let soup = random_soup(20);
        let mesh = via_file("rt.stl", &ascii(&soup));
        assert_eq!(mesh.triangle_soup(), soup);
    }

    #[test]
    fn binary_round_trip_in_single_precision() {
        let soup = random_soup(20);
        let single: Vec<[Vec3; 3]> = soup
            .iter()
            .map(|t| t.map(|p| p.as_vec3().as_dvec3()))
            .collect();
        let bytes = binary(&soup);
        assert_eq!(bytes.len(), 84 + 50 * 20);
        assert_eq!(
            TriMesh::from_stl_bytes(&bytes).unwrap().triangle_soup(),
            single
        );
        // A binary file whose header starts with "solid" (as some exporters write) is binary.
        let mut solid = bytes.clone();
        solid[..12].copy_from_slice(b"solid  part ");
        assert_eq!(
            TriMesh::from_stl_bytes(&solid).unwrap().triangle_soup(),
            single
        );
        // Trailing bytes are tolerated, even after a "solid" header; truncation is reported.
        for mut padded in [bytes, solid] {
            padded.extend([0u8; 7]);
            let mesh = TriMesh::from_stl_bytes(&padded).unwrap();
            assert_eq!(mesh.triangle_soup(), single);
            let e = TriMesh::from_stl_bytes(&padded[..300])
                .unwrap_err()
                .to_string();
            assert!(e.contains("triangle 4 (from 0): file truncated"), "{e}");
        }
    }

    #[test]
    fn example_file_reads() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/two_triangles_ascii.stl");
        let mesh = TriMesh::from_stl(&path).unwrap();
        assert_eq!((mesh.vertices().len(), mesh.triangles().len()), (4, 2));
        assert!((mesh.area() - 1.0).abs() < 1e-15);
    }

    #[test]
    fn grid_from_files_acts_as_plane() {
        let soup = square_grid(4);
        for (name, bytes) in [
            ("grid_ascii.stl", ascii(&soup)),
            ("grid_binary.stl", binary(&soup)),
        ] {
            let mesh = via_file(name, &bytes);
            assert_eq!(
                (mesh.vertices().len(), mesh.triangles().len()),
                (25, 32),
                "{name}"
            );
            assert_like_plane(&mesh, 4);
        }
    }

    #[test]
    fn malformed_ascii_names_the_line() {
        let good = String::from_utf8(ascii(&square_grid(1))).unwrap();
        let lines: Vec<&str> = good.lines().collect();
        // Line 1 is "solid", 2 "facet normal", 3 "outer loop", 4 to 6 "vertex", 7 "endloop".
        for (i, line, want) in [
            (4, "vertex 1 2 abc", "invalid number 'abc'"),
            (5, "vertex 1 nan 0", "non-finite coordinate 'nan'"),
            (
                6,
                "vertex 1 2",
                "expected 3 coordinates after 'vertex', found 2",
            ),
            (
                6,
                "endloop",
                "expected 'vertex' (corner 3 of 3), found 'endloop'",
            ),
            (7, "vertex 0 0 1", "more than 3 vertices in a facet"),
            (3, "inner loop", "expected 'outer loop', found 'inner loop'"),
        ] {
            let mut l = lines.clone();
            l[i - 1] = line;
            let e = err(l.join("\n").as_bytes());
            assert_eq!(e, format!("bad.stl: line {i}: {want}"));
        }
        let cut = lines[..6].join("\n");
        let e = err(cut.as_bytes());
        assert_eq!(
            e,
            "bad.stl: line 6: file ends inside a facet, expected 'endloop'"
        );
        let e = err(b"solid empty\nendsolid empty\n");
        assert_eq!(e, "bad.stl: the mesh has no triangles");
        let e = err(b"solid empty\n");
        assert!(
            e.starts_with("bad.stl: line 1: file ends after 0 facets"),
            "{e}"
        );
        let e = err(b"solid empty\nendsolid empty\n");
        assert_eq!(e, "bad.stl: the mesh has no triangles");
    }

    #[test]
    fn an_ascii_stl_cut_at_a_facet_boundary_is_refused() {
        let good = String::from_utf8(ascii(&square_grid(2))).unwrap();
        let lines: Vec<&str> = good.lines().collect();
        // Each facet takes 7 lines after "solid": cut after the second facet.
        let cut = lines[..1 + 2 * 7].join("\n");
        let e = err(cut.as_bytes());
        assert_eq!(
            e,
            "bad.stl: line 15: file ends after 2 facets without 'endsolid': it looks truncated \
             (triangles missing)"
        );
    }

    #[test]
    fn malformed_binary_names_the_triangle() {
        let mut bytes = binary(&random_soup(5));
        // Triangle 3, vertex 2, y coordinate: record start + normal (12) + vertex 1 (12) + x (4).
        let at = 84 + 3 * 50 + 12 + 12 + 4;
        bytes[at..at + 4].copy_from_slice(&f32::NAN.to_le_bytes());
        let e = err(&bytes);
        assert!(
            e.starts_with("bad.stl: binary STL, triangle 3 (from 0): vertex 2 has a non-finite"),
            "{e}"
        );
        let e = err(&binary(&random_soup(5))[..84 + 3 * 50 + 20]);
        assert_eq!(e, "bad.stl: binary STL, triangle 3 (from 0): file truncated: the header announces 5 triangles (334 bytes) but the file has 254 bytes");
        assert_eq!(err(b""), "bad.stl: empty file");
        let mut long = binary(&random_soup(5));
        long[80..84].copy_from_slice(&3u32.to_le_bytes());
        assert!(err(&long).contains("room for 2 more"), "{}", err(&long));
        assert!(err(b"\x00\x01garbage").contains("too short for a binary STL"));
        let missing = Path::new("/nonexistent/riprap/missing.stl");
        let e = TriMesh::from_stl(missing).unwrap_err().to_string();
        assert!(
            e.starts_with("/nonexistent/riprap/missing.stl: cannot read"),
            "{e}"
        );
    }
}
