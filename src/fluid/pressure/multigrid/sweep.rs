//! A red-black Gauss-Seidel sweep (one colour, then the other) in place and in one pass over
//! the planes, for a level where no cell has a neighbour of its own colour.
//!
//! Two half-sweeps ([`Level::half_sweep`]) stream every array of the level twice and copy x
//! once per colour. When every axis has an even number of cells (two or more), each cell's
//! six neighbours, across the box included, are of the other colour, so x can be updated in
//! place, and the second colour of plane k − 1 can follow the first colour of plane k at
//! once: it reads the first colour on planes k − 2, k − 1 and k, all updated by then, while
//! the first colour of plane k reads the second colour of planes k − 1, k and k + 1, none
//! updated yet. Each cell is computed from the same values by the same operations as in the
//! two half-sweeps: the bits are the same, for half the memory traffic.
//!
//! In parallel each task takes a block of planes. The first colour of a block's first plane
//! reads the second colour of the plane below it, which belongs to the next block down; that
//! task leaves the second colour of its last plane (and of its first) for a second pass, so
//! the value read is the old one. Each task reads the planes beyond its block from a copy
//! made before each pass (a halo of one plane on either side): the second pass's copy holds
//! the first colour's new values. The bits do not depend on the number of blocks.

use rayon::prelude::*;

use super::level::{relax_row, Level};

/// Planes of x of one block and the copies of the planes beyond it.
struct Block<'a> {
    /// The block's planes, mutable.
    x: &'a mut [f64],
    /// Its first plane's index.
    k0: usize,
    /// The plane below the block, then the plane above it (copies).
    halo: &'a [f64],
}

/// Whether a level of `n` cells sweeps in place: every axis has an even number of cells.
pub(super) fn sweeps_in_place(n: [usize; 3]) -> bool {
    n.iter().all(|&n| n >= 2 && n % 2 == 0)
}

impl Level {
    /// One red-black Gauss-Seidel sweep: colour `order[0]`, then colour `order[1]`; the same
    /// result, bit for bit, as `half_sweep(order[0])` then `half_sweep(order[1])` (which it
    /// makes where the level cannot sweep in place: its halo buffer is then empty).
    pub(super) fn sweep(&mut self, order: [usize; 2]) {
        if self.halo.is_empty() {
            self.half_sweep(order[0]);
            self.half_sweep(order[1]);
            return;
        }
        let plane = self.n[0] * self.n[1];
        let per = self.planes_per_block();
        let mut x = std::mem::take(&mut self.x);
        let mut halo = std::mem::take(&mut self.halo);

        // The first colour everywhere, the second on each block's inner planes.
        self.copy_halos(&x, &mut halo, per);
        x.par_chunks_mut(per * plane)
            .zip(halo.par_chunks(2 * plane))
            .enumerate()
            .for_each(|(m, (x, halo))| {
                let mut b = Block {
                    x,
                    k0: m * per,
                    halo,
                };
                let k1 = b.k0 + b.x.len() / plane;
                for k in b.k0..k1 {
                    self.relax_plane(&mut b, k, order[0]);
                    if k >= b.k0 + 2 {
                        self.relax_plane(&mut b, k - 1, order[1]);
                    }
                }
            });

        // The second colour on each block's first and last planes.
        self.copy_halos(&x, &mut halo, per);
        x.par_chunks_mut(per * plane)
            .zip(halo.par_chunks(2 * plane))
            .enumerate()
            .for_each(|(m, (x, halo))| {
                let (first, last) = (m * per, m * per + x.len() / plane - 1);
                let mut b = Block { x, k0: first, halo };
                self.relax_plane(&mut b, first, order[1]);
                if last > first {
                    self.relax_plane(&mut b, last, order[1]);
                }
            });
        self.x = x;
        self.halo = halo;
    }

    /// Planes per block: the planes shared out over the blocks the halo buffer has room for.
    fn planes_per_block(&self) -> usize {
        let blocks = self.halo.len() / (2 * self.n[0] * self.n[1]);
        self.n[2].div_ceil(blocks.max(1))
    }

    /// Copies, for each block of `per` planes, the plane below it and the plane above it
    /// (across the box: a wall's coupling is zero, module docs of [`super::level`]).
    fn copy_halos(&self, x: &[f64], halo: &mut [f64], per: usize) {
        let nz = self.n[2];
        let plane = self.n[0] * self.n[1];
        let at = |k: usize| &x[k * plane..(k + 1) * plane];
        for (m, h) in halo
            .chunks_mut(2 * plane)
            .take(nz.div_ceil(per))
            .enumerate()
        {
            let (k0, k1) = (m * per, ((m + 1) * per).min(nz));
            h[..plane].copy_from_slice(at((k0 + nz - 1) % nz));
            h[plane..].copy_from_slice(at(k1 % nz));
        }
    }

    /// The cells of `colour` on plane `k` of block `b`, in place: x_c = (b_c + Σ w x_nb) /
    /// diag_c with the operations, and their order, of [`Level::half_sweep`].
    fn relax_plane(&self, b: &mut Block, k: usize, colour: usize) {
        let [nx, ny, nz] = self.n;
        let plane = nx * ny;
        let local = k - b.k0;
        let (before, rest) = b.x.split_at_mut(local * plane);
        let (own, after) = rest.split_at_mut(plane);
        let below = match local {
            0 => &b.halo[..plane],
            _ => &before[(local - 1) * plane..],
        };
        let above = match after.is_empty() {
            true => &b.halo[plane..],
            false => &after[..plane],
        };
        for j in 0..ny {
            let (front, rest) = own.split_at_mut(j * nx);
            let (line, back) = rest.split_at_mut(nx);
            let y_lo = if j > 0 {
                &front[(j - 1) * nx..]
            } else {
                &back[(ny - 2) * nx..]
            };
            let y_hi = if j + 1 < ny {
                &back[..nx]
            } else {
                &front[..nx]
            };
            let start = nx * (j + ny * k);
            let low = |a: usize, start: usize| &self.low[a][start..start + nx];
            let w = [
                low(0, start),
                low(1, start),
                low(1, nx * ((j + 1) % ny + ny * k)),
                low(2, start),
                low(2, nx * (j + ny * ((k + 1) % nz))),
            ];
            let xn = [
                &y_lo[..nx],
                &y_hi[..nx],
                &below[j * nx..(j + 1) * nx],
                &above[j * nx..(j + 1) * nx],
            ];
            let (rhs, inv) = (
                &self.b[start..start + nx],
                &self.inv_diag[start..start + nx],
            );
            let first = (j + k + colour) % 2;
            relax_row(line, None, (w, xn), (rhs, inv), first);
        }
    }
}
