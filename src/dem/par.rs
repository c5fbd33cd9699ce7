//! Fork-join over chunks of arrays, with chunk boundaries fixed by the data (never by the
//! number of threads), so that every result is the same for any thread count.
//!
//! `for_chunks` hands chunk c the sub-slices `bounds_a(c)..bounds_a(c + 1)` of one group of
//! arrays and `bounds_b(c)..bounds_b(c + 1)` of another (say, spheres and their pairs), splitting
//! them recursively in halves and running the halves with `rayon::join`. The split tree depends
//! only on the number of chunks, so the order in which `combine` merges the chunks' results does
//! too.

/// The fewest spheres a worker takes in a cheap per-sphere loop (a kick, a drift, zeroing the
/// forces): below it a loop runs on one thread, since handing the other half to another
/// worker costs more than the loop (measured: the DEM sub-steps of case 5's 900 spheres took
/// longer on 2 threads than on 1 before this bound).
pub const MIN_SPHERES_PER_TASK: usize = 4096;

/// `out ← [from[order[0]], from[order[1]], ...]`, in parallel: a column put in a new order.
pub fn gather_into<T: Copy + Send + Sync>(out: &mut Vec<T>, from: &[T], order: &[u32]) {
    use rayon::prelude::*;
    out.clear();
    out.par_extend(
        order
            .par_iter()
            .with_min_len(MIN_SPHERES_PER_TASK)
            .map(|&o| from[o as usize]),
    );
}

/// Something that can be cut in two at an index: a mutable slice, or a tuple of them (cut at
/// the same index), or `()`.
pub trait Split: Sized + Send {
    /// The parts before and after `at`.
    fn split(self, at: usize) -> (Self, Self);
}

impl<T: Send> Split for &mut [T] {
    #[inline]
    fn split(self, at: usize) -> (Self, Self) {
        self.split_at_mut(at)
    }
}

impl Split for () {
    #[inline]
    fn split(self, _: usize) -> (Self, Self) {
        ((), ())
    }
}

impl<A: Split, B: Split> Split for (A, B) {
    #[inline]
    fn split(self, at: usize) -> (Self, Self) {
        let (a0, a1) = self.0.split(at);
        let (b0, b1) = self.1.split(at);
        ((a0, b0), (a1, b1))
    }
}

impl<A: Split, B: Split, C: Split> Split for (A, B, C) {
    #[inline]
    fn split(self, at: usize) -> (Self, Self) {
        let (a0, a1) = self.0.split(at);
        let (b0, b1) = self.1.split(at);
        let (c0, c1) = self.2.split(at);
        ((a0, b0, c0), (a1, b1, c1))
    }
}

/// Runs `leaf(c, a_c, b_c)` for every chunk c in `chunks`, in parallel, where `a_c` and `b_c`
/// are the parts of `a` and `b` between the boundaries `bounds(c)` and `bounds(c + 1)` (the
/// first of the pair for `a`, the second for `b`), measured from `bounds(chunks.start)`: `a` and
/// `b` must start at that boundary. Boundaries must be non-decreasing. The leaves' results are
/// merged with `combine` in a fixed tree; `None` for an empty range.
pub fn for_chunks<A, B, R, F, L, C>(
    chunks: std::ops::Range<usize>,
    a: A,
    b: B,
    bounds: &F,
    leaf: &L,
    combine: &C,
) -> Option<R>
where
    A: Split,
    B: Split,
    R: Send,
    F: Fn(usize) -> (usize, usize) + Sync,
    L: Fn(usize, A, B) -> R + Sync,
    C: Fn(R, R) -> R + Sync,
{
    match chunks.len() {
        0 => None,
        1 => Some(leaf(chunks.start, a, b)),
        len => {
            let mid = chunks.start + len / 2;
            let (s, m) = (bounds(chunks.start), bounds(mid));
            let (a0, a1) = a.split(m.0 - s.0);
            let (b0, b1) = b.split(m.1 - s.1);
            let (r0, r1) = rayon::join(
                || for_chunks(chunks.start..mid, a0, b0, bounds, leaf, combine),
                || for_chunks(mid..chunks.end, a1, b1, bounds, leaf, combine),
            );
            match (r0, r1) {
                (Some(x), Some(y)) => Some(combine(x, y)),
                (x, y) => x.or(y),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Chunks of unequal sizes get exactly their parts, and the combination order is fixed.
    #[test]
    fn chunks_get_their_parts() {
        let bounds = [0usize, 3, 3, 10, 12];
        let mut a: Vec<usize> = (0..12).collect();
        let mut b = [0usize; 24];
        let r = for_chunks(
            0..4,
            &mut a[..],
            &mut b[..],
            &|c| (bounds[c], 2 * bounds[c]),
            &|c, a: &mut [usize], b: &mut [usize]| {
                assert_eq!(a.len(), bounds[c + 1] - bounds[c]);
                assert_eq!(b.len(), 2 * a.len());
                for x in a.iter_mut() {
                    *x += 100 * c;
                }
                b.fill(c);
                vec![c]
            },
            &|mut x: Vec<usize>, y: Vec<usize>| {
                x.extend(y);
                x
            },
        );
        assert_eq!(r, Some(vec![0, 1, 2, 3]));
        assert_eq!(a[2], 2);
        assert_eq!(a[3], 203);
        assert_eq!(a[11], 311);
        assert_eq!(&b[6..8], &[2, 2]);
    }
}
