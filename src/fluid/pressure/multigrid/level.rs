//! One level of the multigrid hierarchy: the positive operator Â = −D((1/ρ̄_f) G) as face
//! couplings on a box of cells, its red-black Gauss-Seidel half-sweeps, and the transfers
//! to and from the next coarser level.
//!
//! Cells are compact, c = i + n_x (j + n_y k). `low[a][c]` is the coupling w [m kg⁻¹] across
//! the low a-face of cell c, to its low neighbour along a (across the box on a periodic
//! axis; 0 on a wall, a closed face, or an axis of one cell), so that
//!
//! ```text
//! (Â x)_c = diag_c x_c − Σ_a ( low_a[c] x_{c−a} + low_a[c+a] x_{c+a} )
//! diag_c  = Σ_a ( low_a[c] + low_a[c+a] ) + open_c
//! ```
//!
//! with `open_c` the coupling to the p = 0 face of an open top. The stencil reads its
//! neighbours across the box along every axis (c − a of the first layer is the last layer):
//! on a wall axis the first layer's low couplings are zero, so what it reads there counts for
//! nothing, and the rows need no branch. Every loop writes each output
//! element from one task, reading the others, and every sum runs in an order fixed by the
//! stencil: the bits do not depend on the number of threads.

use crate::fluid::grid::for_each_chunk;

/// One grid level: couplings, and the vectors of a cycle on it.
pub(super) struct Level {
    /// Cells along x, y, z.
    pub n: [usize; 3],
    /// Whether each axis is periodic.
    pub periodic: [bool; 3],
    /// Couplings across the low faces [m⁻² (kg m⁻³)⁻¹] (module docs).
    pub low: [Vec<f64>; 3],
    /// Coupling to the open top's p = 0 face (zero elsewhere).
    pub open: Vec<f64>,
    /// The diagonal of Â.
    pub diag: Vec<f64>,
    /// 1/diag, 0 where diag is 0 (a cell with every face closed: inside an obstacle).
    pub inv_diag: Vec<f64>,
    /// Right-hand side.
    pub b: Vec<f64>,
    /// The iterate.
    pub x: Vec<f64>,
    /// The next iterate of a half-sweep.
    pub next: Vec<f64>,
    /// Copies of the planes either side of each block of an in-place sweep
    /// ([`super::sweep`]; empty where the level cannot sweep in place).
    pub halo: Vec<f64>,
    /// x after the first of a W-cycle's two visits, while the second is made
    /// ([`Level::restart_from_residual`]; empty on a level visited once).
    saved: Vec<f64>,
}

/// The start of a row (j, k) and of its y and z neighbours (low, high), across the box
/// whatever the boundary: on a wall the coupling across is zero (module docs of [`super`]).
#[derive(Clone, Copy)]
struct Rows {
    own: usize,
    y: [usize; 2],
    z: [usize; 2],
}

/// One row's slices of x and of the couplings, for a branch-free stencil.
pub(super) struct RowView<'a> {
    /// x along the row.
    pub x: &'a [f64],
    /// The couplings: x low face, y low and high, z low and high.
    pub w: [&'a [f64]; 5],
    /// x on the rows y low, y high, z low, z high.
    pub xn: [&'a [f64]; 4],
}

/// Cells computed together along a row (a stack buffer; a multiple of the vector width).
pub(super) const RUN: usize = 32;

/// The cells of one colour along a row of `line.len()` cells, `first` the first of them (0
/// or 1): line_i = (b_i + Σ w x_nb) / diag_i with the couplings `w` and the neighbouring rows
/// `xn` of a [`RowView`], and x along the row `old` (a half-sweep) or `line` itself (a sweep in
/// place, [`super::sweep`]). The ends take their x neighbours across the row; the inner cells
/// are computed in vectorised runs, of which those of the colour are kept (the others' values
/// are discarded, and the kept ones read only the other colour).
pub(super) fn relax_row(
    line: &mut [f64],
    old: Option<&[f64]>,
    (w, xn): ([&[f64]; 5], [&[f64]; 4]),
    (b, inv): (&[f64], &[f64]),
    first: usize,
) {
    fn view<'a>(x: &'a [f64], w: [&'a [f64]; 5], xn: [&'a [f64]; 4]) -> RowView<'a> {
        RowView { x, w, xn }
    }
    let nx = line.len();
    if first == 0 {
        let (lo, hi) = Level::along(0, nx);
        line[0] = (b[0] + view(old.unwrap_or(line), w, xn).sum(0, lo, hi)) * inv[0];
    }
    let mut i0 = 1;
    while i0 + 1 < nx {
        let m = (nx - 1 - i0).min(RUN);
        let mut new = [0.0; RUN];
        view(old.unwrap_or(line), w, xn).run(i0, m, |t, i, s| new[t] = (b[i] + s) * inv[i]);
        for t in ((first + i0) % 2..m).step_by(2) {
            line[i0 + t] = new[t];
        }
        i0 += m;
    }
    if nx > 1 && (nx - 1 + first) % 2 == 0 {
        let (lo, hi) = Level::along(nx - 1, nx);
        let sum = view(old.unwrap_or(line), w, xn).sum(nx - 1, lo, hi);
        line[nx - 1] = (b[nx - 1] + sum) * inv[nx - 1];
    }
}

impl RowView<'_> {
    /// Σ coupling × x over the neighbours of cell i, whose x neighbours are `lo` and `hi`
    /// (order: x low, x high, y low, y high, z low, z high).
    #[inline(always)]
    pub(super) fn sum(&self, i: usize, lo: usize, hi: usize) -> f64 {
        let (w, x, xn) = (&self.w, self.x, &self.xn);
        w[0][i] * x[lo]
            + w[0][hi] * x[hi]
            + w[1][i] * xn[0][i]
            + w[2][i] * xn[1][i]
            + w[3][i] * xn[2][i]
            + w[4][i] * xn[3][i]
    }

    /// Calls `f(t, i, s)` with s = Σ w x over the neighbours (as [`RowView::sum`], term for
    /// term) for the inner cells i = i0 + t, t < m (1 ≤ i0, i0 + m < n_x): along shifted
    /// slices, so that the loop vectorises.
    #[inline(always)]
    pub(super) fn run(&self, i0: usize, m: usize, mut f: impl FnMut(usize, usize, f64)) {
        let r = i0..i0 + m;
        let (x_lo, x_hi) = (&self.x[i0 - 1..i0 - 1 + m], &self.x[i0 + 1..i0 + 1 + m]);
        let (w, xn) = (&self.w, &self.xn);
        let (w0, w0_hi) = (&w[0][r.clone()], &w[0][i0 + 1..i0 + 1 + m]);
        let [w1, w2, w3, w4] = [1, 2, 3, 4].map(|a| &w[a][r.clone()]);
        let [n0, n1, n2, n3] = [0, 1, 2, 3].map(|a| &xn[a][r.clone()]);
        for t in 0..m {
            let s = w0[t] * x_lo[t]
                + w0_hi[t] * x_hi[t]
                + w1[t] * n0[t]
                + w2[t] * n1[t]
                + w3[t] * n2[t]
                + w4[t] * n3[t];
            f(t, i0 + t, s);
        }
    }
}

impl Level {
    /// A level of `n` cells, couplings zero; `revisited` where a W-cycle visits it twice.
    pub fn new(n: [usize; 3], periodic: [bool; 3], revisited: bool) -> Level {
        let len = n[0] * n[1] * n[2];
        let zero = || vec![0.0; len];
        // One block of planes per thread for the in-place sweeps.
        let blocks = rayon::current_num_threads().clamp(1, n[2]);
        let halo = match super::sweep::sweeps_in_place(n) {
            true => 2 * n[0] * n[1] * blocks,
            false => 0,
        };
        Level {
            n,
            periodic,
            low: std::array::from_fn(|_| zero()),
            open: zero(),
            diag: zero(),
            inv_diag: zero(),
            b: zero(),
            x: zero(),
            next: zero(),
            halo: vec![0.0; halo],
            saved: if revisited { zero() } else { Vec::new() },
        }
    }

    /// Number of cells.
    pub fn len(&self) -> usize {
        self.n[0] * self.n[1] * self.n[2]
    }

    /// The rows that row number `row` (= j + n_y k) reads.
    fn rows(&self, row: usize) -> Rows {
        let [nx, ny, nz] = self.n;
        let (j, k) = (row % ny, row / ny);
        let at = |j: usize, k: usize| nx * (j + ny * k);
        Rows {
            own: at(j, k),
            y: [at((j + ny - 1) % ny, k), at((j + 1) % ny, k)],
            z: [at(j, (k + nz - 1) % nz), at(j, (k + 1) % nz)],
        }
    }

    /// The slices of row `r` and its neighbours in `x`.
    fn view<'a>(&'a self, r: &Rows, x: &'a [f64]) -> RowView<'a> {
        let nx = self.n[0];
        let row = |a: usize, start: usize| &self.low[a][start..start + nx];
        let xr = |start: usize| &x[start..start + nx];
        RowView {
            x: xr(r.own),
            w: [
                row(0, r.own),
                row(1, r.own),
                row(1, r.y[1]),
                row(2, r.own),
                row(2, r.z[1]),
            ],
            xn: [xr(r.y[0]), xr(r.y[1]), xr(r.z[0]), xr(r.z[1])],
        }
    }

    /// The x neighbours of cell i of a row of `nx` (across the row: a wall's coupling is 0).
    #[inline(always)]
    fn along(i: usize, nx: usize) -> (usize, usize) {
        (
            if i == 0 { nx - 1 } else { i - 1 },
            if i + 1 == nx { 0 } else { i + 1 },
        )
    }

    /// Sets the low couplings of an axis of one cell to zero (a cell's face to itself carries
    /// nothing), then diag and 1/diag from the couplings.
    pub fn finish(&mut self) {
        for a in 0..3 {
            if self.n[a] == 1 {
                self.low[a].iter_mut().for_each(|w| *w = 0.0);
            }
        }
        let nx = self.n[0];
        let mut diag = std::mem::take(&mut self.diag);
        for_each_chunk(&mut diag, nx, |row, line| {
            let r = self.rows(row);
            let v = self.view(&r, &self.open);
            for (i, d) in line.iter_mut().enumerate() {
                let (_, hi) = Self::along(i, nx);
                *d = v.w[0][i]
                    + v.w[0][hi]
                    + v.w[1][i]
                    + v.w[2][i]
                    + v.w[3][i]
                    + v.w[4][i]
                    + self.open[r.own + i];
            }
        });
        self.diag = diag;
        let (diag, inv) = (&self.diag, &mut self.inv_diag);
        for_each_chunk(inv, nx, |row, line| {
            for (i, v) in line.iter_mut().enumerate() {
                let d = diag[row * nx + i];
                *v = if d > 0.0 { 1.0 / d } else { 0.0 };
            }
        });
    }

    /// For a second visit of a W-cycle: b ← b − Â x and x kept aside, so that the next
    /// cycle from x = 0 solves for the correction, which [`Level::add_saved`] adds back.
    /// By rows in parallel, as [`Level::apply`].
    pub fn restart_from_residual(&mut self) {
        let nx = self.n[0];
        let mut b = std::mem::take(&mut self.b);
        for_each_chunk(&mut b, nx, |row, line| {
            let r = self.rows(row);
            let v = self.view(&r, &self.x);
            for (i, b) in line.iter_mut().enumerate() {
                let (lo, hi) = Self::along(i, nx);
                *b -= self.diag[r.own + i] * v.x[i] - v.sum(i, lo, hi);
            }
        });
        self.b = b;
        std::mem::swap(&mut self.saved, &mut self.x);
    }

    /// x += the x kept by [`Level::restart_from_residual`].
    pub fn add_saved(&mut self) {
        let (nx, saved) = (self.n[0], &self.saved);
        for_each_chunk(&mut self.x, nx, |row, line| {
            let s = &saved[row * nx..(row + 1) * nx];
            line.iter_mut().zip(s).for_each(|(x, s)| *x += s);
        });
    }

    /// out = Â x.
    #[cfg(test)]
    pub fn apply(&self, x: &[f64], out: &mut [f64]) {
        let nx = self.n[0];
        for_each_chunk(out, nx, |row, line| {
            let r = self.rows(row);
            let v = self.view(&r, x);
            for (i, o) in line.iter_mut().enumerate() {
                let (lo, hi) = Self::along(i, nx);
                *o = self.diag[r.own + i] * x[r.own + i] - v.sum(i, lo, hi);
            }
        });
    }

    /// One Gauss-Seidel half-sweep over the cells of `colour` ((i + j + k) mod 2): x_c =
    /// (b_c + Σ w x_nb) / diag_c, the others kept. Written to `next` and swapped, so that a
    /// cell's neighbours of its own colour (only across an odd periodic axis) are read at
    /// their old values: a Jacobi step on those pairs, still symmetric ([`super`]).
    pub fn half_sweep(&mut self, colour: usize) {
        let [nx, ny, _] = self.n;
        let mut next = std::mem::take(&mut self.next);
        let x = &self.x;
        for_each_chunk(&mut next, nx, |row, line| {
            let r = self.rows(row);
            let v = self.view(&r, x);
            let (b, inv) = (
                &self.b[r.own..r.own + nx],
                &self.inv_diag[r.own..r.own + nx],
            );
            line.copy_from_slice(v.x);
            let first = (row % ny + row / ny + colour) % 2;
            relax_row(line, Some(v.x), (v.w, v.xn), (b, inv), first);
        });
        self.next = std::mem::replace(&mut self.x, next);
    }

    /// The coarse right-hand side: `coarse.b` = the sums over each coarse cell's fine cells
    /// (in the order k, j, i) of the residual b − Â x.
    pub fn restrict_residual(&self, coarse: &mut Level) {
        let f = factors(self.n);
        let [cx, cy, _] = coarse.n;
        let mut b = std::mem::take(&mut coarse.b);
        for_each_chunk(&mut b, cx, |crow, line| {
            line.iter_mut().for_each(|v| *v = 0.0);
            let (cj, ck) = (crow % cy, crow / cy);
            for k in f[2] * ck..(f[2] * ck + f[2]).min(self.n[2]) {
                for j in f[1] * cj..(f[1] * cj + f[1]).min(self.n[1]) {
                    let r = self.rows(j + self.n[1] * k);
                    let v = self.view(&r, &self.x);
                    let nx = self.n[0];
                    let (b, d) = (&self.b[r.own..r.own + nx], &self.diag[r.own..r.own + nx]);
                    let end = |i: usize| {
                        let (lo, hi) = Self::along(i, nx);
                        b[i] - (d[i] * v.x[i]) + v.sum(i, lo, hi)
                    };
                    line[0] += end(0);
                    // The inner cells in vectorised runs, summed in order as the ends.
                    let mut i0 = 1;
                    while i0 + 1 < nx {
                        let m = (nx - 1 - i0).min(RUN);
                        let mut res = [0.0; RUN];
                        v.run(i0, m, |t, i, s| res[t] = b[i] - (d[i] * v.x[i]) + s);
                        for (t, res) in res[..m].iter().enumerate() {
                            line[(i0 + t) / f[0]] += res;
                        }
                        i0 += m;
                    }
                    if nx > 1 {
                        line[(nx - 1) / f[0]] += end(nx - 1);
                    }
                }
            }
        });
        coarse.b = b;
    }

    /// x += the coarse level's x, each fine cell taking its coarse cell's value.
    pub fn add_correction(&mut self, coarse: &Level) {
        let f = factors(self.n);
        let [nx, ny, _] = self.n;
        let [cx, cy, _] = coarse.n;
        for_each_chunk(&mut self.x, nx, |row, line| {
            let (j, k) = (row % ny, row / ny);
            let base = cx * (j / f[1] + cy * (k / f[2]));
            for (i, v) in line.iter_mut().enumerate() {
                *v += coarse.x[base + i / f[0]];
            }
        });
    }

    /// The coarser level's couplings from this one's (see [`super`]): each coarse low face
    /// takes the sum of the fine low faces of its lowest fine layer, scaled by 1/f_a (the
    /// re-discretisation with the arithmetic mean of the faces), and the open top likewise.
    pub fn coarsen_into(&self, coarse: &mut Level) {
        let f = factors(self.n);
        for a in 0..3 {
            // The fine low faces of the lowest fine layer along a of each coarse cell.
            let first_layer = |i: usize, j: usize, k: usize| [i, j, k][a] % f[a] == 0;
            self.sum_into(
                &self.low[a],
                first_layer,
                &mut coarse.low[a],
                f[a],
                coarse.n,
            );
        }
        self.sum_into(&self.open, |_, _, _| true, &mut coarse.open, f[2], coarse.n);
        coarse.finish();
    }

    /// out(C) = (1/f) Σ `fine`(c) over the fine cells c of coarse cell C that `take` (in the
    /// order k, j, i), on a coarse level of `n` cells.
    fn sum_into(
        &self,
        fine: &[f64],
        take: impl Fn(usize, usize, usize) -> bool + Sync,
        out: &mut [f64],
        f_axis: usize,
        n: [usize; 3],
    ) {
        let f = factors(self.n);
        let [nx, ny, nz] = self.n;
        let scale = 1.0 / f_axis as f64;
        for_each_chunk(out, n[0], |crow, line| {
            let (cj, ck) = (crow % n[1], crow / n[1]);
            line.iter_mut().for_each(|v| *v = 0.0);
            for k in f[2] * ck..(f[2] * ck + f[2]).min(nz) {
                for j in f[1] * cj..(f[1] * cj + f[1]).min(ny) {
                    let own = nx * (j + ny * k);
                    for i in 0..nx {
                        if take(i, j, k) {
                            line[i / f[0]] += fine[own + i];
                        }
                    }
                }
            }
            line.iter_mut().for_each(|v| *v *= scale);
        });
    }
}

/// The coarsening factor of each axis: 2, or 1 on an axis of one cell.
pub(super) fn factors(n: [usize; 3]) -> [usize; 3] {
    n.map(|n| if n > 1 { 2 } else { 1 })
}

/// The cells of the next coarser level: ⌈n_a / f_a⌉.
pub(super) fn coarser(n: [usize; 3]) -> [usize; 3] {
    let f = factors(n);
    std::array::from_fn(|a| n[a].div_ceil(f[a]))
}
