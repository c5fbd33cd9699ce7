//! Every kind of VTK file riprap writes (.vtu, .vtp, .vti and the .pvd series), compressed and
//! not, Float32 and Float64, read back by VTK itself: `tests/vtk_reader/read_back.py` compares
//! each value with what was written. Skipped, saying so, where Python has no `vtk` package
//! (`pip install vtk`); `cargo test --lib io::vtk` checks the same format in pure Rust.
//!
//! Run: `cargo test --release --test vtk_reader -- --nocapture`.

use riprap::io::pvd::PvdSeries;
use riprap::io::vtk::{
    write_image, write_points, write_surface, Array, Compression, Format, Precision,
};
use riprap::math::Vec3;
use std::process::Command;

/// Points, image cells, and triangles + 2 (the formulas are those of read_back.py).
const N: usize = 1500;

#[test]
fn every_vtk_file_kind_and_format_reads_back_in_vtk() {
    let dir = std::env::temp_dir().join(format!("riprap_vtk_reader_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let f = |i: usize| i as f64;
    let pos: Vec<Vec3> = (0..N)
        .map(|i| Vec3::new(f(i) / 8.0, f(i) * 0.25 - 3.0, 1000.0 + f(i) / 1024.0))
        .collect();
    let id: Vec<i64> = (0..N as i64).map(|i| 3 * i - 7).collect();
    let diameter: Vec<f64> = (0..N).map(|i| 0.01 + f(i) * 2f64.powi(-20)).collect();
    let velocity: Vec<Vec3> = (0..N)
        .map(|i| Vec3::new(f(i) / 3.0, -f(i) / 7.0, 1.0))
        .collect();
    let tri: Vec<[u32; 3]> = (0..N as u32 - 2).map(|i| [i, i + 1, i + 2]).collect();
    let wear: Vec<f64> = (0..N - 2).map(|i| f(i) * 0.25).collect();
    let p: Vec<f64> = (0..N).map(|i| f(i) / 3.0).collect();
    let u: Vec<Vec3> = (0..N).map(|i| Vec3::new(f(i), -f(i) / 7.0, 0.5)).collect();

    let mut series = PvdSeries::new(dir.join("series.pvd"));
    let mut time = 0.0;
    for compression in [Compression::Zlib, Compression::None] {
        for precision in [Precision::Float32, Precision::Float64] {
            let format = Format {
                compression,
                precision,
            };
            let tag = format!(
                "{}_{}",
                match compression {
                    Compression::Zlib => "zlib",
                    Compression::None => "raw",
                },
                match precision {
                    Precision::Float32 => "float32",
                    Precision::Float64 => "float64",
                }
            );
            let points = [
                Array::ints("id", &id),
                Array::scalars("diameter", &diameter),
                Array::vectors("velocity", &velocity),
            ];
            let name = format!("spheres_{tag}.vtu");
            write_points(&dir.join(&name), &pos, &points, format).unwrap();
            series.add(time, &name, 0).unwrap();
            let name = format!("walls_{tag}.vtp");
            let cells = [Array::scalars("wear", &wear)];
            write_surface(&dir.join(&name), &pos, &tri, &cells, format).unwrap();
            series.add(time, &name, 1).unwrap();
            let name = format!("flow_{tag}.vti");
            let (origin, spacing) = (Vec3::new(-1.0, 0.0, 0.5), Vec3::new(0.125, 0.25, 0.5));
            let cells = [Array::scalars("p", &p), Array::vectors("u", &u)];
            write_image(
                &dir.join(&name),
                [10, 15, 10],
                origin,
                spacing,
                &cells,
                format,
            )
            .unwrap();
            series.add(time, &name, 2).unwrap();
            time += 0.5;
        }
    }

    let has_vtk = Command::new("python3")
        .args(["-c", "import vtk, numpy"])
        .output()
        .is_ok_and(|o| o.status.success());
    if !has_vtk {
        eprintln!("skipped: Python with the vtk and numpy packages not found (pip install vtk)");
        return;
    }
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/vtk_reader/read_back.py");
    let out = Command::new("python3")
        .arg(script)
        .arg(&dir)
        .output()
        .unwrap();
    let text =
        String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "VTK could not read the files back:\n{text}"
    );
    eprintln!("{text}");
    std::fs::remove_dir_all(&dir).unwrap();
}
