//! Flow fields to ParaView: `Fluid::cell_fields` gives cell-centred arrays in the order of
//! `io::vtk::write_image` (x fastest), which writes them as a `.vti` image.
//!
//! Run: `cargo test --release --test fluid_output`.

use riprap::fluid::operators::cell_vorticity;
use riprap::fluid::{Boundaries, Boundary, Fluid, FluidParameters, StaggeredGrid};
use riprap::io::vtk::{write_image, Array, Format, Values};
use riprap::math::Vec3;

#[test]
fn cell_fields_write_as_a_vtk_image() {
    let grid = StaggeredGrid::new(
        [8, 4, 6],
        Vec3::new(0.8, 0.4, 0.6),
        Vec3::new(1.0, 0.0, -0.6),
    );
    let bcs = Boundaries::periodic().with(2, Boundary::WALL, Boundary::FreeSlip);
    let mut fluid = Fluid::new(grid, bcs, FluidParameters::water()).unwrap();
    fluid.set_velocity(|x| Vec3::new((x.z + 0.6) * 0.5, 0.0, 0.0));
    fluid.step(1e-3);
    let f = fluid.cell_fields();
    assert_eq!(f.velocity.len(), grid.cell_count());
    // Cell (i, j, k) is entry i + nx (j + ny k): check one against the faces it averages.
    let (i, j, k) = (3, 2, 4);
    let c = grid.cell(i, j, k);
    let u = fluid.velocity()[0];
    let m = i + 8 * (j + 4 * k);
    assert_eq!(f.velocity[m].x, 0.5 * (u[c] + u[c + 1]));
    assert_eq!(f.pressure[m], fluid.pressure()[c]);

    let dir = std::env::temp_dir().join(format!("riprap_fluid_output_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("flow_000001.vti");
    write_image(
        &path,
        grid.n,
        grid.origin,
        grid.spacing,
        &[
            Array {
                name: "velocity_m_s",
                values: Values::Vectors(&f.velocity),
            },
            Array {
                name: "pressure_Pa",
                values: Values::Scalars(&f.pressure),
            },
            Array {
                name: "mixture_density_kg_m3",
                values: Values::Scalars(&f.mixture_density),
            },
            Array {
                name: "eddy_viscosity_Pa_s",
                values: Values::Scalars(&f.eddy_viscosity),
            },
            Array {
                name: "divergence_1_s",
                values: Values::Scalars(&f.divergence),
            },
        ],
        Format::default(),
    )
    .unwrap();
    let bytes = std::fs::read(&path).unwrap();
    let head = String::from_utf8_lossy(&bytes[..bytes.len().min(2000)]);
    assert!(head.contains("ImageData") && head.contains("velocity_m_s"));
    assert!(
        head.contains(r#"type="Float32" Name="pressure_Pa""#),
        "{head}"
    );
    assert!(head.contains(r#"compressor="vtkZLibDataCompressor""#));
    assert!(head.contains(r#"WholeExtent="0 8 0 4 0 6""#));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn cell_vorticity_of_a_solid_body_rotation_is_twice_the_rate() {
    // u = Ω × x with Ω = (0, 0, 2) s⁻¹ about the box centre: ∇ × u = 2 Ω exactly for the
    // central differences of a linear field (interior cells, away from the wall ghosts).
    let grid = StaggeredGrid::new([8, 8, 4], Vec3::new(0.8, 0.8, 0.4), Vec3::ZERO);
    let bcs = Boundaries::periodic()
        .with(0, Boundary::FreeSlip, Boundary::FreeSlip)
        .with(1, Boundary::FreeSlip, Boundary::FreeSlip);
    let mut fluid = Fluid::new(grid, bcs, FluidParameters::laminar(1000.0, 1e-6)).unwrap();
    let omega = Vec3::new(0.0, 0.0, 2.0);
    let centre = Vec3::new(0.4, 0.4, 0.2);
    fluid.set_velocity(|x| omega.cross(x - centre));
    let f = fluid.cell_fields();
    for (k, j, i) in [(1, 3, 3), (2, 1, 6), (0, 6, 2)] {
        let w = f.vorticity[i + 8 * (j + 8 * k)];
        assert!(
            (w - 2.0 * omega).length() < 1e-12,
            "cell ({i}, {j}, {k}): {w}"
        );
        let st = riprap::fluid::grid::Stencil::new(&grid);
        assert_eq!(w, cell_vorticity(&st, fluid.velocity(), grid.cell(i, j, k)));
    }
}
