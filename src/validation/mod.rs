//! The validation cases of `riprap validate`, out of the physics: each case a directory with
//! its README (source, set-up, compared quantity, tolerance, run cost) and reference data, and
//! [`report`] running them and writing the report. It stands right of the scenarios and the
//! output in the module map (it builds runs from scenario files and draws plots); only the CLI
//! and the tests use it.
//!
//! * the flow solver: [`cavity`] (lid-driven cavity, Ghia, Ghia & Shin 1982) and
//!   [`channel180`] (turbulent channel flow, Moser, Kim & Mansour 1999);
//! * the coupling's cases 1 to 5 of METHOD.md §5: [`sphere_drag`], [`cylinder_strouhal`],
//!   [`block_settling`], [`hopper_cloud`] and [`sheet_flow`]; [`morison_sphere`] (Morison's
//!   C_D and C_M of a fixed sphere and a fixed cube in oscillatory flow, issue 29);
//! * beyond the source: [`wet_rebound`] (a sphere rebounding from a wall in a liquid, against
//!   the measurements of Gondret et al. 2002), the lubrication film of wet contacts;
//!   [`dam_break`] (a water column collapsing under air, against Martin & Moyce 1952) and
//!   [`standing_wave`] (the first sloshing mode of a tank, against linear theory), the free
//!   surface; [`regular_waves`] (a linear and a steep wave generated, carried five
//!   wavelengths and absorbed)
//!   and [`absorption`] (the absorbing zone's reflection, kh 0.5 to 3), the wave flume, and
//!   [`wavemaker`] (the height a piston or a flap makes), all on [`flume_case`];
//!   [`solitary_wave`] (a solitary wave's height and speed over ten depths of travel);
//!   [`floating_sphere`] (the coupling under air: Archimedes' draft), [`floating_box`] (a
//!   block's);
//! * the shallow-water solver (`shallow`): [`shallow_lake_at_rest`] (well balanced over a
//!   rough bed with dry islands), [`shallow_dam_break`] (Stoker and Ritter, L1 error and its
//!   order), [`shallow_thacker`] (Thacker's moving shoreline in a paraboloid) and
//!   [`shallow_runup`] (a solitary wave on a plane beach, Synolakis 1987); the debris it
//!   carries (`debris`): [`shallow_debris`] (Archimedes, quadratic drag, Coulomb friction,
//!   flooding, thread bits, against closed forms).

pub mod absorption;
pub mod block_settling;
pub mod cavity;
pub mod channel180;
pub mod cylinder_strouhal;
pub mod dam_break;
pub mod floating_box;
pub mod floating_sphere;
pub mod flume_case;
pub mod hopper_cloud;
pub mod morison_sphere;
pub mod regular_waves;
pub mod report;
pub mod shallow_dam_break;
pub mod shallow_debris;
pub mod shallow_lake_at_rest;
pub mod shallow_runup;
pub mod shallow_thacker;
pub mod sheet_flow;
pub mod solitary_wave;
pub mod sphere_drag;
pub mod standing_wave;
pub mod wavemaker;
pub mod wet_rebound;

pub use report::{run_validation, run_validation_cases, CASES};

use crate::fluid::exchange::Momentum;
use crate::fluid::interface::Reconstruction;
use crate::fluid::phases::Air;
use crate::fluid::{Boundaries, Boundary, Fluid, FluidParameters, StaggeredGrid};
use crate::math::Vec3;

/// The shallow-water cases that `run` (a case name's test) selects, appended to `md`;
/// whether all of them passed.
pub fn shallow_sections(
    out: &std::path::Path,
    quick: bool,
    run: &dyn Fn(&str) -> bool,
    md: &mut String,
) -> anyhow::Result<bool> {
    let mut all = true;
    if run("shallow_lake_at_rest") {
        all &= shallow_lake_at_rest::section(out, quick, md)?;
    }
    if run("shallow_dam_break") {
        all &= shallow_dam_break::section(out, quick, md)?;
    }
    if run("shallow_thacker") {
        all &= shallow_thacker::section(out, quick, md)?;
    }
    if run("shallow_runup") {
        all &= shallow_runup::section(out, quick, md)?;
    }
    if run("shallow_debris") {
        all &= shallow_debris::section(out, md)?;
    }
    Ok(all)
}

/// The upward zero crossings of a record (t, y) after `after` [s], each by linear
/// interpolation between its two samples [s].
pub fn up_crossings(record: &[(f64, f64)], after: f64) -> Vec<f64> {
    record
        .windows(2)
        .filter(|w| w[0].0 > after && w[0].1 < 0.0 && w[1].1 >= 0.0)
        .map(|w| w[0].0 + (w[1].0 - w[0].0) * (-w[0].1) / (w[1].1 - w[0].1))
        .collect()
}

/// The momentum transport across the surface the free-surface cases run with
/// (`riprap validate --momentum`; the default unless set).
static MOMENTUM: std::sync::Mutex<Momentum> = std::sync::Mutex::new(Momentum::Upwind);

/// Sets the momentum transport of the free-surface cases ([`momentum`]).
pub fn set_momentum(m: Momentum) {
    *MOMENTUM.lock().expect("not poisoned") = m;
}

/// The momentum transport the free-surface cases run with ([`set_momentum`]).
pub fn momentum() -> Momentum {
    *MOMENTUM.lock().expect("not poisoned")
}

/// A case's scenario text with [`momentum`] under `[fluid.air]` when it is not the default.
pub fn with_momentum(text: &str) -> String {
    match momentum() {
        m if m.is_default() => text.to_string(),
        m => {
            let line = format!("[fluid.air]\nmomentum = \"{}\"", m.name());
            text.replacen("[fluid.air]", &line, 1)
        }
    }
}

/// The free-surface cases' flow: `cells` over a box of `size` [m] from the origin, a 2D
/// slice (periodic in y), `start` at x = 0 (free slip, or a wavemaker), free-slip walls at x
/// = max and at the bottom, `top` above (a free-slip
/// lid or open to the atmosphere), water without a subgrid model under air at 20 °C whose
/// surface is carried with `reconstruction`, momentum as [`momentum`] says, gravity `g` [m s⁻²] down z. The water is set by
/// the case.
pub fn slice_under_air(
    cells: [usize; 3],
    size: Vec3,
    g: f64,
    start: Boundary,
    top: Boundary,
    reconstruction: Reconstruction,
) -> Fluid {
    let grid = StaggeredGrid::new(cells, size, Vec3::ZERO);
    let bcs = Boundaries::periodic()
        .with(0, start, Boundary::FreeSlip)
        .with(2, Boundary::FreeSlip, top);
    let mut p = FluidParameters::water();
    p.smagorinsky = None;
    p.gravity = Vec3::new(0.0, 0.0, -g);
    p.air = Some(Air {
        reconstruction,
        momentum: momentum(),
        ..Air::default()
    });
    Fluid::new(grid, bcs, p).expect("the slice is a valid fluid")
}
