//! Benchmarks: the DEM on problems shared with LIGGGHTS and LAMMPS (`bench/peers/README.md`),
//! the flow solver, a 3D wave flume, coupled runs, and the tsunami harbour. Speed is measured here, never in tests.

pub mod b1;
pub mod b2;
pub mod coupled;
pub mod fluid;
pub mod flume;
pub mod harbour;

pub use b1::{b1_lattice, b1_row, b1_simulation, peak_memory, run_b1, B1Result, B1Row};
pub use b2::{b2_row, b2_simulation, read_lammps_data, run_b2, B2Result, B2Row, LammpsData};
pub use fluid::{bench_size, median, time_cavity, FluidBenchRow};
