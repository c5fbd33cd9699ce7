//! Eigenvalues and eigenvectors of a real symmetric matrix by cyclic Jacobi rotations.
//!
//! Used for the principal axes of an inertia tensor (3 × 3) and for the small normal-equation
//! matrix of the member-mass fit (10 × 10, `member_masses`). Each sweep visits every
//! off-diagonal entry a_pq and annihilates it with the plane rotation of angle
//! θ = ½ atan2(2 a_pq, a_qq − a_pp) (Golub & Van Loan, *Matrix Computations*, 4th ed., §8.5.2);
//! the sum of squares of the off-diagonal entries falls quadratically once small. Rotations are
//! accumulated into the eigenvector matrix, which therefore stays proper orthogonal (det = +1).
//!
//! An entry already below `1e-15` of the matrix norm is left alone, so a diagonal (or
//! numerically diagonal) input comes back unrotated: the principal axes of a cube or a sphere,
//! whose moments are equal, stay the template's own axes instead of being turned by round-off.

use crate::math::{Mat3, Vec3};

/// Eigen-decomposition of a symmetric n × n matrix: `a = V diag(λ) Vᵀ`.
#[derive(Clone, Debug, PartialEq)]
pub struct SymmetricEigen {
    /// Eigenvalues λ_k, in the order of the columns of `vectors` (not sorted).
    pub values: Vec<f64>,
    /// Eigenvectors as columns, row-major: `vectors[r * n + k]` is component r of vector k.
    pub vectors: Vec<f64>,
    /// Order n.
    pub n: usize,
}

/// Largest number of sweeps; double precision converges in under 10 for n ≤ 10.
const MAX_SWEEPS: usize = 60;

/// Relative size below which an off-diagonal entry counts as zero.
const NEGLIGIBLE: f64 = 1e-15;

/// Diagonalises the symmetric matrix `a` (row-major, n × n; only its upper triangle is read,
/// the lower is taken as its mirror).
pub fn symmetric_eigen(a: &[f64], n: usize) -> SymmetricEigen {
    assert_eq!(a.len(), n * n, "symmetric_eigen: matrix is not n × n");
    let mut m = vec![0.0; n * n];
    for r in 0..n {
        for c in r..n {
            m[r * n + c] = a[r * n + c];
            m[c * n + r] = a[r * n + c];
        }
    }
    let mut v = vec![0.0; n * n];
    for k in 0..n {
        v[k * n + k] = 1.0;
    }
    let norm = m.iter().map(|x| x * x).sum::<f64>().sqrt();
    let tiny = NEGLIGIBLE * norm;
    for _ in 0..MAX_SWEEPS {
        let off: f64 = (0..n)
            .flat_map(|r| (r + 1..n).map(move |c| (r, c)))
            .map(|(r, c)| m[r * n + c] * m[r * n + c])
            .sum();
        if off.sqrt() <= tiny {
            break;
        }
        for p in 0..n {
            for q in p + 1..n {
                let apq = m[p * n + q];
                if apq.abs() <= tiny {
                    continue;
                }
                // tan 2θ = 2 a_pq / (a_qq − a_pp), with |θ| ≤ π/4 (the smaller rotation, so a
                // nearly diagonal matrix keeps its axes in order).
                let gap = m[q * n + q] - m[p * n + p];
                let theta = if gap == 0.0 {
                    std::f64::consts::FRAC_PI_4.copysign(apq)
                } else {
                    0.5 * (2.0 * apq / gap).atan()
                };
                let (s, c) = theta.sin_cos();
                // m ← Jᵀ m J with J the rotation in the (p, q) plane; columns then rows.
                for k in 0..n {
                    let (mkp, mkq) = (m[k * n + p], m[k * n + q]);
                    m[k * n + p] = c * mkp - s * mkq;
                    m[k * n + q] = s * mkp + c * mkq;
                }
                for k in 0..n {
                    let (mpk, mqk) = (m[p * n + k], m[q * n + k]);
                    m[p * n + k] = c * mpk - s * mqk;
                    m[q * n + k] = s * mpk + c * mqk;
                }
                m[p * n + q] = 0.0;
                m[q * n + p] = 0.0;
                for k in 0..n {
                    let (vkp, vkq) = (v[k * n + p], v[k * n + q]);
                    v[k * n + p] = c * vkp - s * vkq;
                    v[k * n + q] = s * vkp + c * vkq;
                }
            }
        }
    }
    SymmetricEigen {
        values: (0..n).map(|k| m[k * n + k]).collect(),
        vectors: v,
        n,
    }
}

/// Principal moments and axes of a symmetric 3 × 3 tensor: `(λ, R)` with `t = R diag(λ) Rᵀ`,
/// the columns of R the principal axes, det R = +1.
pub fn principal_axes(t: Mat3) -> (Vec3, Mat3) {
    let a = [
        t.x_axis.x, t.y_axis.x, t.z_axis.x, //
        t.x_axis.y, t.y_axis.y, t.z_axis.y, //
        t.x_axis.z, t.y_axis.z, t.z_axis.z,
    ];
    let e = symmetric_eigen(&a, 3);
    let col = |k: usize| Vec3::new(e.vectors[k], e.vectors[3 + k], e.vectors[6 + k]);
    let r = Mat3::from_cols(col(0), col(1), col(2));
    (Vec3::new(e.values[0], e.values[1], e.values[2]), r)
}

/// Solves the symmetric system `a x = b` in the least-squares, minimum-norm sense (the
/// pseudo-inverse), dropping eigenvalues below `rcond` times the largest. Returns x.
pub fn pseudo_solve(a: &[f64], b: &[f64], n: usize, rcond: f64) -> Vec<f64> {
    let e = symmetric_eigen(a, n);
    let lmax = e.values.iter().fold(0.0f64, |m, l| m.max(l.abs()));
    let mut x = vec![0.0; n];
    for k in 0..n {
        let l = e.values[k];
        if l.abs() <= rcond * lmax || l == 0.0 {
            continue;
        }
        // x += v_k (v_k · b) / λ_k
        let vb: f64 = (0..n).map(|r| e.vectors[r * n + k] * b[r]).sum();
        for (r, xr) in x.iter_mut().enumerate() {
            *xr += e.vectors[r * n + k] * vb / l;
        }
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reconstructs_a_full_symmetric_matrix() {
        let t = Mat3::from_cols(
            Vec3::new(4.0, 1.0, -2.0),
            Vec3::new(1.0, 3.0, 0.5),
            Vec3::new(-2.0, 0.5, 7.0),
        );
        let (l, r) = principal_axes(t);
        let back = r * Mat3::from_diagonal(l) * r.transpose();
        assert!((back - t).to_cols_array().iter().all(|x| x.abs() < 1e-13));
        assert!((r.determinant() - 1.0).abs() < 1e-13);
        // Trace and determinant are invariants.
        assert!((l.x + l.y + l.z - 14.0).abs() < 1e-13);
        assert!((l.x * l.y * l.z - t.determinant()).abs() < 1e-11);
    }

    #[test]
    fn a_diagonal_matrix_is_left_unrotated() {
        let t = Mat3::from_diagonal(Vec3::new(2.0, 2.0, 2.0 + 1e-17));
        let (l, r) = principal_axes(t);
        assert_eq!(r, Mat3::IDENTITY);
        assert_eq!(l.x, 2.0);
    }

    #[test]
    fn pseudo_solve_handles_a_singular_system() {
        // [[1,1],[1,1]] x = [2,2]: minimum-norm solution (1, 1).
        let x = pseudo_solve(&[1.0, 1.0, 1.0, 1.0], &[2.0, 2.0], 2, 1e-12);
        assert!((x[0] - 1.0).abs() < 1e-14 && (x[1] - 1.0).abs() < 1e-14);
    }
}
