//! Direct solver of the discrete Poisson equation by eigen-decomposition: Fourier transforms
//! along periodic axes, cosine transforms (DCT-II / DCT-III) along axes with Neumann walls,
//! quarter-wave cosine transforms (DCT-IV) along an axis open at its high end.
//!
//! The 7-point Laplacian L = D G of the staggered grid is a sum of one-dimensional second
//! differences, L = L_x + L_y + L_z, each acting along one axis. Along an axis of n cells of
//! size h:
//!
//! * periodic: the eigenvectors of L_a are exp(2πi k m / n) (the DFT), eigenvalues
//!   λ_k = −(4/h²) sin²(π k / n), k = 0 … n−1;
//! * homogeneous Neumann at both ends (the boundary face velocity is fixed, so the projection
//!   never moves it): the eigenvectors are cos(π k (m + ½) / n) (the DCT-II basis),
//!   eigenvalues λ_k = −(4/h²) sin²(π k / (2n));
//! * Neumann at the low end, p = 0 on the high end's face (a top open to the atmosphere,
//!   [`super::super::boundary::Boundary::Open`]): the eigenvectors are
//!   cos(π (k + ½)(m + ½) / n) (the DCT-IV basis), eigenvalues
//!   λ_k = −(4/h²) sin²(π (k + ½) / (2n)), none zero.
//!
//! So L p = f is solved exactly (to round-off) by transforming f along x, y and z, dividing
//! each mode by λ_x + λ_y + λ_z, and transforming back; the single zero mode (the additive
//! constant of the pressure) is set to zero. Cost O(N log N), no iteration, and
//! `divergence ∘ gradient ∘ solve` is the identity on zero-mean data, which is what makes the
//! projected velocity divergence-free to round-off.
//!
//! The data are held as complex numbers so that Fourier and cosine axes mix freely (a DCT acts
//! on the real and imaginary parts separately); when no axis is periodic the imaginary part
//! stays zero and is skipped. x-lines are contiguous; y and z are made contiguous by
//! transposing. Every line is transformed independently and every output element is written by
//! one task, so the result is identical for any number of threads. All buffers and plans are
//! made once in [`SpectralPoisson::new`]; `solve` allocates nothing.

use super::PoissonSolver;
use crate::fluid::grid::{for_each_chunk, SERIAL_BELOW};
use rayon::prelude::*;
use rustdct::{DctPlanner, TransformType2And3, TransformType4};
use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};
use std::f64::consts::PI;
use std::sync::Arc;

/// The boundary type of one axis as the pressure equation sees it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AxisKind {
    /// Periodic axis: Fourier transform.
    Periodic,
    /// Homogeneous Neumann at both ends: cosine transform.
    Neumann,
    /// Homogeneous Neumann at the low end, p = 0 on the high end's face: quarter-wave cosine
    /// transform.
    NeumannOpen,
}

/// How one axis is transformed.
enum Transform {
    /// A single cell along this axis: nothing to do (λ = 0).
    Identity,
    /// Forward and inverse complex FFT (unnormalised; a round trip multiplies by n).
    Fourier(Arc<dyn Fft<f64>>, Arc<dyn Fft<f64>>),
    /// DCT-II forward, DCT-III inverse (unnormalised; a round trip multiplies by n/2).
    Cosine(Arc<dyn TransformType2And3<f64>>),
    /// DCT-IV both ways (unnormalised; a round trip multiplies by n/2).
    QuarterCosine(Arc<dyn TransformType4<f64>>),
}

/// Scratch space of one task: FFT scratch, one real line, the DCT scratch, and a block of
/// [`BLOCK`] y-lines gathered from a plane.
struct LineScratch {
    fft: Vec<Complex<f64>>,
    line: Vec<f64>,
    dct: Vec<f64>,
    block: Vec<Complex<f64>>,
}

/// Number of groups of lines handed to tasks; fixed so that scratch is allocated once.
const GROUPS: usize = 64;

/// Lines gathered together when a transform runs across the storage order: the y-lines of
/// [`BLOCK`] neighbouring x, or the z-lines of the transposition. [`BLOCK`] consecutive
/// complex numbers (256 bytes, four cache lines) are read or written at a time, instead of one
/// number per cache line.
const BLOCK: usize = 16;

/// The FFT/DCT Poisson solver for a box of `n` cells with spacing `h`.
pub struct SpectralPoisson {
    n: [usize; 3],
    transforms: [Transform; 3],
    /// λ_a(k) [m⁻²] along each axis.
    eigenvalues: [Vec<f64>; 3],
    /// The product of the round-trip factors of the unnormalised transforms of the three axes.
    round_trip: f64,
    /// True when some axis is periodic (the imaginary part is needed).
    complex: bool,
    /// The data in storage order (x fastest): i + nx (j + ny k).
    a: Vec<Complex<f64>>,
    /// The data transposed for the z-transforms (z fastest): k + nz (i + nx j).
    b: Vec<Complex<f64>>,
    scratch: Vec<LineScratch>,
}

impl SpectralPoisson {
    /// Plans the transforms and allocates the workspace for `n` cells of size `h` [m].
    pub fn new(n: [usize; 3], h: [f64; 3], kinds: [AxisKind; 3]) -> SpectralPoisson {
        let mut fft_planner = FftPlanner::<f64>::new();
        let mut dct_planner = DctPlanner::<f64>::new();
        let mut fft_scratch = 0;
        let mut dct_scratch = 0;
        let transforms = std::array::from_fn(|a| {
            if kinds[a] == AxisKind::NeumannOpen {
                let d = dct_planner.plan_dct4(n[a]);
                dct_scratch = dct_scratch.max(d.get_scratch_len());
                Transform::QuarterCosine(d)
            } else if n[a] == 1 {
                Transform::Identity
            } else if kinds[a] == AxisKind::Periodic {
                let f = fft_planner.plan_fft_forward(n[a]);
                let i = fft_planner.plan_fft_inverse(n[a]);
                fft_scratch = fft_scratch
                    .max(f.get_inplace_scratch_len())
                    .max(i.get_inplace_scratch_len());
                Transform::Fourier(f, i)
            } else {
                let d = dct_planner.plan_dct2(n[a]);
                dct_scratch = dct_scratch.max(d.get_scratch_len());
                Transform::Cosine(d)
            }
        });
        let mut round_trip = 1.0;
        let eigenvalues = std::array::from_fn(|a| {
            let (len, h2) = (n[a], h[a] * h[a]);
            // λ_k = −(4/h²) sin²(arg (k + shift)).
            let (arg, shift, factor) = match (kinds[a], len) {
                (AxisKind::NeumannOpen, _) => (PI / (2.0 * len as f64), 0.5, 0.5 * len as f64),
                (_, 1) => (0.0, 0.0, 1.0),
                (AxisKind::Periodic, _) => (PI / len as f64, 0.0, len as f64),
                (AxisKind::Neumann, _) => (PI / (2.0 * len as f64), 0.0, 0.5 * len as f64),
            };
            round_trip *= factor;
            (0..len)
                .map(|k| -4.0 * (arg * (k as f64 + shift)).sin().powi(2) / h2)
                .collect()
        });
        let complex = (0..3).any(|a| kinds[a] == AxisKind::Periodic && n[a] > 1);
        let total = n[0] * n[1] * n[2];
        let max_n = n.iter().copied().max().unwrap_or(1);
        let zero = Complex::new(0.0, 0.0);
        let scratch = (0..GROUPS)
            .map(|_| LineScratch {
                fft: vec![zero; fft_scratch],
                line: vec![0.0; max_n],
                dct: vec![0.0; dct_scratch],
                block: vec![zero; BLOCK * n[1]],
            })
            .collect();
        SpectralPoisson {
            n,
            transforms,
            eigenvalues,
            round_trip,
            complex,
            a: vec![zero; total],
            b: vec![zero; total],
            scratch,
        }
    }
}

/// Transforms every contiguous line of length `len` of `chunk`, on one task, with the
/// scratch `fft`, `line` and `dct` of [`LineScratch`].
#[allow(clippy::too_many_arguments)]
fn transform_chunk(
    chunk: &mut [Complex<f64>],
    len: usize,
    transform: &Transform,
    forward: bool,
    complex: bool,
    fft: &mut [Complex<f64>],
    line: &mut [f64],
    dct: &mut [f64],
) {
    match transform {
        Transform::Identity => {}
        Transform::Fourier(f, i) => {
            let plan = if forward { f } else { i };
            plan.process_with_scratch(chunk, fft);
        }
        Transform::Cosine(_) | Transform::QuarterCosine(_) => {
            for z_line in chunk.chunks_mut(len) {
                let parts = if complex { 2 } else { 1 };
                for part in 0..parts {
                    let r = &mut line[..len];
                    for (x, z) in r.iter_mut().zip(z_line.iter()) {
                        *x = if part == 0 { z.re } else { z.im };
                    }
                    match transform {
                        Transform::Cosine(d) if forward => d.process_dct2_with_scratch(r, dct),
                        Transform::Cosine(d) => d.process_dct3_with_scratch(r, dct),
                        Transform::QuarterCosine(d) => d.process_dct4_with_scratch(r, dct),
                        _ => unreachable!("a cosine transform"),
                    }
                    for (z, x) in z_line.iter_mut().zip(r.iter()) {
                        if part == 0 {
                            z.re = *x;
                        } else {
                            z.im = *x;
                        }
                    }
                }
            }
        }
    }
}

/// Transforms every contiguous line of length `len` of `buf` along one axis, in parallel
/// over groups of lines.
fn transform_lines(
    buf: &mut [Complex<f64>],
    len: usize,
    transform: &Transform,
    forward: bool,
    complex: bool,
    scratch: &mut [LineScratch],
) {
    if let Transform::Identity = transform {
        return;
    }
    let lines = buf.len() / len;
    let per_group = lines.div_ceil(scratch.len());
    let work = |(chunk, s): (&mut [Complex<f64>], &mut LineScratch)| {
        let (fft, line, dct) = (&mut s.fft, &mut s.line, &mut s.dct);
        transform_chunk(chunk, len, transform, forward, complex, fft, line, dct);
    };
    if buf.len() < SERIAL_BELOW {
        buf.chunks_mut(per_group * len)
            .zip(scratch.iter_mut())
            .for_each(work);
    } else {
        buf.par_chunks_mut(per_group * len)
            .zip(scratch.par_iter_mut())
            .for_each(work);
    }
}

/// Transforms the y-lines of `buf` (storage order i + nx (j + ny k)) in place, in parallel
/// over xy-planes: in each plane the lines of [`BLOCK`] neighbouring x are gathered into
/// contiguous scratch, transformed there and put back.
fn transform_y_lines(
    buf: &mut [Complex<f64>],
    [nx, ny, nz]: [usize; 3],
    transform: &Transform,
    forward: bool,
    complex: bool,
    scratch: &mut [LineScratch],
) {
    if let Transform::Identity = transform {
        return;
    }
    let plane = nx * ny;
    let per_group = nz.div_ceil(scratch.len());
    let work = |(chunk, s): (&mut [Complex<f64>], &mut LineScratch)| {
        let (fft, line, dct, block) = (&mut s.fft, &mut s.line, &mut s.dct, &mut s.block);
        for p in chunk.chunks_mut(plane) {
            for i0 in (0..nx).step_by(BLOCK) {
                let w = BLOCK.min(nx - i0);
                let lines = &mut block[..w * ny];
                for j in 0..ny {
                    let row = &p[i0 + nx * j..i0 + nx * j + w];
                    for (q, z) in row.iter().enumerate() {
                        lines[q * ny + j] = *z;
                    }
                }
                transform_chunk(lines, ny, transform, forward, complex, fft, line, dct);
                for j in 0..ny {
                    let row = &mut p[i0 + nx * j..i0 + nx * j + w];
                    for (q, z) in row.iter_mut().enumerate() {
                        *z = lines[q * ny + j];
                    }
                }
            }
        }
    };
    if buf.len() < SERIAL_BELOW {
        buf.chunks_mut(per_group * plane)
            .zip(scratch.iter_mut())
            .for_each(work);
    } else {
        buf.par_chunks_mut(per_group * plane)
            .zip(scratch.par_iter_mut())
            .for_each(work);
    }
}

/// The transpose `dst[l·R + r] = src[r·L + l]` of the R × L row-major `src` (R = src.len()/L),
/// in parallel over blocks of [`BLOCK`] rows of `dst`, each reading [`BLOCK`] consecutive
/// numbers of every row of `src` at a time.
fn transpose(src: &[Complex<f64>], dst: &mut [Complex<f64>], len: usize) {
    let rows = src.len() / len;
    let work = |(b, chunk): (usize, &mut [Complex<f64>])| {
        let l0 = b * BLOCK;
        let w = chunk.len() / rows;
        for r in 0..rows {
            let from = &src[r * len + l0..r * len + l0 + w];
            for (q, z) in from.iter().enumerate() {
                chunk[q * rows + r] = *z;
            }
        }
    };
    if dst.len() < SERIAL_BELOW {
        dst.chunks_mut(BLOCK * rows).enumerate().for_each(work);
    } else {
        dst.par_chunks_mut(BLOCK * rows).enumerate().for_each(work);
    }
}

impl PoissonSolver for SpectralPoisson {
    fn solve(&mut self, data: &mut [f64]) {
        let n = self.n;
        let [nx, _, nz] = n;
        assert_eq!(
            data.len(),
            n[0] * n[1] * n[2],
            "Poisson data must be nx·ny·nz"
        );
        let complex = self.complex;
        let (a, b, s) = (&mut self.a, &mut self.b, &mut self.scratch);
        let t = &self.transforms;
        // a: storage order, i + nx (j + ny k); b: z fastest, k + nz (i + nx j).
        for_each_chunk(a, nx, |m, line| {
            let f = &data[m * nx..(m + 1) * nx];
            for (z, &x) in line.iter_mut().zip(f) {
                *z = Complex::new(x, 0.0);
            }
        });
        transform_lines(a, nx, &t[0], true, complex, s);
        transform_y_lines(a, n, &t[1], true, complex, s);
        transpose(a, b, nx * n[1]);
        transform_lines(b, nz, &t[2], true, complex, s);

        // Divide each mode by its eigenvalue λ_x + λ_y + λ_z and by the round-trip factor.
        let (lam, round_trip) = (&self.eigenvalues, self.round_trip);
        for_each_chunk(b, nz, |m, line| {
            let (i, j) = (m % nx, m / nx);
            for (k, z) in line.iter_mut().enumerate() {
                let l = (lam[0][i] + lam[1][j] + lam[2][k]) * round_trip;
                *z = if l == 0.0 {
                    Complex::new(0.0, 0.0)
                } else {
                    *z / l
                };
            }
        });

        transform_lines(b, nz, &t[2], false, complex, s);
        transpose(b, a, nz);
        transform_y_lines(a, n, &t[1], false, complex, s);
        transform_lines(a, nx, &t[0], false, complex, s);
        for_each_chunk(data, nx, |m, f| {
            let line = &a[m * nx..(m + 1) * nx];
            for (x, z) in f.iter_mut().zip(line) {
                *x = z.re;
            }
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Applies the 7-point Laplacian with periodic or Neumann ends to compact data.
    pub(super) fn laplacian(
        n: [usize; 3],
        h: [f64; 3],
        kinds: [AxisKind; 3],
        p: &[f64],
    ) -> Vec<f64> {
        let idx = |i: usize, j: usize, k: usize| i + n[0] * (j + n[1] * k);
        let mut out = vec![0.0; p.len()];
        for k in 0..n[2] {
            for j in 0..n[1] {
                for i in 0..n[0] {
                    let c = [i, j, k];
                    let mut sum = 0.0;
                    for a in 0..3 {
                        for step in [-1i64, 1] {
                            let mut d = c;
                            let m = c[a] as i64 + step;
                            if m < 0 || m >= n[a] as i64 {
                                if kinds[a] == AxisKind::NeumannOpen && m >= n[a] as i64 {
                                    // p = 0 on the face: the ghost is −p.
                                    sum -= 2.0 * p[idx(i, j, k)] / (h[a] * h[a]);
                                    continue;
                                }
                                if kinds[a] != AxisKind::Periodic {
                                    continue; // zero flux through the wall
                                }
                                d[a] = m.rem_euclid(n[a] as i64) as usize;
                            } else {
                                d[a] = m as usize;
                            }
                            sum += (p[idx(d[0], d[1], d[2])] - p[idx(i, j, k)]) / (h[a] * h[a]);
                        }
                    }
                    out[idx(i, j, k)] = sum;
                }
            }
        }
        out
    }

    #[test]
    fn inverts_the_discrete_laplacian_for_every_axis_kind() {
        use AxisKind::{Neumann, NeumannOpen, Periodic};
        for (n, kinds) in [
            ([8, 1, 6], [Neumann, Periodic, NeumannOpen]),
            ([6, 4, 1], [Periodic, Periodic, NeumannOpen]),
            ([5, 3, 7], [Neumann, Neumann, NeumannOpen]),
            ([8, 6, 5], [Periodic, Periodic, Periodic]),
            ([8, 6, 5], [Neumann, Neumann, Neumann]),
            ([7, 1, 6], [Neumann, Periodic, Periodic]),
            ([6, 4, 9], [Periodic, Neumann, Periodic]),
            ([5, 8, 4], [Periodic, Periodic, Neumann]),
        ] {
            let h = [0.3, 0.7, 0.45];
            let total = n[0] * n[1] * n[2];
            // A zero-mean right-hand side.
            let mut f: Vec<f64> = (0..total)
                .map(|m| ((m * 7919) % 101) as f64 - 50.0)
                .collect();
            let mean = f.iter().sum::<f64>() / total as f64;
            f.iter_mut().for_each(|x| *x -= mean);
            let mut p = f.clone();
            let mut solver = SpectralPoisson::new(n, h, kinds);
            solver.solve(&mut p);
            let lp = laplacian(n, h, kinds, &p);
            let scale = f.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let err = lp
                .iter()
                .zip(&f)
                .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
            // Round-off of O(N log N) operations on O(1) data: 1e-12 relative is ~10⁴ ulps.
            assert!(err < 1e-12 * scale, "{kinds:?} {n:?}: residual {err:e}");
            // With Neumann and periodic ends only, the solution is the one of zero mean.
            if !kinds.contains(&NeumannOpen) {
                let p_mean = p.iter().sum::<f64>() / total as f64;
                assert!(p_mean.abs() < 1e-12 * scale, "solution mean {p_mean:e}");
            }
        }
    }
}
