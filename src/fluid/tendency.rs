//! The advection-diffusion tendency Hⁿ of the fractional step ([`super::step`]), row by row.
//!
//! On the a-face c, with ρ̄_f = (ρ̄[c] + ρ̄[c − s_a]) / 2 the face density [kg m⁻³],
//!
//! ```text
//! H_a = −A_a(u) + ( μ ∇²u_a + Σ_b δ_b(2 μ_SGS S_ab) ) / ρ̄_f          [51][56]   [m s⁻²]
//! ```
//!
//! with A_a the flux-form advection of [`super::advection::advection`], μ ∇²u_a the molecular
//! term of [`super::diffusion::molecular`] and the subgrid term of
//! [`super::diffusion::subgrid`]. Those functions give the formulas point by point; this
//! module evaluates exactly the same expressions, in the same order (so bit for bit the
//! same values, which a test checks), for a whole x-row at once: every neighbour is read
//! through a slice of the row shifted by its stencil offset ([`shifted`]), so the loop has no
//! bounds checks and the compiler vectorises it. The component a and the presence of the
//! subgrid model are compile-time constants, which removes the branches from the loop.

use super::advection::Transport;
use super::grid::{shifted, Stencil};
use super::operators::Velocity;

/// The density the viscous stress divergence is divided by on each face.
#[derive(Clone, Copy)]
pub enum Inertia<'a> {
    /// ρ̄ at cell centres [kg m⁻³], averaged to the face (interp_to_face).
    Cells(&'a [f64]),
    /// ρ_f on the a-faces themselves [kg m⁻³] (water and air: `phases::face_density`).
    Faces(&'a [f64]),
    /// With solids in water under air: the face's ρ̃_f (`solids`) on the a-faces for the
    /// inertia, and the fluid's own ρ_f(α) for the weights of the transported velocity [kg m⁻³]
    /// (`super::solids`: the solids' mass is not carried by the flow).
    Mixture {
        /// ρ̃_f [kg m⁻³].
        inertia: &'a [f64],
        /// ρ_f(α) [kg m⁻³].
        fluid: &'a [f64],
    },
}

/// Writes H_a [m s⁻²] for the `out.len()` consecutive a-faces from padded index `start` on.
///
/// `u` is the velocity with filled ghosts [m s⁻¹], `mu_t` μ_SGS at cell centres with filled
/// ghosts [Pa s] (read only with `sgs`), `rho` the density on the faces [kg m⁻³], `mu` the dynamic
/// viscosity [Pa s]. With face densities, `transport` says how the transported velocity across
/// the faces parallel to u_a is formed ([`super::advection::Transport`]); with cell densities
/// (one fluid) it is the plain mean. The faces and
/// all their neighbours must lie inside the padded fields.
#[allow(clippy::too_many_arguments)]
pub fn tendency_row(
    st: &Stencil,
    a: usize,
    sgs: bool,
    u: Velocity,
    mu_t: &[f64],
    rho: Inertia,
    transport: Transport,
    mu: f64,
    start: usize,
    out: &mut [f64],
) {
    // The transported velocity: 0 plain, 1 weighted, 2 bounded, 3 upwind off the water (only
    // with face densities).
    let (t, water) = match (transport, rho) {
        (_, Inertia::Cells(_)) | (Transport::Plain, _) => (0, 0.0),
        (Transport::Weighted, _) => (1, 0.0),
        (Transport::Bounded, _) => (2, 0.0),
        (Transport::Upwind { water }, _) => (3, water),
    };
    match (a, sgs, t) {
        (0, false, 0) => row::<0, false, 0>(st, u, mu_t, rho, mu, water, start, out),
        (1, false, 0) => row::<1, false, 0>(st, u, mu_t, rho, mu, water, start, out),
        (2, false, 0) => row::<2, false, 0>(st, u, mu_t, rho, mu, water, start, out),
        (0, true, 0) => row::<0, true, 0>(st, u, mu_t, rho, mu, water, start, out),
        (1, true, 0) => row::<1, true, 0>(st, u, mu_t, rho, mu, water, start, out),
        (2, true, 0) => row::<2, true, 0>(st, u, mu_t, rho, mu, water, start, out),
        (0, false, 1) => row::<0, false, 1>(st, u, mu_t, rho, mu, water, start, out),
        (1, false, 1) => row::<1, false, 1>(st, u, mu_t, rho, mu, water, start, out),
        (2, false, 1) => row::<2, false, 1>(st, u, mu_t, rho, mu, water, start, out),
        (0, true, 1) => row::<0, true, 1>(st, u, mu_t, rho, mu, water, start, out),
        (1, true, 1) => row::<1, true, 1>(st, u, mu_t, rho, mu, water, start, out),
        (2, true, 1) => row::<2, true, 1>(st, u, mu_t, rho, mu, water, start, out),
        (0, false, 2) => row::<0, false, 2>(st, u, mu_t, rho, mu, water, start, out),
        (1, false, 2) => row::<1, false, 2>(st, u, mu_t, rho, mu, water, start, out),
        (2, false, 2) => row::<2, false, 2>(st, u, mu_t, rho, mu, water, start, out),
        (0, true, 2) => row::<0, true, 2>(st, u, mu_t, rho, mu, water, start, out),
        (1, true, 2) => row::<1, true, 2>(st, u, mu_t, rho, mu, water, start, out),
        (2, true, 2) => row::<2, true, 2>(st, u, mu_t, rho, mu, water, start, out),
        (0, false, 3) => row::<0, false, 3>(st, u, mu_t, rho, mu, water, start, out),
        (1, false, 3) => row::<1, false, 3>(st, u, mu_t, rho, mu, water, start, out),
        (2, false, 3) => row::<2, false, 3>(st, u, mu_t, rho, mu, water, start, out),
        (0, true, 3) => row::<0, true, 3>(st, u, mu_t, rho, mu, water, start, out),
        (1, true, 3) => row::<1, true, 3>(st, u, mu_t, rho, mu, water, start, out),
        (2, true, 3) => row::<2, true, 3>(st, u, mu_t, rho, mu, water, start, out),
        _ => panic!("velocity component {a} does not exist"),
    }
}

/// [`tendency_row`] for component `A`, with the subgrid term when `SGS`, and the transported
/// velocity across the faces parallel to u_a plain (`W` = 0), weighted by the face densities
/// (1), weighted and bounded (2), or bounded in the water and donor-cell on the faces with air
/// (3) (water and air; [`super::advection`]); `water` is ρ_w [kg m⁻³], read only with `W` = 3.
///
/// Names of the shifted rows: `u0` = u_a[c], `up[b]`/`um[b]` = u_a[c ± s_b]; for b ≠ a
/// `vb0[b]` = u_b[c], `vbma[b]` = u_b[c − s_a], `vbp[b]` = u_b[c + s_b],
/// `vbpma[b]` = u_b[c + s_b − s_a]; μ_SGS: `m0` at c, `mma` at c − s_a, `mmb[b]` at c − s_b,
/// `mmamb[b]` at c − s_a − s_b, `mpb[b]` at c + s_b, `mpbma[b]` at c + s_b − s_a.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn row<const A: usize, const SGS: bool, const W: u8>(
    st: &Stencil,
    u: Velocity,
    mu_t: &[f64],
    rho: Inertia,
    mu: f64,
    water: f64,
    start: usize,
    out: &mut [f64],
) {
    let len = out.len();
    let s = st.s.map(|x| x as isize);
    let sa = s[A];
    let at = |f, off| shifted(f, start, off, len);
    let (inv_d, inv_d2) = (st.inv_d, st.inv_d2);
    let inv_a = inv_d[A];

    let ua = u[A];
    let u0 = at(ua, 0);
    let up: [&[f64]; 3] = std::array::from_fn(|b| at(ua, s[b]));
    let um: [&[f64]; 3] = std::array::from_fn(|b| at(ua, -s[b]));
    // Rows of the other components b ≠ a (entry a is a placeholder at offset 0, never read).
    let off = |b: usize, o: isize| if b == A { 0 } else { o };
    let vb0: [&[f64]; 3] = std::array::from_fn(|b| at(u[b], 0));
    let vbma: [&[f64]; 3] = std::array::from_fn(|b| at(u[b], off(b, -sa)));
    let vbp: [&[f64]; 3] = std::array::from_fn(|b| at(u[b], off(b, s[b])));
    let vbpma: [&[f64]; 3] = std::array::from_fn(|b| at(u[b], off(b, s[b] - sa)));
    // ρ̄_f = (r0 + rma) / 2: the mean of two cells, or of a face row with itself (exact).
    let (r0, rma) = match rho {
        Inertia::Cells(r) => (at(r, 0), at(r, -sa)),
        Inertia::Faces(f) | Inertia::Mixture { inertia: f, .. } => (at(f, 0), at(f, 0)),
    };
    // With `W` > 0, the a-face densities either side along each b (for the transported velocity).
    let rf = match rho {
        Inertia::Cells(r) | Inertia::Faces(r) | Inertia::Mixture { fluid: r, .. } => r,
    };
    let r_own = at(rf, 0);
    let rp: [&[f64]; 3] = std::array::from_fn(|b| at(rf, s[b]));
    let rm: [&[f64]; 3] = std::array::from_fn(|b| at(rf, -s[b]));
    // μ_SGS rows; without the model they are never read (any in-bounds row will do).
    let m = if SGS { mu_t } else { u[A] };
    let (m0, mma) = (at(m, 0), at(m, -sa));
    let mmb: [&[f64]; 3] = std::array::from_fn(|b| at(m, off(b, -s[b])));
    let mmamb: [&[f64]; 3] = std::array::from_fn(|b| at(m, off(b, -sa - s[b])));
    let mpb: [&[f64]; 3] = std::array::from_fn(|b| at(m, off(b, s[b])));
    let mpbma: [&[f64]; 3] = std::array::from_fn(|b| at(m, off(b, s[b] - sa)));

    for i in 0..len {
        let c = u0[i];
        // μ ∇²u_a: the 7-point Laplacian (operators::laplacian).
        let mut lap = 0.0;
        for b in 0..3 {
            lap += (up[b][i] - 2.0 * c + um[b][i]) * inv_d2[b];
        }
        let mut viscous = mu * lap;
        if SGS {
            // Σ_b δ_b(2 μ_SGS S_ab) (diffusion::subgrid): normal stresses at the cell centres
            // c and c − s_a, shear stresses at the a-b edges of c + s_b and c.
            let t_hi = 2.0 * m0[i] * (up[A][i] - c) * inv_a;
            let t_lo = 2.0 * mma[i] * (c - um[A][i]) * inv_a;
            let mut sum = (t_hi - t_lo) * inv_a;
            for b in 0..3 {
                if b == A {
                    continue;
                }
                let mu_hi = 0.25 * (mpb[b][i] + mpbma[b][i] + m0[i] + mma[i]);
                let e_hi = mu_hi * ((up[b][i] - c) * inv_d[b] + (vbp[b][i] - vbpma[b][i]) * inv_a);
                let mu_lo = 0.25 * (m0[i] + mma[i] + mmb[b][i] + mmamb[b][i]);
                let e_lo = mu_lo * ((c - um[b][i]) * inv_d[b] + (vb0[b][i] - vbma[b][i]) * inv_a);
                sum += (e_hi - e_lo) * inv_d[b];
            }
            viscous += sum;
        }
        // A_a (advection::advection): fluxes at the cell centres (b = a) and at the a-b
        // edges of c + s_b and c (b ≠ a).
        let mut adv = 0.0;
        // A face with air under the upwind transport: donor-cell (advection::advection_upwind).
        let donor = W == 3 && r_own[i] < water;
        for b in 0..3 {
            if donor {
                let (t_hi, t_lo) = if b == A {
                    (0.5 * (c + up[A][i]), 0.5 * (um[A][i] + c))
                } else {
                    (
                        0.5 * (vbp[b][i] + vbpma[b][i]),
                        0.5 * (vb0[b][i] + vbma[b][i]),
                    )
                };
                let m_hi = if t_hi > 0.0 { c } else { up[b][i] };
                let m_lo = if t_lo > 0.0 { um[b][i] } else { c };
                adv += (t_hi * m_hi - t_lo * m_lo) * inv_d[b];
            } else if W > 0 && b != A {
                // Across the faces parallel to u_a the transported u_a is the density-weighted
                // mean of the two faces (advection::advection_weighted), or with W = 2 or 3
                // each face's own weight is at least ½ (advection::advection_bounded).
                let q = r_own[i];
                let (m_hi, m_lo) = if W == 1 {
                    (
                        (q * c + rp[b][i] * up[b][i]) / (q + rp[b][i]),
                        (rm[b][i] * um[b][i] + q * c) / (rm[b][i] + q),
                    )
                } else {
                    let w_hi = (q / (q + rp[b][i])).max(0.5);
                    let w_lo = (q / (q + rm[b][i])).max(0.5);
                    (
                        w_hi * c + (1.0 - w_hi) * up[b][i],
                        w_lo * c + (1.0 - w_lo) * um[b][i],
                    )
                };
                let t_hi = 0.5 * (vbp[b][i] + vbpma[b][i]);
                let t_lo = 0.5 * (vb0[b][i] + vbma[b][i]);
                adv += (t_hi * m_hi - t_lo * m_lo) * inv_d[b];
            } else if b == A {
                let hi = 0.5 * (c + up[A][i]);
                let lo = 0.5 * (um[A][i] + c);
                adv += (hi * hi - lo * lo) * inv_a;
            } else {
                let f_hi = 0.25 * (vbp[b][i] + vbpma[b][i]) * (up[b][i] + c);
                let f_lo = 0.25 * (vb0[b][i] + vbma[b][i]) * (c + um[b][i]);
                adv += (f_hi - f_lo) * inv_d[b];
            }
        }
        let rho_f = 0.5 * (r0[i] + rma[i]);
        out[i] = -adv + viscous / rho_f;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fluid::advection::{
        advection, advection_bounded, advection_upwind, advection_weighted,
    };
    use crate::fluid::diffusion::{molecular, subgrid};
    use crate::fluid::grid::StaggeredGrid;
    use crate::fluid::operators::interp_to_face;
    use crate::math::Vec3;

    /// A field of `grid` with pseudo-random values in [−0.15, 0.15) [m s⁻¹].
    fn field(grid: &StaggeredGrid, seed: usize) -> Vec<f64> {
        (0..grid.len())
            .map(|m| (((m * 7919 + seed * 104729) % 1009) as f64 / 1009.0 - 0.5) * 0.3)
            .collect()
    }

    /// A pointwise advection with face densities.
    type Adv = fn(&Stencil, Velocity, &[f64], usize, usize) -> f64;

    /// The row kernel gives the same bits as the point-by-point formulas, on every face of
    /// every component, with and without the subgrid term, with each transport, on a
    /// non-cubic grid.
    #[test]
    fn rows_match_the_pointwise_formulas_bit_for_bit() {
        let grid = StaggeredGrid::new([7, 5, 6], Vec3::new(0.7, 0.4, 0.9), Vec3::ZERO);
        let st = Stencil::new(&grid);
        let field = |seed: usize| field(&grid, seed);
        let (u0, u1, u2) = (field(1), field(2), field(3));
        let mu_t: Vec<f64> = field(4).iter().map(|x| x.abs() * 1e-3).collect();
        let rho: Vec<f64> = field(5).iter().map(|x| 1000.0 + 500.0 * x).collect();
        let u = [&u0[..], &u1[..], &u2[..]];
        let mu = 1.0e-3;
        for sgs in [false, true] {
            for a in 0..3 {
                let lo = 1 + (a == 0) as usize;
                for k in 1..=grid.n[2] {
                    for j in 1..=grid.n[1] {
                        let start = grid.index(lo, j, k);
                        let mut out = vec![0.0; grid.n[0] + 1 - lo];
                        tendency_row(
                            &st,
                            a,
                            sgs,
                            u,
                            &mu_t,
                            Inertia::Cells(&rho),
                            Transport::Plain,
                            mu,
                            start,
                            &mut out,
                        );
                        for (i, h) in out.iter().enumerate() {
                            let c = start + i;
                            let mut viscous = molecular(&st, mu, u[a], c);
                            if sgs {
                                viscous += subgrid(&st, u, &mu_t, a, c);
                            }
                            let rho_f = interp_to_face(&st, a, &rho, c);
                            let expected = -advection(&st, u, a, c) + viscous / rho_f;
                            assert_eq!(h.to_bits(), expected.to_bits(), "a {a} sgs {sgs} c {c}");
                        }
                        // With air: face densities, and the weighted or bounded advection.
                        // ρ_w = 1000 puts about half the faces on either side (rho 925-1075).
                        let upwind: Adv =
                            |st, u, rho, a, c| advection_upwind(st, u, rho, 1e3, a, c);
                        let air: [(Transport, Adv); 3] = [
                            (Transport::Weighted, advection_weighted),
                            (Transport::Bounded, advection_bounded),
                            (Transport::Upwind { water: 1e3 }, upwind),
                        ];
                        for (transport, adv) in air {
                            let inertia = Inertia::Faces(&rho);
                            tendency_row(
                                &st, a, sgs, u, &mu_t, inertia, transport, mu, start, &mut out,
                            );
                            for (i, h) in out.iter().enumerate() {
                                let c = start + i;
                                let mut viscous = molecular(&st, mu, u[a], c);
                                if sgs {
                                    viscous += subgrid(&st, u, &mu_t, a, c);
                                }
                                let rho_f = 0.5 * (rho[c] + rho[c]);
                                let expected = -adv(&st, u, &rho, a, c) + viscous / rho_f;
                                assert_eq!(
                                    h.to_bits(),
                                    expected.to_bits(),
                                    "{transport:?}: a {a} sgs {sgs} c {c}"
                                );
                            }
                        }
                    }
                }
            }
        }
    }

    /// Uniform density: the weighted advection is the plain one (to round-off), and on a
    /// field with a density jump the water face does not see the air face's velocity.
    #[test]
    fn weighted_advection_is_plain_at_uniform_density_and_keeps_the_air_out_of_the_water() {
        let grid = StaggeredGrid::new([6, 5, 7], Vec3::new(0.6, 0.5, 0.7), Vec3::ZERO);
        let st = Stencil::new(&grid);
        let field = |seed: usize| field(&grid, seed);
        let (u0, u1, u2) = (field(1), field(2), field(3));
        let u = [&u0[..], &u1[..], &u2[..]];
        let rho = vec![998.0; grid.len()];
        for a in 0..3 {
            for k in 2..grid.n[2] {
                for j in 2..grid.n[1] {
                    for i in 2..grid.n[0] {
                        let c = grid.index(i, j, k);
                        let (p, w) = (
                            advection(&st, u, a, c),
                            advection_weighted(&st, u, &rho, a, c),
                        );
                        assert!((p - w).abs() < 1e-13, "a {a} c {c}: {p} {w}");
                    }
                }
            }
        }
        // Water (u = 0.1 m/s) up to row ks, air above running faster (0.2 + 0.1 k m/s), a
        // uniform w = 0.01 m/s: divergence-free, uniform along x. On the top water face the
        // vertical flux carries out the mean of the water's and the air's u_x, so the plain
        // mean decelerates the water by w (u_air − u_w)/(2 Δz) (0.03 m/s²); the weighted mean
        // by that times 2 ρ_a/(ρ_w + ρ_a) = 0.0024.
        let sz = grid.strides()[2];
        let ks = 4;
        let (mut ux, uz) = (vec![0.0; grid.len()], vec![0.01; grid.len()]);
        let mut rho_x = vec![0.0; grid.len()];
        for (c, (u, r)) in ux.iter_mut().zip(rho_x.iter_mut()).enumerate() {
            let k = c / sz;
            (*u, *r) = if k <= ks {
                (0.1, 998.0)
            } else {
                (0.2 + 0.1 * k as f64, 1.2)
            };
        }
        let zero = vec![0.0; grid.len()];
        let u = [&ux[..], &zero[..], &uz[..]];
        let c = grid.index(3, 3, ks);
        let plain = advection(&st, u, 0, c);
        let weighted = advection_weighted(&st, u, &rho_x, 0, c);
        let u_air = 0.2 + 0.1 * (ks + 1) as f64;
        let expected = 0.01 * (u_air - 0.1) / (2.0 * grid.spacing.z);
        assert!(
            (plain - expected).abs() < 1e-12,
            "{plain} against {expected}"
        );
        let ratio = 2.0 * 1.2 / (998.0 + 1.2);
        assert!(
            (weighted / plain - ratio).abs() < 1e-12,
            "{weighted} against {plain}"
        );
        // Bounded: the water face as weighted (to round-off: the weights are formed apart);
        // the air face above it, whose weighted edge took in the water's velocity, sees the
        // plain mean there, to the bit (w = ½).
        let bounded = advection_bounded(&st, u, &rho_x, 0, c);
        assert!(
            (bounded / weighted - 1.0).abs() < 1e-12,
            "{bounded} against {weighted}"
        );
        let air = c + sz;
        let (p, w, b) = (
            advection(&st, u, 0, air),
            advection_weighted(&st, u, &rho_x, 0, air),
            advection_bounded(&st, u, &rho_x, 0, air),
        );
        assert_eq!(b.to_bits(), p.to_bits(), "air face: bounded {b}, plain {p}");
        // Weighted, the air face's lower edge carries nearly the water's 0.1 m/s in place of
        // the mean, which adds w (u_air − u_w)/(2 Δz) (ρ_w − ρ_a)/(ρ_w + ρ_a) to its advection
        // (here upwind; with the flow from the air into the water, downwind: anti-diffusive).
        let more = 0.01 * (u_air - 0.1) / (2.0 * grid.spacing.z) * (998.0 - 1.2) / (998.0 + 1.2);
        assert!(
            (w - p - more).abs() < 1e-12,
            "weighted {w}, plain {p}, more {more}"
        );
    }

    /// At uniform density the bounded transport is the plain one, to the bit (w = ½ on every
    /// edge, and halving is exact).
    #[test]
    fn bounded_advection_is_plain_at_uniform_density() {
        let grid = StaggeredGrid::new([6, 5, 7], Vec3::new(0.6, 0.5, 0.7), Vec3::ZERO);
        let st = Stencil::new(&grid);
        let field = |seed: usize| field(&grid, seed);
        let (u0, u1, u2) = (field(1), field(2), field(3));
        let u = [&u0[..], &u1[..], &u2[..]];
        let rho = vec![998.0; grid.len()];
        for a in 0..3 {
            for c in grid.index(2, 2, 2)..grid.index(grid.n[0] - 1, grid.n[1] - 1, grid.n[2] - 1) {
                let (p, b) = (
                    advection(&st, u, a, c),
                    advection_bounded(&st, u, &rho, a, c),
                );
                assert_eq!(p.to_bits(), b.to_bits(), "a {a} c {c}: {p} {b}");
            }
        }
    }

    /// Upwind off the water: a face in the water takes the bounded form to the bit; on a face
    /// with air the donor cell damps the two-cell mode u_x = ±U alternating along z under a
    /// uniform w, at the rate 2 w/Δz, which the central form leaves alone (its two
    /// neighbours are equal, so their difference is zero).
    #[test]
    fn the_donor_cell_damps_the_two_cell_mode_that_central_differences_keep() {
        let grid = StaggeredGrid::new([6, 5, 8], Vec3::new(0.6, 0.5, 0.8), Vec3::ZERO);
        let st = Stencil::new(&grid);
        let sz = grid.strides()[2];
        let (w, amp) = (0.01, 0.3);
        let ux: Vec<f64> = (0..grid.len())
            .map(|c| if (c / sz) % 2 == 0 { amp } else { -amp })
            .collect();
        let (uy, uz) = (vec![0.0; grid.len()], vec![w; grid.len()]);
        let u = [&ux[..], &uy[..], &uz[..]];
        let (water, air) = (vec![998.0; grid.len()], vec![1.2; grid.len()]);
        let faces = (2..6).flat_map(|k| (2..4).flat_map(move |j| (2..5).map(move |i| (i, j, k))));
        for c in faces.map(|(i, j, k)| grid.index(i, j, k)) {
            let bounded = advection_bounded(&st, u, &water, 0, c);
            let upwind = advection_upwind(&st, u, &water, 998.0, 0, c);
            assert_eq!(upwind.to_bits(), bounded.to_bits(), "water face {c}");
            let central = advection_bounded(&st, u, &air, 0, c);
            assert!(central.abs() < 1e-15, "central keeps the mode: {central}");
            // −A = −w (u[c] − u[c − s_z]) / Δz = −2 w u[c] / Δz: towards zero.
            let donor = -advection_upwind(&st, u, &air, 998.0, 0, c);
            let expected = -2.0 * w * ux[c] / grid.spacing.z;
            assert!(
                (donor - expected).abs() < 1e-12,
                "face {c}: {donor} against {expected}"
            );
        }
    }
}
