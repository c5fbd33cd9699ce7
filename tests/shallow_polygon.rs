//! Structures as polygons (`[[shallow.structure]] polygon = …`, issue 31): solid cells for the
//! flow, walls for the debris.
//!
//! * a slanted polygon wall across a channel holds back a dam break: the still water behind it
//!   keeps its very bits (no flux crosses a wall face), and a lake at rest around a polygon
//!   building stays at rest to round-off;
//! * a polygon structure is a wall (a DEM mesh) of the debris;
//! * a polygon with fewer than three vertices, one that crosses itself and one outside the
//!   grid are refused with the file, the line and the key.
//!
//! Run: `cargo test --release --test shallow_polygon`.

use std::path::PathBuf;

use riprap::dem::walls::Shape;
use riprap::scenario::shallow::{build, ShallowSource};

/// A channel 40 m × 20 m of 0.5 m cells over a flat bed at −2 m, still water at 0, with
/// `extra` appended.
fn channel(extra: &str) -> String {
    format!(
        r#"
[run]
name = "polygon"
end_time = 10.0

[shallow]

[shallow.grid]
min = [0.0, 0.0]
max = [40.0, 20.0]
cell_size = 0.5

[shallow.bed]
kind = "flat"
elevation = -2.0

[shallow.initial]
level = 0.0
{extra}
"#
    )
}

fn source(text: &str) -> ShallowSource {
    ShallowSource::from_str(text, "polygon.toml", PathBuf::new()).unwrap()
}

/// A slanted wall across the whole channel (its ends beyond the grid), 3 m thick.
const WALL: &str = r#"
[[shallow.structure]]
name = "slanted_wall"
polygon = [[18.0, -1.0], [21.0, -1.0], [25.0, 21.0], [22.0, 21.0]]
"#;

#[test]
fn a_polygon_wall_holds_back_a_dam_break_to_the_bit() {
    let reservoir =
        "[[shallow.initial.region]]\nmin = [0.0, 0.0]\nmax = [10.0, 20.0]\nlevel = 1.0\n";
    let text = channel(&format!("{reservoir}{WALL}"));
    let mut w = build(&source(&text)).unwrap().water;
    let g = *w.grid();
    let solid = g.interior(w.solid());
    // The wall covers cells in every row.
    for j in 0..g.ny {
        assert!((0..g.nx).any(|i| solid[i + g.nx * j]), "row {j} open");
    }
    // Behind the wall: the cells whose centre lies beyond its far face x = 22 + 4 (y + 1)/22.
    let behind = |i: usize, j: usize| {
        let [x, y] = g.centre(i as isize, j as isize);
        x > 22.0 + 4.0 * (y + 1.0) / 22.0 && !solid[i + g.nx * j]
    };
    let start: Vec<[f64; 3]> = (0..g.ny)
        .flat_map(|j| (0..g.nx).map(move |i| (i, j)))
        .map(|(i, j)| w.cell(i, j))
        .collect();
    let before = w.volume();
    // 30 s: the bore reaches the wall after about 2 s and reflects.
    while w.time() < 30.0 {
        w.step_towards(30.0);
    }
    let mut moved = 0.0f64;
    for j in 0..g.ny {
        for i in 0..g.nx {
            let c = w.cell(i, j);
            let k = i + g.nx * j;
            if solid[k] {
                assert_eq!(c, [0.0; 3], "solid cell ({i}, {j}) holds water");
            } else if behind(i, j) {
                assert_eq!(c, start[k], "({i}, {j}) behind the wall changed");
            } else {
                moved = moved.max((c[0] - start[k][0]).abs());
            }
        }
    }
    // The dam broke on the near side (the test is not vacuous), and the volume is kept.
    assert!(moved > 0.1, "the reservoir did not move: {moved}");
    assert!((w.volume() - before).abs() < 1e-9 * before);
}

#[test]
fn a_lake_at_rest_around_a_polygon_building_stays_at_rest() {
    // An L-shaped building, concave, at an angle to the grid.
    let text = channel(
        r#"
[[shallow.structure]]
name = "building"
polygon = [[12.3, 4.1], [25.7, 6.2], [24.9, 11.0], [18.2, 9.9], [16.8, 16.4], [11.1, 15.3]]
"#,
    );
    let mut w = build(&source(&text)).unwrap().water;
    let g = *w.grid();
    let solid = g.interior(w.solid());
    assert!(solid.iter().filter(|&&s| s).count() > 100);
    for _ in 0..500 {
        w.step();
    }
    let mut worst = (0.0f64, 0.0f64);
    for j in 0..g.ny {
        for i in 0..g.nx {
            if solid[i + g.nx * j] {
                assert_eq!(w.cell(i, j), [0.0; 3]);
                continue;
            }
            let (h, [u, v]) = w.depth_velocity(i, j);
            worst.0 = worst.0.max((h - 2.0).abs());
            worst.1 = worst.1.max(u.hypot(v));
        }
    }
    // Round-off of O(1) numbers over 500 steps (as `shallow_lake_at_rest`).
    assert!(worst.0 < 1e-12 && worst.1 < 1e-12, "{worst:?}");
}

#[test]
fn a_polygon_structure_is_a_wall_of_the_debris() {
    let text = channel(&format!(
        "{WALL}\n[[shallow.debris]]\ncontainer = \"20ft\"\nposition = [8.0, 10.0]\n\n\
         [[shallow.structure]]\nname = \"kiosk\"\nmin = [30.0, 2.0]\nmax = [32.0, 4.0]\n"
    ));
    let d = build(&source(&text)).unwrap().debris.unwrap();
    let walls = &d.dem().walls;
    assert_eq!(walls.len(), 2);
    assert!(matches!(walls[0].shape, Shape::Mesh(_)));
    assert!(matches!(walls[1].shape, Shape::Cuboid(_)));
}

#[test]
fn bad_polygons_are_refused_with_file_line_and_key() {
    for (polygon, says) in [
        ("[[1.0, 1.0], [5.0, 1.0]]", "at least three vertices"),
        (
            "[[1.0, 1.0], [5.0, 5.0], [5.0, 1.0], [1.0, 5.0]]",
            "must not cross itself",
        ),
        (
            "[[100.0, 1.0], [105.0, 1.0], [105.0, 5.0]]",
            "covers no cell centre",
        ),
    ] {
        let text = channel(&format!(
            "\n[[shallow.structure]]\nname = \"bad\"\npolygon = {polygon}\n"
        ));
        let line = text.lines().position(|l| l.starts_with("polygon")).unwrap() + 1;
        let key_line = if says.contains("covers") {
            line - 2 // the table's header
        } else {
            line
        };
        let e = build(&source(&text)).err().unwrap().to_string();
        assert!(e.starts_with(&format!("polygon.toml:{key_line}:")), "{e}");
        assert!(e.contains("shallow.structure[0]"), "{e}");
        assert!(e.contains(says), "{e}");
    }
}
