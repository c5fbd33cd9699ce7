//! The bed and the structures on it: bathymetry and topography from an ESRI ASCII grid or a
//! CSV of points on a regular grid, sampled at the cell centres, and structures (quay walls,
//! buildings) as polygons that make cells solid or raise their bed.
//!
//! **ESRI ASCII grid** (the `.asc` format of ArcGIS, GDAL's "AAIGrid"): a header of
//! `ncols`, `nrows`, `xllcorner` or `xllcenter`, `yllcorner` or `yllcenter`, `cellsize` (or
//! `dx` and `dy`, as GDAL writes non-square cells) and optionally `NODATA_value`, one per
//! line, keys in any case; then nrows rows of ncols values, the northernmost row first. A
//! corner origin is the lower-left corner of the lower-left cell; a centre origin is its
//! centre. The values are the elevations at the cell centres [m, positive up].
//!
//! **CSV of points**: lines `x,y,z` [m] (a header line and blank lines allowed), one per node
//! of a regular grid, in any order. The distinct x and y give the grid; each node must appear
//! once and the spacing must be uniform (to a millionth of a cell).
//!
//! **Sampling**: the bed of a cell is the bilinear interpolation of the raster's values at
//! the cell's centre, the raster's nodes being its cell centres; beyond the outermost nodes
//! the edge values hold. A grid that coincides with the raster takes its values as they are.
//!
//! **Structures**: a polygon (vertices [m], in either order; the even-odd rule) covers the
//! cells whose centre lies inside it. A solid structure turns them into walls; one with a
//! `top` [m] raises their bed to it (a quay or a breakwater that water may overtop).

/// Values on a regular grid of nodes: value (i, j) at x₀ + i Δx, y₀ + j Δy.
#[derive(Clone, Debug, PartialEq)]
pub struct Raster {
    /// Nodes along x.
    pub nx: usize,
    /// Nodes along y.
    pub ny: usize,
    /// The first node (x₀, y₀) [m]: the centre of the lower-left cell.
    pub origin: [f64; 2],
    /// Node spacing (Δx, Δy) [m].
    pub spacing: [f64; 2],
    /// Values, x fastest, from the southern row up.
    pub values: Vec<f64>,
}

impl Raster {
    /// The value at (x, y) [m] by bilinear interpolation, edge values beyond the nodes.
    pub fn sample(&self, x: f64, y: f64) -> f64 {
        let fx = ((x - self.origin[0]) / self.spacing[0]).clamp(0.0, (self.nx - 1) as f64);
        let fy = ((y - self.origin[1]) / self.spacing[1]).clamp(0.0, (self.ny - 1) as f64);
        let (i0, j0) = (fx.floor() as usize, fy.floor() as usize);
        let (i1, j1) = ((i0 + 1).min(self.nx - 1), (j0 + 1).min(self.ny - 1));
        let (tx, ty) = (fx - i0 as f64, fy - j0 as f64);
        let v = |i: usize, j: usize| self.values[i + self.nx * j];
        if tx == 0.0 && ty == 0.0 {
            return v(i0, j0);
        }
        (1.0 - ty) * ((1.0 - tx) * v(i0, j0) + tx * v(i1, j0))
            + ty * ((1.0 - tx) * v(i0, j1) + tx * v(i1, j1))
    }

    /// The lower-left and upper-right corners of the cells the nodes are centres of [m].
    pub fn extent(&self) -> ([f64; 2], [f64; 2]) {
        let [x0, y0] = self.origin;
        let [dx, dy] = self.spacing;
        (
            [x0 - 0.5 * dx, y0 - 0.5 * dy],
            [
                x0 + (self.nx as f64 - 0.5) * dx,
                y0 + (self.ny as f64 - 0.5) * dy,
            ],
        )
    }
}

/// Reads an ESRI ASCII grid; the error names the line.
pub fn read_esri_ascii(text: &str) -> Result<Raster, String> {
    let mut header: Vec<(String, f64)> = Vec::new();
    let mut lines = text.lines().enumerate().peekable();
    while let Some(&(n, line)) = lines.peek() {
        let mut words = line.split_whitespace();
        let Some(key) = words.next() else {
            lines.next();
            continue;
        };
        if !key.starts_with(|c: char| c.is_ascii_alphabetic()) {
            break;
        }
        let value = words
            .next()
            .and_then(|v| v.parse::<f64>().ok())
            .ok_or_else(|| format!("line {}: `{key}` needs a number", n + 1))?;
        header.push((key.to_ascii_lowercase(), value));
        lines.next();
    }
    let get = |k: &str| header.iter().find(|(h, _)| h == k).map(|(_, v)| *v);
    let need = |k: &str| get(k).ok_or_else(|| format!("the header lacks `{k}`"));
    let ncols = need("ncols")?;
    let nrows = need("nrows")?;
    if !(ncols >= 2.0 && nrows >= 2.0 && ncols.fract() == 0.0 && nrows.fract() == 0.0) {
        return Err(format!(
            "ncols {ncols} and nrows {nrows} must be whole numbers of at least 2"
        ));
    }
    let (nx, ny) = (ncols as usize, nrows as usize);
    let (dx, dy) = match (get("cellsize"), get("dx"), get("dy")) {
        (Some(c), _, _) => (c, c),
        (None, Some(dx), Some(dy)) => (dx, dy),
        _ => return Err("the header lacks `cellsize` (or `dx` and `dy`)".into()),
    };
    if !(dx > 0.0 && dy > 0.0) {
        return Err(format!("the cell size {dx} × {dy} must be positive"));
    }
    let x0 = match (get("xllcenter"), get("xllcorner")) {
        (Some(c), _) => c,
        (None, Some(c)) => c + 0.5 * dx,
        _ => return Err("the header lacks `xllcorner` or `xllcenter`".into()),
    };
    let y0 = match (get("yllcenter"), get("yllcorner")) {
        (Some(c), _) => c,
        (None, Some(c)) => c + 0.5 * dy,
        _ => return Err("the header lacks `yllcorner` or `yllcenter`".into()),
    };
    let nodata = get("nodata_value");
    let mut rows: Vec<Vec<f64>> = Vec::with_capacity(ny);
    let mut pending: Vec<f64> = Vec::with_capacity(nx);
    for (n, line) in lines {
        for w in line.split_whitespace() {
            let v: f64 = w
                .parse()
                .map_err(|_| format!("line {}: `{w}` is not a number", n + 1))?;
            if nodata == Some(v) {
                return Err(format!(
                    "line {}: a NODATA value ({v}) in row {} from the top: give every cell of \
                     the grid an elevation (mark structures with [[shallow.structure]])",
                    n + 1,
                    rows.len() + 1
                ));
            }
            if !v.is_finite() {
                return Err(format!("line {}: `{w}` is not a finite number", n + 1));
            }
            pending.push(v);
            if pending.len() == nx {
                rows.push(std::mem::replace(&mut pending, Vec::with_capacity(nx)));
            }
        }
    }
    if rows.len() != ny || !pending.is_empty() {
        return Err(format!(
            "{} values for {nrows} rows of {ncols}",
            rows.len() * nx + pending.len()
        ));
    }
    let values = rows.into_iter().rev().flatten().collect();
    Ok(Raster {
        nx,
        ny,
        origin: [x0, y0],
        spacing: [dx, dy],
        values,
    })
}

/// Reads a CSV of points `x,y,z` on a regular grid; the error names the line.
pub fn read_xyz_csv(text: &str) -> Result<Raster, String> {
    let mut points = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        let parsed: Option<Vec<f64>> = fields.iter().map(|f| f.parse().ok()).collect();
        match parsed {
            Some(v) if v.len() == 3 && v.iter().all(|x| x.is_finite()) => {
                points.push([v[0], v[1], v[2]])
            }
            _ if points.is_empty() && n == 0 => continue, // a header
            _ => return Err(format!("line {}: expected `x,y,z`, found `{line}`", n + 1)),
        }
    }
    let axis = |a: usize| -> Result<(f64, f64, usize), String> {
        let mut v: Vec<f64> = points.iter().map(|p| p[a]).collect();
        v.sort_by(f64::total_cmp);
        v.dedup();
        if v.len() < 2 {
            return Err(format!(
                "the points need at least two distinct {}",
                ["x", "y"][a]
            ));
        }
        let d = (v[v.len() - 1] - v[0]) / (v.len() - 1) as f64;
        for (k, x) in v.iter().enumerate() {
            if (x - (v[0] + k as f64 * d)).abs() > 1e-6 * d {
                return Err(format!(
                    "the {} of the points are not equally spaced: {x} is off the grid of \
                     spacing {d} from {}",
                    ["x", "y"][a],
                    v[0]
                ));
            }
        }
        Ok((v[0], d, v.len()))
    };
    let (x0, dx, nx) = axis(0)?;
    let (y0, dy, ny) = axis(1)?;
    if points.len() != nx * ny {
        return Err(format!(
            "{} points for a grid of {nx} × {ny} nodes",
            points.len()
        ));
    }
    let mut values = vec![f64::NAN; nx * ny];
    for p in &points {
        let i = ((p[0] - x0) / dx).round() as usize;
        let j = ((p[1] - y0) / dy).round() as usize;
        let v = &mut values[i + nx * j];
        if !v.is_nan() {
            return Err(format!("the node ({}, {}) appears twice", p[0], p[1]));
        }
        *v = p[2];
    }
    Ok(Raster {
        nx,
        ny,
        origin: [x0, y0],
        spacing: [dx, dy],
        values,
    })
}

/// Whether (x, y) lies inside the polygon `vertices` (even-odd rule).
pub fn inside_polygon(vertices: &[[f64; 2]], x: f64, y: f64) -> bool {
    let mut inside = false;
    let n = vertices.len();
    for k in 0..n {
        let (a, b) = (vertices[k], vertices[(k + n - 1) % n]);
        if (a[1] > y) != (b[1] > y) {
            let xc = a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
            if x < xc {
                inside = !inside;
            }
        }
    }
    inside
}

/// What makes `vertices` no simple polygon, if anything: two consecutive vertices at the same
/// point, two edges that are not neighbours touching or crossing (checked pair by pair: O(n²),
/// for the few vertices of a building), or no area (the shoelace formula). The edges' orientations
/// are compared by the signs of cross products (exact for coincident and crossing edges in
/// general position; collinear touching edges are found by their overlap).
pub fn polygon_defect(vertices: &[[f64; 2]]) -> Option<String> {
    let n = vertices.len();
    if n < 3 {
        return Some(format!("a polygon needs at least 3 vertices, not {n}"));
    }
    let edge = |k: usize| (vertices[k], vertices[(k + 1) % n]);
    for k in 0..n {
        let (a, b) = edge(k);
        if a == b {
            return Some(format!(
                "vertices {k} and {} (from 0) are the same point {a:?}",
                (k + 1) % n
            ));
        }
    }
    let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let on = |p: [f64; 2], a: [f64; 2], b: [f64; 2]| {
        cross(a, b, p) == 0.0
            && p[0] >= a[0].min(b[0])
            && p[0] <= a[0].max(b[0])
            && p[1] >= a[1].min(b[1])
            && p[1] <= a[1].max(b[1])
    };
    for i in 0..n {
        for j in i + 2..n {
            if i == 0 && j == n - 1 {
                continue; // neighbours through the closing edge
            }
            let ((a, b), (c, d)) = (edge(i), edge(j));
            let (d1, d2) = (cross(c, d, a), cross(c, d, b));
            let (d3, d4) = (cross(a, b, c), cross(a, b, d));
            let proper = (d1 > 0.0) != (d2 > 0.0)
                && (d3 > 0.0) != (d4 > 0.0)
                && d1 != 0.0
                && d2 != 0.0
                && d3 != 0.0
                && d4 != 0.0;
            if proper || on(a, c, d) || on(b, c, d) || on(c, a, b) || on(d, a, b) {
                return Some(format!(
                    "edges {i} and {j} (from 0: vertex k to k + 1) cross or touch: the polygon \
                     must not cross itself"
                ));
            }
        }
    }
    let area: f64 = (0..n)
        .map(|k| {
            let (a, b) = edge(k);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum();
    if area == 0.0 {
        return Some("the polygon has no area (its vertices lie on a line)".into());
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_esri_grid_is_read_from_the_top_row_down() {
        let text = "ncols 3\nNROWS 2\nxllcorner 100\nyllcorner 200\ncellsize 10\n\
                    NODATA_value -9999\n1 2 3\n4 5 6\n";
        let r = read_esri_ascii(text).unwrap();
        assert_eq!((r.nx, r.ny), (3, 2));
        assert_eq!(r.origin, [105.0, 205.0]);
        // The southern row (the last in the file) comes first.
        assert_eq!(r.values, vec![4.0, 5.0, 6.0, 1.0, 2.0, 3.0]);
        assert_eq!(r.sample(105.0, 205.0), 4.0);
        assert_eq!(r.sample(110.0, 210.0), 0.25 * (4.0 + 5.0 + 1.0 + 2.0));
        // Beyond the nodes, the edge.
        assert_eq!(r.sample(0.0, 0.0), 4.0);
        assert_eq!(r.extent(), ([100.0, 200.0], [130.0, 220.0]));
        let e = read_esri_ascii(&text.replace("4 5 6", "4 -9999 6")).unwrap_err();
        assert!(e.contains("line 8") && e.contains("NODATA"), "{e}");
        let e = read_esri_ascii(&text.replace("4 5 6\n", "4 5\n")).unwrap_err();
        assert!(e.contains("5 values for 2 rows of 3"), "{e}");
        let e = read_esri_ascii(&text.replace("cellsize 10\n", "")).unwrap_err();
        assert!(e.contains("cellsize"), "{e}");
    }

    #[test]
    fn a_csv_of_points_in_any_order_makes_the_same_raster() {
        let text = "x,y,z\n0,0,1\n10,0,2\n0,5,3\n10,5,4\n0,10,5\n10,10,6\n";
        let r = read_xyz_csv(text).unwrap();
        assert_eq!((r.nx, r.ny, r.spacing), (2, 3, [10.0, 5.0]));
        assert_eq!(r.values, vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        let shuffled = "10,10,6\n0,0,1\n0,5,3\n10,0,2\n0,10,5\n10,5,4\n";
        assert_eq!(read_xyz_csv(shuffled).unwrap(), r);
        let e = read_xyz_csv("0,0,1\n10,0,2\n0,5,3\n").unwrap_err();
        assert!(e.contains("3 points for a grid of 2 × 2"), "{e}");
        let e = read_xyz_csv("0,0,1\n10,0,x\n").unwrap_err();
        assert!(e.contains("line 2"), "{e}");
    }

    #[test]
    fn the_even_odd_rule_finds_the_inside_of_a_concave_polygon() {
        // An L shape.
        let l = [
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [1.0, 1.0],
            [1.0, 2.0],
            [0.0, 2.0],
        ];
        assert!(inside_polygon(&l, 0.5, 0.5));
        assert!(inside_polygon(&l, 1.5, 0.5));
        assert!(inside_polygon(&l, 0.5, 1.5));
        assert!(!inside_polygon(&l, 1.5, 1.5));
        assert!(!inside_polygon(&l, -0.1, 0.5));
        assert_eq!(polygon_defect(&l), None);
    }

    #[test]
    fn polygons_that_cross_themselves_or_have_no_area_are_named() {
        let bow_tie = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]];
        let e = polygon_defect(&bow_tie).unwrap();
        assert!(e.contains("edges 0 and 2") && e.contains("cross"), "{e}");
        let line = [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]];
        assert!(polygon_defect(&line).unwrap().contains("no area"));
        let repeated = [[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        assert!(polygon_defect(&repeated).unwrap().contains("same point"));
        // A vertex touching a non-neighbouring edge.
        let pinched = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [1.0, 0.0], [0.0, 2.0]];
        assert!(polygon_defect(&pinched).unwrap().contains("cross or touch"));
        assert!(polygon_defect(&[[0.0, 0.0], [1.0, 0.0]]).is_some());
        // Either orientation of a square is fine.
        let sq = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert_eq!(polygon_defect(&sq), None);
        let mut rev = sq;
        rev.reverse();
        assert_eq!(polygon_defect(&rev), None);
    }
}
