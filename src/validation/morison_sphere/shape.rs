//! The two fixed armour units of the case, the sphere and the cube, and the cube's references
//! (the sphere's are in the parent module). See `README.md` in this directory, "The cube".
//!
//! The cube is the library's armour cube, `rigid::library::cube(3)` (the scenario default: 27
//! overlapping spheres of diameter 1.25 a on a lattice of spacing a; a block of member
//! spheres, METHOD.md §3), with nominal diameter D_n = V^(1/3) = D, V the volume of the union
//! of its spheres. Each member is a fixed resolved sphere of the grid: [62] holds the water in it at rest, [59] gives its
//! force, each face counted with the member's share of the solid on it, so that the sum over
//! the members is the force on their union. The members are a block's ([`Shape::block`]):
//! each carries its fitted mass m_i = f_i ρ_s V, so that the coupling gives it the
//! Froude-Krylov force of its share V_i = m_i / ρ_s of the union (Σ V_i = V).

use std::f64::consts::PI;

use crate::coupling::drag::haider_levenspiel_1989;
use crate::math::Vec3;
use crate::rigid::library;

/// Spheres per edge of the cube (the scenario's default for `shape = "cube"`).
pub const CUBE_PER_EDGE: usize = 3;

/// The fixed armour unit of a run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// One resolved sphere of diameter D.
    Sphere,
    /// The library's cube of `CUBE_PER_EDGE`³ spheres, nominal diameter D_n = D, a face
    /// towards the flow (x).
    Cube,
}

impl Shape {
    /// The name in the report ("sphere", "cube").
    pub fn name(self) -> &'static str {
        match self {
            Shape::Sphere => "sphere",
            Shape::Cube => "cube",
        }
    }

    /// The reference area A of the Morison drag [D²]: the sphere's πD²/4; the cube's face
    /// D_n² (face-on).
    pub fn area(self) -> f64 {
        match self {
            Shape::Sphere => 0.25 * PI,
            Shape::Cube => 1.0,
        }
    }

    /// The reference volume V of the Morison inertia [D³]: πD³/6; D_n³.
    pub fn volume(self) -> f64 {
        match self {
            Shape::Sphere => PI / 6.0,
            Shape::Cube => 1.0,
        }
    }

    /// The member spheres (centre [D], radius [D]) of the unit centred at `centre`, axes along
    /// the grid's.
    pub fn members(self, centre: Vec3) -> Vec<(Vec3, f64)> {
        match self {
            Shape::Sphere => vec![(centre, 0.5)],
            Shape::Cube => {
                let t = library::cube(CUBE_PER_EDGE);
                // The body frame is the principal frame, which the cube's isotropic inertia
                // leaves arbitrary: orient by the template's own axes (the definition frame).
                let at = t.member_positions(centre, t.principal_axes);
                at.into_iter()
                    .zip(&t.members)
                    .map(|(x, m)| (x, m.radius))
                    .collect()
            }
        }
    }

    /// For a unit that is a block (the cube): its members' mass fractions f_i (Σ f_i = 1,
    /// in the order of [`Shape::members`]) and the volume V of their union [D³]. None for the
    /// lone sphere, a free sphere.
    pub fn block(self) -> Option<(Vec<f64>, f64)> {
        match self {
            Shape::Sphere => None,
            Shape::Cube => {
                let t = library::cube(CUBE_PER_EDGE);
                let fractions = t.members.iter().map(|m| m.mass_fraction).collect();
                Some((fractions, t.volume))
            }
        }
    }
}

/// Sphericity of a cube, ψ = π^(1/3) (6V)^(2/3) / S = (π/6)^(1/3) [–] (0.806).
pub fn cube_sphericity() -> f64 {
    (PI / 6.0).cbrt()
}

/// Steady C_D of a cube on its face area D_n² at Re = U D_n/ν [–]: Haider & Levenspiel's
/// non-spherical particle ([`haider_levenspiel_1989`], ψ = 0.806) moved from the
/// volume-equivalent sphere, d_v = (6/π)^(1/3) D_n, to the cube's face:
/// C_D = C_D,HL(Re d_v/D_n) (π/4) (d_v/D_n)².
pub fn cube_steady_drag(re: f64) -> f64 {
    let dv = (6.0 / PI).cbrt();
    haider_levenspiel_1989(re * dv, cube_sphericity()) * 0.25 * PI * dv * dv
}

/// The Stokes layer's part of C_M for the cube [–], by the sphere's: the sphere's (9/4) δ/R
/// is (3/4) δ S/V, scaled here by the cube's S/V = 6/D_n: 4.5 δ/D_n = 4.5/√(πβ) (the same
/// per diameter as the sphere's). An estimate: the cube's edges, where the potential slip is
/// largest, are not in it.
pub fn cube_stokes_inertia(beta: f64) -> f64 {
    4.5 / (PI * beta).sqrt()
}

/// The Stokes layer's part of C_D for the cube [–], by the same scaling: in the linear Stokes
/// layer the force in phase with velocity has the amplitude of the one in phase with
/// acceleration, 4.5 (δ/D_n) ρ D_n³ ω U_m = 9 μ D_n² U_m/δ, projected on |U|U as the fit does
/// (× 32/(9π)) over ½ ρ D_n² U_m²: C_D,B = (64/π) (D_n/δ)/Re, D_n/δ = √(πβ), Re = β KC.
pub fn cube_history_drag(kc: f64, beta: f64) -> f64 {
    64.0 / PI * (PI * beta).sqrt() / (beta * kc)
}

/// Potential-flow added mass of a cube, C_a = m_a/(ρ D_n³), the range of the published
/// values (README, "The cube": about 0.64 to 0.70).
pub const CUBE_ADDED_MASS: (f64, f64) = (0.64, 0.70);

#[cfg(test)]
mod tests {
    use super::*;

    /// The cube's members fill a cube of edge about D_n about the centre, its faces normal to
    /// the axes, and its references have their values.
    #[test]
    fn the_cube_is_axis_aligned_and_its_references_hold() {
        let c = Vec3::new(2.0, 2.0, 2.0);
        let m = Shape::Cube.members(c);
        assert_eq!(m.len(), CUBE_PER_EDGE.pow(3));
        for a in 0..3 {
            let mut xs: Vec<f64> = m.iter().map(|(x, _)| x[a] - c[a]).collect();
            xs.sort_by(f64::total_cmp);
            xs.dedup_by(|p, q| (*p - *q).abs() < 1e-9);
            // Three lattice planes per axis, symmetric about the centre.
            assert_eq!(xs.len(), 3, "axis {a}: {xs:?}");
            assert!((xs[0] + xs[2]).abs() < 1e-9 && xs[1].abs() < 1e-9);
            // The union's extent, spacing × (3 − 1) + member diameter, close to D_n.
            let extent = xs[2] - xs[0] + 2.0 * m[0].1;
            assert!(extent > 1.0 && extent < 1.15, "extent {extent}");
        }
        assert!((cube_sphericity() - 0.806).abs() < 1e-3);
        // Steady drag falls with Re and stays above the sphere's on its own area.
        let (c100, c200) = (cube_steady_drag(100.0), cube_steady_drag(200.0));
        assert!(c100 > c200 && c200 > 1.0 && c100 < 2.0, "{c100} {c200}");
        assert!((cube_stokes_inertia(10.0) - 0.803).abs() < 1e-3);
        assert!((cube_history_drag(20.0, 10.0) - 0.571).abs() < 1e-3);
    }
}
