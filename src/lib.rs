//! # riprap
//!
//! Sand grains and concrete armour blocks under water: a 3D discrete element method (DEM) for
//! spheres and rigid blocks built from spheres, with a large-eddy simulation of the water coupled
//! in both directions. The method, with its equation numbers, is
//! `docs/METHOD.md`; doc comments cite those numbers in brackets, e.g. [9].
//!
//! Module map (a module uses what is above it, never what is below; `fluid` uses only `math`,
//! and `run`, `bench`, `validation` do not use each other; `tests/layering.rs`
//! fails on an import against it):
//!
//! * [`math`]: vector types (one name each) and the few vector helpers
//! * [`geometry`]: where a sphere touches a plane, box, cylinder or triangle mesh
//! * [`dem`]: spheres, materials, contact laws, neighbour search, walls, integration
//! * [`rigid`]: blocks made of spheres (the passively moving solid model [34]-[49]), wires
//!   and bonds
//! * [`fluid`]: the LES of the water on a staggered grid (METHOD.md §4)
//! * [`shallow`]: the 2D nonlinear shallow-water equations by finite volumes (inundation at
//!   harbour scale, issue 31); uses nothing else of the crate
//! * [`coupling`]: the Euler-Lagrange coupling of spheres and water ([53], [59]-[63], drag [5])
//! * [`debris`]: tsunami debris (containers) as rigid blocks carried one way by the
//!   shallow-water flow, their contacts by the DEM; the one module using both `shallow` and
//!   `rigid`/`dem`
//! * [`simulation`]: the order of the phases of a time step
//! * [`io`]: VTK and `.pvd` output, CSV time series, plots, checkpoints
//! * [`scenario`]: TOML scenario files and the checks and derived quantities of `riprap check`
//! * [`run`]: a run with its outputs, checkpoints and progress, as the CLI drives it
//! * [`bench`]: benchmarks: the DEM against LIGGGHTS and LAMMPS, the flow solver, coupled runs
//! * [`validation`]: the validation cases of `riprap validate`, each a directory with its
//!   README and reference data
//!
//! Threads: the parallel loops run on rayon's global pool, and their results do not depend on
//! its size. Drive a simulation from a thread of that pool, as the `riprap` binary does
//! (`rayon::scope(|_| ...)` around the run): a parallel loop started from any other thread
//! hands its work over and sleeps until it is done, a trip through the kernel per loop (case 5
//! of the coupling on 1 thread: 116 ms per fluid step that way, 68 ms from a pool thread).

#![warn(missing_docs)]

pub mod armour;
pub mod bench;
pub mod coupling;
pub mod debris;
pub mod dem;
pub mod fluid;
pub mod geometry;
pub mod io;
pub mod math;
pub mod rigid;
pub mod run;
pub mod scenario;
pub mod shallow;
pub mod simulation;
pub mod validation;
