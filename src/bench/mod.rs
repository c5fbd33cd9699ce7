//! Benchmarks: the DEM on problems shared with LIGGGHTS and LAMMPS (`shared/bench/README.md`),
//! and the flow solver. Speed is measured here, never in tests.

pub mod b1;
pub mod fluid;

pub use b1::{b1_lattice, b1_row, b1_simulation, peak_memory, run_b1, B1Result, B1Row};
pub use fluid::{bench_size, median, time_cavity, FluidBenchRow};
