//! Placing armour units on a slope, as a laboratory does: at random, each unit dropped along
//! the slope's normal onto the under-layer or the units already there (the lowest of a few
//! random drops kept, which stands for the placer's hand and for rolling into a hollow; 32
//! drops place 89 flat stones of `examples/breakwater.toml` within 2 t_a where 8 placed 69), or in
//! a pattern of staggered rows lying flat on the slope.
//!
//! A drop: a unit at (s, y) with its member spheres at offsets (Δs_i, Δy_i, Δη_i) and radii r_i
//! comes down along −n until a member meets the plane (η_i = r_i + gap), the bed
//! (z_i = z_bed + r_i + gap) or a member j already placed at lateral distance d < r_i + r_j + gap,
//! which stops it at η_i = η_j + √((r_i + r_j + gap)² − d²): the highest of these stops is
//! where it rests (ballistic deposition, Visscher & Bolsterli 1972, Nature 239, 504). Members
//! of different units are then at least r_i + r_j + gap apart: no overlaps. Periodic across the
//! width by the nearest image.

use crate::armour::slope::Slope;
use crate::math::{Quat, Rng, Vec3};
use crate::rigid::templates::BlockTemplate;

/// Random drops tried for each unit; the lowest is kept.
pub const CANDIDATES: usize = 32;

/// A random placement gives up after this many tries per unit asked for.
pub const MAX_TRIES_PER_UNIT: usize = 40;

/// Where the units go.
#[derive(Clone, Debug)]
pub struct UnitLayer {
    /// The under-layer plane and the width.
    pub slope: Slope,
    /// Length of the slope from the toe to the crest [m]: centres at s in [0, length).
    pub length: f64,
    /// z of the bed plane, if any [m].
    pub bed_z: Option<f64>,
    /// Clearance above the plane and between units [m].
    pub gap: f64,
    /// Random placement: every unit's top within this height above the plane [m].
    pub ceiling: f64,
    /// Random placement: the largest tilt θ_max of a unit's definition frame from lying on
    /// the slope [rad] (π: any orientation).
    pub max_tilt: f64,
    /// The heap's seaward face at the toe: (x where it meets the toe's level [m], its cot [-]):
    /// every member centre lies on or behind it, so that the units at the toe do not start on
    /// a face steeper than they can stand on (a layer ending normal to a 1:2 slope, 63°,
    /// avalanches onto the bed).
    pub toe_face: (f64, f64),
    /// Periodic across the width.
    pub periodic_y: bool,
    /// The domain's x range [m].
    pub x_range: (f64, f64),
    /// The domain's top [m].
    pub z_max: f64,
    /// Fixed spheres the units rest on besides the plane and the bed, in slope coordinates
    /// [s, y, η, r] [m] (the under-layer's top stones).
    pub underlayer: Vec<[f64; 4]>,
}

impl UnitLayer {
    /// The lowest s a random unit's centre is drawn from: where the toe's face meets the bed
    /// (≤ 0: units in front of the toe make its berm, and count among the layer's).
    pub fn first_s(&self) -> f64 {
        let (cos, _) = self.slope.cos_sin();
        ((self.toe_face.0 - self.slope.toe_x) * cos).min(0.0)
    }
}

/// A unit: its members in the template's definition frame.
#[derive(Clone, Debug)]
pub struct Unit {
    /// (offset from the centre of mass in the definition frame [m], radius [m]).
    pub members: Vec<(Vec3, f64)>,
    /// D_n [m].
    pub nominal_diameter: f64,
}

impl Unit {
    /// The members of a template, in its definition frame.
    pub fn of(t: &BlockTemplate) -> Unit {
        Unit {
            members: t
                .members
                .iter()
                .map(|m| (t.principal_axes * m.offset, m.radius))
                .collect(),
            nominal_diameter: t.nominal_diameter(),
        }
    }
}

/// A unit placed: its centre [m] and its rotation from the definition frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placed {
    /// Centre of mass [m].
    pub centre: Vec3,
    /// Rotation from the template's definition frame.
    pub rotation: Quat,
}

/// A random placement that could not place them all.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shortfall {
    /// Units placed.
    pub placed: usize,
    /// Tries made.
    pub tries: usize,
}

/// A member placed, in slope coordinates.
#[derive(Clone, Copy, Debug)]
struct Sphere {
    s: f64,
    y: f64,
    eta: f64,
    r: f64,
}

/// The members placed, binned along the slope.
struct Placed3 {
    bins: Vec<Vec<Sphere>>,
    s0: f64,
    bin: f64,
    r_max: f64,
}

impl Placed3 {
    fn new(layer: &UnitLayer, unit: &Unit) -> Placed3 {
        let reach = unit
            .members
            .iter()
            .map(|(o, r)| o.length() + r)
            .fold(0.0, f64::max);
        let r_max = (unit.members.iter().map(|m| m.1))
            .chain(layer.underlayer.iter().map(|u| u[3]))
            .fold(0.0, f64::max);
        let bin = 2.0 * r_max + layer.gap;
        let s0 = -reach;
        let n = ((layer.length + 2.0 * reach) / bin).ceil() as usize + 1;
        let mut placed = Placed3 {
            bins: vec![Vec::new(); n],
            s0,
            bin,
            r_max,
        };
        for &[s, y, eta, r] in &layer.underlayer {
            placed.insert(Sphere { s, y, eta, r });
        }
        placed
    }

    fn index(&self, s: f64) -> usize {
        (((s - self.s0) / self.bin).floor().max(0.0) as usize).min(self.bins.len() - 1)
    }

    fn insert(&mut self, m: Sphere) {
        let i = self.index(m.s);
        self.bins[i].push(m);
    }
}

/// A unit's members turned by `q`: (Δs, Δy, Δη, r).
fn turned(slope: &Slope, unit: &Unit, q: Quat) -> Vec<[f64; 4]> {
    let (t, n) = (slope.tangent(), slope.normal());
    unit.members
        .iter()
        .map(|&(o, r)| {
            let w = q * o;
            [w.dot(t), w.y, w.dot(n), r]
        })
        .collect()
}

/// The height η of the centre where a unit dropped at (s, y) comes to rest, or None where a
/// member would leave the domain.
fn drop_height(layer: &UnitLayer, placed: &Placed3, m: &[[f64; 4]], s: f64, y: f64) -> Option<f64> {
    let sl = &layer.slope;
    let (cos, sin) = sl.cos_sin();
    let g = layer.gap;
    let mut eta = f64::NEG_INFINITY;
    for &[ds, dy, de, r] in m {
        eta = eta.max(g + r - de);
        if let Some(bed) = layer.bed_z {
            eta = eta.max((bed + r + g - sl.toe_z - (s + ds) * sin) / cos - de);
        }
        let (si, yi) = (s + ds, y + dy);
        let reach = r + placed.r_max + g;
        let (lo, hi) = (placed.index(si - reach), placed.index(si + reach));
        for bin in &placed.bins[lo..=hi] {
            for p in bin {
                let mut d_y = yi - p.y;
                if layer.periodic_y {
                    d_y = sl.nearest_image_dy(d_y);
                }
                let d2 = (si - p.s).powi(2) + d_y * d_y;
                let c = r + p.r + g;
                if d2 < c * c {
                    eta = eta.max(p.eta + (c * c - d2).sqrt() - de);
                }
            }
        }
    }
    inside(layer, m, s, y, eta).then_some(eta)
}

/// Whether every member of a unit with its centre at (s, y, η) lies in the domain and behind
/// the toe's face.
fn inside(layer: &UnitLayer, m: &[[f64; 4]], s: f64, y: f64, eta: f64) -> bool {
    let sl = &layer.slope;
    m.iter().all(|&[ds, dy, de, r]| {
        let (x, z) = sl.to_flume(s + ds, eta + de);
        let yy = y + dy;
        let y_ok = layer.periodic_y || (yy - r >= sl.y_min && yy + r <= sl.y_min + sl.width);
        let (x0, cot) = layer.toe_face;
        let face_ok = z <= sl.toe_z + (x - x0) / cot;
        x - r >= layer.x_range.0
            && x + r <= layer.x_range.1
            && z + r <= layer.z_max
            && y_ok
            && face_ok
    })
}

/// Records a unit at rest and returns it placed.
fn settle(
    layer: &UnitLayer,
    placed: &mut Placed3,
    m: &[[f64; 4]],
    c: (f64, f64, f64),
    q: Quat,
) -> Placed {
    let (s, y, eta) = c;
    for &[ds, dy, de, r] in m {
        let mut yy = y + dy;
        if layer.periodic_y {
            let w = layer.slope.width;
            yy = layer.slope.y_min + (yy - layer.slope.y_min).rem_euclid(w);
        }
        placed.insert(Sphere {
            s: s + ds,
            y: yy,
            eta: eta + de,
            r,
        });
    }
    Placed {
        centre: layer.slope.to_flume_point(Vec3::new(s, y, eta)),
        rotation: q,
    }
}

/// A random rotation from the definition frame: the frame laid on the slope ([`on_slope`]),
/// turned about the normal by a uniform yaw ψ, then tilted by θ about a horizontal axis of
/// uniform direction, with cos θ uniform in [cos θ_max, 1] (the normal's image uniform on a
/// spherical cap). With θ_max = π the rotations are uniform (Haar): a uniform axis on the
/// sphere and a uniform spin about it (Shoemake 1992, Graphics Gems III).
fn random_rotation(rng: &mut Rng, slope: &Slope, max_tilt: f64) -> Quat {
    let tau = std::f64::consts::TAU;
    let psi = tau * rng.uniform();
    let cos_t = 1.0 - rng.uniform() * (1.0 - max_tilt.cos());
    let phi = tau * rng.uniform();
    let axis = Vec3::new(phi.cos(), phi.sin(), 0.0);
    let tilt = Quat::from_axis_angle(axis, cos_t.clamp(-1.0, 1.0).acos());
    (on_slope(slope) * tilt * Quat::from_rotation_z(psi)).normalize()
}

/// A drop tried: (s, y, η) of the centre [m], the rotation, the members turned.
type Candidate = (f64, f64, f64, Quat, Vec<[f64; 4]>);

/// `target` units at random: each the lowest of [`CANDIDATES`] random drops whose top stays
/// within the ceiling; at most [`MAX_TRIES_PER_UNIT`] × `target` tries. Deterministic: the
/// same seed gives the same bits (one thread, a fixed order).
pub fn random(
    layer: &UnitLayer,
    unit: &Unit,
    target: usize,
    seed: u64,
) -> Result<Vec<Placed>, Shortfall> {
    let mut rng = Rng(seed);
    let mut placed = Placed3::new(layer, unit);
    let mut out = Vec::with_capacity(target);
    let max_tries = MAX_TRIES_PER_UNIT * target.max(1);
    let mut tries = 0;
    while out.len() < target && tries < max_tries {
        tries += 1;
        let mut best: Option<Candidate> = None;
        for _ in 0..CANDIDATES {
            let s0 = layer.first_s();
            let s = s0 + (layer.length - s0) * rng.uniform();
            let y = layer.slope.y_min + layer.slope.width * rng.uniform();
            let q = random_rotation(&mut rng, &layer.slope, layer.max_tilt);
            let m = turned(&layer.slope, unit, q);
            let Some(eta) = drop_height(layer, &placed, &m, s, y) else {
                continue;
            };
            let top = m
                .iter()
                .map(|v| v[2] + v[3])
                .fold(f64::NEG_INFINITY, f64::max);
            if eta + top > layer.ceiling + layer.gap {
                continue;
            }
            if best.as_ref().is_none_or(|b| eta < b.2) {
                best = Some((s, y, eta, q, m));
            }
        }
        if let Some((s, y, eta, q, m)) = best {
            out.push(settle(layer, &mut placed, &m, (s, y, eta), q));
        }
    }
    if out.len() < target {
        return Err(Shortfall {
            placed: out.len(),
            tries,
        });
    }
    Ok(out)
}

/// The rotation that lays the definition frame on the slope: x up the slope, z its normal.
fn on_slope(slope: &Slope) -> Quat {
    Quat::from_rotation_y(-slope.cot_alpha.recip().atan())
}

/// Staggered rows lying flat on the slope, `layers` deep, φ/n units per D_n² in each layer:
/// `across` units across the width (a whole number, for the periodic width; about
/// W √(φ/n)/D_n), rows spaced along the slope to give φ. Returns (units, across); every layer
/// has rows × across units. Each unit is dropped onto what lies below it (second-layer units
/// settle into the hollows of the first).
pub fn pattern(
    layer: &UnitLayer,
    unit: &Unit,
    layers: u32,
    phi: f64,
) -> Result<(Vec<Placed>, usize), String> {
    let d_n = unit.nominal_diameter;
    let (w, l) = (layer.slope.width, layer.length);
    let phi1 = phi / layers as f64;
    let across = ((w * phi1.sqrt() / d_n).round() as usize).max(1);
    let rows = ((phi1 * l * w / (d_n * d_n * across as f64)).round() as usize).max(1);
    // Layer k is staggered k/2 rows up the slope: the rows are spaced so that the top layer's
    // last row too lies half a spacing inside the crest (at s = l it hung half over it, and
    // settled past the crest, out of the layer before the waves came).
    let (dy, ds) = (
        w / across as f64,
        l / (rows as f64 + 0.5 * (layers - 1) as f64),
    );
    let q = on_slope(&layer.slope);
    let m = turned(&layer.slope, unit, q);
    let ext = |k: usize| {
        let lo = m.iter().map(|v| v[k] - v[3]).fold(f64::INFINITY, f64::min);
        let hi = m
            .iter()
            .map(|v| v[k] + v[3])
            .fold(f64::NEG_INFINITY, f64::max);
        hi - lo
    };
    if ds < ext(0) + layer.gap || dy < ext(1) + layer.gap {
        return Err(format!(
            "a pattern of {across} units across and {rows} rows (spaced {dy:.4} m across, {ds:.4} m \
             along the slope) is denser than the units lying flat allow ({:.4} m × {:.4} m each, \
             at most φ = {:.3} in {layers} layer(s)); lower the packing density or place at random",
            ext(0),
            ext(1),
            layers as f64 * d_n * d_n / ((ext(0) + layer.gap) * (ext(1) + layer.gap)),
        ));
    }
    let mut placed = Placed3::new(layer, unit);
    let mut out = Vec::new();
    for k in 0..layers as usize {
        for row in 0..rows {
            let s = (row as f64 + 0.5 + 0.5 * k as f64) * ds;
            let shift = 0.5 * (row % 2) as f64 + 0.25 * k as f64;
            for j in 0..across {
                let y = layer.slope.y_min + (j as f64 + shift) * dy;
                let eta = drop_height(layer, &placed, &m, s, y)
                    .ok_or_else(|| format!("row {row} of layer {} leaves the domain", k + 1))?;
                out.push(settle(layer, &mut placed, &m, (s, y, eta), q));
            }
        }
    }
    Ok((out, across))
}

/// The layer the tests place on: a 1:2 slope 0.3 m high from x = 1 m, 0.18 m across and
/// periodic, 1 mm gap, a 0.12 m release zone.
#[cfg(test)]
pub(super) fn test_layer() -> UnitLayer {
    UnitLayer {
        slope: Slope {
            toe_x: 1.0,
            toe_z: 0.0,
            cot_alpha: 2.0,
            y_min: 0.0,
            width: 0.18,
        },
        length: 0.3 * 5f64.sqrt(),
        bed_z: Some(0.0),
        gap: 0.001,
        ceiling: 0.12,
        max_tilt: std::f64::consts::PI,
        // Through the top of the release zone over the toe, as `breakwater::unit_layer`.
        toe_face: (1.0 - 0.12 * 5f64.sqrt() / 2.0 * 1.5, 1.5),
        periodic_y: true,
        x_range: (0.0, 3.0),
        z_max: 1.0,
        underlayer: Vec::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn layer() -> UnitLayer {
        test_layer()
    }

    fn flat_stone() -> Unit {
        // rubble_mound.toml's flat stone: four spheres of 0.6 at (±0.25, ±0.2), × 0.0533.
        let (scale, r) = (0.0533, 0.016);
        Unit {
            members: [(0.25, 0.2), (0.25, -0.2), (-0.25, 0.2), (-0.25, -0.2)]
                .iter()
                .map(|&(x, y)| (Vec3::new(x, y, 0.0) * scale, r))
                .collect(),
            nominal_diameter: 0.04,
        }
    }

    /// Every pair of members of different units at least r_i + r_j + gap apart (periodic).
    fn min_clearance(layer: &UnitLayer, unit: &Unit, units: &[Placed]) -> f64 {
        let mut worst = f64::INFINITY;
        let world: Vec<Vec<(Vec3, f64)>> = units
            .iter()
            .map(|p| {
                unit.members
                    .iter()
                    .map(|&(o, r)| (p.centre + p.rotation * o, r))
                    .collect()
            })
            .collect();
        for a in 0..world.len() {
            for b in a + 1..world.len() {
                for &(x, r) in &world[a] {
                    for &(y, q) in &world[b] {
                        let mut d = y - x;
                        d.y = layer.slope.nearest_image_dy(d.y);
                        worst = worst.min(d.length() - r - q);
                    }
                }
            }
        }
        worst
    }

    #[test]
    fn random_places_the_target_without_overlaps_and_repeats_by_seed() {
        let (l, u) = (layer(), flat_stone());
        let a = random(&l, &u, 60, 3).unwrap();
        assert_eq!(a.len(), 60);
        assert!(min_clearance(&l, &u, &a) >= l.gap - 1e-12);
        let b = random(&l, &u, 60, 3).unwrap();
        let bits = |v: &[Placed]| -> Vec<u64> {
            v.iter()
                .flat_map(|p| p.centre.to_array().map(f64::to_bits))
                .collect()
        };
        assert_eq!(bits(&a), bits(&b));
        let c = random(&l, &u, 60, 4).unwrap();
        assert_ne!(bits(&a), bits(&c));
    }

    #[test]
    fn random_refuses_a_layer_it_cannot_fill() {
        let (mut l, u) = (layer(), flat_stone());
        l.ceiling = 0.03;
        let e = random(&l, &u, 400, 1).unwrap_err();
        assert!(
            e.placed < 400 && e.tries == 400 * MAX_TRIES_PER_UNIT,
            "{e:?}"
        );
    }

    #[test]
    fn pattern_gives_rows_times_across_per_layer() {
        let (l, u) = (layer(), flat_stone());
        let (units, across) = pattern(&l, &u, 2, 0.8).unwrap();
        assert_eq!(units.len() % (2 * across), 0);
        assert!(min_clearance(&l, &u, &units) >= l.gap - 1e-12);
        assert!(pattern(&l, &u, 1, 3.0).is_err());
    }

    /// The second layer's last row was centred on the crest line (s = l), half over it: its
    /// units settled past the crest, out of the layer from the start. Every layer's centres
    /// now lie at least half a row spacing inside the slope.
    #[test]
    fn pattern_top_row_hung_over_the_crest() {
        let (l, u) = (layer(), flat_stone());
        for layers in [1, 2] {
            let (units, across) = pattern(&l, &u, layers, 0.4 * layers as f64).unwrap();
            let rows = units.len() / (across * layers as usize);
            let ds = l.length / (rows as f64 + 0.5 * (layers - 1) as f64);
            for p in &units {
                let (s, _) = l.slope.to_slope(p.centre.x, p.centre.z);
                assert!(
                    s > 0.0 && s <= l.length - 0.5 * ds + 1e-9,
                    "s = {s}, l = {}",
                    l.length
                );
            }
        }
    }
}
