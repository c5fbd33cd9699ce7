//! What a probe file reports of one sphere's contacts (`run`'s `probe_<id>.csv`): how many it
//! has, the deepest overlap and that contact's normal, found from the positions as the force
//! evaluation found them.

use super::spheres::NO_BODY;
use super::walls::Hits;
use super::Dem;
use crate::geometry::ContactBuf;
use crate::math::Vec3;

/// The contacts of one sphere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactSummary {
    /// Contacts with spheres and walls.
    pub count: usize,
    /// The largest overlap δ [m] (0 without contact).
    pub overlap: f64,
    /// The unit normal of that contact, from the sphere towards its partner (zero without
    /// contact).
    pub normal: Vec3,
}

impl Dem {
    /// The contacts of the sphere in slot `i` at time `t` [s] (the walls' position): every
    /// sphere it overlaps (the nearest periodic image; members of its own block excepted, and
    /// fixed spheres when it is fixed, as the neighbour list pairs them) and every wall
    /// within reach. Costs a pass over all spheres: for probes, not for a time step.
    pub fn contact_summary(&self, i: usize, t: f64) -> ContactSummary {
        let s = &self.spheres;
        let (xi, ri, bi, fi) = (s.position[i], s.radius[i], s.body[i], s.fixed[i]);
        let im = self.domain.images();
        let mut sum = ContactSummary {
            count: 0,
            overlap: 0.0,
            normal: Vec3::ZERO,
        };
        let mut add = |delta: f64, n: Vec3| {
            sum.count += 1;
            if delta > sum.overlap {
                (sum.overlap, sum.normal) = (delta, n);
            }
        };
        for j in 0..s.len() {
            let same_body = bi != NO_BODY && s.body[j] == bi;
            if j == i || same_body || (fi && s.fixed[j]) {
                continue;
            }
            let d = im.nearest(s.position[j] - xi);
            let r_sum = ri + s.radius[j];
            if d.length_squared() < r_sum * r_sum {
                let dist = d.length();
                add(r_sum - dist, d / dist);
            }
        }
        let wc = &self.wall_contacts;
        let (mut buf, mut hits) = (ContactBuf::new(), Hits::default());
        for e in wc.entries.iter().filter(|e| e.sphere as usize == i) {
            for nw in &wc.near[e.near.0 as usize..e.near.1 as usize] {
                self.walls[nw.wall as usize].contacts(
                    nw.wall,
                    xi,
                    ri,
                    t,
                    &wc.triangles[nw.tri.0 as usize..nw.tri.1 as usize],
                    &mut buf,
                    &mut hits,
                );
            }
        }
        for h in hits.iter() {
            add(h.contact.overlap, h.contact.normal);
        }
        sum
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::domain::Domain;
    use crate::dem::material::{ContactModel, Material};
    use crate::dem::walls::{Motion, Shape, Wall};
    use crate::geometry::Plane;

    /// A sphere resting on a floor and touched by a second sphere from the side: two
    /// contacts, the deepest one reported with its normal.
    #[test]
    fn a_sphere_on_a_floor_touched_from_the_side() {
        let m = Material {
            name: "glass".into(),
            density: 2500.0,
            young_modulus: 1e7,
            poisson_ratio: 0.3,
            friction_coefficient: 0.5,
            restitution_coefficient: 0.5,
        };
        let domain = Domain {
            min: Vec3::splat(-1.0),
            max: Vec3::splat(1.0),
            periodic: [false; 3],
        };
        let mut dem = Dem::new(
            vec![m],
            ContactModel::HertzMindlin(Default::default()),
            domain,
            1e-5,
        );
        let r = 0.01;
        dem.add_sphere(Vec3::new(0.0, 0.0, r - 2e-4), Vec3::ZERO, Vec3::ZERO, r, 0);
        dem.add_sphere(
            Vec3::new(2.0 * r - 1e-4, 0.0, r),
            Vec3::ZERO,
            Vec3::ZERO,
            r,
            0,
        );
        dem.add_sphere(Vec3::new(0.5, 0.5, 0.5), Vec3::ZERO, Vec3::ZERO, r, 0);
        dem.walls.push(Wall {
            name: "floor".into(),
            shape: Shape::Plane(Plane::new(Vec3::ZERO, Vec3::Z)),
            material: 0,
            motion: Motion::Fixed,
        });
        dem.rebuild_lists(0.0);
        let i = dem.spheres.slot_of(0).unwrap();
        let c = dem.contact_summary(i, 0.0);
        assert_eq!(c.count, 2);
        assert!((c.overlap - 2e-4).abs() < 1e-12, "{c:?}");
        assert!((c.normal - -Vec3::Z).length() < 1e-12, "{c:?}");
        let free = dem.spheres.slot_of(2).unwrap();
        assert_eq!(dem.contact_summary(free, 0.0).count, 0);
    }
}
