//! Rienecker & Fenton's (1981) nonlinear system for a steady wave and its solution by Newton's
//! method with the height stepped up (Fenton 1988): the set-up work behind
//! [`super::StreamFunction::with_current`].

use std::f64::consts::PI;

use super::*;

#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Criterion {
    MassTransport,
    Eulerian,
}

/// cos(jmπ/N) and sin(jmπ/N), m = 0 … N (rows), j = 0 … N (columns).
pub(super) struct Tables {
    pub(super) cos: Vec<f64>,
    pub(super) sin: Vec<f64>,
}

impl Tables {
    pub(super) fn new(n: usize) -> Tables {
        let at = |f: fn(f64) -> f64| {
            (0..=n)
                .flat_map(|m| (0..=n).map(move |j| f(((j * m) % (2 * n)) as f64 * PI / n as f64)))
                .collect()
        };
        Tables {
            cos: at(f64::cos),
            sin: at(f64::sin),
        }
    }
}

/// The dimensionless system: τ = T √(g/d) [-], the criterion's value σ = c_{S or E}/√(g d)
/// [-], and the layout of the 2N + 6 unknowns (all scaled by g and k): k d, η_m k (from the
/// bed, m = 0 … N), B_j √(k³/g) (j = 1 … N), Ū √(k/g), c √(k/g), Q √(k³/g), R k/g.
pub(super) struct Problem {
    pub(super) n: usize,
    pub(super) tau: f64,
    pub(super) criterion: Criterion,
    pub(super) sigma: f64,
    pub(super) tables: Tables,
}

/// Newton's iterations allowed per height step.
const ITERATIONS: usize = 40;

impl Problem {
    pub(super) fn size(&self) -> usize {
        2 * self.n + 6
    }
    pub(super) fn eta(&self, m: usize) -> usize {
        1 + m
    }
    pub(super) fn b(&self, j: usize) -> usize {
        self.n + 1 + j
    }
    pub(super) fn ubar(&self) -> usize {
        2 * self.n + 2
    }
    pub(super) fn c(&self) -> usize {
        2 * self.n + 3
    }
    pub(super) fn q(&self) -> usize {
        2 * self.n + 4
    }
    pub(super) fn r(&self) -> usize {
        2 * self.n + 5
    }

    /// Linear theory's solution for H/d = `alpha`: kd from ω² = g k tanh kd, c = √(tanh kd),
    /// η = d + (H/2) cos X, B_1 = c (kH/2)/tanh kd, Ū = c, Q = c d (c_S = 0), R = ½ c² + d.
    pub(super) fn linear(&self, alpha: f64) -> Vec<f64> {
        let kd = crate::fluid::waves::wavenumber(2.0 * PI / self.tau, 1.0, 1.0);
        let c = kd.tanh().sqrt();
        let a = 0.5 * alpha * kd;
        let mut x = vec![0.0; self.size()];
        x[0] = kd;
        for m in 0..=self.n {
            x[self.eta(m)] = kd + a * (m as f64 * PI / self.n as f64).cos();
        }
        x[self.b(1)] = c * a / kd.tanh();
        x[self.ubar()] = c;
        x[self.c()] = c;
        x[self.q()] = c * kd;
        x[self.r()] = 0.5 * c * c + kd;
        x
    }

    /// The residuals f(x) and, when `jac` is given, the Jacobian ∂f/∂x (row-major), for the
    /// wave of H/d = `alpha`.
    pub(super) fn residual(
        &self,
        x: &[f64],
        alpha: f64,
        f: &mut [f64],
        mut jac: Option<&mut [f64]>,
    ) {
        let n = self.n;
        let size = self.size();
        let kd = x[0];
        let (ubar, c, q, r) = (x[self.ubar()], x[self.c()], x[self.q()], x[self.r()]);
        if let Some(j) = jac.as_deref_mut() {
            j.fill(0.0);
        }
        let set = |jac: &mut Option<&mut [f64]>, row: usize, col: usize, v: f64| {
            if let Some(j) = jac.as_deref_mut() {
                j[row * size + col] = v;
            }
        };
        // Mean depth: (1/N) Σ'' η_m − d = 0.
        let mut mean = 0.0;
        for m in 0..=n {
            let w = if m == 0 || m == n { 0.5 } else { 1.0 } / n as f64;
            mean += w * x[self.eta(m)];
            set(&mut jac, 0, self.eta(m), w);
        }
        f[0] = mean - kd;
        set(&mut jac, 0, 0, -1.0);
        // Height: η_0 − η_N − (H/d) kd = 0.
        f[1] = x[self.eta(0)] - x[self.eta(n)] - alpha * kd;
        set(&mut jac, 1, self.eta(0), 1.0);
        set(&mut jac, 1, self.eta(n), -1.0);
        set(&mut jac, 1, 0, -alpha);
        // Period: k c T = 2π, as c √(k/g) · T √(g/d) · √(kd) − 2π = 0.
        f[2] = c * self.tau * kd.sqrt() - 2.0 * PI;
        set(&mut jac, 2, self.c(), self.tau * kd.sqrt());
        set(&mut jac, 2, 0, c * self.tau / (2.0 * kd.sqrt()));
        // Current: c − Q/d − c_S = 0 or c − Ū − c_E = 0 (c_S √(k/g) = σ √(kd)).
        let s = self.sigma * kd.sqrt();
        let ds = 0.5 * self.sigma / kd.sqrt();
        set(&mut jac, 3, self.c(), 1.0);
        match self.criterion {
            Criterion::MassTransport => {
                f[3] = c - q / kd - s;
                set(&mut jac, 3, self.q(), -1.0 / kd);
                set(&mut jac, 3, 0, q / (kd * kd) - ds);
            }
            Criterion::Eulerian => {
                f[3] = c - ubar - s;
                set(&mut jac, 3, self.ubar(), -1.0);
                set(&mut jac, 3, 0, -ds);
            }
        }
        // The surface conditions at X_m = mπ/N (k = 1 here).
        let (p_d, r_d) = ((-kd).exp(), (-2.0 * kd).exp());
        for m in 0..=n {
            let (rk, rd) = (4 + m, 5 + n + m);
            let y = x[self.eta(m)];
            // sinh(jY)/cosh(jd) = (pʲ − qʲ)/(1 + rʲ), cosh: pʲ + qʲ, p = e^{Y−d}, q = e^{−Y−d}.
            let (p1, q1) = ((y - kd).exp(), (-y).exp() * p_d);
            let (mut pj, mut qj, mut rj) = (1.0, 1.0, 1.0);
            let (mut psi, mut u, mut v) = (-ubar * y, -ubar, 0.0);
            let (mut u_y, mut v_y, mut u_d, mut v_d, mut psi_d) = (0.0, 0.0, 0.0, 0.0, 0.0);
            for j in 1..=n {
                pj *= p1;
                qj *= q1;
                rj *= r_d;
                let (sj, cj) = ((pj - qj) / (1.0 + rj), (pj + qj) / (1.0 + rj));
                let tj = (1.0 - rj) / (1.0 + rj); // tanh(jd)
                let (cos, sin) = (
                    self.tables.cos[m * (n + 1) + j],
                    self.tables.sin[m * (n + 1) + j],
                );
                let (bj, jf) = (x[self.b(j)], j as f64);
                psi += bj * sj * cos;
                u += jf * bj * cj * cos;
                v += jf * bj * sj * sin;
                if jac.is_some() {
                    psi_d -= jf * bj * sj * tj * cos;
                    u_y += jf * jf * bj * sj * cos;
                    v_y += jf * jf * bj * cj * sin;
                    u_d -= jf * jf * bj * cj * tj * cos;
                    v_d -= jf * jf * bj * sj * tj * sin;
                    set(&mut jac, rk, self.b(j), sj * cos);
                }
            }
            // Kinematic: ψ(X_m, η_m) + Q = 0.
            f[rk] = psi + q;
            // Dynamic: ½ (U² + W²) + η_m − R = 0.
            f[rd] = 0.5 * (u * u + v * v) + y - r;
            if jac.is_some() {
                set(&mut jac, rk, self.eta(m), u);
                set(&mut jac, rk, 0, psi_d);
                set(&mut jac, rk, self.ubar(), -y);
                set(&mut jac, rk, self.q(), 1.0);
                // ∂/∂B_j of ½(U² + W²) = U j C_j cos + W j S_j sin, with the full U, W.
                let (mut pj, mut qj, mut rj) = (1.0, 1.0, 1.0);
                for j in 1..=n {
                    pj *= p1;
                    qj *= q1;
                    rj *= r_d;
                    let (sj, cj) = ((pj - qj) / (1.0 + rj), (pj + qj) / (1.0 + rj));
                    let (cos, sin) = (
                        self.tables.cos[m * (n + 1) + j],
                        self.tables.sin[m * (n + 1) + j],
                    );
                    let jf = j as f64;
                    set(
                        &mut jac,
                        rd,
                        self.b(j),
                        u * jf * cj * cos + v * jf * sj * sin,
                    );
                }
                set(&mut jac, rd, self.eta(m), u * u_y + v * v_y + 1.0);
                set(&mut jac, rd, 0, u * u_d + v * v_d);
                set(&mut jac, rd, self.ubar(), -u);
                set(&mut jac, rd, self.r(), -1.0);
            }
        }
    }

    /// Newton's method from `x` for H/d = `alpha`: the solution, or `None` when it does not
    /// converge (every residual below 1e-13 max(kd, 1), or the largest correction below
    /// 1e-12) within [`ITERATIONS`], or converges on something that is not a wave (below).
    pub(super) fn newton(&self, mut x: Vec<f64>, alpha: f64) -> Option<Vec<f64>> {
        let size = self.size();
        let mut f = vec![0.0; size];
        let mut jac = vec![0.0; size * size];
        for _ in 0..ITERATIONS {
            self.residual(&x, alpha, &mut f, Some(&mut jac));
            // The residuals are O(kd) numbers: round-off leaves ~1e-16 kd of them, and the
            // high harmonics' B_j, below round-off for large N, may keep the corrections
            // from shrinking further while the equations already hold.
            let worst = f.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            if worst < 1e-13 * x[0].max(1.0) {
                return self.is_a_wave(&x).then_some(x);
            }
            for v in f.iter_mut() {
                *v = -*v;
            }
            if !solve_dense(&mut jac, &mut f, size) {
                return None;
            }
            let mut largest = 0.0f64;
            for (xi, dx) in x.iter_mut().zip(&f) {
                *xi += dx;
                largest = largest.max(dx.abs());
            }
            if !largest.is_finite() || x[0] <= 0.0 {
                return None;
            }
            if largest < 1e-12 {
                return self.is_a_wave(&x).then_some(x);
            }
        }
        None
    }

    /// A converged solution is a wave: every unknown finite, the surface falling from crest
    /// to trough, and the water on it slower than the wave (U < 0 in the wave's frame: at
    /// the highest wave the crest is a stagnation point, beyond it there is none).
    pub(super) fn is_a_wave(&self, x: &[f64]) -> bool {
        let n = self.n;
        if x.iter().any(|v| !v.is_finite()) || x[0] <= 0.0 || x[self.c()] <= 0.0 {
            return false;
        }
        let falls = (0..n).all(|m| x[self.eta(m + 1)] <= x[self.eta(m)]);
        // R − η_m = ½ (U² + W²) at the surface; U < 0 there: check the crest, the fastest.
        let y = x[self.eta(0)];
        let kd = x[0];
        let mut u = -x[self.ubar()];
        for j in 1..=n {
            let jf = j as f64;
            let cj =
                ((jf * (y - kd)).exp() + (-jf * (y + kd)).exp()) / (1.0 + (-2.0 * jf * kd).exp());
            u += jf * x[self.b(j)] * cj;
        }
        falls && u < 0.0
    }

    /// The residual of the surface conditions at the N points X = (m + ½) π/N between the
    /// collocation points, η there from the cosine series: the larger of
    /// |ψ(X, η) + Q| / (c kH) and |½ (U² + W²) + η − R| / kH (k = g = 1).
    pub(super) fn between_points(&self, x: &[f64]) -> f64 {
        let n = self.n;
        let kd = x[0];
        let kh = x[self.eta(0)] - x[self.eta(n)];
        let (ubar, c, q, r) = (x[self.ubar()], x[self.c()], x[self.q()], x[self.r()]);
        let e: Vec<f64> = (0..=n)
            .map(|j| {
                let s: f64 = (0..=n)
                    .map(|m| {
                        let end = if m == 0 || m == n { 0.5 } else { 1.0 };
                        end * x[self.eta(m)] * self.tables.cos[m * (n + 1) + j]
                    })
                    .sum();
                let half = if j == 0 || j == n { 0.5 } else { 1.0 };
                half * 2.0 / n as f64 * s
            })
            .collect();
        let mut worst = 0.0f64;
        for m in 0..n {
            let xm = (m as f64 + 0.5) * PI / n as f64;
            let y: f64 = e
                .iter()
                .enumerate()
                .map(|(j, ej)| ej * (j as f64 * xm).cos())
                .sum();
            let (mut psi, mut u, mut v) = (-ubar * y, -ubar, 0.0);
            for j in 1..=n {
                let jf = j as f64;
                let den = 1.0 + (-2.0 * jf * kd).exp();
                let (p, qq) = ((jf * (y - kd)).exp(), (-jf * (y + kd)).exp());
                let (sj, cj) = ((p - qq) / den, (p + qq) / den);
                let (sin, cos) = (jf * xm).sin_cos();
                let bj = x[self.b(j)];
                psi += bj * sj * cos;
                u += jf * bj * cj * cos;
                v += jf * bj * sj * sin;
            }
            let kinematic = (psi + q).abs() / (c * kh);
            let dynamic = (0.5 * (u * u + v * v) + y - r).abs() / kh;
            worst = worst.max(kinematic).max(dynamic);
        }
        worst
    }

    /// The wave of H/d = `alpha`, the height raised in steps from a low wave. On failure,
    /// the highest H/d reached and the last k d.
    pub(super) fn solve_stepped(&self, alpha: f64) -> Result<Vec<f64>, (f64, f64)> {
        let start = self.linear(alpha);
        let kd_lin = start[0];
        // Steps: one per tenth of the highest wave of the linear length (at least one).
        let steep = alpha / highest_wave(2.0 * PI / kd_lin);
        let steps = (10.0 * steep).ceil().clamp(1.0, 40.0) as usize;
        let mut done = 0.0; // H/d reached
        let mut increment = alpha / steps as f64;
        let mut last: Option<Vec<f64>> = None;
        let mut before: Option<(Vec<f64>, f64)> = None;
        let mut halvings = 0;
        while done < alpha {
            let target = (done + increment).min(alpha);
            let guess = match (&last, &before) {
                (None, _) => self.linear(target),
                (Some(x1), None) => {
                    // Scale the wave's part of the solution by the height.
                    let mut g = x1.clone();
                    let ratio = target / done;
                    for j in 1..=self.n {
                        g[self.b(j)] *= ratio;
                    }
                    for m in 0..=self.n {
                        g[self.eta(m)] = x1[0] + (x1[self.eta(m)] - x1[0]) * ratio;
                    }
                    g
                }
                (Some(x1), Some((x0, a0))) => {
                    let s = (target - done) / (done - a0);
                    x1.iter().zip(x0).map(|(b, a)| b + s * (b - a)).collect()
                }
            };
            match self.newton(guess, target) {
                Some(x) => {
                    before = last.take().map(|l| (l, done));
                    last = Some(x);
                    done = target;
                }
                None => {
                    halvings += 1;
                    if halvings > 8 {
                        let kd = last.as_ref().map_or(kd_lin, |x| x[0]);
                        return Err((done, kd));
                    }
                    increment *= 0.5;
                }
            }
        }
        Ok(last.expect("at least one step"))
    }
}

/// Solves A x = b in place (x into `b`) by Gaussian elimination with partial pivoting, A
/// `n` × `n` row-major; false if A is singular to working precision.
fn solve_dense(a: &mut [f64], b: &mut [f64], n: usize) -> bool {
    for col in 0..n {
        let pivot = (col..n)
            .max_by(|&i, &j| a[i * n + col].abs().total_cmp(&a[j * n + col].abs()))
            .unwrap_or(col);
        let size = a[pivot * n + col].abs();
        if size.is_nan() || size <= 1e-300 {
            return false;
        }
        if pivot != col {
            for k in 0..n {
                a.swap(pivot * n + k, col * n + k);
            }
            b.swap(pivot, col);
        }
        let d = a[col * n + col];
        for row in col + 1..n {
            let factor = a[row * n + col] / d;
            if factor != 0.0 {
                for k in col..n {
                    a[row * n + k] -= factor * a[col * n + k];
                }
                b[row] -= factor * b[col];
            }
        }
    }
    for row in (0..n).rev() {
        let mut s = b[row];
        for k in row + 1..n {
            s -= a[row * n + k] * b[k];
        }
        b[row] = s / a[row * n + row];
    }
    true
}
