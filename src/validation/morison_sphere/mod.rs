//! Morison's drag and inertia coefficients of a fixed sphere and a fixed cube in oscillatory
//! flow (issue 29, "Armour under waves"): the resolved coupling's force on one fixed armour
//! unit at the example's resolution (4 to 8 cells per diameter). See `README.md` in this
//! directory for the set-up, the references, the criteria and the measured coefficients.
//!
//! In units of the diameter D (the cube's nominal diameter D_n), the velocity amplitude U_m
//! and ρ = 1: a periodic box, the flow driven by the uniform pressure gradient
//! −∇P = ρ dU_∞/dt of U_∞(t) = U_m sin ωt ([`DrivingPressureGradient::Oscillatory`]), period
//! T = KC D / U_m, ν = U_m D / (β KC), no subgrid model. The unit ([`Shape`]) is made of fixed
//! resolved DEM spheres, one for the sphere, the cube's 27 members for the cube, a block's
//! members with its fitted masses ([62] holds the water in them at rest, [59] gives their
//! force, plus the Froude-Krylov force of the drive, V_i (−∇P) on each member's share V_i of
//! the unit's volume, `Coupling::fluid_forces`; all summed over the members). The in-line
//! force F(t) is fitted by least squares over whole periods after a start-up with
//!
//! F = ½ ρ C_D A |U| U + ρ V C_M dU/dt   [N],
//!
//! A = π D²/4, V = π D³/6 (sphere) or A = D_n², V = D_n³ (cube, face-on) [m², m³], U the mean
//! velocity of the water in the box [m s⁻¹]. The drive's Froude-Krylov force is ρ V dU/dt
//! (Σ V_i = V), so C_M = 1 + C_a for both units. (The grid sees the cube's volume as V_s, the
//! union of the members' cell fractions: 1.09 V at D/Δ = 4; its added mass is the grid's.)

pub mod report;
pub mod shape;

use std::f64::consts::PI;
use std::time::Instant;

use crate::coupling::drag::clift_grace_weber_1978;
use crate::coupling::{Coupling, CouplingMode, CouplingParameters};
use crate::dem::material::Material;
use crate::dem::spheres::{NewSphere, Spheres};
use crate::fluid::forcing::DrivingPressureGradient;
use crate::fluid::{Boundaries, Fluid, FluidParameters, StaggeredGrid};
use crate::math::Vec3;
pub use shape::Shape;
use shape::{cube_history_drag, cube_steady_drag, cube_stokes_inertia, CUBE_ADDED_MASS};

/// One run of the case.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MorisonCase {
    /// The unit.
    pub shape: Shape,
    /// Keulegan-Carpenter number KC = U_m T / D [–].
    pub kc: f64,
    /// Stokes number β = Re / KC = D² / (ν T) [–].
    pub beta: f64,
    /// Cells per diameter D/Δ.
    pub cells_per_diameter: usize,
    /// Box lengths [D].
    pub lengths: [f64; 3],
    /// Periods before the fit (start-up).
    pub start_up: usize,
    /// Periods fitted.
    pub periods: usize,
}

impl MorisonCase {
    /// The sphere's set-up at `kc`, `beta`, D/Δ = `cells`: a box 4 D across and, along the
    /// flow, the water's excursion 2A = KC D/π plus 4 D (whole diameters), so that the wake a
    /// half period leaves does not reach the next image sphere; one period of start-up, then
    /// three periods fitted at KC ≤ 5, two above.
    pub fn new(kc: f64, beta: f64, cells: usize) -> MorisonCase {
        MorisonCase::of(Shape::Sphere, kc, beta, cells)
    }

    /// The same set-up for `shape` (the cube's box is the sphere's, in D_n).
    pub fn of(shape: Shape, kc: f64, beta: f64, cells: usize) -> MorisonCase {
        MorisonCase {
            shape,
            kc,
            beta,
            cells_per_diameter: cells,
            lengths: [(4.0 + kc / PI).ceil(), 4.0, 4.0],
            start_up: 1,
            periods: if kc <= 5.0 { 3 } else { 2 },
        }
    }

    /// Reynolds number Re = U_m D / ν = β KC [–].
    pub fn re(&self) -> f64 {
        self.beta * self.kc
    }
}

/// What a run gives.
#[derive(Clone, Debug)]
pub struct MorisonResult {
    /// The case.
    pub case: MorisonCase,
    /// Fitted C_D [–].
    pub drag: f64,
    /// Fitted C_M [–].
    pub inertia: f64,
    /// Fit residual ‖F − F_Morison‖ / ‖F‖ over the fitted periods [–].
    pub residual: f64,
    /// Amplitude of the measured mean velocity over U_m over the fitted periods [–].
    pub velocity_ratio: f64,
    /// The volume the grid sees, V_s = Σ_c min(1, Σ_i φ_ic) Δ³, over V [–].
    pub seen_volume: f64,
    /// The volume the coupling gives the Froude-Krylov force, Σ_i V_i over V [–]: the whole
    /// sphere, the cube's members their shares m_i / ρ_s of the union
    /// (`coupling::Coupling::fluid_forces`); 1 to round-off.
    pub member_volume: f64,
    /// (t [T], F_x [½ ρ A U_m²], U [U_m]) each step.
    pub history: Vec<(f64, f64, f64)>,
    /// Fluid steps.
    pub steps: u64,
    /// Wall time [s].
    pub seconds: f64,
}

/// Runs the case.
pub fn run_morison(case: &MorisonCase) -> MorisonResult {
    let clock = Instant::now();
    let (d, um, rho) = (1.0, 1.0, 1.0);
    let period = case.kc * d / um;
    let h = d / case.cells_per_diameter as f64;
    let n = case.lengths.map(|l| (l / h).round() as usize);
    let lengths = Vec3::from_array(case.lengths);
    let grid = StaggeredGrid::new(n, lengths, Vec3::ZERO);
    let mut p = FluidParameters::laminar(rho, um * d / case.re());
    p.driving_pressure_gradient = DrivingPressureGradient::Oscillatory {
        velocity_amplitude: Vec3::X * um,
        period,
    };
    // At least 100 steps a period: the fit needs dU/dt resolved near flow reversal, where
    // the advective limit alone would allow long steps.
    p.time_step.max = period / 100.0;
    let members = case.shape.members(0.5 * lengths);
    let seen = seen_volume(&grid, &members);
    let mut fluid = Fluid::new(grid, Boundaries::periodic(), p).expect("valid set-up");
    let (mut spheres, d_max) = fixed_spheres(&members, rho);
    let materials = [unit_material(rho)];
    if let Some((fractions, union)) = case.shape.block() {
        // The cube is one block: its members carry the fitted masses m_i = f_i ρ_s V.
        for (i, f) in fractions.iter().enumerate() {
            spheres.body[i] = 0;
            spheres.mass[i] = f * rho * union * d * d * d;
            spheres.inertia[i] = 0.4 * spheres.mass[i] * spheres.radius[i].powi(2);
        }
    }
    let member_volume: f64 = (0..spheres.len())
        .map(|i| match case.shape.block() {
            Some(_) => spheres.mass[i] / rho,
            None => 4.0 / 3.0 * PI * spheres.radius[i].powi(3),
        })
        .sum();
    let mut coupling = Coupling::new(resolved(), &fluid, d_max);
    coupling.initialise(&mut fluid, &mut spheres);
    fluid.project();
    let area = case.shape.area() * d * d;
    let volume = case.shape.volume() * d * d * d;
    let q = 0.5 * rho * area * um * um;
    // The water's share of the box: U is the mean over the water, the unit's faces at rest.
    let water = 1.0 - seen / (lengths.x * lengths.y * lengths.z);
    let t_end = (case.start_up + case.periods) as f64 * period;
    // (t, F_x, U) each step.
    let mut record: Vec<(f64, f64, f64)> = Vec::new();
    while fluid.time() < t_end - 1e-9 {
        let dt = fluid.step_adaptive(t_end);
        coupling.fluid_forces(&fluid, &mut spheres, &materials, dt);
        coupling.correct(&mut fluid, &mut spheres, dt, dt);
        let u = mean_x_velocity(&fluid) / water;
        // [59] and the drive's Froude-Krylov force on V_i, summed over the members.
        let f: f64 = spheres.fluid.iter().map(|l| l.force.x).sum();
        record.push((fluid.time(), f, u));
    }
    let fit = fit_morison(&record, case.start_up as f64 * period, rho, area, volume);
    let omega = 2.0 * PI / period;
    let history = record
        .iter()
        .map(|&(t, f, u)| (t / period, f / q, u / um))
        .collect();
    MorisonResult {
        case: *case,
        drag: fit.drag,
        inertia: fit.inertia,
        residual: fit.residual,
        velocity_ratio: amplitude(&record, case.start_up as f64 * period, omega) / um,
        seen_volume: seen / volume,
        member_volume: member_volume / volume,
        history,
        steps: fluid.steps(),
        seconds: clock.elapsed().as_secs_f64(),
    }
}

/// The coupling of the case: every sphere resolved.
fn resolved() -> CouplingParameters {
    CouplingParameters {
        mode: CouplingMode::Resolved,
        ..CouplingParameters::default()
    }
}

/// The unit's material, of density `density` [kg m⁻³] (its elastic constants unused: the
/// unit is fixed and alone).
fn unit_material(density: f64) -> Material {
    Material {
        name: "unit".to_string(),
        density,
        young_modulus: 1.0e9,
        poisson_ratio: 0.25,
        friction_coefficient: 0.5,
        restitution_coefficient: 0.5,
    }
}

/// Fixed spheres of density `density` at `members` (centre, radius), and the largest
/// diameter.
fn fixed_spheres(members: &[(Vec3, f64)], density: f64) -> (Spheres, f64) {
    let mut spheres = Spheres::default();
    for &(position, radius) in members {
        spheres.push(NewSphere {
            position,
            velocity: Vec3::ZERO,
            angular_velocity: Vec3::ZERO,
            radius,
            material: 0,
            density,
            fixed: true,
        });
    }
    let d_max = members.iter().map(|m| 2.0 * m.1).fold(0.0, f64::max);
    (spheres, d_max)
}

/// The volume of the solid the grid sees [m³]: Σ_c min(1, Σ_i φ_ic) Δ³, the union of the
/// members' cell fractions as [53] and [62] clamp it. Read off the mixture density [53] of
/// members of density 2 ρ_w in still water, ρ̄ − ρ_w = min(1, φ) ρ_w.
pub fn seen_volume(grid: &StaggeredGrid, members: &[(Vec3, f64)]) -> f64 {
    let p = FluidParameters::laminar(1.0, 1.0);
    let mut fluid = Fluid::new(*grid, Boundaries::periodic(), p).expect("valid set-up");
    let (mut spheres, d_max) = fixed_spheres(members, 2.0);
    let mut coupling = Coupling::new(resolved(), &fluid, d_max);
    coupling.initialise(&mut fluid, &mut spheres);
    let rho = fluid.mixture_density();
    let [nx, ny, nz] = grid.n;
    let mut sum = 0.0;
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                sum += rho[grid.cell(i, j, k)] - 1.0;
            }
        }
    }
    sum * grid.cell_volume()
}

/// Mean of u over the x-faces of the box [m s⁻¹] (periodic: faces 0..n_x are all of them).
fn mean_x_velocity(fluid: &Fluid) -> f64 {
    let g = fluid.grid();
    let u = fluid.velocity()[0];
    let [nx, ny, nz] = g.n;
    let mut sum = 0.0;
    for k in 0..nz {
        for j in 0..ny {
            let c = g.cell(0, j, k);
            sum += u[c..c + nx].iter().sum::<f64>();
        }
    }
    sum / (nx * ny * nz) as f64
}

/// Least-squares Morison coefficients.
#[derive(Clone, Copy, Debug)]
pub struct MorisonFit {
    /// C_D [–].
    pub drag: f64,
    /// C_M [–].
    pub inertia: f64,
    /// ‖F − F_Morison‖ / ‖F‖ [–].
    pub residual: f64,
}

/// Fits F = ½ ρ C_D A |U| U + ρ V C_M dU/dt to `record` (t [s], F [N], U [m s⁻¹]) after
/// `after` [s], each sample weighted by its time step (so unequal steps count by duration);
/// dU/dt by central differences of the record. `rho` [kg m⁻³], `area` A [m²], `volume` V [m³].
pub fn fit_morison(
    record: &[(f64, f64, f64)],
    after: f64,
    rho: f64,
    area: f64,
    volume: f64,
) -> MorisonFit {
    // Normal equations of the two regressors X = ½ρA|U|U, Y = ρV dU/dt.
    let (mut xx, mut xy, mut yy, mut xf, mut yf, mut ff) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    let mut rows = Vec::new();
    for w in record.windows(3) {
        let (t, f, u) = w[1];
        if t <= after {
            continue;
        }
        let weight = 0.5 * (w[2].0 - w[0].0);
        let dudt = (w[2].2 - w[0].2) / (w[2].0 - w[0].0);
        let x = 0.5 * rho * area * u.abs() * u;
        let y = rho * volume * dudt;
        xx += weight * x * x;
        xy += weight * x * y;
        yy += weight * y * y;
        xf += weight * x * f;
        yf += weight * y * f;
        ff += weight * f * f;
        rows.push((weight, x, y, f));
    }
    let det = xx * yy - xy * xy;
    let drag = (xf * yy - yf * xy) / det;
    let inertia = (yf * xx - xf * xy) / det;
    let misfit: f64 = rows
        .iter()
        .map(|&(w, x, y, f)| w * (f - drag * x - inertia * y).powi(2))
        .sum();
    MorisonFit {
        drag,
        inertia,
        residual: (misfit / ff).sqrt(),
    }
}

/// Amplitude of the first harmonic at `omega` [s⁻¹] of the record's U after `after` [s].
fn amplitude(record: &[(f64, f64, f64)], after: f64, omega: f64) -> f64 {
    let (mut s, mut c, mut time) = (0.0, 0.0, 0.0);
    for w in record.windows(2).filter(|w| w[0].0 >= after) {
        let dt = w[1].0 - w[0].0;
        s += dt * w[1].2 * (omega * w[1].0).sin();
        c += dt * w[1].2 * (omega * w[1].0).cos();
        time += dt;
    }
    2.0 * (s * s + c * c).sqrt() / time
}

/// C_M of the unsteady Stokes solution for a sphere in a sinusoidal stream (Stokes 1851;
/// Landau & Lifshitz, *Fluid Mechanics*, §24): Froude-Krylov 1, potential added mass ½, and
/// the in-phase-with-acceleration part 3πR²ρδ of the history (Basset) force over ρV:
/// C_M = 1.5 + (9/4) δ/R = 1.5 + 4.5/√(πβ), with δ = √(2ν/ω) the Stokes layer, R = D/2.
pub fn stokes_inertia(beta: f64) -> f64 {
    1.5 + 4.5 / (PI * beta).sqrt()
}

/// The history force's part in phase with velocity, 6πμR (R/δ) U (Stokes 1851), as a
/// Morison C_D by the same least-squares projection as the fit (a force k U_m sin ωt on
/// |sin| sin: k U_m ⟨|sin|³⟩/⟨sin⁴⟩ = k U_m 32/(9π)): C_D,B = (256/(3π)) (R/δ) / Re, with
/// R/δ = √(πβ)/2, Re = β KC [–].
pub fn basset_drag(kc: f64, beta: f64) -> f64 {
    256.0 / (3.0 * PI) * 0.5 * (PI * beta).sqrt() / (beta * kc)
}

/// Quasi-steady C_D: the standard drag curve (Clift, Grace & Weber 1978) at the instantaneous
/// Reynolds number Re |sin ωt|, projected on |U| U by least squares over a period:
/// C_D,qs = ⟨C_D(Re |s|) s⁴⟩ / ⟨s⁴⟩, s = sin ωt [–].
pub fn quasi_steady_drag(re: f64) -> f64 {
    quasi_steady(re, clift_grace_weber_1978)
}

/// The steady drag curve projected as [`quasi_steady_drag`] does, for any `law` C_D(Re) [–].
pub fn quasi_steady(re: f64, law: impl Fn(f64) -> f64) -> f64 {
    let m = 4000;
    let (mut num, mut den) = (0.0, 0.0);
    for i in 0..m {
        let s = (PI * (i as f64 + 0.5) / m as f64).sin();
        let s4 = s.powi(4);
        num += law(re * s) * s4;
        den += s4;
    }
    num / den
}

/// The reference band of C_D [–]: the quasi-steady drag alone (low: the history force fades
/// at finite Re) to it plus the Stokes history part (high). Sphere: the standard curve and
/// Stokes's history force; cube: Haider & Levenspiel's curve on the face area
/// ([`shape::cube_steady_drag`]) and the sphere's history force scaled by S/V
/// ([`shape::cube_history_drag`]).
pub fn drag_band(case: &MorisonCase) -> (f64, f64) {
    match case.shape {
        Shape::Sphere => {
            let qs = quasi_steady_drag(case.re());
            (qs, qs + basset_drag(case.kc, case.beta))
        }
        Shape::Cube => {
            let qs = quasi_steady(case.re(), cube_steady_drag);
            (qs, qs + cube_history_drag(case.kc, case.beta))
        }
    }
}

/// The reference band of C_M [–]. Sphere: potential flow 1.5 (low) to the unsteady Stokes
/// value (high). Cube: 1 plus the published potential added mass, 1.64 (low) to 1.70 plus the
/// Stokes layer's part scaled by S/V ([`shape::cube_stokes_inertia`]) (high).
pub fn inertia_band(case: &MorisonCase) -> (f64, f64) {
    match case.shape {
        Shape::Sphere => (1.5, stokes_inertia(case.beta)),
        Shape::Cube => (
            1.0 + CUBE_ADDED_MASS.0,
            1.0 + CUBE_ADDED_MASS.1 + cube_stokes_inertia(case.beta),
        ),
    }
}

/// Which coefficients a run is judged on (README): C_M where inertia dominates (KC ≤ 5), C_D
/// where drag dominates (KC ≥ 10); (judge C_D, judge C_M).
pub fn judged(case: &MorisonCase) -> (bool, bool) {
    (case.kc >= 10.0, case.kc <= 5.0)
}

/// Tolerances outside the bands (README): (C_D below, C_D above, C_M) as fractions [–].
/// C_D above the band: +30 % at D/Δ ≥ 8 (the steady sphere's over-prediction at Re 100-200,
/// case sphere_drag), +50 % at coarser grids; C_D below 10 % (sphere) or 20 % (cube: its
/// steady curve is a randomly oriented cube's, not a face-on one's); C_M either side 10 %.
pub fn tolerances(case: &MorisonCase) -> (f64, f64, f64) {
    let above = if case.cells_per_diameter >= 8 {
        0.30
    } else {
        0.50
    };
    let below = match case.shape {
        Shape::Sphere => 0.10,
        Shape::Cube => 0.20,
    };
    (below, above, 0.10)
}

/// Whether a run's judged coefficients are inside their bands widened by the tolerances.
pub fn passes(r: &MorisonResult) -> bool {
    let (jd, jm) = judged(&r.case);
    let (below, above, tm) = tolerances(&r.case);
    let (dl, dh) = drag_band(&r.case);
    let (ml, mh) = inertia_band(&r.case);
    let drag_ok = !jd || (r.drag >= dl * (1.0 - below) && r.drag <= dh * (1.0 + above));
    let inertia_ok = !jm || (r.inertia >= ml * (1.0 - tm) && r.inertia <= mh * (1.0 + tm));
    drag_ok && inertia_ok && r.drag.is_finite() && r.inertia.is_finite()
}

/// Stokes number of every run [–]: β = 10, so that Re = β KC stays within 20-200, the range
/// case sphere_drag validates at these resolutions.
pub const BETA: f64 = 10.0;

/// The runs of a level for `shape`: quick D/Δ = 4 (the example's resolution) at KC 2, 5, 10
/// and 20 (seconds); full the same at D/Δ = 4, 8 and 16 (16: the convergence of the Stokes
/// layer's share of C_M and of C_D, README).
pub fn level(shape: Shape, quick: bool) -> Vec<MorisonCase> {
    let cells: &[usize] = if quick { &[4] } else { &[4, 8, 16] };
    cells
        .iter()
        .flat_map(|&c| {
            [2.0, 5.0, 10.0, 20.0]
                .into_iter()
                .map(move |kc| MorisonCase::of(shape, kc, BETA, c))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fit recovers the coefficients of a synthetic Morison force on unequal steps.
    #[test]
    fn the_fit_recovers_known_coefficients() {
        let (rho, area, volume, omega): (f64, f64, f64, f64) = (1.0, 0.785, 0.524, 0.9);
        let mut t: f64 = 0.0;
        let mut record = Vec::new();
        for i in 0..3000 {
            let u = (omega * t).sin();
            let dudt = omega * (omega * t).cos();
            let f = 0.5 * rho * 1.3 * area * u.abs() * u + rho * volume * 1.7 * dudt;
            record.push((t, f, u));
            t += 0.004 + 0.002 * ((i % 7) as f64 / 7.0);
        }
        let fit = fit_morison(&record, 1.0, rho, area, volume);
        assert!((fit.drag - 1.3).abs() < 1e-3, "{fit:?}");
        assert!((fit.inertia - 1.7).abs() < 1e-3, "{fit:?}");
        assert!(fit.residual < 1e-3);
    }

    /// The volume the grid sees: the sphere's fractions hold its exact volume; the cube's
    /// union is near D_n³ and less than its members' volumes summed (they overlap).
    #[test]
    fn the_seen_volume_is_the_union_of_the_members() {
        let grid = StaggeredGrid::new([16, 16, 16], Vec3::splat(4.0), Vec3::ZERO);
        let centre = Vec3::splat(2.0);
        let sphere = seen_volume(&grid, &Shape::Sphere.members(centre));
        assert!((sphere - PI / 6.0).abs() < 1e-9, "{sphere}");
        let members = Shape::Cube.members(centre);
        let cube = seen_volume(&grid, &members);
        let sum: f64 = members.iter().map(|m| 4.0 / 3.0 * PI * m.1.powi(3)).sum();
        eprintln!("cube: seen {cube:.4} D_n³, members {sum:.4} D_n³");
        assert!(
            (cube - 1.0).abs() < 0.1 && sum > 1.02 * cube,
            "{cube} {sum}"
        );
    }

    /// The references: the Stokes C_M at β = 10 and the quasi-steady C_D at high Re tends to
    /// the standard curve's value (C_D varies slowly there).
    #[test]
    fn the_references_have_their_limits() {
        assert!((stokes_inertia(10.0) - 2.303).abs() < 1e-3);
        assert!((stokes_inertia(1e12) - 1.5).abs() < 1e-5);
        let qs = quasi_steady_drag(1000.0);
        assert!(qs > clift_grace_weber_1978(1000.0) && qs < 1.3 * clift_grace_weber_1978(1000.0));
    }
}
