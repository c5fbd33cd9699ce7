//! The coarsest level's direct solve: Â = L D Lᵀ (L unit lower triangular) of the dense
//! matrix, with the pivots that fall to round-off (the constant of an all-Neumann or
//! periodic box, a cell inside an obstacle, a region that obstacles cut off) set to zero and
//! their components of the solution to zero. The result, x = L⁻ᵀ D⁺ L⁻¹ b, is a symmetric
//! positive semi-definite generalised inverse of Â (Golub & Van Loan 2013, §4.2), which is
//! what the V-cycle needs to stay symmetric.

use super::level::Level;

/// A pivot below this fraction of its diagonal entry is taken as zero: the singular pivots
/// are round-off, about 1e-16 of the largest coupling, or 1e-13 of the smallest with a
/// density ratio of 830; a true pivot of a connected level is at least of the order of the
/// smallest coupling over the number of cells.
const ZERO_PIVOT: f64 = 1e-10;

/// The factorisation, in a buffer sized once.
#[derive(Default)]
pub(super) struct Dense {
    n: usize,
    /// L below the diagonal, D on it (row-major n × n).
    m: Vec<f64>,
}

impl Dense {
    /// Factors the operator of `level`.
    pub fn factor(&mut self, level: &Level) {
        let n = level.len();
        self.n = n;
        self.m.clear();
        self.m.resize(n * n, 0.0);
        let m = &mut self.m;
        let [nx, ny, nz] = level.n;
        // Â: the diagonal, and −w for each low face (both triangles).
        for k in 0..nz {
            for j in 0..ny {
                for i in 0..nx {
                    let c = i + nx * (j + ny * k);
                    m[c * n + c] = level.diag[c];
                    for (a, idx) in [i, j, k].into_iter().enumerate() {
                        if level.n[a] == 1 || (idx == 0 && !level.periodic[a]) {
                            continue;
                        }
                        let mut q = [i, j, k];
                        q[a] = if idx == 0 { level.n[a] - 1 } else { idx - 1 };
                        let d = q[0] + nx * (q[1] + ny * q[2]);
                        m[c * n + d] -= level.low[a][c];
                        m[d * n + c] -= level.low[a][c];
                    }
                }
            }
        }
        // L D Lᵀ by columns.
        for j in 0..n {
            let a_jj = m[j * n + j];
            let mut d = a_jj;
            for k in 0..j {
                d -= m[j * n + k] * m[j * n + k] * m[k * n + k];
            }
            if d.is_nan() || d <= ZERO_PIVOT * a_jj {
                m[j * n + j] = 0.0;
                for i in j + 1..n {
                    m[i * n + j] = 0.0;
                }
                continue;
            }
            m[j * n + j] = d;
            for i in j + 1..n {
                let mut s = m[i * n + j];
                for k in 0..j {
                    s -= m[i * n + k] * m[j * n + k] * m[k * n + k];
                }
                m[i * n + j] = s / d;
            }
        }
    }

    /// x = L⁻ᵀ D⁺ L⁻¹ b, in place.
    pub fn solve(&self, x: &mut [f64]) {
        let (n, m) = (self.n, &self.m);
        for i in 0..n {
            let mut s = x[i];
            for k in 0..i {
                s -= m[i * n + k] * x[k];
            }
            x[i] = s;
        }
        for i in 0..n {
            let d = m[i * n + i];
            x[i] = if d > 0.0 { x[i] / d } else { 0.0 };
        }
        for i in (0..n).rev() {
            let mut s = x[i];
            for k in i + 1..n {
                s -= m[k * n + i] * x[k];
            }
            x[i] = s;
        }
    }
}
