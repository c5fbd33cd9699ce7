//! Evaluation of all forces and torques on the spheres: contacts [6]-[14], walls, gravity [1][2].

use rayon::prelude::*;

use super::contact::{contact_force, Pair, Reaction};
use super::walls::{match_history, Hits, Shape, WALL_SLOTS};
use super::Dem;
use crate::geometry::ContactBuf;
use crate::math::Vec3;

/// Mesh triangles near each sphere, per wall (empty for walls that are not meshes).
#[derive(Clone, Debug, Default)]
pub struct MeshCandidates {
    /// Per wall: CSR offsets over spheres.
    pub offsets: Vec<Vec<u32>>,
    /// Per wall: triangle indices.
    pub triangles: Vec<Vec<u32>>,
    /// Per wall: its displacement when the candidates were found [m].
    pub displacement: Vec<Vec3>,
}

impl MeshCandidates {
    /// Finds, for every sphere and mesh wall, the triangles within r + skin of the sphere.
    pub fn build(dem: &Dem, t: f64) -> MeshCandidates {
        let mut mc = MeshCandidates::default();
        let skin = dem.neighbors.skin;
        let mut buf = Vec::new();
        for wall in &dem.walls {
            let d = wall.motion.displacement(t);
            let mut offsets = vec![0u32];
            let mut tris = Vec::new();
            if let Shape::Mesh(mesh) = &wall.shape {
                for i in 0..dem.spheres.len() {
                    let c = dem.spheres.position[i] - d;
                    mesh.candidates(c, dem.spheres.radius[i] + skin, &mut buf);
                    tris.extend_from_slice(&buf);
                    offsets.push(tris.len() as u32);
                }
            }
            mc.offsets.push(offsets);
            mc.triangles.push(tris);
            mc.displacement.push(d);
        }
        mc
    }

    /// True when a mesh wall has moved more than skin/2 since the candidates were found.
    pub fn stale(&self, dem: &Dem, t: f64) -> bool {
        dem.walls.iter().enumerate().any(|(w, wall)| {
            matches!(wall.shape, Shape::Mesh(_))
                && (w >= self.displacement.len()
                    || (wall.motion.displacement(t) - self.displacement[w]).length()
                        > 0.5 * dem.neighbors.skin)
        })
    }

    fn of(&self, wall: usize, sphere: usize) -> &[u32] {
        match self.offsets.get(wall) {
            Some(o) if o.len() > sphere + 1 => {
                &self.triangles[wall][o[sphere] as usize..o[sphere + 1] as usize]
            }
            _ => &[],
        }
    }
}

/// Computes `force` and `torque` of every sphere at time `t` (positions already at t) and
/// updates the contact history. Deterministic for any number of threads.
pub fn compute_forces(dem: &mut Dem, t: f64) {
    let dt = dem.dt;
    let s = &dem.spheres;
    let domain = dem.domain;
    let n_mat = dem.materials.len();
    let laws = &dem.laws;
    let pairs = &dem.neighbors.pairs;
    let c = &mut dem.contacts;

    // Pass 1: one reaction per candidate pair, in parallel.
    let ((max_ratio, max_slot), touching) = c
        .history
        .par_iter_mut()
        .zip(c.reaction.par_iter_mut())
        .zip(c.touching.par_iter_mut())
        .zip(pairs.par_iter())
        .map(|(((hist, reaction), touching), &(i, j))| {
            let (i, j) = (i as usize, j as usize);
            let d = domain.minimum_image(s.position[j] - s.position[i]);
            let dist = d.length();
            let delta = s.radius[i] + s.radius[j] - dist;
            if delta <= 0.0 || dist == 0.0 {
                *touching = false;
                *hist = Vec3::ZERO;
                *reaction = Reaction::default();
                return ((0.0, usize::MAX), 0usize);
            }
            *touching = true;
            let mass = |k: usize| if s.fixed[k] { f64::INFINITY } else { s.mass[k] };
            let p = Pair {
                n: d / dist,
                delta,
                dv: s.velocity[i] - s.velocity[j],
                w_i: s.angular_velocity[i],
                w_j: s.angular_velocity[j],
                r_i: s.radius[i],
                r_j: s.radius[j],
                m_i: mass(i),
                m_j: mass(j),
            };
            let law = &laws[s.material[i] as usize * n_mat + s.material[j] as usize];
            *reaction = contact_force(law, &p, hist, dt);
            let ratio = delta / s.radius[i].min(s.radius[j]);
            ((ratio, i), 1)
        })
        .reduce(
            || ((0.0, usize::MAX), 0),
            |a, b| (larger(a.0, b.0), a.1 + b.1),
        );

    // Pass 2: per sphere, pair reactions in pair order, then walls, then gravity.
    let c = &dem.contacts;
    let walls = &dem.walls;
    let mc = &dem.mesh_candidates;
    let gravity = dem.gravity;
    // Taken out of `spheres` for the duration of the pass, so that the rest can be read.
    let mut force = std::mem::take(&mut dem.spheres.force);
    let mut torque = std::mem::take(&mut dem.spheres.torque);
    let s = &dem.spheres;
    let (wall_contacts, dropped, wall_ratio, wall_slot) = force
        .par_iter_mut()
        .zip(torque.par_iter_mut())
        .zip(dem.wall_slots.par_iter_mut())
        .enumerate()
        .map(|(i, ((f, tq), slots))| {
            let (mut fi, mut ti) = c.gather(pairs, i);
            let mut hits = Hits::default();
            let mut buf = ContactBuf::new();
            for (w, wall) in walls.iter().enumerate() {
                wall.contacts(
                    w as u32,
                    s.position[i],
                    s.radius[i],
                    t,
                    mc.of(w, i),
                    &mut buf,
                    &mut hits,
                );
            }
            let mut hist = [Vec3::ZERO; WALL_SLOTS];
            match_history(slots, &hits, &mut hist);
            let mut ratio: f64 = 0.0;
            for (k, h) in hits.iter().enumerate() {
                let p = Pair {
                    n: h.contact.normal,
                    delta: h.contact.overlap,
                    dv: s.velocity[i] - h.velocity,
                    w_i: s.angular_velocity[i],
                    w_j: Vec3::ZERO,
                    r_i: s.radius[i],
                    r_j: f64::INFINITY,
                    m_i: if s.fixed[i] { f64::INFINITY } else { s.mass[i] },
                    m_j: f64::INFINITY,
                };
                let m_wall = walls[h.wall as usize].material as usize;
                let law = &laws[s.material[i] as usize * n_mat + m_wall];
                let r = contact_force(law, &p, &mut hist[k], dt);
                slots[k].history = hist[k];
                fi += r.force;
                ti += r.torque_i;
                ratio = ratio.max(h.contact.overlap / s.radius[i]);
            }
            if !s.fixed[i] {
                fi += s.mass[i] * gravity;
            }
            *f = fi;
            *tq = ti;
            (hits.len, hits.dropped, ratio, i)
        })
        .reduce(
            || (0, 0, 0.0, usize::MAX),
            |a, b| {
                let (r, k) = larger((a.2, a.3), (b.2, b.3));
                (a.0 + b.0, a.1 + b.1, r, k)
            },
        );

    dem.spheres.force = force;
    dem.spheres.torque = torque;
    let st = &mut dem.stats;
    st.pair_contacts = touching;
    st.wall_contacts = wall_contacts;
    st.dropped_wall_contacts += dropped;
    if wall_ratio > max_ratio {
        st.max_overlap_ratio = wall_ratio;
        st.max_overlap_slot = wall_slot;
    } else {
        st.max_overlap_ratio = max_ratio;
        st.max_overlap_slot = max_slot;
    }
}

/// The larger of two (ratio, slot) pairs, ties to the lower slot, so that the reduction is
/// independent of how rayon splits the work.
fn larger(a: (f64, usize), b: (f64, usize)) -> (f64, usize) {
    if b.0 > a.0 || (b.0 == a.0 && b.1 < a.1) {
        b
    } else {
        a
    }
}
