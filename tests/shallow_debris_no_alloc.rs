//! A step of the debris (`crate::debris::Debris::advance`) allocates nothing: counted with a
//! counting global allocator (this test binary only), on one thread, through the DEM's
//! contacts, wall contacts, flooding and grounding, once the DEM's buffers have grown: the
//! run is made twice over the same flow steps, and the second pass counted. The exception is
//! the DEM's own neighbour rebuild, which still allocates a few times per rebuild (about two:
//! its wall lists' and contact history's carry-over); the flow steps with a rebuild are
//! counted apart and printed, not asserted.
//!
//! Run: `cargo test --release --test shallow_debris_no_alloc`.

use riprap::scenario::shallow::{build, ShallowSource};

const FLUME: &str = r#"
[run]
name = "flume"
end_time = 6.0

[shallow]
manning = 0.012

[shallow.grid]
min = [0.0, 0.0]
max = [40.0, 6.0]
cell_size = 0.5

[shallow.bed]
kind = "flat"
elevation = -0.5

[shallow.initial]
level = 0.0
[[shallow.initial.region]]
min = [0.0, 0.0]
max = [8.0, 6.0]
level = 0.5

[shallow.boundaries]
x_max = { kind = "transmissive" }

[[shallow.structure]]
name = "pier"
min = [20.0, 2.0]
max = [21.0, 4.0]

[[shallow.debris]]
name = "box"
length = 1.0
width = 0.5
height = 0.5
mass = 60.0
position = [11.0, 2.4]
count = [3, 2]
spacing = [1.5, 1.0]
flooding_time = 4.0

[output]
vtk_interval = 1.0
series_interval = 0.25
debris_interval = 0.1
checkpoint_interval = 2.0
plots = false
"#;

#[test]
fn a_debris_step_allocates_nothing_once_running() {
    let src = ShallowSource::from_str(FLUME, "flume.toml", std::env::temp_dir()).unwrap();
    let mut b = build(&src).unwrap();
    let d = b.debris.as_mut().unwrap();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    pool.install(|| {
        let mut dts = Vec::with_capacity(400);
        for _ in 0..400 {
            dts.push(b.water.step_towards(100.0));
        }
        // The flow first, then the debris through the same steps twice: once to grow the
        // DEM's buffers, then again from the start, counted after 50 steps (the spheres'
        // scratch regrows at the first rebuild after a restore).
        let start = d.snapshot();
        for &dt in &dts {
            d.advance(&b.water, dt).unwrap();
        }
        let end = d.snapshot();
        d.restore(start).unwrap();
        for &dt in &dts[..50] {
            d.advance(&b.water, dt).unwrap();
        }
        let (mut quiet, mut at_rebuilds, mut rebuilds) = (0, 0, 0);
        for &dt in &dts[50..] {
            let (a0, b0) = (counting::allocations(), d.dem().neighbors.builds);
            d.advance(&b.water, dt).unwrap();
            let a = counting::allocations() - a0;
            if d.dem().neighbors.builds == b0 {
                quiet += a;
            } else {
                at_rebuilds += a;
                rebuilds += d.dem().neighbors.builds - b0;
            }
        }
        eprintln!("{rebuilds} neighbour rebuilds, {at_rebuilds} allocations in their flow steps");
        assert!(rebuilds > 3, "the test should see rebuilds: {rebuilds}");
        assert_eq!(
            quiet, 0,
            "the debris allocated {quiet} times in steps without a rebuild"
        );
        assert_eq!(d.snapshot().blocks, end.blocks, "the second pass differs");
    });
}

mod counting {
    use std::alloc::{GlobalAlloc, Layout, System};
    use std::sync::atomic::{AtomicUsize, Ordering};

    struct Counting;

    static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

    pub fn allocations() -> usize {
        ALLOCATIONS.load(Ordering::Relaxed)
    }

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
}
