//! One level of the multigrid hierarchy: the positive operator Â = −D((1/ρ̄_f) G) as face
//! couplings on a box of cells, its red-black Gauss-Seidel half-sweeps, and the transfers
//! to and from the next coarser level.
//!
//! Cells are compact, c = i + n_x (j + n_y k). `low[a][c]` is the coupling w [m⁻² m³ kg⁻¹ =
//! Pa⁻¹ s⁻² … in units of 1/(ρ h²)] across the low a-face of cell c, to its low neighbour
//! along a (across the box on a periodic axis; 0 on a wall, a closed face, or an axis of one
//! cell), so that
//!
//! ```text
//! (Â x)_c = diag_c x_c − Σ_a ( low_a[c] x_{c−a} + low_a[c+a] x_{c+a} )
//! diag_c  = Σ_a ( low_a[c] + low_a[c+a] ) + open_c
//! ```
//!
//! with `open_c` the coupling to the p = 0 face of an open top. Every loop writes each output
//! element from one task, reading the others, and every sum runs in an order fixed by the
//! stencil: the bits do not depend on the number of threads.

use crate::fluid::grid::for_each_chunk;

/// One grid level: couplings, and the vectors of a V-cycle on it.
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
}

/// The rows a row (j, k) reads: its own start and those of its y and z neighbours (`None`
/// past a wall).
#[derive(Clone, Copy)]
struct Rows {
    own: usize,
    y: [Option<usize>; 2],
    z: [Option<usize>; 2],
}

impl Level {
    /// A level of `n` cells, couplings zero.
    pub fn new(n: [usize; 3], periodic: [bool; 3]) -> Level {
        let len = n[0] * n[1] * n[2];
        let zero = || vec![0.0; len];
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
        }
    }

    /// Number of cells.
    pub fn len(&self) -> usize {
        self.n[0] * self.n[1] * self.n[2]
    }

    /// The neighbour of index `m` along an axis of `n` cells, `step` −1 or +1 (`None` past a
    /// wall, and on an axis of one cell).
    #[inline]
    fn step(&self, a: usize, m: usize, step: isize) -> Option<usize> {
        let n = self.n[a];
        if n == 1 {
            return None;
        }
        match (step, m) {
            (-1, 0) => self.periodic[a].then_some(n - 1),
            (-1, _) => Some(m - 1),
            (_, m) if m + 1 == n => self.periodic[a].then_some(0),
            _ => Some(m + 1),
        }
    }

    /// The rows that row number `row` (= j + n_y k) reads.
    fn rows(&self, row: usize) -> Rows {
        let [nx, ny, _] = self.n;
        let (j, k) = (row % ny, row / ny);
        let at = |j: usize, k: usize| nx * (j + ny * k);
        Rows {
            own: at(j, k),
            y: [self.step(1, j, -1), self.step(1, j, 1)].map(|m| m.map(|m| at(m, k))),
            z: [self.step(2, k, -1), self.step(2, k, 1)].map(|m| m.map(|m| at(j, m))),
        }
    }

    /// Σ over the neighbours of cell i of row `r` of coupling × x (the order: x low, x high,
    /// y low, y high, z low, z high).
    #[inline]
    fn neighbours(&self, r: &Rows, i: usize, x: &[f64]) -> f64 {
        let c = r.own + i;
        let mut s = 0.0;
        if let Some(m) = self.step(0, i, -1) {
            s += self.low[0][c] * x[r.own + m];
        }
        if let Some(m) = self.step(0, i, 1) {
            s += self.low[0][r.own + m] * x[r.own + m];
        }
        if let Some(lo) = r.y[0] {
            s += self.low[1][c] * x[lo + i];
        }
        if let Some(hi) = r.y[1] {
            s += self.low[1][hi + i] * x[hi + i];
        }
        if let Some(lo) = r.z[0] {
            s += self.low[2][c] * x[lo + i];
        }
        if let Some(hi) = r.z[1] {
            s += self.low[2][hi + i] * x[hi + i];
        }
        s
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
            for (i, d) in line.iter_mut().enumerate() {
                let c = r.own + i;
                let hi_x = self.step(0, i, 1).map_or(0.0, |m| self.low[0][r.own + m]);
                let hi_y = r.y[1].map_or(0.0, |h| self.low[1][h + i]);
                let hi_z = r.z[1].map_or(0.0, |h| self.low[2][h + i]);
                *d = self.low[0][c]
                    + hi_x
                    + self.low[1][c]
                    + hi_y
                    + self.low[2][c]
                    + hi_z
                    + self.open[c];
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

    /// out = Â x.
    #[cfg(test)]
    pub fn apply(&self, x: &[f64], out: &mut [f64]) {
        for_each_chunk(out, self.n[0], |row, line| {
            let r = self.rows(row);
            for (i, o) in line.iter_mut().enumerate() {
                *o = self.diag[r.own + i] * x[r.own + i] - self.neighbours(&r, i, x);
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
            let parity = (row % ny + row / ny + colour) % 2;
            line.copy_from_slice(&x[r.own..r.own + nx]);
            for i in (parity..nx).step_by(2) {
                let c = r.own + i;
                line[i] = (self.b[c] + self.neighbours(&r, i, x)) * self.inv_diag[c];
            }
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
                    for i in 0..self.n[0] {
                        let c = r.own + i;
                        let res = self.b[c] - (self.diag[c] * self.x[c])
                            + self.neighbours(&r, i, &self.x);
                        line[i / f[0]] += res;
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
        let [cx, cy, _] = coarse.n;
        let scale = f.map(|f| 1.0 / f as f64);
        for a in 0..3 {
            let mut low = std::mem::take(&mut coarse.low[a]);
            let mut open = std::mem::take(&mut coarse.open);
            let fine = &self.low[a];
            for_each_chunk(&mut low, cx, |crow, line| {
                let (cj, ck) = (crow % cy, crow / cy);
                line.iter_mut().for_each(|v| *v = 0.0);
                for k in f[2] * ck..(f[2] * ck + f[2]).min(self.n[2]) {
                    for j in f[1] * cj..(f[1] * cj + f[1]).min(self.n[1]) {
                        let own = self.n[0] * (j + self.n[1] * k);
                        for i in 0..self.n[0] {
                            let m = [i, j, k][a];
                            if m % f[a] == 0 {
                                line[i / f[0]] += fine[own + i];
                            }
                        }
                    }
                }
                line.iter_mut().for_each(|v| *v *= scale[a]);
            });
            if a == 2 {
                let fine = &self.open;
                for_each_chunk(&mut open, cx, |crow, line| {
                    let (cj, ck) = (crow % cy, crow / cy);
                    line.iter_mut().for_each(|v| *v = 0.0);
                    for k in f[2] * ck..(f[2] * ck + f[2]).min(self.n[2]) {
                        for j in f[1] * cj..(f[1] * cj + f[1]).min(self.n[1]) {
                            let own = self.n[0] * (j + self.n[1] * k);
                            for i in 0..self.n[0] {
                                line[i / f[0]] += fine[own + i];
                            }
                        }
                    }
                    line.iter_mut().for_each(|v| *v *= scale[2]);
                });
            }
            coarse.low[a] = low;
            coarse.open = open;
        }
        coarse.finish();
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
