//! Validation case 2 (METHOD.md §5): the Strouhal number of the vortex street behind a circular
//! cylinder held fixed in a uniform stream, against Roshko's measurements. See `README.md`.
//!
//! In units of the diameter D and the stream speed U (ρ = 1): a two-dimensional box (one cell
//! thick, periodic in z) L_x × L_y, uniform inflow U on x = 0, convective outflow on x = L_x,
//! periodic in y; the cylinder's axis along z at (x_c, L_y/2); ν = U D / Re; no subgrid model.
//! The cylinder is a fixed solid of the coupling (`Coupling::set_obstacle`, its cell fractions
//! sub-sampled 8 × 8 in each cell): [62] holds the water in it at rest, [59] gives its force.
//! A small cross-stream velocity blob behind it starts the shedding. After a spin-up the
//! lift's upward zero crossings give the shedding period T and St = D / (U T).

use crate::math::Vec3;

use crate::coupling::{Coupling, CouplingParameters};
use crate::dem::spheres::Spheres;
use crate::fluid::{Boundaries, Boundary, Fluid, FluidParameters, InflowVelocity, StaggeredGrid};

/// Roshko (1954, NACA Report 1191) for the stable range 40 < Re < 150:
/// St = 0.212 (1 − 21.2/Re); for the irregular range 300 < Re < 2000 he gives
/// St = 0.212 (1 − 12.7/Re).
pub fn roshko_1954(re: f64) -> f64 {
    if re <= 200.0 {
        0.212 * (1.0 - 21.2 / re)
    } else {
        0.212 * (1.0 - 12.7 / re)
    }
}

/// One run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CylinderCase {
    /// Reynolds number U D / ν.
    pub re: f64,
    /// Cells per diameter D/Δ.
    pub cells_per_diameter: usize,
    /// Box L_x × L_y [D].
    pub lengths: [f64; 2],
    /// Distance of the axis from the inflow [D].
    pub upstream: f64,
    /// Time before the period is measured [D/U].
    pub spin_up: f64,
    /// Time over which it is measured [D/U].
    pub measure: f64,
}

impl CylinderCase {
    /// The validation set-up: D/Δ = 12, 24 D × 12 D (blockage 1/12), axis 6 D from the inflow,
    /// 100 D/U of spin-up, 50 D/U of measurement (about 8 periods).
    pub fn validation(re: f64) -> CylinderCase {
        CylinderCase {
            re,
            cells_per_diameter: 12,
            lengths: [24.0, 12.0],
            upstream: 6.0,
            spin_up: 100.0,
            measure: 50.0,
        }
    }

    /// The quick level: D/Δ = 6, 16 D × 8 D, 50 + 25 D/U.
    pub fn quick(re: f64) -> CylinderCase {
        CylinderCase {
            re,
            cells_per_diameter: 6,
            lengths: [16.0, 8.0],
            upstream: 4.0,
            spin_up: 50.0,
            measure: 25.0,
        }
    }
}

/// What a run gives.
#[derive(Clone, Debug)]
pub struct CylinderResult {
    /// The case.
    pub case: CylinderCase,
    /// Measured Strouhal number (0 if no shedding).
    pub strouhal: f64,
    /// Roshko's.
    pub reference: f64,
    /// Periods measured.
    pub periods: usize,
    /// Lift coefficient C_L = F_y / (½ ρ U² D L_z) against time [D/U].
    pub lift: Vec<(f64, f64)>,
    /// Mean drag coefficient over the measurement.
    pub drag: f64,
    /// Fluid steps.
    pub steps: u64,
}

impl CylinderResult {
    /// St / St_ref − 1.
    pub fn error(&self) -> f64 {
        self.strouhal / self.reference - 1.0
    }
}

/// Runs the case.
pub fn run_cylinder(case: &CylinderCase) -> CylinderResult {
    let h = 1.0 / case.cells_per_diameter as f64;
    let n = [
        (case.lengths[0] / h).round() as usize,
        (case.lengths[1] / h).round() as usize,
        1,
    ];
    let grid = StaggeredGrid::new(
        n,
        Vec3::new(case.lengths[0], case.lengths[1], h),
        Vec3::ZERO,
    );
    let inflow = Boundary::Inflow(InflowVelocity::steady(Vec3::X));
    let bcs = Boundaries::periodic().with(0, inflow, Boundary::Outflow);
    let mut fluid =
        Fluid::new(grid, bcs, FluidParameters::laminar(1.0, 1.0 / case.re)).expect("valid");
    let (xc, yc) = (case.upstream, 0.5 * case.lengths[1]);
    // A cross-stream blob behind the cylinder breaks the symmetry.
    fluid.set_velocity(|x| {
        let r2 = (x.x - xc - 1.5).powi(2) + (x.y - yc).powi(2);
        Vec3::new(1.0, 0.3 * (-r2).exp(), 0.0)
    });
    fluid.project();
    let mut coupling = Coupling::new(CouplingParameters::default(), &fluid, 1.0);
    const M: usize = 8;
    coupling.set_obstacle(|i, j, _| {
        let mut inside = 0;
        for a in 0..M {
            for b in 0..M {
                let x = (i as f64 + (a as f64 + 0.5) / M as f64) * h - xc;
                let y = (j as f64 + (b as f64 + 0.5) / M as f64) * h - yc;
                inside += (x * x + y * y <= 0.25) as usize;
            }
        }
        inside as f64 / (M * M) as f64
    });
    let mut spheres = Spheres::default();
    let q = 0.5 * h; // ½ ρ U² D L_z
    let t_end = case.spin_up + case.measure;
    let (mut lift, mut drag, mut time) = (Vec::new(), 0.0, 0.0);
    while fluid.time() < t_end - 1e-9 {
        let dt = fluid.step_adaptive(t_end);
        coupling.fluid_forces(&fluid, &mut spheres, &[], dt);
        coupling.correct(&mut fluid, &mut spheres, dt, dt);
        let f = coupling.obstacle_force;
        lift.push((fluid.time(), f.y / q));
        if fluid.time() > case.spin_up {
            drag += f.x / q * dt;
            time += dt;
        }
    }
    // Upward zero crossings of the lift after the spin-up, linearly interpolated.
    let crossings = super::up_crossings(&lift, case.spin_up);
    let periods = crossings.len().saturating_sub(1);
    let strouhal = if periods > 0 {
        periods as f64 / (crossings[periods] - crossings[0])
    } else {
        0.0
    };
    CylinderResult {
        case: *case,
        strouhal,
        reference: roshko_1954(case.re),
        periods,
        lift,
        drag: drag / time.max(1e-300),
        steps: fluid.steps(),
    }
}

/// The runs of a level with their tolerances on |St / St_ref − 1| (README).
pub fn cylinder_level(quick: bool) -> Vec<(CylinderCase, f64)> {
    if quick {
        vec![(CylinderCase::quick(100.0), 0.15)]
    } else {
        vec![
            (CylinderCase::validation(60.0), 0.10),
            (CylinderCase::validation(100.0), 0.10),
            (CylinderCase::validation(150.0), 0.10),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The quick level of case 2 (Re = 100, D/Δ = 6): the cylinder sheds vortices at
    /// Roshko's Strouhal number within 15 % (README).
    #[test]
    fn quick_cylinder_sheds_at_roshkos_strouhal_number() {
        for (case, tol) in cylinder_level(true) {
            let r = run_cylinder(&case);
            eprintln!(
                "Re {}: St {:.4} ({} periods), Roshko {:.4}, error {:+.1} %, C_D {:.3}, {} steps",
                case.re,
                r.strouhal,
                r.periods,
                r.reference,
                100.0 * r.error(),
                r.drag,
                r.steps
            );
            assert!(r.periods >= 3, "no shedding");
            assert!(r.error().abs() < tol, "error {}", r.error());
        }
    }
}
