//! `ShallowWater::step` allocates nothing: every buffer is made in `ShallowWater::new`.
//! Checked with a counting global allocator (this test binary only), on one thread, with every
//! kind of side, structures, friction and wetting and drying.
//!
//! Run: `cargo test --release --test shallow_no_alloc`.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

use riprap::shallow::{Boundaries, Boundary, Grid, Parameters, Series, ShallowWater};

struct Counting;

thread_local! {
    /// Allocations made by this thread: the test harness's own threads allocate at times of
    /// their choosing (a global count failed once under load), the step runs on one thread.
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn count() {
    ALLOCATIONS.with(|c| c.set(c.get() + 1));
}

fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn a_step_allocates_nothing() {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    pool.install(|| {
        let grid = Grid::new([30, 20], [0.0, 0.0], [30.0, 20.0]);
        let bed: Vec<f64> = (0..grid.cells())
            .map(|k| -1.0 + 0.05 * (k % 30) as f64)
            .collect();
        let mut solid = vec![false; grid.cells()];
        solid[10 + 30 * 8] = true;
        let b = Boundaries([
            Boundary::Solitary {
                height: 0.2,
                level: 0.0,
                crest_time: 1.0,
            },
            Boundary::Transmissive,
            Boundary::Elevation {
                series: Series {
                    points: vec![[0.0, 0.0], [5.0, 0.1]],
                },
            },
            Boundary::Discharge {
                series: Series {
                    points: vec![[0.0, 0.1]],
                },
            },
        ]);
        let p = Parameters {
            manning: 0.03,
            ..Parameters::default()
        };
        let mut w = ShallowWater::new(grid, &bed, &solid, p, b).unwrap();
        w.set_still(0.0);
        w.step();
        let before = allocations();
        for _ in 0..20 {
            w.step_towards(100.0);
        }
        let during = allocations() - before;
        assert_eq!(during, 0, "step() allocated {during} times in 20 steps");
    });
}
