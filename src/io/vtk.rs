//! VTK XML files for ParaView: particles (.vtu), surfaces (.vtp) and uniform
//! grids (.vti).
//!
//! All files use "raw appended" encoding: a small XML header followed by one
//! binary block of little-endian data, each array either prefixed by its byte
//! count or zlib-compressed in blocks ([`Format`], `appended`). Field data is
//! Float32 or Float64 as asked; point coordinates are always Float64. Each
//! file is written atomically, so ParaView never loads a half-written frame.

mod appended;

use super::{invalid_input, write_replacing, xml_escape};
use crate::math::Vec3;
use serde::{Deserialize, Serialize};
use std::fmt::Write as _;
use std::path::Path;

/// Whether the binary data is compressed (`[output] compression`).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Compression {
    /// zlib in 32 KiB blocks, as VTK's `vtkZLibDataCompressor` (ParaView reads it).
    #[default]
    Zlib,
    /// Plain bytes: larger, but readable by simple parsers.
    None,
}

/// The precision of the floating-point field data (`[output] precision`).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Precision {
    /// 4 bytes a value, 7 significant digits: plenty for viewing and plotting.
    #[default]
    Float32,
    /// 8 bytes a value, every f64 exactly.
    Float64,
}

/// How a VTK file stores its binary data.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Format {
    /// Compressed or not.
    pub compression: Compression,
    /// Precision of the float arrays other than the point coordinates.
    pub precision: Precision,
}

impl Format {
    /// Uncompressed Float64: every value exactly, as plain bytes.
    pub const EXACT: Format = Format {
        compression: Compression::None,
        precision: Precision::Float64,
    };

    /// Bytes of one float of field data.
    pub fn float_bytes(self) -> usize {
        match self.precision {
            Precision::Float32 => 4,
            Precision::Float64 => 8,
        }
    }
}

/// The values of one data array: one entry per point or per cell.
#[derive(Debug, Clone, Copy)]
pub enum Values<'a> {
    /// One f64 per item (written as Float64, one component).
    Scalars(&'a [f64]),
    /// One 3-vector per item (Float64, three components), e.g. velocity \[m/s\].
    Vectors(&'a [Vec3]),
    /// One integer per item (Int64), e.g. particle ids or material indices.
    Ints(&'a [i64]),
}

impl Values<'_> {
    /// Number of items (points or cells) the array covers.
    pub fn len(&self) -> usize {
        match self {
            Values::Scalars(v) => v.len(),
            Values::Vectors(v) => v.len(),
            Values::Ints(v) => v.len(),
        }
    }

    /// True when the array has no items.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// A named data array attached to points or cells; the name is what ParaView
/// shows in its colouring menu (put units in it, e.g. `"velocity_m_s"`).
#[derive(Debug, Clone, Copy)]
pub struct Array<'a> {
    /// Array name as shown in ParaView.
    pub name: &'a str,
    /// The values, one per point or cell.
    pub values: Values<'a>,
}

impl<'a> Array<'a> {
    /// A scalar array (Float64).
    pub fn scalars(name: &'a str, values: &'a [f64]) -> Self {
        Array {
            name,
            values: Values::Scalars(values),
        }
    }

    /// A 3-vector array (Float64, three components).
    pub fn vectors(name: &'a str, values: &'a [Vec3]) -> Self {
        Array {
            name,
            values: Values::Vectors(values),
        }
    }

    /// An integer array (Int64).
    pub fn ints(name: &'a str, values: &'a [i64]) -> Self {
        Array {
            name,
            values: Values::Ints(values),
        }
    }
}

/// VTK cell type id of a single-point cell.
const VTK_VERTEX: u8 = 1;

/// Writes particles as an UnstructuredGrid (.vtu): one point per particle at
/// `positions` \[m\], one VTK_VERTEX cell each, and `point_data` arrays with one
/// value per particle. Spheres: ParaView's Point Gaussian or Glyph filter,
/// scaled by a radius array, shows them.
///
/// Errors with `InvalidInput`, naming the array, when an array's length is not
/// `positions.len()`. An empty `positions` gives a valid file with no points.
pub fn write_points(
    path: &Path,
    positions: &[Vec3],
    point_data: &[Array],
    format: Format,
) -> std::io::Result<()> {
    let n = positions.len();
    check_lengths(point_data, n, "points")?;
    let mut f = VtkFile::new("UnstructuredGrid", "", format);
    let _ = writeln!(
        f.xml,
        r#"    <Piece NumberOfPoints="{n}" NumberOfCells="{n}">"#
    );
    f.attributes("PointData", point_data);
    f.xml.push_str("      <CellData>\n      </CellData>\n");
    f.points(positions);
    f.xml.push_str("      <Cells>\n");
    f.array_i64("connectivity", 1, 0..n as i64);
    f.array_i64("offsets", 1, 1..=n as i64);
    f.array("UInt8", Some("types"), 1, |b| b.resize(n, VTK_VERTEX));
    f.xml.push_str("      </Cells>\n    </Piece>\n");
    f.finish(path)
}

/// Writes a triangulated surface as PolyData (.vtp): `vertices` \[m\],
/// `triangles` as indices into `vertices`, and `cell_data` arrays with one
/// value per triangle (e.g. wall force or wear).
///
/// Errors with `InvalidInput` when an array's length is not
/// `triangles.len()` (naming the array) or a triangle refers to a vertex that
/// does not exist; ParaView would crash or draw garbage on such a file.
pub fn write_surface(
    path: &Path,
    vertices: &[Vec3],
    triangles: &[[u32; 3]],
    cell_data: &[Array],
    format: Format,
) -> std::io::Result<()> {
    check_lengths(cell_data, triangles.len(), "triangles")?;
    if let Some((i, t)) = triangles
        .iter()
        .enumerate()
        .find(|(_, t)| t.iter().any(|&v| v as usize >= vertices.len()))
    {
        return Err(invalid_input(format!(
            "triangle {i} {t:?} refers to a vertex >= the vertex count {}",
            vertices.len()
        )));
    }
    let (nv, nt) = (vertices.len(), triangles.len());
    let mut f = VtkFile::new("PolyData", "", format);
    let _ = writeln!(
        f.xml,
        r#"    <Piece NumberOfPoints="{nv}" NumberOfVerts="0" NumberOfLines="0" NumberOfStrips="0" NumberOfPolys="{nt}">"#
    );
    f.xml.push_str("      <PointData>\n      </PointData>\n");
    f.attributes("CellData", cell_data);
    f.points(vertices);
    f.xml.push_str("      <Polys>\n");
    let conn = triangles.iter().flat_map(|t| t.map(i64::from));
    f.array_i64("connectivity", 1, conn);
    f.array_i64("offsets", 1, (1..=nt as i64).map(|i| 3 * i));
    f.xml.push_str("      </Polys>\n    </Piece>\n");
    f.finish(path)
}

/// Writes a uniform grid as ImageData (.vti) with `n = [nx, ny, nz]` cells,
/// the grid's lowest corner at `origin` \[m\] and cell size `spacing` \[m\].
/// `cell_data` arrays hold one value per cell, x fastest, then y, then z
/// (index `i + nx * (j + ny * k)`).
///
/// Errors with `InvalidInput` when an array's length is not `nx * ny * nz`
/// (naming the array), or when `origin` or `spacing` is not finite.
pub fn write_image(
    path: &Path,
    n: [usize; 3],
    origin: Vec3,
    spacing: Vec3,
    cell_data: &[Array],
    format: Format,
) -> std::io::Result<()> {
    if !origin.is_finite() || !spacing.is_finite() {
        return Err(invalid_input(format!(
            "image origin {origin} and spacing {spacing} must be finite"
        )));
    }
    let cells = n[0]
        .checked_mul(n[1])
        .and_then(|c| c.checked_mul(n[2]))
        .ok_or_else(|| invalid_input(format!("image size {n:?} overflows")))?;
    check_lengths(cell_data, cells, "cells")?;
    // Extents count points, so n cells span points 0..=n.
    let extent = format!("0 {} 0 {} 0 {}", n[0], n[1], n[2]);
    let grid = format!(
        r#"WholeExtent="{extent}" Origin="{} {} {}" Spacing="{} {} {}""#,
        origin.x, origin.y, origin.z, spacing.x, spacing.y, spacing.z
    );
    let mut f = VtkFile::new("ImageData", &grid, format);
    let _ = writeln!(f.xml, r#"    <Piece Extent="{extent}">"#);
    f.xml.push_str("      <PointData>\n      </PointData>\n");
    f.attributes("CellData", cell_data);
    f.xml.push_str("    </Piece>\n");
    f.finish(path)
}

/// Errors unless every array has exactly `n` items.
fn check_lengths(arrays: &[Array], n: usize, what: &str) -> std::io::Result<()> {
    for a in arrays {
        if a.values.len() != n {
            return Err(invalid_input(format!(
                "VTK array '{}' has {} values but there are {n} {what}",
                a.name,
                a.values.len()
            )));
        }
    }
    Ok(())
}

/// A VTK XML file under construction: the header text and the appended
/// binary block that the header's `offset` attributes point into.
struct VtkFile {
    xml: String,
    data: Vec<u8>,
    kind: &'static str,
    format: Format,
    /// One array's bytes before they are appended (compressed or not).
    raw: Vec<u8>,
}

impl VtkFile {
    /// Starts a file of dataset type `kind`; `attrs` go on the dataset element.
    fn new(kind: &'static str, attrs: &str, format: Format) -> Self {
        let mut xml = String::from("<?xml version=\"1.0\"?>\n");
        let compressor = match format.compression {
            Compression::Zlib => r#" compressor="vtkZLibDataCompressor""#,
            Compression::None => "",
        };
        let _ = writeln!(
            xml,
            r#"<VTKFile type="{kind}" version="1.0" byte_order="LittleEndian" header_type="UInt64"{compressor}>"#
        );
        let sep = if attrs.is_empty() { "" } else { " " };
        let _ = writeln!(xml, "  <{kind}{sep}{attrs}>");
        VtkFile {
            xml,
            data: Vec::new(),
            kind,
            format,
            raw: Vec::new(),
        }
    }

    /// Declares a DataArray of VTK type `ty` at the current end of the binary
    /// block and appends the bytes that `fill` writes, in the file's format.
    fn array(
        &mut self,
        ty: &str,
        name: Option<&str>,
        comps: usize,
        fill: impl FnOnce(&mut Vec<u8>),
    ) {
        let name = name
            .map(|n| format!(r#" Name="{}""#, xml_escape(n)))
            .unwrap_or_default();
        let _ = writeln!(
            self.xml,
            r#"        <DataArray type="{ty}"{name} NumberOfComponents="{comps}" format="appended" offset="{}"/>"#,
            self.data.len()
        );
        self.raw.clear();
        fill(&mut self.raw);
        match self.format.compression {
            Compression::None => appended::append_raw(&self.raw, &mut self.data),
            Compression::Zlib => appended::append_zlib(&self.raw, &mut self.data),
        }
    }

    /// A float array, Float32 or Float64 by `precision`.
    fn array_float(
        &mut self,
        name: Option<&str>,
        comps: usize,
        precision: Precision,
        v: impl Iterator<Item = f64>,
    ) {
        match precision {
            Precision::Float64 => self.array("Float64", name, comps, |b| {
                v.for_each(|x| b.extend_from_slice(&x.to_le_bytes()))
            }),
            // Rounded to nearest: the closest Float32 to each value.
            Precision::Float32 => self.array("Float32", name, comps, |b| {
                v.for_each(|x| b.extend_from_slice(&(x as f32).to_le_bytes()))
            }),
        }
    }

    fn array_i64(&mut self, name: &str, comps: usize, v: impl Iterator<Item = i64>) {
        self.array("Int64", Some(name), comps, |b| {
            v.for_each(|x| b.extend_from_slice(&x.to_le_bytes()))
        });
    }

    /// Writes a `<PointData>` or `<CellData>` section holding `arrays`.
    fn attributes(&mut self, section: &str, arrays: &[Array]) {
        let _ = writeln!(self.xml, "      <{section}>");
        let p = self.format.precision;
        for a in arrays {
            let name = Some(a.name);
            match a.values {
                Values::Scalars(v) => self.array_float(name, 1, p, v.iter().copied()),
                Values::Vectors(v) => self.array_float(name, 3, p, flatten(v)),
                Values::Ints(v) => self.array_i64(a.name, 1, v.iter().copied()),
            }
        }
        let _ = writeln!(self.xml, "      </{section}>");
    }

    /// Writes the `<Points>` section, always in Float64: positions keep every
    /// digit (a 1e-7 relative error is 10 µm at 100 m, the size of contact
    /// overlaps), and they are a small part of a file.
    fn points(&mut self, positions: &[Vec3]) {
        self.xml.push_str("      <Points>\n");
        self.array_float(Some("Points"), 3, Precision::Float64, flatten(positions));
        self.xml.push_str("      </Points>\n");
    }

    /// Closes the XML, appends the binary block and writes the file atomically.
    fn finish(mut self, path: &Path) -> std::io::Result<()> {
        let _ = write!(
            self.xml,
            "  </{}>\n  <AppendedData encoding=\"raw\">\n   _",
            self.kind
        );
        let mut bytes = self.xml.into_bytes();
        bytes.reserve(self.data.len() + 40);
        bytes.extend_from_slice(&self.data);
        bytes.extend_from_slice(b"\n  </AppendedData>\n</VTKFile>\n");
        write_replacing(path, &bytes)
    }
}

fn flatten(v: &[Vec3]) -> impl Iterator<Item = f64> + '_ {
    v.iter().flat_map(|p| p.to_array())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::test_dir;
    use std::collections::HashMap;
    use std::io::ErrorKind::InvalidInput;

    /// A file read back: its XML header, and each DataArray's attributes
    /// with the payload bytes its offset points to.
    struct Parsed {
        header: String,
        arrays: Vec<(HashMap<String, String>, Vec<u8>)>,
    }

    impl Parsed {
        /// Reads a file of either compression, as a VTK reader does.
        fn read(path: &Path) -> Self {
            let bytes = std::fs::read(path).unwrap();
            let marker = b"<AppendedData encoding=\"raw\">\n   _";
            let pos = bytes.windows(marker.len()).position(|w| w == marker);
            let pos = pos.unwrap();
            let data = &bytes[pos + marker.len()..];
            let header = String::from_utf8(bytes[..pos].to_vec()).unwrap();
            assert!(bytes.ends_with(b"\n  </AppendedData>\n</VTKFile>\n"));
            assert!(header.contains(r#"header_type="UInt64""#));
            let compressed = header.contains(r#"compressor="vtkZLibDataCompressor""#);
            check_nesting(&header);
            let mut arrays = Vec::new();
            for tag in header.split("<DataArray ").skip(1) {
                let mut attrs = HashMap::new();
                for kv in tag[..tag.find("/>").unwrap()].split("\" ") {
                    let (k, v) = kv.split_once("=\"").unwrap();
                    attrs.insert(k.to_string(), v.trim_end_matches('"').to_string());
                }
                let off: usize = attrs["offset"].parse().unwrap();
                arrays.push((attrs, appended::read(data, off, compressed)));
            }
            Parsed { header, arrays }
        }

        /// The array called `name`, checked to be of VTK type `ty`.
        fn bytes(&self, name: &str, ty: &str) -> &[u8] {
            let (attrs, payload) = self.arrays.iter().find(|a| a.0["Name"] == name).unwrap();
            assert_eq!(attrs["type"], ty, "{name}");
            payload
        }

        fn f32s(&self, name: &str) -> Vec<f32> {
            let words = self.bytes(name, "Float32").chunks_exact(4);
            words
                .map(|c| f32::from_le_bytes(c.try_into().unwrap()))
                .collect()
        }

        fn f64s(&self, name: &str) -> Vec<f64> {
            let words = self.bytes(name, "Float64").chunks_exact(8);
            words
                .map(|c| f64::from_le_bytes(c.try_into().unwrap()))
                .collect()
        }

        fn i64s(&self, name: &str) -> Vec<i64> {
            let words = self.bytes(name, "Int64").chunks_exact(8);
            words
                .map(|c| i64::from_le_bytes(c.try_into().unwrap()))
                .collect()
        }
    }

    /// Every opened element is closed in order (self-closing ones excepted);
    /// only VTKFile is still open where AppendedData begins.
    fn check_nesting(header: &str) {
        let mut stack = Vec::new();
        for tag in header.split('<').skip(1) {
            let tag = &tag[..tag.find('>').unwrap()];
            if let Some(closed) = tag.strip_prefix('/') {
                assert_eq!(stack.pop(), Some(closed), "in {header}");
            } else if !tag.starts_with('?') && !tag.ends_with('/') {
                stack.push(tag.split(' ').next().unwrap());
            }
        }
        assert_eq!(stack, ["VTKFile"], "in {header}");
    }

    fn flat(v: &[Vec3]) -> Vec<f64> {
        flatten(v).collect()
    }

    #[test]
    fn points_round_trip() {
        let dir = test_dir("vtk_points");
        let pos = [
            Vec3::new(0.1, -2.0, 3.5e-7),
            Vec3::new(1.0 / 3.0, 5.0, -0.0),
        ];
        let vel = [Vec3::X, Vec3::new(-1.0, 2.0, f64::MAX)];
        let arrays = [
            Array::scalars("radius", &[0.01, 0.0125]),
            Array::vectors("velocity <m/s>", &vel),
            Array::ints("id", &[7, -3]),
        ];
        write_points(&dir.join("p.vtu"), &pos, &arrays, Format::EXACT).unwrap();
        let f = Parsed::read(&dir.join("p.vtu"));
        assert!(f.header.contains(r#"type="UnstructuredGrid""#));
        assert!(f.header.contains(r#"NumberOfPoints="2" NumberOfCells="2""#));
        assert_eq!(f.f64s("Points"), [0.1, -2.0, 3.5e-7, 1.0 / 3.0, 5.0, -0.0]);
        assert_eq!(f.f64s("radius"), [0.01, 0.0125]);
        let vel_name = "velocity &lt;m/s&gt;";
        assert_eq!(f.f64s(vel_name), flat(&vel));
        let vel_attrs = &f.arrays.iter().find(|a| a.0["Name"] == vel_name).unwrap().0;
        assert_eq!(vel_attrs["NumberOfComponents"], "3");
        assert_eq!(f.i64s("id"), [7, -3]);
        assert_eq!(f.i64s("connectivity"), [0, 1]);
        assert_eq!(f.i64s("offsets"), [1, 2]);
        assert_eq!(f.bytes("types", "UInt8"), [VTK_VERTEX; 2]);
    }

    #[test]
    fn empty_points_still_valid() {
        let dir = test_dir("vtk_empty");
        let arrays = [Array::scalars("radius", &[])];
        write_points(&dir.join("p.vtu"), &[], &arrays, Format::EXACT).unwrap();
        let f = Parsed::read(&dir.join("p.vtu"));
        assert!(f.header.contains(r#"NumberOfPoints="0""#));
        assert_eq!(f.arrays.len(), 5);
        assert!(f.arrays.iter().all(|a| a.1.is_empty()));
    }

    #[test]
    fn bad_input_is_invalid_input_and_writes_nothing() {
        const F: Format = Format::EXACT;
        let dir = test_dir("vtk_bad");
        let one = [Array::scalars("radius", &[1.0])];
        let err = write_points(&dir.join("p.vtu"), &[Vec3::ZERO; 2], &one, F).unwrap_err();
        assert_eq!(err.kind(), InvalidInput);
        assert!(err.to_string().contains("radius"), "{err}");
        let bad_tri = write_surface(&dir.join("s.vtp"), &[Vec3::ZERO; 3], &[[0, 1, 3]], &[], F);
        assert_eq!(bad_tri.unwrap_err().kind(), InvalidInput);
        let (o, h) = (Vec3::ZERO, Vec3::ONE);
        let err = write_image(&dir.join("g.vti"), [2, 2, 2], o, h, &one, F).unwrap_err();
        assert!(err.to_string().contains("radius"), "{err}");
        let huge = write_image(&dir.join("g.vti"), [usize::MAX, 2, 1], o, h, &[], F);
        assert_eq!(huge.unwrap_err().kind(), InvalidInput);
        let nan = write_image(&dir.join("g.vti"), [1, 1, 1], o, h * f64::NAN, &[], F);
        assert_eq!(nan.unwrap_err().kind(), InvalidInput);
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
    }

    #[test]
    fn surface_round_trip() {
        let dir = test_dir("vtk_surface");
        let v = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::new(1.0, 1.0, 0.25)];
        let force = [Vec3::new(0.0, 0.0, -9.81), Vec3::new(1e-300, 0.0, 2.5)];
        let arrays = [
            Array::vectors("force", &force),
            Array::scalars("wear", &[0.5, 1.5]),
        ];
        let tri = [[0, 1, 2], [1, 3, 2]];
        write_surface(&dir.join("s.vtp"), &v, &tri, &arrays, Format::EXACT).unwrap();
        let f = Parsed::read(&dir.join("s.vtp"));
        assert!(f.header.contains(r#"NumberOfPoints="4""#));
        assert!(f.header.contains(r#"NumberOfPolys="2""#));
        assert_eq!(f.f64s("Points"), flat(&v));
        assert_eq!(f.i64s("connectivity"), [0, 1, 2, 1, 3, 2]);
        assert_eq!(f.i64s("offsets"), [3, 6]);
        assert_eq!(f.f64s("force"), flat(&force));
        assert_eq!(f.f64s("wear"), [0.5, 1.5]);
    }

    #[test]
    fn image_round_trip() {
        let dir = test_dir("vtk_image");
        let p: Vec<f64> = (0..6).map(|i| i as f64 * 0.1).collect();
        let u: Vec<Vec3> = (0..6).map(|i| Vec3::splat(i as f64)).collect();
        let arrays = [Array::scalars("p", &p), Array::vectors("u", &u)];
        let (origin, spacing) = (Vec3::new(-1.0, 0.0, 0.5), Vec3::new(0.1, 0.2, 0.3));
        write_image(
            &dir.join("g.vti"),
            [3, 2, 1],
            origin,
            spacing,
            &arrays,
            Format::EXACT,
        )
        .unwrap();
        let f = Parsed::read(&dir.join("g.vti"));
        let grid = r#"WholeExtent="0 3 0 2 0 1" Origin="-1 0 0.5" Spacing="0.1 0.2 0.3""#;
        assert!(f.header.contains(grid), "{}", f.header);
        assert!(f.header.contains(r#"<Piece Extent="0 3 0 2 0 1">"#));
        assert_eq!(f.f64s("p"), p);
        assert_eq!(f.f64s("u"), flat(&u));
    }

    /// The default-run output of 292 MB: flow images and sphere files now default to zlib and
    /// Float32 field data; every kind of file reads back to the values written (Float32: the
    /// nearest f32), positions exactly, in every format.
    #[test]
    fn compressed_float32_output_reads_back_to_the_values_written() {
        assert_eq!(
            Format::default(),
            Format {
                compression: Compression::Zlib,
                precision: Precision::Float32
            }
        );
        let dir = test_dir("vtk_formats");
        // Over two zlib blocks of vectors, so the block header and the partial block count.
        let n = 1500;
        let pos: Vec<Vec3> = (0..n)
            .map(|i| Vec3::new(i as f64 / 7.0, (i as f64).sin(), 1e3 + 1e-9 * i as f64))
            .collect();
        let vel: Vec<Vec3> = pos.iter().map(|p| *p * 0.1 - Vec3::Y).collect();
        let d: Vec<f64> = (0..n).map(|i| 0.01 + 1e-5 * i as f64).collect();
        let ids: Vec<i64> = (0..n as i64).map(|i| 3 * i - 7).collect();
        let tri: Vec<[u32; 3]> = (0..n as u32 - 2).map(|i| [i, i + 1, i + 2]).collect();
        let wear: Vec<f64> = (0..tri.len()).map(|i| i as f64 * 0.25).collect();
        for compression in [Compression::Zlib, Compression::None] {
            for precision in [Precision::Float32, Precision::Float64] {
                let fmt = Format {
                    compression,
                    precision,
                };
                let arrays = [
                    Array::ints("id", &ids),
                    Array::scalars("diameter", &d),
                    Array::vectors("velocity", &vel),
                ];
                write_points(&dir.join("p.vtu"), &pos, &arrays, fmt).unwrap();
                let wall = [Array::scalars("wear", &wear)];
                write_surface(&dir.join("s.vtp"), &pos, &tri, &wall, fmt).unwrap();
                let (o, h) = (Vec3::new(-1.0, 0.0, 0.5), Vec3::splat(0.1));
                write_image(&dir.join("g.vti"), [10, 15, 10], o, h, &arrays[1..], fmt).unwrap();
                let (p, s, g) = (
                    Parsed::read(&dir.join("p.vtu")),
                    Parsed::read(&dir.join("s.vtp")),
                    Parsed::read(&dir.join("g.vti")),
                );
                let zlib = compression == Compression::Zlib;
                for f in [&p, &s, &g] {
                    assert_eq!(f.header.contains("vtkZLibDataCompressor"), zlib);
                }
                assert_eq!(p.f64s("Points"), flat(&pos));
                assert_eq!(s.f64s("Points"), flat(&pos));
                assert_eq!(p.i64s("id"), ids);
                assert_eq!(p.i64s("offsets"), (1..=n as i64).collect::<Vec<_>>());
                assert_eq!(p.bytes("types", "UInt8"), vec![VTK_VERTEX; n]);
                assert_eq!(s.i64s("connectivity").len(), 3 * tri.len());
                let f32s = |v: &[f64]| v.iter().map(|&x| x as f32).collect::<Vec<_>>();
                for f in [&p, &g] {
                    if precision == Precision::Float32 {
                        assert_eq!(f.f32s("diameter"), f32s(&d));
                        assert_eq!(f.f32s("velocity"), f32s(&flat(&vel)));
                    } else {
                        assert_eq!(f.f64s("diameter"), d);
                        assert_eq!(f.f64s("velocity"), flat(&vel));
                    }
                }
                if precision == Precision::Float32 {
                    assert_eq!(s.f32s("wear"), f32s(&wear));
                } else {
                    assert_eq!(s.f64s("wear"), wear);
                }
            }
        }
    }
}
