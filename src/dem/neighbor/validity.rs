//! How long a neighbour list stays valid (`NeighborList::needs_rebuild`).
//!
//! A pair left out at the build was at least r_i + r_j + skin apart, so its spheres can touch
//! only once their displacements since the build, Δ_i and Δ_j, differ by more than the skin.
//! The pairs therefore stay valid while max |Δ_i − Δ_j| ≤ skin. That spread is bounded here by
//! the smaller of 2 max |Δ_i| (the usual rule: rebuild when a sphere has moved skin/2) and the
//! diagonal of the box around all Δ_i. The second is far smaller where spheres move together: a
//! bed falling as a block. And only spheres that can meet need their Δ compared: the spheres are
//! grouped in `Bands` across one axis, two cells thick, so that two spheres of bands that are
//! not next to each other are more than 2 (2 r_max + skin) apart and need a relative
//! displacement `Bands::apart`, far more than the skin, to touch. Across a shear flow (a chute
//! over its fixed base) neighbouring bands move nearly alike.
//!
//! What is tied to absolute positions gives each sphere a `Room`, the displacements it may
//! reach before the lists need a rebuild: a wall not listed for it (at least a skin away at the
//! build), the periodic faces it must not cross while a plain owner takes x_j − x_i as it is
//! (`NeighborList::mark_plain`).
//!
//! The test reads every position, so it runs only once the drift bound (the sum of the steps'
//! largest drifts, `NeighborList::drift`) may have used up 0.9 of the margin the last test
//! found; the rest covers the rounding of the steps' additions.

use std::sync::atomic::{AtomicBool, Ordering};

use rayon::prelude::*;

use super::super::domain::Domain;
use crate::math::Vec3;

/// The displacements Δ from its build position that a sphere may reach before something other
/// than its pairs needs a rebuild [m]: lo < Δ < hi in each axis and |Δ| < `radius`: the
/// periodic faces, 3 skins away or more (`NeighborList::mark_plain`); a wall left out, at least
/// a skin away less the skin/2 a moving wall may come closer, that over |n|₁ ≤ √3 for a plane
/// (`WallContacts::rebuild`); `FARTHEST` skins at most.
///
/// In single precision, rounded toward zero (so never larger than asked): the test that reads
/// the rooms streams them with the positions, 28 bytes a sphere instead of 56.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Room {
    /// Lower bound of each component of Δ [m], ≤ 0.
    lo: [f32; 3],
    /// Upper bound of each component of Δ [m], ≥ 0.
    hi: [f32; 3],
    /// Bound on |Δ| [m].
    radius: f32,
}

/// `x` in single precision, rounded toward zero.
fn toward_zero(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f).abs() > x.abs() {
        // One ulp toward zero, for either sign (f is finite and not zero here).
        f32::from_bits(f.to_bits() - 1)
    } else {
        f
    }
}

impl Room {
    /// No bound.
    pub const FREE: Room = Room {
        lo: [f32::NEG_INFINITY; 3],
        hi: [f32::INFINITY; 3],
        radius: f32::INFINITY,
    };

    /// The farthest reach of any room along an axis, in skins. A sphere that has gone that far
    /// gets a rebuild whatever its neighbours do: the cell sort that keeps neighbours close in
    /// memory has aged. And the walls farther away need not narrow the rooms (most spheres'
    /// walls, B1: a wall pass at each build 1/3 longer otherwise).
    pub const FARTHEST: f64 = 4.0;

    /// The room between `lo` and `hi` [m] (≤ 0 and ≥ 0 in each axis).
    pub fn between(lo: Vec3, hi: Vec3) -> Room {
        let mut room = Room::FREE;
        for k in 0..3 {
            room.lo[k] = toward_zero(lo[k]);
            room.hi[k] = toward_zero(hi[k]);
        }
        room
    }

    /// Keeps n·Δ > −`gap` [m] for the unit normal `n` (a plane `gap` away on the side −n), as
    /// bounds on the components moving against n: each gets gap/|n|₁, so that
    /// n·Δ ≥ −|n|₁ gap/|n|₁ (exact for a plane normal to an axis).
    #[inline]
    pub fn keep_off(&mut self, n: Vec3, gap: f64) {
        let h = toward_zero(gap / (n.x.abs() + n.y.abs() + n.z.abs()));
        for k in 0..3 {
            if n[k] > 0.0 {
                self.lo[k] = self.lo[k].max(-h);
            } else if n[k] < 0.0 {
                self.hi[k] = self.hi[k].min(h);
            }
        }
    }

    /// Keeps |Δ| < `gap` [m] (something `gap` away in an unknown direction).
    #[inline]
    pub fn within(&mut self, gap: f64) {
        self.radius = self.radius.min(toward_zero(gap));
    }

    /// How far the room reaches in the direction it reaches least [m].
    pub fn reach(&self) -> f64 {
        let sides = self.hi.iter().zip(&self.lo).map(|(&h, &l)| h.min(-l));
        f64::from(sides.fold(self.radius, f32::min))
    }

    /// How far Δ [m] lies inside the room: the least distance to its bounds, ≤ 0 outside.
    #[inline]
    fn slack(&self, d: Vec3) -> f64 {
        let (lo, hi) = (self.lo.map(f64::from), self.hi.map(f64::from));
        let by_axis = least(
            least(
                least(d.x - lo[0], hi[0] - d.x),
                least(d.y - lo[1], hi[1] - d.y),
            ),
            least(d.z - lo[2], hi[2] - d.z),
        );
        if self.radius < f32::INFINITY {
            least(by_axis, f64::from(self.radius) - d.length())
        } else {
            by_axis
        }
    }
}

/// min(a, b) as one compare and select (`f64::min` also takes care of NaN, which costs a
/// second compare in the passes' loops; here a NaN b gives b, and the instability checks stop a
/// run with NaN positions anyway).
#[inline(always)]
fn least(a: f64, b: f64) -> f64 {
    if a < b {
        a
    } else {
        b
    }
}

/// max(a, b) as one compare and select (see `least`).
#[inline(always)]
fn most(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

/// The spheres grouped in bands across one axis at the build (see the module documentation).
#[derive(Clone, Debug, Default)]
pub struct Bands {
    /// Band of each sphere, by slot.
    pub of: Vec<u32>,
    /// Number of bands (1: all spheres in one).
    pub count: usize,
    /// The relative displacement two spheres of bands not next to each other need before they
    /// can touch [m] (infinite with one band).
    pub apart: f64,
    /// The box around the Δ of each band, for each part of the pass (`Moves::measure`).
    boxes: Vec<[Vec3; 2]>,
}

impl Bands {
    /// All of `n` spheres in one band.
    #[cfg(test)]
    pub fn one(n: usize) -> Bands {
        Bands {
            of: vec![0; n],
            count: 1,
            apart: f64::INFINITY,
            boxes: Vec::new(),
        }
    }
}

/// The box around no displacement.
const NO_BOX: [Vec3; 2] = [Vec3::INFINITY, Vec3::NEG_INFINITY];

/// The diagonal of the box around the boxes `a` and `b` [m] (0 when both are empty).
fn diagonal(a: [Vec3; 2], b: [Vec3; 2]) -> f64 {
    (a[1].max(b[1]) - a[0].min(b[0])).max(Vec3::ZERO).length()
}

/// What one pass over the displacements Δ_i since the build finds.
#[derive(Clone, Copy, Debug)]
pub(super) struct Moves {
    /// The least slack of any sphere in its room [m] (≤ 0: some sphere left it).
    pub slack: f64,
    /// max |Δ_i|² [m²].
    pub max2: f64,
    /// The box around all Δ_i [m].
    pub lo: Vec3,
    /// See `lo`.
    pub hi: Vec3,
    /// A bound on |Δ_i − Δ_j| for spheres of one band or of bands next to each other [m].
    pub near: f64,
    /// The relative displacement spheres of bands not next to each other need to touch [m].
    pub apart: f64,
}

impl Moves {
    const NONE: Moves = Moves {
        slack: f64::INFINITY,
        max2: 0.0,
        lo: Vec3::INFINITY,
        hi: Vec3::NEG_INFINITY,
        near: 0.0,
        apart: f64::INFINITY,
    };

    fn join(a: Moves, b: Moves) -> Moves {
        Moves {
            slack: a.slack.min(b.slack),
            max2: a.max2.max(b.max2),
            lo: a.lo.min(b.lo),
            hi: a.hi.max(b.hi),
            near: a.near.max(b.near),
            apart: a.apart.min(b.apart),
        }
    }

    /// The displacements of spheres at `pos` built at `reference` [m], with their rooms and
    /// bands, to be judged against the skin `skin` [m] (`verdict`). Minima and maxima only, so
    /// the answer does not depend on how the pass is split; once a part of it alone condemns
    /// the list, the parts not yet started are skipped (the verdict is then the same).
    pub fn measure(
        pos: &[Vec3],
        reference: &[Vec3],
        room: &[Room],
        bands: &mut Bands,
        domain: &Domain,
        skin: f64,
    ) -> Moves {
        const CHUNK: usize = 4096;
        let n = reference.len();
        if n == 0 {
            return Moves::NONE;
        }
        let im = domain.images();
        let (pos, room, of) = (&pos[..n], &room[..n], &bands.of[..n]);
        let nb = bands.count.max(1);
        bands.boxes.clear();
        bands.boxes.resize(n.div_ceil(CHUNK) * nb, NO_BOX);
        let apart = bands.apart;
        let condemned = AtomicBool::new(false);
        let mut m = reference
            .par_chunks(CHUNK)
            .zip(pos.par_chunks(CHUNK))
            .zip(room.par_chunks(CHUNK))
            .zip(of.par_chunks(CHUNK))
            .zip(bands.boxes.par_chunks_mut(nb))
            .map(|((((x0, x), room), of), boxes)| {
                let mut m = Moves {
                    apart,
                    ..Moves::NONE
                };
                if condemned.load(Ordering::Relaxed) {
                    return m;
                }
                // The box of the current band is kept apart, in registers: the spheres are
                // sorted by cell, so the band changes only every row of cells or so.
                let mut band = of.first().copied().unwrap_or(0) as usize;
                let [mut lo, mut hi] = NO_BOX;
                for (((&x0, &x), r), &b) in x0.iter().zip(x).zip(room).zip(of) {
                    let d = im.nearest(x - x0);
                    m.slack = least(m.slack, r.slack(d));
                    m.max2 = most(m.max2, d.length_squared());
                    if b as usize != band {
                        let to = &mut boxes[band];
                        *to = [to[0].min(lo), to[1].max(hi)];
                        [lo, hi] = NO_BOX;
                        band = b as usize;
                    }
                    lo = Vec3::new(least(lo.x, d.x), least(lo.y, d.y), least(lo.z, d.z));
                    hi = Vec3::new(most(hi.x, d.x), most(hi.y, d.y), most(hi.z, d.z));
                }
                if let Some(to) = boxes.get_mut(band) {
                    *to = [to[0].min(lo), to[1].max(hi)];
                }
                [m.lo, m.hi] = boxes
                    .iter()
                    .fold(NO_BOX, |a, b| [a[0].min(b[0]), a[1].max(b[1])]);
                if m.verdict(skin).is_err() {
                    condemned.store(true, Ordering::Relaxed);
                }
                m
            })
            .reduce(|| Moves::NONE, Moves::join);
        // The boxes of the bands over all parts, then the largest box of two bands in a row.
        let (first, rest) = bands.boxes.split_at_mut(nb);
        for part in rest.chunks(nb) {
            for (a, b) in first.iter_mut().zip(part) {
                *a = [a[0].min(b[0]), a[1].max(b[1])];
            }
        }
        m.near = (0..nb)
            .map(|b| diagonal(first[b], first[(b + 1).min(nb - 1)]))
            .fold(0.0, f64::max);
        m
    }

    /// A bound on max |Δ_i − Δ_j| over all pairs of spheres [m].
    pub fn spread(&self) -> f64 {
        let diagonal = (self.hi - self.lo).max(Vec3::ZERO).length();
        (2.0 * self.max2.sqrt()).min(diagonal)
    }

    /// Whether the lists built with `skin` [m] are still valid; if so, the drift the spheres
    /// may add before the next test is needed [m] (`None`: test at the next step).
    pub fn verdict(&self, skin: f64) -> Result<Option<f64>, ()> {
        let spread = self.spread();
        let near = self.near.min(spread);
        if self.slack <= 0.0 || near > skin || spread > self.apart {
            return Err(());
        }
        // Each Δ_i moves by at most the drift added; two of them apart by twice that.
        let margin = (self.slack)
            .min(0.5 * (skin - near))
            .min(0.5 * (self.apart - spread));
        // Below a hundredth of the skin, 0.1 of the margin might not cover the rounding of the
        // coordinates over many slow steps: test at every step instead.
        Ok((margin >= 0.01 * skin).then_some(0.9 * margin))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `keep_off` keeps a sphere on its side of an oblique plane: every Δ in the box has
    /// n·Δ ≥ −gap, and the box reaches the plane along the axis moving fastest against n.
    #[test]
    fn oblique_plane_room_stays_on_its_side() {
        let n = Vec3::new(0.6, -0.8, 0.0);
        let gap = 0.01;
        let mut r = Room::FREE;
        r.keep_off(n, gap);
        let h = gap / 1.4;
        assert!(h - f64::from(r.hi[1]) < 1e-9 && f64::from(r.hi[1]) <= h);
        assert_eq!((r.lo[0], r.hi[1]), (-r.hi[1], r.hi[1]));
        assert_eq!((r.lo[1], r.lo[2]), (f32::NEG_INFINITY, f32::NEG_INFINITY));
        assert_eq!((r.hi[0], r.hi[2]), (f32::INFINITY, f32::INFINITY));
        // The corner reaching the plane, and every move along n, or across it, stay inside.
        let corner = Vec3::new(-h, h, 0.0);
        assert!((n.dot(corner) + gap).abs() < 1e-15);
        assert!(r.slack(corner) <= 0.0 && r.slack(0.99 * corner) > 0.0);
        assert!(r.slack(Vec3::new(5.0, -5.0, 7.0)) > 1.0);
    }

    /// Rounding to single precision never widens a room.
    #[test]
    fn rooms_round_toward_zero() {
        for x in [0.1, -0.1, 1.0 / 3.0, -2.0 / 3.0, 0.002 / 3.0, 0.0] {
            let f = f64::from(toward_zero(x));
            assert!(
                f.abs() <= x.abs() && (x - f).abs() <= 1.2e-7 * x.abs(),
                "{x}"
            );
        }
        assert_eq!(toward_zero(f64::INFINITY), f32::INFINITY);
    }

    /// The spread bound is the box diagonal when everything moves alike and 2 max |Δ| when the
    /// moves point every way.
    #[test]
    fn spread_takes_the_smaller_bound() {
        let d = Domain {
            min: Vec3::ZERO,
            max: Vec3::splat(10.0),
            periodic: [false; 3],
        };
        let x0 = vec![Vec3::splat(1.0), Vec3::splat(2.0), Vec3::splat(3.0)];
        let room = vec![Room::FREE; 3];
        let along: Vec<Vec3> = x0
            .iter()
            .enumerate()
            .map(|(k, &x)| x + Vec3::new(1.0 + 0.001 * k as f64, 0.0, 0.0))
            .collect();
        let m = Moves::measure(&along, &x0, &room, &mut Bands::one(3), &d, 1.0);
        assert!((m.spread() - 0.002).abs() < 1e-12, "{}", m.spread());
        let apart = vec![x0[0] + Vec3::X, x0[1] - Vec3::X, x0[2] + Vec3::Y];
        let m = Moves::measure(&apart, &x0, &room, &mut Bands::one(3), &d, 1.0);
        assert!((m.spread() - 2.0).abs() < 1e-12, "{}", m.spread());
        assert!(m.verdict(1.0).is_err() && m.verdict(2.5).is_ok());
    }
}
