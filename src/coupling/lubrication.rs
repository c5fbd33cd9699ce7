//! Lubrication: the force of the liquid film between a sphere and a wall, or two spheres,
//! when the gap is thinner than the grid resolves (wet contacts).
//!
//! Not in the source, which lets resolved spheres meet with the dry contact law. A grid of a
//! few cells per diameter cannot see the film that a sphere must squeeze out to touch a wall,
//! so a resolved sphere settling in a viscous liquid reaches the wall nearly at speed and
//! rebounds with the dry restitution, where a real one (Gondret, Lance & Petit 2002) stops
//! without bouncing below a Stokes number of about 10. Following Brändle de Motta et al.
//! (2013, J. Comput. Phys. 239), the part of the film force that the grid misses is added for
//! gaps h below a cut-off h_c of about a cell, the leading term of Reynolds lubrication
//! (Brenner 1961; Jeffrey 1982 for two spheres):
//!
//! ```text
//! F_i = −6π μ R*² (v_i − v_j)·n (1/max(h, h_r) − 1/h_c) n     0 < h < h_c        [N]
//! F_j = −F_i ;   zero for h ≥ h_c (the grid resolves it) and in contact (h ≤ 0)
//! ```
//!
//! μ = ρ_w ν the water's viscosity [Pa s]; R* = r_i r_j/(r_i + r_j) [m] (r_i against a wall);
//! n the unit normal from i to j (or to the wall) [-]; h the gap [m]; h_r a roughness [m]
//! below which the film no longer thins (asperities touch first), so that the force stays
//! finite; h_c the cut-off [m]. Subtracting 1/h_c makes the force start from zero at h_c.
//! Only the normal film force is modelled: the tangential one grows only as ln(1/h).
//!
//! The force depends on the current velocities, so it is evaluated in every DEM sub-step,
//! like the drag of unresolved spheres. The candidates (pairs of spheres, and spheres with
//! walls, within h_c plus a margin) are found once per fluid step, by id (slots change when
//! the contact lists are rebuilt), in an order fixed by the data; the sums run serially in
//! that order, so the result does not depend on the number of threads.

use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

use crate::dem::domain::Domain;
use crate::dem::neighbor::NearPairs;
use crate::dem::spheres::{SphereId, Spheres, NO_BODY};
use crate::dem::walls::{Hits, Shape, Wall};
use crate::geometry::ContactBuf;
use crate::math::Vec3;

/// The film's two lengths.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct LubricationParameters {
    /// h_c [m]: gaps thinner than this get the film force (about a cell: thicker films the
    /// grid resolves itself).
    pub cutoff: f64,
    /// h_r [m]: the film force stops growing below this gap (the surface roughness).
    pub roughness: f64,
}

/// The film force along n on sphere i [N] (negative: pushes i away from j) for a gap `h`
/// [m], an approach speed `v_n` = (v_i − v_j)·n [m s⁻¹] and R* [m], with viscosity `mu`
/// [Pa s] (module docs).
#[inline]
pub fn film_force(p: &LubricationParameters, mu: f64, r_star: f64, h: f64, v_n: f64) -> f64 {
    if h <= 0.0 || h >= p.cutoff {
        return 0.0;
    }
    -6.0 * PI * mu * r_star * r_star * v_n * (1.0 / h.max(p.roughness) - 1.0 / p.cutoff)
}

/// The largest film damping rate c/m [s⁻¹] of a sphere of radius `r` [m] and mass `m` [kg]:
/// against a wall at the roughness gap, c = 6π μ r² (1/h_r − 1/h_c). The explicit sub-step
/// is stable for c Δt/m < 2; `scenario` asks for less than 1.
pub fn damping_rate(p: &LubricationParameters, mu: f64, r: f64, m: f64) -> f64 {
    6.0 * PI * mu * r * r * (1.0 / p.roughness - 1.0 / p.cutoff) / m
}

/// The film between spheres and walls: its parameters and the candidates of the fluid step.
#[derive(Clone, Debug)]
pub struct Lubrication {
    /// h_c and h_r.
    pub parameters: LubricationParameters,
    /// μ = ρ_w ν [Pa s].
    mu: f64,
    near: NearPairs,
    /// Pairs of spheres within reach, by id.
    pairs: Vec<(SphereId, SphereId)>,
    /// Spheres within reach of a wall: (sphere id, wall index).
    walls: Vec<(SphereId, u32)>,
}

impl Lubrication {
    /// The film of a liquid of viscosity `mu` [Pa s].
    pub fn new(parameters: LubricationParameters, mu: f64) -> Lubrication {
        Lubrication {
            parameters,
            mu,
            near: NearPairs::default(),
            pairs: Vec::new(),
            walls: Vec::new(),
        }
    }

    /// At the start of a fluid step: the pairs and the sphere-wall gaps that may come within
    /// h_c during it, given that no sphere moves more than `travel` [m] relative to another or
    /// to a wall in the step. Pairs inside one block, and pairs of fixed spheres, are left out.
    /// Mesh walls are left out (`scenario` says so).
    pub fn find(&mut self, s: &Spheres, walls: &[Wall], domain: &Domain, t: f64, travel: f64) {
        let reach = self.parameters.cutoff + travel;
        self.near.find(s, domain, reach);
        self.pairs.clear();
        for &(i, j) in &self.near.pairs {
            let (i, j) = (i as usize, j as usize);
            let same_body = s.body[i] != NO_BODY && s.body[i] == s.body[j];
            let both_fixed = s.fixed[i] && s.fixed[j];
            if !(same_body || both_fixed) {
                self.pairs.push((s.id[i], s.id[j]));
            }
        }
        self.walls.clear();
        let mut buf = ContactBuf::new();
        let mut hits = Hits::default();
        for i in 0..s.len() {
            if s.fixed[i] {
                continue;
            }
            for (w, wall) in walls.iter().enumerate() {
                if matches!(wall.shape, Shape::Mesh(_)) {
                    continue;
                }
                hits.clear();
                let r = s.radius[i] + reach;
                wall.contacts(w as u32, s.position[i], r, t, &[], &mut buf, &mut hits);
                if hits.len > 0 {
                    self.walls.push((s.id[i], w as u32));
                }
            }
        }
    }

    /// In each force evaluation of the DEM sub-steps: adds the film force of every candidate
    /// to the spheres' forces at time `t` [s] (module docs).
    pub fn add_forces(&self, s: &mut Spheres, walls: &[Wall], domain: &Domain, t: f64) {
        let p = &self.parameters;
        for &(a, b) in &self.pairs {
            let (Some(i), Some(j)) = (s.slot_of(a), s.slot_of(b)) else {
                continue;
            };
            let d = domain.minimum_image(s.position[j] - s.position[i]);
            let dist = d.length();
            let (ri, rj) = (s.radius[i], s.radius[j]);
            let h = dist - ri - rj;
            if h <= 0.0 || h >= p.cutoff {
                continue;
            }
            let n = d / dist;
            let v_n = (s.velocity[i] - s.velocity[j]).dot(n);
            let f = film_force(p, self.mu, ri * rj / (ri + rj), h, v_n) * n;
            s.force[i] += f;
            s.force[j] -= f;
        }
        let mut buf = ContactBuf::new();
        let mut hits = Hits::default();
        for &(a, w) in &self.walls {
            let Some(i) = s.slot_of(a) else {
                continue;
            };
            let r = s.radius[i];
            hits.clear();
            let wall = &walls[w as usize];
            wall.contacts(w, s.position[i], r + p.cutoff, t, &[], &mut buf, &mut hits);
            let mut f = Vec3::ZERO;
            for hit in hits.iter() {
                // The query's radius is r + h_c: its overlap is h_c − h.
                let h = p.cutoff - hit.contact.overlap;
                let n = hit.contact.normal;
                let v_n = (s.velocity[i] - hit.velocity).dot(n);
                f += film_force(p, self.mu, r, h, v_n) * n;
            }
            s.force[i] += f;
        }
    }

    /// The candidates of the fluid step: (pairs of spheres, spheres near a wall).
    pub fn candidates(&self) -> (usize, usize) {
        (self.pairs.len(), self.walls.len())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::spheres::NewSphere;
    use crate::dem::walls::Motion;
    use crate::geometry::Plane;

    fn params() -> LubricationParameters {
        LubricationParameters {
            cutoff: 1e-3,
            roughness: 1e-6,
        }
    }

    /// A sphere approaching a plane with the film force alone obeys m dv/dt = −c(h) v with
    /// dh/dt = −v, so m dv = c(h) dh and, exactly,
    /// v(h) = v0 − (6π μ r²/m) [ln(h0/h) − (h0 − h)/h_c]  for h_r < h < h0 ≤ h_c.
    /// Integrated with small explicit steps, the speed at h = h_c/100 must match to 0.5 %
    /// (the first-order error of the steps, measured 0.05 %).
    #[test]
    fn a_sphere_slowed_by_the_film_follows_the_exact_approach() {
        let (r, rho, mu, v0) = (0.005, 2500.0, 0.01, 0.05);
        let mut s = Spheres::default();
        let h0 = 0.9e-3;
        s.push(NewSphere {
            position: Vec3::new(0.0, 0.0, r + h0),
            velocity: Vec3::new(0.0, 0.0, -v0),
            radius: r,
            density: rho,
            angular_velocity: Vec3::ZERO,
            material: 0,
            fixed: false,
        });
        let floor = Wall {
            name: "floor".into(),
            shape: Shape::Plane(Plane::new(Vec3::ZERO, Vec3::Z)),
            material: 0,
            motion: Motion::Fixed,
        };
        let walls = [floor];
        let domain = Domain {
            min: Vec3::splat(-0.1),
            max: Vec3::splat(0.1),
            periodic: [false; 3],
        };
        let mut lub = Lubrication::new(params(), mu);
        lub.find(&s, &walls, &domain, 0.0, 0.0);
        assert_eq!(lub.candidates(), (0, 1));
        let m = s.mass[0];
        let dt = 1e-7;
        let h_end = 1e-5;
        for _ in 0..1_000_000 {
            if s.position[0].z - r <= h_end || s.velocity[0].z >= 0.0 {
                break;
            }
            s.force[0] = Vec3::ZERO;
            lub.add_forces(&mut s, &walls, &domain, 0.0);
            s.velocity[0] += dt * s.force[0] / m;
            s.position[0] += dt * s.velocity[0];
        }
        let h = s.position[0].z - r;
        let c = 6.0 * PI * mu * r * r / m;
        let exact = v0 - c * ((h0 / h).ln() - (h0 - h) / params().cutoff);
        let v = -s.velocity[0].z;
        assert!(
            exact > 0.2 * v0,
            "the test must not stop the sphere: {exact}"
        );
        assert!((v / exact - 1.0).abs() < 5e-3, "v {v}, exact {exact}");
    }

    /// Two equal spheres approaching each other feel equal and opposite film forces with
    /// R* = r/2; beyond h_c and in contact nothing.
    #[test]
    fn the_film_between_two_spheres_is_equal_and_opposite() {
        let r = 0.005;
        let mut s = Spheres::default();
        for (x, v) in [(0.0, 0.01), (2.0 * r + 5e-4, -0.01)] {
            s.push(NewSphere {
                position: Vec3::new(x, 0.0, 0.0),
                velocity: Vec3::new(v, 0.0, 0.0),
                radius: r,
                density: 2500.0,
                angular_velocity: Vec3::ZERO,
                material: 0,
                fixed: false,
            });
        }
        let domain = Domain {
            min: Vec3::splat(-0.1),
            max: Vec3::splat(0.1),
            periodic: [false; 3],
        };
        let mu = 1e-3;
        let mut lub = Lubrication::new(params(), mu);
        lub.find(&s, &[], &domain, 0.0, 0.0);
        assert_eq!(lub.candidates(), (1, 0));
        lub.add_forces(&mut s, &[], &domain, 0.0);
        let expected = 6.0 * PI * mu * (0.5 * r).powi(2) * 0.02 * (1.0 / 5e-4 - 1.0 / 1e-3);
        assert!((s.force[0].x + expected).abs() < 1e-12 * expected.max(1.0));
        assert_eq!(s.force[0], -s.force[1]);
        let p = params();
        assert_eq!(film_force(&p, mu, r, 1.5e-3, 1.0), 0.0);
        assert_eq!(film_force(&p, mu, r, -1e-6, 1.0), 0.0);
        // Below the roughness the force stays that of h_r.
        assert_eq!(
            film_force(&p, mu, r, 1e-7, 1.0),
            film_force(&p, mu, r, 1e-6, 1.0)
        );
    }
}
