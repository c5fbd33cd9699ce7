//! Candidate pairs and the storage order of the spheres: a cell grid and a Verlet list.
//!
//! At each build the spheres are binned into cells at least 2 r_max + skin wide and **sorted
//! by cell** (`Spheres::permute`), so that spheres close in space are close in memory. The
//! linear cell index runs fastest along the axis with the fewest cells and slowest along the
//! axis with the most; the layers of cells across that slowest axis are therefore contiguous
//! ranges of slots, and so are "slabs", runs of whole layers (`slab_count`). A pair only joins
//! spheres of the same or of adjacent layers, hence slabs, which
//! lets the force computation scatter pair forces from several threads at once without two
//! threads ever writing the same sphere (`forces`).
//!
//! Each pair closer than r_i + r_j + skin is listed once, under its *owner*: the sphere with the
//! lower slot, except for a pair across a periodic boundary along the slab axis, which belongs to
//! the sphere in the last slab. The partners of sphere i are `partner[offsets[i]..offsets[i+1]]`,
//! ascending. The list stays valid while no two spheres' displacements since the build differ by
//! more than the skin, and no sphere has left its `Room` (`validity`).
//! Building is O(N) and allocates nothing once its buffers have grown.

mod grid;
mod validity;

use rayon::prelude::*;

use grid::CellGrid;
pub use validity::Room;
use validity::{Bands, Moves};

use super::domain::Domain;
use super::par::{for_chunks, gather_into, MIN_SPHERES_PER_TASK};
use super::spheres::{PermuteScratch, SphereId, Spheres, NO_BODY};
use crate::math::Vec3;

/// "No slot": a sphere that was not present at the previous build.
pub const NONE: u32 = u32::MAX;

/// Owners per parallel work item of the build; fixed, so the result is thread-count independent.
const CHUNK: usize = 1024;

/// The spheres a slab should hold at least, on average (`slab_count`).
const SLAB_SPHERES: usize = 2048;

/// The fewest slabs worth cutting the layers into (`slab_count`).
const MIN_SLABS: usize = 8;

/// The number of slabs for `layers` layers of cells holding `n` spheres: whole layers of at
/// least `SLAB_SPHERES` spheres together (a thread sweeps each slab in slot order, so a sphere
/// is still in the cache when it is met again as an owner after being a partner: B1 100k on
/// 1 thread -7 %), but no fewer than `MIN_SLABS` (each phase of the pair pass runs half of them
/// in parallel), nor than the layers allow. Fixed by the data, never by the thread count.
fn slab_count(layers: usize, n: usize) -> usize {
    let per_layer = n.div_ceil(layers.max(1)).max(1);
    let thick = SLAB_SPHERES.div_ceil(per_layer);
    (layers / thick).max(MIN_SLABS).min(layers).max(1)
}

/// Per-chunk output of a build.
#[derive(Clone, Debug, Default)]
struct ChunkOut {
    partner: Vec<u32>,
    count: Vec<u32>,
}

/// The Verlet skin, as a fraction of the largest sphere diameter, when none is set (a
/// scenario's `run.skin_fraction`, a `Dem` built by hand): thick enough that lists last many
/// steps, thin enough that few pairs are listed in vain.
pub const DEFAULT_SKIN_FRACTION: f64 = 0.2;

/// A Verlet neighbour list that also keeps the spheres sorted by cell.
#[derive(Clone, Debug, Default)]
pub struct NeighborList {
    /// Skin distance added to the contact distance [m].
    pub skin: f64,
    /// Number of builds so far.
    pub builds: u64,
    /// The sum of each step's largest drift |Δt v| since the build [m] (`note_drift`): no
    /// sphere has moved farther. Infinite when unknown (a list rebuilt at a saved run's
    /// positions).
    pub drift: f64,
    /// The drift at which the displacements must next be measured (`needs_rebuild`) [m]; NaN
    /// until the first test after a build.
    next_check: f64,
    /// Each sphere's room at the periodic faces and walls (`validity`), by slot.
    room: Vec<Room>,
    /// The axis across which the spheres are grouped in bands for the rebuild test
    /// (`validity`): best the one along which velocities vary most, gravity's as a rule
    /// (`Dem::rebuild_lists` sets it).
    pub band_axis: usize,
    /// The spheres' bands at the build.
    bands: Bands,
    /// CSR over owner slots: the pairs of owner i are `offsets[i]..offsets[i + 1]`.
    pub offsets: Vec<u32>,
    /// Partner slot of each pair.
    pub partner: Vec<u32>,
    /// For each owner slot, true when none of its pairs needs a periodic image until the next
    /// build (`mark_plain`): the pair loop may then take x_j - x_i as it is.
    pub plain: Vec<bool>,
    /// Owner slot of each pair (so that the pair loop runs over pairs, not owners).
    pub owner: Vec<u32>,
    /// For each slot, the slot the same sphere had at the previous build (`NONE` if it was not
    /// there, and for every sphere at the first build or after `forget`).
    pub previous_slot: Vec<u32>,
    /// The previous build's list (CSR over its slots), with partners given by id.
    pub old_offsets: Vec<u32>,
    /// See `old_offsets`.
    pub old_partner_id: Vec<SphereId>,
    /// Slot ranges of the slabs: slab k holds slots `slabs[k]..slabs[k + 1]`.
    slabs: Vec<u32>,
    /// Whether pairs cross a periodic boundary along the slab axis (owned by the last slab).
    slab_wraps: bool,
    /// Positions at the last build [m].
    reference: Vec<Vec3>,
    /// Ids at the last build, by slot.
    built_ids: Vec<SphereId>,
    grid: CellGrid,
    chunks: Vec<ChunkOut>,
    /// The first pair of each chunk of `chunks` at the join, and the total.
    chunk_base: Vec<u32>,
    order: Vec<u32>,
    slot_before: Vec<u32>,
    scratch: PermuteScratch,
    tmp: Vec<Vec3>,
}

impl NeighborList {
    /// An empty list with the given skin [m].
    pub fn new(skin: f64) -> Self {
        Self {
            skin,
            band_axis: 2,
            ..Default::default()
        }
    }

    /// Positions at the last build [m], by slot.
    pub fn reference(&self) -> &[Vec3] {
        &self.reference
    }

    /// Slot ranges of the slabs (`slabs()[k]..slabs()[k + 1]`): a pair joins spheres of the
    /// same slab or of consecutive slabs, or of the last and the first when `slab_wraps()`.
    pub fn slabs(&self) -> &[u32] {
        &self.slabs
    }

    /// True when pairs join the last slab to the first across a periodic boundary; those pairs
    /// are owned by the spheres of the last slab.
    pub fn slab_wraps(&self) -> bool {
        self.slab_wraps
    }

    /// Drops the memory of the previous build, so that the next build carries nothing over
    /// (used when the history is restored from a checkpoint instead).
    pub fn forget(&mut self) {
        self.builds = 0;
        self.built_ids.clear();
        self.offsets.clear();
        self.partner.clear();
    }

    /// Adds a step's largest drift |Δt v| [m] to the displacement bound `drift`. Whatever
    /// moves spheres outside the opening of a step (the blocks' recovery; research code that
    /// places spheres by hand) must add its largest move here too, or set `drift` to infinity.
    pub fn note_drift(&mut self, max_drift: f64) {
        self.drift += max_drift;
    }

    /// The index of the listed pair owned by slot `i` with partner `j`, if listed so.
    #[inline]
    pub fn pair_index(&self, i: usize, j: usize) -> Option<usize> {
        let (p0, p1) = (self.offsets[i] as usize, self.offsets[i + 1] as usize);
        (p0..p1).find(|&p| self.partner[p] as usize == j)
    }

    /// True when the list may miss a pair or a wall contact, or spheres were added or removed:
    /// when the displacements since the build of two spheres may differ by more than the skin,
    /// or a sphere has left its room (`validity`).
    ///
    /// The positions are compared with those of the build only once the drift bound has grown
    /// by 0.9 of the margin the last comparison found (the first time, of the smaller of skin/2
    /// and the reach of the smallest room). A sphere's displacement grows by at most the drifts added plus the rounding of
    /// each step's addition, an ulp of the coordinate; the rest of the margin, at least 10⁻³
    /// skin, covers 10⁴ steps of coordinates 10⁷ times the skin. The answer is the same as
    /// comparing every step, so a restart, which compares every step, rebuilds when the run
    /// did.
    pub fn needs_rebuild(&mut self, spheres: &Spheres, domain: &Domain) -> bool {
        if self.reference.len() != spheres.len() || self.builds == 0 {
            return true;
        }
        if self.next_check.is_nan() {
            // The first test after a build: none is needed before a sphere may have moved
            // skin/2 (pairs) or the reach of the smallest room.
            let least = self
                .room
                .par_iter()
                .map(Room::reach)
                .reduce(|| f64::INFINITY, f64::min);
            self.next_check = 0.9 * least.min(0.5 * self.skin);
        }
        if self.drift < self.next_check {
            return false;
        }
        let moves = Moves::measure(
            &spheres.position,
            &self.reference,
            &self.room,
            &mut self.bands,
            domain,
            self.skin,
        );
        match moves.verdict(self.skin) {
            Err(()) => true,
            Ok(margin) => {
                self.next_check = self.drift + margin.unwrap_or(0.0);
                false
            }
        }
    }

    /// What the wall lists read and narrow at each build (`WallContacts::rebuild`), by slot:
    /// the build positions, the previous slots and each sphere's room.
    pub fn for_walls(&mut self) -> (&[Vec3], &[u32], &mut [Room]) {
        (&self.reference, &self.previous_slot, &mut self.room)
    }

    /// Sorts the spheres by cell and rebuilds the candidate pairs. The list is built at the
    /// positions `at` (by slot; default: the current positions), which a restart uses to
    /// rebuild exactly the list of the saved run.
    pub fn build(&mut self, spheres: &mut Spheres, domain: &Domain, at: Option<&[Vec3]>) {
        let n = spheres.len();
        self.keep_old_list(spheres);
        self.reference.clear();
        self.reference
            .extend_from_slice(at.unwrap_or(&spheres.position));
        self.drift = if at.is_some() { f64::INFINITY } else { 0.0 };
        // Planned at the first test, once the walls have narrowed the rooms.
        self.next_check = f64::NAN;
        assert_eq!(
            self.reference.len(),
            n,
            "build: positions of the wrong length"
        );
        let r_max = spheres.radius.iter().cloned().fold(0.0, f64::max);
        let edge = (2.0 * r_max + self.skin).max(1e-12);
        self.grid.lay_out(domain, &self.reference, edge);
        self.grid.bin(&self.reference, &mut self.order);

        // Reorder the spheres and everything indexed by slot.
        let identity = self.order.iter().enumerate().all(|(k, &o)| k == o as usize);
        if !identity {
            spheres.permute(&self.order, &mut self.scratch);
            gather_into(&mut self.tmp, &self.reference, &self.order);
            std::mem::swap(&mut self.reference, &mut self.tmp);
        }
        gather_into(&mut self.previous_slot, &self.slot_before, &self.order);
        // After sorting, cell c holds slots start[c]..start[c + 1].
        let cells = self.grid.cells();
        self.grid.cell_of.clear();
        for c in 0..cells {
            let k = (self.grid.start[c + 1] - self.grid.start[c]) as usize;
            self.grid.cell_of.extend(std::iter::repeat_n(c as u32, k));
        }
        self.set_slabs(n);
        self.set_bands(r_max);
        self.find_pairs(spheres, domain);
        self.mark_plain(domain, edge);
        self.built_ids.clear();
        self.built_ids.extend_from_slice(&spheres.id);
        self.builds += 1;
    }

    /// Moves the current list to `old_*` with partners as ids, and writes in `slot_before`, for
    /// each current slot, the slot of the same sphere at that build.
    fn keep_old_list(&mut self, spheres: &Spheres) {
        let n = spheres.len();
        self.slot_before.clear();
        self.slot_before.resize(n, NONE);
        self.old_offsets.clear();
        self.old_partner_id.clear();
        let valid = self.builds > 0 && self.offsets.len() == self.built_ids.len() + 1;
        if !valid {
            return;
        }
        std::mem::swap(&mut self.old_offsets, &mut self.offsets);
        let ids = &self.built_ids;
        self.old_partner_id
            .par_extend(self.partner.par_iter().map(|&p| ids[p as usize]));
        let unchanged = spheres.len() == ids.len() && spheres.id == *ids;
        if unchanged {
            for (k, s) in self.slot_before.iter_mut().enumerate() {
                *s = k as u32;
            }
        } else {
            for (o, &id) in ids.iter().enumerate() {
                if let Some(k) = spheres.slot_of(id) {
                    self.slot_before[k] = o as u32;
                }
            }
        }
    }

    /// Sets `plain`: owner i is plain when, at the build's positions, it lies farther than
    /// `edge` + 3 skin from every periodic face, `edge` (the cell edge) being more than any
    /// pair's distance r_i + r_j + skin. Then its partners lie more than 3 skins from the faces,
    /// and each sphere farther than that from every periodic face gets the room of its distances
    /// to the faces (strict bounds): until the next build none of those spheres is wrapped.
    /// (The 2 skins more than needed let the lists outlive moves of a few skins, as in a chute
    /// where neighbours move alike, up to `Room::FARTHEST` skins.) As
    /// two spheres' displacements differ by at most the skin (`needs_rebuild`),
    /// |x_j - x_i| < edge + skin stays at most half a period (checked): the nearest image of
    /// x_j - x_i is x_j - x_i itself.
    fn mark_plain(&mut self, domain: &Domain, edge: f64) {
        let clear = 3.0 * self.skin;
        let reach = edge + clear;
        let (mut lo, mut hi) = (Vec3::NEG_INFINITY, Vec3::INFINITY);
        let mut short = false;
        let periodic = domain.periodic;
        let axes = || (0..3).filter(move |&a| periodic[a]);
        for a in axes() {
            (lo[a], hi[a]) = (domain.min[a] + reach, domain.max[a] - reach);
            short |= reach > 0.5 * (domain.max[a] - domain.min[a]);
        }
        self.plain.clear();
        self.plain.par_extend(
            self.reference
                .par_iter()
                .with_min_len(MIN_SPHERES_PER_TASK)
                .map(|x| !short && x.cmpgt(lo).all() && x.cmplt(hi).all()),
        );
        // Spheres no farther than `clear` from a face are never plain owners nor their
        // partners: free (0.99: the comparisons above round).
        let free_within = 0.99 * clear;
        let far = Room::FARTHEST * self.skin;
        let guard = !short && periodic.contains(&true);
        self.room.clear();
        self.room.par_extend(
            self.reference
                .par_iter()
                .with_min_len(MIN_SPHERES_PER_TASK)
                .map(|&x| {
                    let (below, above) = (x - domain.min, domain.max - x);
                    let (mut lo, mut hi) = (Vec3::splat(-far), Vec3::splat(far));
                    if !guard || axes().any(|a| below[a].min(above[a]) <= free_within) {
                        return Room::between(lo, hi);
                    }
                    for a in axes() {
                        (lo[a], hi[a]) = (-below[a].min(far), above[a].min(far));
                    }
                    Room::between(lo, hi)
                }),
        );
    }

    /// Groups the spheres in bands of two cells across `band_axis` (`validity::Bands`); one
    /// band when that axis is periodic. Spheres of bands not next to each other lie more than
    /// two cells apart along it, so they need a relative displacement of 2 w - 2 r_max (w the
    /// cell width) to touch (less a part in 10⁹ for the rounding of the binning).
    fn set_bands(&mut self, r_max: f64) {
        let g = &self.grid;
        let a = self.band_axis.min(2);
        let b = &mut self.bands;
        b.of.clear();
        if g.periodic[a] {
            b.of.resize(g.cell_of.len(), 0);
            (b.count, b.apart) = (1, f64::INFINITY);
            return;
        }
        // Cell by cell in storage order (no division per sphere).
        let p = g.axes.iter().position(|&k| k == a).unwrap_or(2);
        let [n0, n1, n2] = g.axes.map(|k| g.n[k]);
        let mut c = 0;
        for c2 in 0..n2 {
            for c1 in 0..n1 {
                for c0 in 0..n0 {
                    let band = [c0, c1, c2][p] / 2;
                    let k = (g.start[c + 1] - g.start[c]) as usize;
                    b.of.extend(std::iter::repeat_n(band as u32, k));
                    c += 1;
                }
            }
        }
        b.count = g.n[a].div_ceil(2);
        b.apart = 2.0 * g.width[a] * (1.0 - 1e-9) - 2.0 * r_max;
    }

    fn set_slabs(&mut self, n: usize) {
        let g = &self.grid;
        let s = g.layers();
        let sc = g.layer_cells();
        let axis = g.axes[2];
        self.slabs.clear();
        // One slab only when the slabs would wrap onto themselves (fewer than 3 layers across
        // a periodic axis): then a single task computes every pair.
        if g.periodic[axis] && s < 3 {
            self.slabs.extend([0, n as u32]);
            self.slab_wraps = false;
        } else {
            let m = slab_count(s, n);
            self.slabs.extend((0..=m).map(|k| g.start[k * s / m * sc]));
            self.slab_wraps = g.periodic[axis];
        }
    }

    fn find_pairs(&mut self, spheres: &Spheres, domain: &Domain) {
        let n = spheres.len();
        let n_chunks = n.div_ceil(CHUNK);
        self.chunks.resize_with(n_chunks, ChunkOut::default);
        let grid = &self.grid;
        let skin = self.skin;
        let wrap = self.slab_wraps;
        let layers = grid.layers() as u32;
        let layer_cells = grid.layer_cells() as u32;
        let pos = &self.reference;
        let (rad, fixed, body) = (&spheres.radius, &spheres.fixed, &spheres.body);
        let im = domain.images();
        let [a0, a1, a2] = grid.axes;
        let (n0, n1, n2) = (grid.n[a0], grid.n[a1], grid.n[a2]);
        // Cells one cell or more from every periodic face search at most five runs of
        // consecutive cells: the rest of their own row from the next slot on, the row above,
        // and the three rows of the next layer, each cut at the open faces (B1's bed, a few
        // cells thick, has most of its spheres in cells on the floor or the free surface).
        // Those runs are ranges of consecutive slots, already ascending, and hold the cells
        // of the general search (`CellGrid::around`, those after the cell itself) in order.
        let wraps_at = [a0, a1, a2].map(|k| grid.periodic[k]);
        let fast_cell = |c: usize| {
            let cc = [c % n0, (c / n0) % n1, c / (n0 * n1)];
            let n = [n0, n1, n2];
            (0..3).all(|k| !wraps_at[k] || (1..n[k] - 1).contains(&cc[k]))
        };
        let start = |c: usize| grid.start[c];
        let index = |c0: usize, c1: usize, c2: usize| c0 + n0 * (c1 + n1 * c2);
        // With four cells or more along every periodic axis, a pair between a fast cell (off
        // every periodic face) and its neighbours is never nearer through a face (|d| < 2
        // cells <= half a period), so the fast path takes the plain separation.
        let plain = (0..3).all(|k| !grid.periodic[k] || grid.n[k] >= 4);
        self.chunks.par_iter_mut().enumerate().for_each(|(c, out)| {
            out.count.clear();
            // The partners found so far are `buf[..len]`; the rest is room to write to.
            let buf = &mut out.partner;
            let mut len = 0;
            let mut around = Vec::with_capacity(27);
            // (first slot, end slot, only slots above the owner's) of the cells to search.
            let mut ranges: Vec<(u32, u32, bool)> = Vec::with_capacity(27);
            let mut last_cell = NONE;
            let mut fast = false;
            for i in c * CHUNK..((c + 1) * CHUNK).min(n) {
                let cell = grid.cell_of[i];
                if cell != last_cell {
                    last_cell = cell;
                    ranges.clear();
                    let cu = cell as usize;
                    fast = fast_cell(cu);
                    if fast {
                        let (c0, c1, c2) = (cu % n0, (cu / n0) % n1, cu / (n0 * n1));
                        // Along the fastest axis, cells lo..=hi of a row.
                        let (lo, hi) = (c0.saturating_sub(1), (c0 + 1).min(n0 - 1));
                        let run = |r1, r2| (start(index(lo, r1, r2)), start(index(hi, r1, r2) + 1));
                        ranges.push((0, start(index(hi, c1, c2) + 1), true));
                        if c1 + 1 < n1 {
                            let (s, e) = run(c1 + 1, c2);
                            ranges.push((s, e, false));
                        }
                        if c2 + 1 < n2 {
                            for r1 in c1.saturating_sub(1)..=(c1 + 1).min(n1 - 1) {
                                let (s, e) = run(r1, c2 + 1);
                                ranges.push((s, e, false));
                            }
                        }
                    } else {
                        grid.around(cu, &mut around);
                        let layer = cell / layer_cells;
                        for &q in &around {
                            let q_layer = q / layer_cells;
                            let (s, e) = (grid.start[q as usize], grid.start[q as usize + 1]);
                            if s == e {
                                continue;
                            }
                            if wrap && layer == layers - 1 && q_layer == 0 {
                                ranges.push((s, e, false));
                            } else if wrap && layer == 0 && q_layer == layers - 1 {
                                continue;
                            } else if q >= cell {
                                ranges.push((s, e, q == cell));
                            }
                        }
                    }
                }
                let (xi, ri, fi, bi) = (pos[i], rad[i], fixed[i], body[i]);
                // Two fixed spheres never move apart; members of one block never touch
                // (their contact is internal to the block). Most owners are neither.
                let may_skip = fi || bi != NO_BODY;
                let before = len;
                for &(s, e, above) in &ranges {
                    let s = if above { s.max(i as u32 + 1) } else { s } as usize;
                    let e = (e as usize).max(s);
                    // Room for every candidate of the range: each is written to the next
                    // place, which only a close one keeps (no branch on the distance).
                    if buf.len() < len + (e - s) {
                        buf.resize(2 * (len + (e - s)), 0);
                    }
                    for j in s..e {
                        let d = pos[j] - xi;
                        let d = if fast && plain { d } else { im.nearest(d) };
                        let cut = ri + rad[j] + skin;
                        let skip =
                            may_skip && ((fi && fixed[j]) || (bi != NO_BODY && body[j] == bi));
                        buf[len] = j as u32;
                        len += usize::from(d.length_squared() < cut * cut && !skip);
                    }
                }
                out.count.push((len - before) as u32);
            }
            buf.truncate(len);
        });
        self.join_chunks(n);
    }

    /// Puts the chunks' pairs end to end (offsets, partners, owners), each chunk in parallel
    /// from where the pairs of the chunks before it end. Every element is written, so the
    /// columns are resized, not cleared.
    fn join_chunks(&mut self, n: usize) {
        self.chunk_base.clear();
        let mut total = 0u32;
        for ch in &self.chunks {
            self.chunk_base.push(total);
            total += ch.partner.len() as u32;
        }
        self.chunk_base.push(total);
        self.offsets.resize(n + 1, 0);
        self.offsets[0] = 0;
        self.partner.resize(total as usize, 0);
        self.owner.resize(total as usize, 0);
        let (chunks, base) = (&self.chunks, &self.chunk_base);
        let bounds = |c: usize| ((c * CHUNK).min(n), base[c] as usize);
        let leaf = |c: usize, ends: &mut [u32], (partner, owner): (&mut [u32], &mut [u32])| {
            let ch = &chunks[c];
            partner.copy_from_slice(&ch.partner);
            let (mut end, mut q) = (base[c], 0);
            for ((i, &k), e) in (c * CHUNK..).zip(&ch.count).zip(ends) {
                end += k;
                *e = end;
                owner[q..q + k as usize].fill(i as u32);
                q += k as usize;
            }
        };
        let pairs = (&mut self.partner[..], &mut self.owner[..]);
        let chunks = 0..chunks.len();
        for_chunks(
            chunks,
            &mut self.offsets[1..],
            pairs,
            &bounds,
            &leaf,
            &|(), ()| (),
        );
    }
}

/// All pairs of spheres (slots i < j) closer than r_i + r_j + `margin`, sorted, without
/// reordering the spheres: for one-off checks such as overlaps in a scenario.
pub fn close_pairs(spheres: &Spheres, domain: &Domain, margin: f64) -> Vec<(u32, u32)> {
    let mut near = NearPairs::default();
    near.find(spheres, domain, margin);
    near.pairs
}

/// The pairs of spheres closer than r_i + r_j + a margin, found on a cell grid of its own
/// with buffers kept from one search to the next (nothing allocates once they have grown):
/// for passes that need pairs beyond the contact list's reach, such as the lubrication film
/// of the coupling.
#[derive(Clone, Debug, Default)]
pub struct NearPairs {
    grid: CellGrid,
    sorted: Vec<u32>,
    around: Vec<u32>,
    /// The pairs of the last search, slots i < j, sorted.
    pub pairs: Vec<(u32, u32)>,
}

impl NearPairs {
    /// Finds the pairs (slots i < j) with |x_j − x_i| < r_i + r_j + `margin` (minimum image
    /// across periodic faces), sorted, into `self.pairs`.
    pub fn find(&mut self, spheres: &Spheres, domain: &Domain, margin: f64) {
        let pos = &spheres.position;
        let rad = &spheres.radius;
        let r_max = rad.iter().cloned().fold(0.0, f64::max);
        let grid = &mut self.grid;
        grid.lay_out(domain, pos, (2.0 * r_max + margin).max(1e-12));
        grid.bin(pos, &mut self.sorted);
        let out = &mut self.pairs;
        out.clear();
        for i in 0..pos.len() {
            grid.around(grid.cell_of[i] as usize, &mut self.around);
            let first = out.len();
            for &q in &self.around {
                let cell = grid.start[q as usize] as usize..grid.start[q as usize + 1] as usize;
                for &j in &self.sorted[cell] {
                    let cut = rad[i] + rad[j as usize] + margin;
                    if j as usize > i
                        && domain
                            .minimum_image(pos[j as usize] - pos[i])
                            .length_squared()
                            < cut * cut
                    {
                        out.push((i as u32, j));
                    }
                }
            }
            out[first..].sort_unstable();
        }
    }
}

#[cfg(test)]
pub(crate) mod tests;
