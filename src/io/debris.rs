//! Output of tsunami debris (`crate::debris`):
//!
//! * `debris_tracks.csv`: per output time and piece, [`TRACK_COLUMNS`]: the centre, the
//!   velocity, the heading, the wet height (the draft afloat), the mass (flooding included)
//!   and the state, coded 0 floating, 1 grounded, 2 sunk, 3 out of the domain;
//! * `debris_NNNNNN.vtp` (series `debris.pvd`): each piece as its box, 12 triangles, with
//!   the piece's id, state, mass and speed as cell data, beside the flow's frames;
//! * `debris_tracks.png`: the tracks over the bed (drawn by `run::shallow` from the CSV).

use std::path::Path;

use super::csv::CsvSeries;
use super::vtk::{write_surface, Array, Format};
use crate::debris::Debris;
use crate::math::Vec3;

/// Columns of `debris_tracks.csv`.
pub const TRACK_COLUMNS: [&str; 11] = [
    "time",
    "id",
    "x_m",
    "y_m",
    "z_m",
    "u_m_s",
    "v_m_s",
    "heading_rad",
    "draft_m",
    "mass_kg",
    "state",
];

/// Appends one row per piece to `debris_tracks.csv`.
pub fn track_rows(d: &Debris, csv: &mut CsvSeries) -> std::io::Result<()> {
    let b = d.blocks();
    for (k, st) in d.states().iter().enumerate() {
        let (c, v) = (b.centre[k], b.velocity[k]);
        csv.row(&[
            d.time(),
            b.id[k] as f64,
            c.x,
            c.y,
            c.z,
            v.x,
            v.y,
            d.heading(k),
            st.wet_height,
            b.mass[k],
            st.phase.code(),
        ])?;
    }
    Ok(())
}

/// The 8 corners [m] and 12 triangles (outward) of each piece's box, piece after piece.
pub fn boxes(d: &Debris) -> (Vec<Vec3>, Vec<[u32; 3]>) {
    let b = d.blocks();
    let (mut v, mut t) = (Vec::new(), Vec::new());
    for (k, p) in d.pieces().iter().enumerate() {
        let s = p.shape;
        let h = Vec3::new(0.5 * s.length, 0.5 * s.width, 0.5 * s.height);
        let o = v.len() as u32;
        for n in 0..8 {
            let corner = Vec3::new(
                if n & 1 == 0 { -h.x } else { h.x },
                if n & 2 == 0 { -h.y } else { h.y },
                if n & 4 == 0 { -h.z } else { h.z },
            );
            v.push(b.centre[k] + b.orientation[k] * corner);
        }
        // Faces as corner quads (outward, counter-clockwise), two triangles each.
        for q in [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ] {
            t.push([o + q[0], o + q[1], o + q[2]]);
            t.push([o + q[0], o + q[2], o + q[3]]);
        }
    }
    (v, t)
}

/// Writes the pieces as boxes (module docs).
pub fn write_debris_frame(d: &Debris, path: &Path, format: Format) -> std::io::Result<()> {
    let (v, t) = boxes(d);
    let b = d.blocks();
    let per =
        |f: &dyn Fn(usize) -> f64| -> Vec<f64> { (0..b.len()).flat_map(|k| [f(k); 12]).collect() };
    let id: Vec<i64> = b.id.iter().flat_map(|&i| [i as i64; 12]).collect();
    let state = per(&|k| d.states()[k].phase.code());
    let mass = per(&|k| b.mass[k]);
    let speed = per(&|k| b.velocity[k].length());
    write_surface(
        path,
        &v,
        &t,
        &[
            Array::ints("id", &id),
            Array::scalars("state", &state),
            Array::scalars("mass", &mass),
            Array::scalars("speed", &speed),
        ],
        format,
    )
}
