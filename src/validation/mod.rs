//! The validation cases of `riprap validate`, out of the physics: each case a directory with
//! its README (source, set-up, compared quantity, tolerance, run cost) and reference data, and
//! [`report`] running them and writing the report. It stands right of the scenarios and the
//! output in the module map (it builds runs from scenario files and draws plots); only the CLI
//! and the tests use it.
//!
//! * the flow solver: [`cavity`] (lid-driven cavity, Ghia, Ghia & Shin 1982) and
//!   [`channel180`] (turbulent channel flow, Moser, Kim & Mansour 1999);
//! * the coupling's cases 1 to 5 of METHOD.md §5: [`sphere_drag`], [`cylinder_strouhal`],
//!   [`block_settling`], [`hopper_cloud`] and [`sheet_flow`];
//! * beyond the source: [`wet_rebound`] (a sphere rebounding from a wall in a liquid, against
//!   the measurements of Gondret et al. 2002), the lubrication film of wet contacts;
//!   [`dam_break`] (a water column collapsing under air, against Martin & Moyce 1952) and
//!   [`standing_wave`] (the first sloshing mode of a tank, against linear theory), the free
//!   surface; [`regular_waves`] (a wave generated, carried five wavelengths and absorbed),
//!   the wave flume.

pub mod block_settling;
pub mod cavity;
pub mod channel180;
pub mod cylinder_strouhal;
pub mod dam_break;
pub mod hopper_cloud;
pub mod regular_waves;
pub mod report;
pub mod sheet_flow;
pub mod sphere_drag;
pub mod standing_wave;
pub mod wet_rebound;

pub use report::{run_validation, run_validation_cases, CASES};
