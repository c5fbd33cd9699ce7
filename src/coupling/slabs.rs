//! Sums over spheres into grid fields, in parallel and with the same bits on any thread count.
//!
//! The padded storage is cut into slabs of whole z-planes; each thread owns a slab and visits
//! the spheres whose box reaches it, in slot order, adding only to its own points. Every
//! point therefore receives its terms in slot order, as a serial loop would give them, for
//! any cut. The cuts balance the spheres (by the plane of their lowest cell) between the
//! slabs, since a bed fills the bottom of a domain.

use super::fraction::CellBox;
use crate::fluid::{Boundaries, StaggeredGrid};

/// Scratch for the cuts, allocated once.
#[derive(Clone, Debug, Default)]
pub struct Slabs {
    /// Spheres whose box starts on each storage plane.
    per_plane: Vec<usize>,
    /// The storage planes at which the slabs are cut (ascending).
    cuts: Vec<usize>,
    /// The storage planes [first, end) that some box reaches (empty: (0, 0)).
    span: (usize, usize),
}

/// The smallest range of planes that holds both `a` and `b` (an empty range holds nothing).
pub fn union(a: (usize, usize), b: (usize, usize)) -> (usize, usize) {
    match (a.0 < a.1, b.0 < b.1) {
        (false, _) => b,
        (_, false) => a,
        _ => (a.0.min(b.0), a.1.max(b.1)),
    }
}

/// The storage planes (K = k + 1 of the padded storage) that the box `cells` reaches, faces
/// on its high side included: wrapped on a periodic z, dropped outside 0..nz otherwise.
pub fn planes(
    grid: &StaggeredGrid,
    bcs: &Boundaries,
    cells: &CellBox,
) -> impl Iterator<Item = usize> {
    let n = grid.n[2] as i64;
    let periodic = bcs.is_periodic(2);
    let k0 = cells.low[2];
    let k1 = if cells.extent[2] == 0 {
        k0 - 1
    } else {
        k0 + cells.extent[2] as i64
    };
    (k0..=k1).filter_map(move |k| {
        let k = if periodic { k.rem_euclid(n) } else { k };
        (0..n).contains(&k).then_some(k as usize + 1)
    })
}

impl Slabs {
    /// Cuts the storage planes into `parts` slabs with about equal numbers of the boxes
    /// `boxes` starting in each.
    pub fn cut(&mut self, grid: &StaggeredGrid, bcs: &Boundaries, boxes: &[CellBox], parts: usize) {
        let planes_n = grid.padded()[2];
        self.per_plane.clear();
        self.per_plane.resize(planes_n, 0);
        let mut total = 0;
        let (mut lo, mut hi) = (usize::MAX, 0);
        for b in boxes.iter().filter(|b| b.extent[2] > 0) {
            if let Some(p) = planes(grid, bcs, b).next() {
                self.per_plane[p] += 1;
                total += 1;
            }
            for p in planes(grid, bcs, b) {
                (lo, hi) = (lo.min(p), hi.max(p + 1));
            }
        }
        self.span = if lo < hi { (lo, hi) } else { (0, 0) };
        self.cuts.clear();
        let mut seen = 0;
        for (p, &count) in self.per_plane.iter().enumerate().skip(1) {
            seen += count;
            let next = self.cuts.len() + 1;
            if next < parts && seen * parts >= next * total.max(1) {
                self.cuts.push(p + 1);
            }
        }
    }

    /// The storage planes [first, end) that the boxes of the last cut reach: the sums over
    /// spheres write nothing outside them.
    pub fn span(&self) -> (usize, usize) {
        self.span
    }

    /// Calls `work(first_plane, last_plane + 1, fields)` on each slab in parallel, `fields`
    /// being the slab's parts of `fields` (each a padded field of `grid`).
    pub fn for_each<T: Send, const K: usize>(
        &self,
        grid: &StaggeredGrid,
        fields: [&mut [T]; K],
        work: &(impl Fn(usize, usize, [&mut [T]; K]) + Sync),
    ) {
        let plane = grid.strides()[2];
        split(&self.cuts, 0, grid.padded()[2], plane, fields, work);
    }
}

fn split<T: Send, const K: usize>(
    cuts: &[usize],
    first: usize,
    end: usize,
    plane: usize,
    fields: [&mut [T]; K],
    work: &(impl Fn(usize, usize, [&mut [T]; K]) + Sync),
) {
    if cuts.is_empty() {
        work(first, end, fields);
        return;
    }
    let m = cuts.len() / 2;
    let at = cuts[m];
    let mut lo: [&mut [T]; K] = std::array::from_fn(|_| &mut [][..]);
    let mut hi: [&mut [T]; K] = std::array::from_fn(|_| &mut [][..]);
    for (q, f) in fields.into_iter().enumerate() {
        let (l, h) = f.split_at_mut((at - first) * plane);
        lo[q] = l;
        hi[q] = h;
    }
    rayon::join(
        || split(&cuts[..m], first, at, plane, lo, work),
        || split(&cuts[m + 1..], at, end, plane, hi, work),
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Vec3;

    /// Adding 1 at every plane a box reaches gives the same field for 1, 2, 3 and 7 slabs.
    #[test]
    fn any_cut_gives_the_same_sums() {
        let grid = StaggeredGrid::new([4, 4, 12], Vec3::splat(1.0), Vec3::ZERO);
        let bcs = Boundaries::periodic();
        let boxes: Vec<CellBox> = (0..20)
            .map(|i| CellBox {
                low: [0, 0, (i % 9) as i64 - 1],
                extent: [1, 1, 1 + i % 4],
            })
            .collect();
        let plane = grid.strides()[2];
        let mut reference = None;
        for parts in [1, 2, 3, 7] {
            let mut slabs = Slabs::default();
            slabs.cut(&grid, &bcs, &boxes, parts);
            assert!(slabs.cuts.len() < parts);
            let mut field = grid.field();
            slabs.for_each(&grid, [&mut field[..]], &|first, end, [f]| {
                for b in &boxes {
                    for p in planes(&grid, &bcs, b).filter(|p| (first..end).contains(p)) {
                        f[(p - first) * plane] += 1.0;
                    }
                }
            });
            match &reference {
                None => reference = Some(field),
                Some(r) => assert_eq!(r, &field, "{parts} slabs"),
            }
        }
    }
}
