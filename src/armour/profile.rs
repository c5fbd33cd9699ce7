//! Surface profiles of the armour layer as a laboratory profiler takes them, and the damage
//! level S from the eroded area between two profiles.
//!
//! A mechanical profiler lowers a vertical rod with a ball at its tip onto the armour at
//! points a step Δx apart along lines down the slope, on a few lines spread across the flume
//! (Van der Meer 1988 measured along several lines and averaged them; Rock Manual 2007
//! §5.2.2.2). The damage level of Broderick (1983), used by Van der Meer (1988), is
//!
//! S = A_e / D_n50²   [-]
//!
//! A_e [m²] the eroded area of the cross-section: the area between the width-averaged profile
//! before and after the storm, where the latter is lower (de Almeida, Van Gent & Hofland 2019,
//! "Damage characterization of rock slopes", J. Mar. Sci. Eng. 7(10), §1.1: "the eroded area
//! (difference between the initial and final width-averaged profiles)"). S is the number of
//! cubes of side D_n50 that fit in A_e, i.e. eroded in a strip D_n50 wide.
//!
//! **The probe.** [`measure_profiles`] takes the radius r_p of the ball: r_p = 0 gives the
//! envelope of the sphere caps (a perfect point gauge, or a laser, which also sees into gaps
//! between units), r_p > 0 the contact of a ball lowered vertically until it touches a sphere.
//! A ball of finite size bridges the pores as the laboratory profiler does, so the simulated
//! and measured S compare like for like; a ball diameter of about half the stone size is used
//! in practice, but no definitive value was found, so it is left to the caller.
//!
//! **The integration range.** In the laboratory A_e is taken around the still-water level,
//! over the zone where the profiles can differ, because measurement noise outside it would add
//! up. A simulated profile has no such noise: [`eroded_area`] integrates over the range
//! [x_from, x_to] the caller gives, and the slope face from the toe to the crest is the natural
//! choice ([`Slope::plane_x`] of the toe and crest levels).
//!
//! Symbols: x along the flume [m], z up [m], r sphere radius [m], c sphere centre [m],
//! r_p probe ball radius [m], ρ horizontal distance from the probe axis to c [m].

use crate::math::{Quat, Vec3};

use super::slope::Slope;

/// Where the profiles are taken: `n_points` points x_i = x_start + i Δx on each of the
/// lines at y = `lines`, with a probe ball of radius r_p.
#[derive(Debug, Clone, PartialEq)]
pub struct ProfileGrid {
    /// x of the first point [m]
    pub x_start: f64,
    /// Δx, the step along the flume [m]
    pub dx: f64,
    /// points per line [-]
    pub n_points: usize,
    /// y of each line [m]
    pub lines: Vec<f64>,
    /// r_p, the radius of the probe's ball; 0 for the envelope of the sphere caps [m]
    pub probe_radius: f64,
}

impl ProfileGrid {
    /// `n_lines` lines in the middles of equal strips across the slope's width
    /// ([`Slope::line_y`]), points from x_start to (at least) x_end [m] every Δx [m].
    pub fn across(
        slope: &Slope,
        n_lines: usize,
        x_start: f64,
        x_end: f64,
        dx: f64,
        probe_radius: f64,
    ) -> ProfileGrid {
        let n_points = ((x_end - x_start) / dx).ceil() as usize + 1;
        ProfileGrid {
            x_start,
            dx,
            n_points,
            lines: (0..n_lines).map(|k| slope.line_y(k, n_lines)).collect(),
            probe_radius,
        }
    }

    /// x_i = x_start + i Δx [m].
    pub fn x(&self, i: usize) -> f64 {
        self.x_start + i as f64 * self.dx
    }
}

/// Profiles measured on a [`ProfileGrid`]: z [m] per line and point, and their mean over the
/// lines.
#[derive(Debug, Clone, PartialEq)]
pub struct Profiles {
    /// z of line k at point i is `lines[k * n_points + i]` [m]
    pub lines: Vec<f64>,
    /// z̄_i = (1/n_lines) Σ_k z_ki, the width-averaged profile [m]
    pub mean: Vec<f64>,
}

/// The height the probe reads over one sphere, or None when it misses it. The ball's centre
/// stops at distance r + r_p from c, so its lowest point is at
///
/// z = c_z + √((r + r_p)² − ρ²) − r_p,   ρ < r + r_p
///
/// (r_p = 0: the top of the sphere cap over the point).
fn probe_height(centre_z: f64, radius: f64, probe_radius: f64, rho2: f64) -> Option<f64> {
    let reach = radius + probe_radius;
    let h2 = reach * reach - rho2;
    (h2 > 0.0).then(|| centre_z + h2.sqrt() - probe_radius)
}

/// The profiles over spheres of centres c [m] and radii r [m] (loose stones and the member
/// spheres of blocks alike), periodic in y with the slope's width:
///
/// z_ki = max( base(x_i), max over spheres of z_probe(c, r, x_i, y_k) )
///
/// with `base(x)` [m] what the probe reads where it meets no sphere (the under-layer plane,
/// e.g. `|x| slope.plane_z(x)`); spheres with a non-finite centre are skipped. A maximum does not depend on the order of the spheres, so the
/// result is the same bit for bit for any order. Each sphere visits only the points within
/// r + r_p of it: the cost is Σ (r + r_p)/Δx per line, not spheres × points.
pub fn measure_profiles(
    slope: &Slope,
    grid: &ProfileGrid,
    centres: &[Vec3],
    radii: &[f64],
    base: impl Fn(f64) -> f64,
) -> Profiles {
    assert_eq!(centres.len(), radii.len(), "one radius per sphere");
    let n = grid.n_points;
    let mut z: Vec<f64> = (0..grid.lines.len())
        .flat_map(|_| (0..n).map(|i| base(grid.x(i))))
        .collect();
    for (c, &r) in centres.iter().zip(radii) {
        let reach = r + grid.probe_radius;
        // Point indices within reach in x, clamped to the grid.
        let lo = ((c.x - reach - grid.x_start) / grid.dx).ceil().max(0.0);
        let hi = ((c.x + reach - grid.x_start) / grid.dx).floor();
        if !(hi >= 0.0 && lo < n as f64) {
            continue;
        }
        let (lo, hi) = (lo as usize, (hi as usize).min(n - 1));
        for (k, &y) in grid.lines.iter().enumerate() {
            let dy = slope.nearest_image_dy(y - c.y);
            if dy.abs() >= reach {
                continue;
            }
            let row = &mut z[k * n..(k + 1) * n];
            for (i, zi) in row.iter_mut().enumerate().take(hi + 1).skip(lo) {
                let dx = grid.x(i) - c.x;
                if let Some(h) = probe_height(c.z, r, grid.probe_radius, dx * dx + dy * dy) {
                    *zi = zi.max(h);
                }
            }
        }
    }
    let n_lines = grid.lines.len() as f64;
    let mean = (0..n)
        .map(|i| (0..grid.lines.len()).map(|k| z[k * n + i]).sum::<f64>() / n_lines)
        .collect();
    Profiles { lines: z, mean }
}

/// World centres c_i = x_g + Q q_i⁰ [m] of a block's member spheres, from its centre x_g [m],
/// orientation Q (body → world) and body-frame offsets q_i⁰ [m], appended to `out` (for
/// blocks read back from a blocks.csv, where only x_g and Q are stored).
pub fn member_centres(centre: Vec3, orientation: Quat, offsets: &[Vec3], out: &mut Vec<Vec3>) {
    out.extend(offsets.iter().map(|&q| centre + orientation * q));
}

/// Areas between two profiles on the same grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfileChange {
    /// A_e = ∫ max(0, z_before − z_after) dx [m²]
    pub eroded: f64,
    /// A_a = ∫ max(0, z_after − z_before) dx [m²]
    pub accreted: f64,
}

/// Eroded and accreted areas [m²] between the profiles `before` and `after` [m] sampled every
/// Δx [m] from x_start [m], over [x_from, x_to] [m] (clamped to the sampled range):
///
/// A_e = ∫ max(0, z_b − z_a) dx,  A_a = ∫ max(0, z_a − z_b) dx
///
/// by the trapezoidal rule on the samples inside the range.
pub fn eroded_area(
    x_start: f64,
    dx: f64,
    before: &[f64],
    after: &[f64],
    x_from: f64,
    x_to: f64,
) -> ProfileChange {
    assert_eq!(before.len(), after.len(), "profiles on the same grid");
    let lo = ((x_from - x_start) / dx).ceil().max(0.0) as usize;
    let hi = (((x_to - x_start) / dx).floor().max(-1.0) + 1.0) as usize;
    let hi = hi.min(before.len());
    let mut change = ProfileChange {
        eroded: 0.0,
        accreted: 0.0,
    };
    for i in lo..hi {
        // Trapezoid weights: Δx inside, Δx/2 at the ends of the range.
        let w = if i == lo || i + 1 == hi { 0.5 * dx } else { dx };
        let d = before[i] - after[i];
        change.eroded += w * d.max(0.0);
        change.accreted += w * (-d).max(0.0);
    }
    change
}

/// The damage level S = A_e / D_n50² [-] (Broderick 1983; Van der Meer 1988) of the eroded
/// area A_e [m²] and the nominal diameter D_n50 [m].
pub fn damage_level(eroded_area: f64, nominal_diameter: f64) -> f64 {
    eroded_area / (nominal_diameter * nominal_diameter)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// Sphere radius r [m].
    const R: f64 = 0.02;
    /// Columns (in x) and rows (in y) of the bed.
    const COLUMNS: usize = 10;
    const ROWS: usize = 6;

    /// A flat, periodic section: width W = ROWS · 2r, under a "slope" used only for its
    /// width (the frame is not needed over a flat bed).
    fn section() -> Slope {
        Slope {
            toe_x: 0.0,
            toe_z: 0.0,
            cot_alpha: 1.0,
            y_min: 0.0,
            width: ROWS as f64 * 2.0 * R,
        }
    }

    /// A flat bed of touching spheres in a square lattice of side 2r on the plane z = 0:
    /// centres ((2i + 1) r, (2j + 1) r, r), without the column `skip` if given.
    fn bed(skip: Option<usize>) -> (Vec<Vec3>, Vec<f64>) {
        let mut c = Vec::new();
        for i in (0..COLUMNS).filter(|&i| Some(i) != skip) {
            for j in 0..ROWS {
                c.push(Vec3::new((2 * i + 1) as f64 * R, (2 * j + 1) as f64 * R, R));
            }
        }
        let r = vec![R; c.len()];
        (c, r)
    }

    fn grid(n_lines: usize, dx: f64, probe_radius: f64) -> ProfileGrid {
        ProfileGrid::across(
            &section(),
            n_lines,
            0.0,
            COLUMNS as f64 * 2.0 * R,
            dx,
            probe_radius,
        )
    }

    /// Lines at y = (k + ½) r, a quarter of the way between rows: each at δ = r/2 from the
    /// axis of one row and 3r/2 from the next, so each sees one row, whose caps are discs of
    /// radius a = √(r² − δ²) = (√3/2) r: z = r + √(a² − u²) at distance |u| < a from a
    /// centre along x, the floor z = 0 elsewhere. The code computes the same quantity by
    /// another route (ρ² = u² + δ²), so 1e-12 r covers the rounding.
    #[test]
    fn envelope_over_a_square_bed() {
        let (c, r) = bed(None);
        let g = grid(2 * ROWS, R / 8.0, 0.0);
        let p = measure_profiles(&section(), &g, &c, &r, |_| 0.0);
        let a = (3.0f64).sqrt() / 2.0 * R;
        for k in 0..2 * ROWS {
            for (i, &z) in p.lines[k * g.n_points..(k + 1) * g.n_points]
                .iter()
                .enumerate()
            {
                let x = g.x(i);
                // Distance to the nearest centre along x, (2m + 1) r.
                let u = x - (2.0 * (x / (2.0 * R)).floor() + 1.0) * R;
                let expected = if u.abs() < a {
                    R + (a * a - u * u).sqrt()
                } else {
                    0.0
                };
                assert!(
                    (z - expected).abs() < 1e-12 * R,
                    "k {k} x {x}: {z} vs {expected}"
                );
            }
        }
        // Known points (on the grid): over a centre r + a; at u = r/2, r + √(a² − r²/4) =
        // r + r/√2; at u = r, past the rim a, the floor.
        let at = |x: f64| p.mean[(x / g.dx).round() as usize];
        assert!((at(5.0 * R) - (R + a)).abs() < 1e-12 * R);
        assert!((at(5.5 * R) - (R + R / 2f64.sqrt())).abs() < 1e-12 * R);
        assert_eq!(at(6.0 * R), 0.0);
    }

    /// A ball probe on the lines over the row axes (δ = 0), r_p = r/2: over a centre it reads
    /// the top 2r; over the contact of two spheres (ρ = r from both) its ball stops at
    /// r + √((r + r_p)² − r²) and reads that − r_p, = r + (√5/2 − 1/2) r, above the cusp r of
    /// the bare envelope: the probe bridges the pore.
    #[test]
    fn ball_probe_bridges_pores() {
        let (c, r) = bed(None);
        let g = grid(ROWS, R / 8.0, 0.5 * R);
        let p = measure_profiles(&section(), &g, &c, &r, |_| 0.0);
        let at = |x: f64| p.mean[(x / g.dx).round() as usize];
        assert!((at(7.0 * R) - 2.0 * R).abs() < 1e-12 * R);
        let bridged = R + (1.25f64.sqrt() - 0.5) * R;
        assert!((at(8.0 * R) - bridged).abs() < 1e-12 * R, "{}", at(8.0 * R));
    }

    /// Removing the spheres of column 3 from every row. Each line loses one cap of radius
    /// a = (√3/2) r over the floor: A_e = ∫_{−a}^{a} (r + √(a² − u²)) du = 2 a r + π a²/2,
    /// nothing accreted. The trapezoidal rule is exact on the flat parts; it errs by at most
    /// (jump r) Δx/2 at each of the two jumps from the floor to the cap's rim, and by
    /// O(√a Δx^1.5) on the square-root edges: 2 r Δx bounds both for Δx = r/500.
    #[test]
    fn eroded_area_of_a_missing_column() {
        let dx = R / 500.0;
        let g = grid(2 * ROWS, dx, 0.0);
        let (c0, r0) = bed(None);
        let (c1, r1) = bed(Some(3));
        let before = measure_profiles(&section(), &g, &c0, &r0, |_| 0.0);
        let after = measure_profiles(&section(), &g, &c1, &r1, |_| 0.0);
        let x_end = g.x(g.n_points - 1);
        let ch = eroded_area(0.0, dx, &before.mean, &after.mean, 0.0, x_end);
        let a = (3.0f64).sqrt() / 2.0 * R;
        let expected = 2.0 * a * R + PI * a * a / 2.0;
        assert!(
            (ch.eroded - expected).abs() < 2.0 * R * dx,
            "{ch:?} vs {expected}"
        );
        assert_eq!(ch.accreted, 0.0);
        // S in units of the spheres' D_n.
        let dn = (PI / 6.0).cbrt() * 2.0 * R;
        let s = damage_level(ch.eroded, dn);
        assert!((s - expected / (dn * dn)).abs() < 2.0 * R * dx / (dn * dn));
        // A range that stops short of the missing column sees nothing of it.
        let short = eroded_area(0.0, dx, &before.mean, &after.mean, 0.0, 5.0 * R);
        assert_eq!(short.eroded, 0.0);
        // Swapped roles: the same area as accretion.
        let back = eroded_area(0.0, dx, &after.mean, &before.mean, 0.0, x_end);
        assert_eq!((back.eroded, back.accreted), (0.0, ch.eroded));
    }

    /// The same spheres in another order give the same profiles bit for bit (a maximum of the
    /// same numbers, and a mean over the lines in line order).
    #[test]
    fn profiles_do_not_depend_on_sphere_order() {
        let (mut c, _) = bed(Some(4));
        let mut rng = crate::math::Rng(9);
        for p in c.iter_mut() {
            *p += 0.3 * R * (Vec3::new(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5);
        }
        let r: Vec<f64> = (0..c.len()).map(|i| R * (1.0 + 0.01 * i as f64)).collect();
        let g = grid(5, R / 20.0, 0.4 * R);
        let p = measure_profiles(&section(), &g, &c, &r, |_| 0.0);
        let mut order: Vec<usize> = (0..c.len()).collect();
        order.reverse();
        order.rotate_left(13);
        let cp: Vec<Vec3> = order.iter().map(|&i| c[i]).collect();
        let rp: Vec<f64> = order.iter().map(|&i| r[i]).collect();
        assert_eq!(measure_profiles(&section(), &g, &cp, &rp, |_| 0.0), p);
    }

    /// Periodic in y: a sphere just across the face y = W is seen by a line just inside y = 0.
    #[test]
    fn profiles_are_periodic_across_the_width() {
        let sl = section();
        let g = ProfileGrid {
            x_start: 0.0,
            dx: R,
            n_points: 3,
            lines: vec![0.1 * R],
            probe_radius: 0.0,
        };
        // The second sphere, removed from the simulation (NaN), is skipped.
        let c = [Vec3::new(R, sl.width - 0.1 * R, R), Vec3::NAN];
        let p = measure_profiles(&sl, &g, &c, &[R, R], |_| -1.0);
        let expected = R + (R * R - 0.04 * R * R).sqrt();
        assert!((p.lines[1] - expected).abs() < 1e-12 * R);
        // At x = 0, ρ² = r² + (0.2 r)² > r²: the probe misses and reads the base.
        assert_eq!(p.lines[0], -1.0);
    }
}
