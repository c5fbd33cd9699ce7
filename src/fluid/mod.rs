//! The flow solver (METHOD.md §4): variable-density LES on a staggered grid.
//!
//! The water is the density-weighted filtered incompressible flow of [50][51] on a uniform
//! Cartesian staggered (MAC) grid ([`grid`]): velocities on faces, pressure and mixture density
//! ρ̄ [53] at cell centres. Momentum is advanced by a fractional step ([`step`]): second-order
//! central differences, Adams-Bashforth (AB2) for advection ([`advection`]) and viscous and
//! subgrid stresses ([`diffusion`], Smagorinsky with van Driest damping [56]-[58] in [`sgs`]),
//! body forces (driving pressure gradient, buoyancy (ρ̄ − ρ_w) g unless the coupling carries
//! it, external force F; [`forcing`]), then a projection ([`pressure`]) that makes the
//! velocity divergence-free to round-off with variable density (Dodd & Ferrante 2014 splitting, FFT/DCT direct solver).
//! Each face of the box is periodic, a no-slip wall (fixed or moving), free slip, an inflow
//! (steady or oscillating) or an outflow ([`boundary`]). The time step adapts to CFL and
//! viscous limits ([`timestep`]). [`diagnostics`] gives whole-flow numbers (kinetic energy,
//! largest speed, a memory estimate). With air ([`phases`]) the step carries the water
//! fraction α ([`interface`]: conservative and bounded, THINC or planes ([`plic`]) with Weymouth
//! & Yue's splitting) and takes ρ and μ from it. A wave flume ([`flume`]) generates and absorbs
//! the waves of [`waves`] (linear, Stokes second order, cnoidal, solitary, JONSWAP seas, and
//! stream-function waves from [`stream_function`]) in relaxation zones; [`reflection`]
//! separates the incident and the reflected wave of gauge records. [`porous`] adds the
//! Darcy-Forchheimer resistance of porous zones (breakwater cores, filters, rubble beds; beyond
//! the source). The longer verification cases (the lid-driven cavity against Ghia et al. 1982,
//! turbulent channel flow, the free-surface cases) are in `riprap::validation`.
//!
//! In use:
//!
//! ```
//! use riprap::fluid::{Boundaries, Boundary, Fluid, FluidParameters, StaggeredGrid};
//! use riprap::math::Vec3;
//!
//! // A 2D lid-driven cavity (thin periodic y), lid on top moving at 1 m/s, Re = 100.
//! let grid = StaggeredGrid::new([16, 1, 16], Vec3::new(1.0, 0.0625, 1.0), Vec3::ZERO);
//! let lid = Boundary::Wall { velocity: Vec3::X };
//! let bcs = Boundaries::periodic()
//!     .with(0, Boundary::WALL, Boundary::WALL)
//!     .with(2, Boundary::WALL, lid);
//! let mut fluid = Fluid::new(grid, bcs, FluidParameters::laminar(1.0, 0.01)).unwrap();
//! while fluid.time() < 0.1 {
//!     fluid.step_adaptive(0.1);
//! }
//! assert!(fluid.max_divergence() < 1e-10);
//! ```
//!
//! Determinism: every parallel loop writes only its own elements and reductions are min/max,
//! so results are bitwise identical on any number of threads. [`FluidState`] (serde) holds
//! all that evolves, Adams-Bashforth history included, for bit-for-bit restarts.

pub mod advection;
pub mod boundary;
pub mod diagnostics;
pub mod diffusion;
pub mod exchange;
pub mod flume;
pub mod forcing;
pub mod grid;
pub mod interface;
pub mod model;
pub mod obstacle;
pub mod operators;
pub mod phases;
pub mod plic;
pub mod porous;
pub mod pressure;
pub mod reflection;
pub mod sea_state;
pub mod sgs;
pub mod solids;
pub mod solitary;
pub mod step;
pub mod stokes5;
pub mod stream_function;
pub mod tendency;
pub mod timestep;
pub mod timing;
pub mod wavemaker;
pub mod waves;

pub use boundary::{Boundaries, Boundary, CurrentProfile, InflowVelocity};
pub use forcing::DrivingPressureGradient;
pub use grid::StaggeredGrid;
pub use model::{CellFields, Fluid, FluidParameters, FluidState};
pub use porous::PorousZone;
pub use sgs::Smagorinsky;
pub use timestep::TimeStepLimits;
