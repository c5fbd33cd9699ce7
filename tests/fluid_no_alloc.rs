//! `Fluid::step` allocates nothing: every buffer and transform plan is made in `Fluid::new`.
//! Checked with a counting global allocator (this test binary only), on one thread.
//!
//! Run: `cargo test --release --test fluid_no_alloc`.

use riprap::fluid::phases::{box_fraction, Air};
use riprap::fluid::pressure::Preconditioner;
use riprap::fluid::{
    Boundaries, Boundary, DrivingPressureGradient, Fluid, FluidParameters, InflowVelocity,
    StaggeredGrid,
};
use riprap::math::Vec3;
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn a_step_allocates_nothing() {
    // Everything on: walls, inflow/outflow, SGS, variable density, drive, both the serial
    // (small) and the parallel (large) code paths; one thread so that rayon's own job
    // bookkeeping stays out of the count.
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    pool.install(|| {
        for n in [[12, 4, 10], [40, 12, 40]] {
            let grid = StaggeredGrid::new(n, Vec3::new(1.2, 0.4, 1.0), Vec3::ZERO);
            let bcs = Boundaries::periodic()
                .with(
                    0,
                    Boundary::Inflow(InflowVelocity::steady(Vec3::new(0.1, 0.0, 0.0))),
                    Boundary::Outflow,
                )
                .with(2, Boundary::WALL, Boundary::FreeSlip);
            let mut par = FluidParameters::water();
            par.driving_pressure_gradient = DrivingPressureGradient::Oscillatory {
                velocity_amplitude: Vec3::new(0.1, 0.0, 0.0),
                period: 3.0,
            };
            par.pressure_passes = 2;
            let mut fluid = Fluid::new(grid, bcs, par).unwrap();
            fluid.set_velocity(|_| Vec3::new(0.1, 0.0, 0.0));
            fluid.set_mixture_density(|x| if x.z < 0.3 { 1300.0 } else { 998.2 });
            fluid.step(1e-3); // the first step, iterated
            let before = ALLOCATIONS.load(Ordering::Relaxed);
            for _ in 0..5 {
                let dt = fluid.stable_time_step().min(1e-2);
                fluid.step(dt);
            }
            let during = ALLOCATIONS.load(Ordering::Relaxed) - before;
            println!("{n:?}: {during} allocations in 5 steps");
            assert_eq!(during, 0, "{n:?}: step() allocated");
        }
        // Water and air: the interface scheme and the exact projection (its vectors and the
        // multigrid levels sized on the first step), with each preconditioner.
        for preconditioner in [Preconditioner::Spectral, Preconditioner::Multigrid] {
            let grid = StaggeredGrid::new([16, 4, 16], Vec3::new(0.4, 0.1, 0.4), Vec3::ZERO);
            let bcs = Boundaries::periodic()
                .with(0, Boundary::FreeSlip, Boundary::FreeSlip)
                .with(2, Boundary::WALL, Boundary::FreeSlip);
            let mut par = FluidParameters::water();
            par.air = Some(Air {
                pressure_preconditioner: preconditioner,
                ..Air::default()
            });
            let mut fluid = Fluid::new(grid, bcs, par).unwrap();
            fluid
                .set_water_fraction(|lo, hi| box_fraction(lo, hi, [-1.0; 3], [0.1, 1.0, 0.2]))
                .unwrap();
            fluid.step(1e-3);
            let before = ALLOCATIONS.load(Ordering::Relaxed);
            for _ in 0..5 {
                let dt = fluid.stable_time_step().min(1e-2);
                fluid.step(dt);
            }
            let during = ALLOCATIONS.load(Ordering::Relaxed) - before;
            println!("water and air, {preconditioner:?}: {during} allocations in 5 steps");
            assert_eq!(
                during, 0,
                "water and air, {preconditioner:?}: step() allocated"
            );
        }
    });
}
