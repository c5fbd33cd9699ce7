//! Walls: planes, boxes, cylinders and triangle meshes that push on spheres with the same
//! contact law as sphere-sphere contacts (a wall acts as a sphere of infinite radius and mass).
//!
//! A wall may move rigidly with a prescribed motion (a gate that opens, a shaking table). Its
//! shape is stored as it is at t = 0; at time t a sphere centre is queried at c - d(t), with d the
//! wall's displacement, and the contact is moved back by d(t).
//!
//! Wall-contact history is kept per sphere in a few fixed slots and matched from one step to
//! the next by wall and contact normal, so that a sphere crossing from one triangle of a mesh to
//! its coplanar neighbour keeps its tangential spring, exactly as on a plane.

use serde::{Deserialize, Serialize};

use crate::geometry::{Cuboid, Cylinder, Plane, SurfaceContact, TriMesh};
use crate::math::Vec3;

use super::spheres::MaterialIndex;

/// Prescribed rigid motion of a wall.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Motion {
    /// The wall stays where it is.
    Fixed,
    /// Translation at constant `velocity` [m s⁻¹] between `start` and `stop` [s].
    Linear {
        /// Velocity [m s⁻¹].
        velocity: Vec3,
        /// Time the motion starts [s].
        #[serde(default)]
        start: f64,
        /// Time the motion stops [s].
        #[serde(default = "forever")]
        stop: f64,
    },
    /// Oscillation d(t) = A [sin(2π f t + φ) - sin φ].
    Oscillation {
        /// Amplitude vector A [m].
        amplitude: Vec3,
        /// Frequency f [Hz].
        frequency: f64,
        /// Phase φ [rad].
        #[serde(default)]
        phase: f64,
    },
}

fn forever() -> f64 {
    f64::INFINITY
}

impl Motion {
    /// Displacement d(t) from the initial position [m].
    pub fn displacement(&self, t: f64) -> Vec3 {
        match *self {
            Motion::Fixed => Vec3::ZERO,
            Motion::Linear {
                velocity,
                start,
                stop,
            } => velocity * (t.min(stop) - start).max(0.0),
            Motion::Oscillation {
                amplitude,
                frequency,
                phase,
            } => {
                let w = 2.0 * std::f64::consts::PI * frequency;
                amplitude * ((w * t + phase).sin() - phase.sin())
            }
        }
    }

    /// Velocity d'(t) [m s⁻¹].
    pub fn velocity(&self, t: f64) -> Vec3 {
        match *self {
            Motion::Fixed => Vec3::ZERO,
            Motion::Linear {
                velocity,
                start,
                stop,
            } => {
                if t >= start && t < stop {
                    velocity
                } else {
                    Vec3::ZERO
                }
            }
            Motion::Oscillation {
                amplitude,
                frequency,
                phase,
            } => {
                let w = 2.0 * std::f64::consts::PI * frequency;
                amplitude * w * (w * t + phase).cos()
            }
        }
    }
}

/// The geometry of a wall.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub enum Shape {
    /// An infinite plane (a half-space).
    Plane(Plane),
    /// A box, as a container or a solid obstacle.
    Cuboid(Cuboid),
    /// A finite cylinder, as a tube or a solid obstacle.
    Cylinder(Cylinder),
    /// A triangle mesh (e.g. from STL).
    Mesh(TriMesh),
}

/// One wall.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Wall {
    /// Name for output and messages.
    pub name: String,
    /// Geometry at t = 0.
    pub shape: Shape,
    /// Material.
    pub material: MaterialIndex,
    /// Prescribed motion.
    pub motion: Motion,
}

/// Most wall contacts one sphere can have at once (a box corner gives three).
pub const WALL_SLOTS: usize = 6;

/// History of one sphere-wall contact.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct WallContact {
    /// Index of the wall, `u32::MAX` for an empty slot.
    pub wall: u32,
    /// Contact normal of the last step (sphere to wall).
    pub normal: Vec3,
    /// History vector (see `contact`).
    pub history: Vec3,
}

impl WallContact {
    /// An empty slot.
    pub const EMPTY: WallContact = WallContact {
        wall: u32::MAX,
        normal: Vec3::ZERO,
        history: Vec3::ZERO,
    };
}

/// Wall contacts of one sphere.
pub type WallSlots = [WallContact; WALL_SLOTS];

/// A current contact between a sphere and a wall.
#[derive(Clone, Copy, Debug)]
pub struct WallHit {
    /// Index of the wall.
    pub wall: u32,
    /// Geometry of the contact, in the current (moved) position.
    pub contact: SurfaceContact,
    /// Velocity of the wall [m s⁻¹].
    pub velocity: Vec3,
}

/// A small fixed-capacity list, so that the per-sphere wall query does not allocate.
#[derive(Clone, Copy, Debug)]
pub struct Hits {
    /// Number of valid entries.
    pub len: usize,
    /// The entries.
    pub items: [Option<WallHit>; WALL_SLOTS],
    /// Contacts that did not fit (reported as a warning by the caller).
    pub dropped: usize,
}

impl Default for Hits {
    fn default() -> Self {
        Hits {
            len: 0,
            items: [None; WALL_SLOTS],
            dropped: 0,
        }
    }
}

impl Hits {
    /// Empties the list for reuse (the entries are overwritten, not cleared).
    #[inline]
    pub fn clear(&mut self) {
        self.len = 0;
        self.dropped = 0;
    }

    fn push(&mut self, h: WallHit) {
        if self.len < WALL_SLOTS {
            self.items[self.len] = Some(h);
            self.len += 1;
        } else {
            self.dropped += 1;
        }
    }

    /// The valid entries.
    pub fn iter(&self) -> impl Iterator<Item = &WallHit> {
        self.items[..self.len].iter().flatten()
    }
}

impl Wall {
    /// All contacts of a sphere (centre `c`, radius `r`) with this wall at time `t`.
    /// `candidates` lists mesh triangles near the sphere (ignored for other shapes); `buf` is
    /// scratch space, reused so that nothing is initialised or allocated per call.
    #[allow(clippy::too_many_arguments)]
    pub fn contacts(
        &self,
        index: u32,
        c: Vec3,
        r: f64,
        t: f64,
        candidates: &[u32],
        buf: &mut crate::geometry::ContactBuf,
        out: &mut Hits,
    ) {
        let (d, u) = match self.motion {
            Motion::Fixed => (Vec3::ZERO, Vec3::ZERO),
            m => (m.displacement(t), m.velocity(t)),
        };
        let q = c - d;
        let push = |out: &mut Hits, mut contact: SurfaceContact| {
            contact.point += d;
            out.push(WallHit {
                wall: index,
                contact,
                velocity: u,
            });
        };
        buf.clear();
        match &self.shape {
            // At most one contact, the most common wall: straight to `out`, not via `buf`.
            Shape::Plane(s) => {
                if let Some(contact) = s.sphere_contact(q, r) {
                    push(out, contact);
                }
                return;
            }
            Shape::Cuboid(s) => s.sphere_contacts(q, r, buf),
            Shape::Cylinder(s) => s.sphere_contacts(q, r, buf),
            Shape::Mesh(s) => s.sphere_contacts(q, r, candidates, buf),
        }
        for &contact in buf.iter() {
            push(out, contact);
        }
    }

    /// Triangles of the wall at time `t` for output, with planes clipped to the given box.
    pub fn surface(&self, t: f64, lo: Vec3, hi: Vec3) -> (Vec<Vec3>, Vec<[u32; 3]>) {
        let d = self.motion.displacement(t);
        let (mut v, tri) = match &self.shape {
            Shape::Plane(s) => s.surface(lo - d, hi - d),
            Shape::Cuboid(s) => s.surface(lo - d, hi - d),
            Shape::Cylinder(s) => s.surface(lo - d, hi - d),
            Shape::Mesh(s) => s.surface(lo - d, hi - d),
        };
        for x in &mut v {
            *x += d;
        }
        (v, tri)
    }
}

/// Matches this step's contacts of one sphere to last step's slots: a contact inherits the
/// history of the old contact with the same wall whose normal is closest (within 60°).
/// Returns the history to use for each hit, in hit order, and rewrites the slots.
pub fn match_history(slots: &mut WallSlots, hits: &Hits, out: &mut [Vec3; WALL_SLOTS]) {
    if hits.len == 0 && slots[0].wall == u32::MAX {
        return; // Slots fill from the front: no contact now and none before.
    }
    if hits.len <= 1 && slots[1].wall == u32::MAX {
        out[0] = match_one(&mut slots[0], hits.iter().next());
        return;
    }
    match_any(slots, hits, out);
}

/// `match_history` in the common cases, a sphere on one wall or coming to it, reading only
/// the first slot: at most one contact now (`hit`) and at most one before (in `slot`).
/// Returns the history to use for `hit` (zero without one), and rewrites the slot.
#[inline]
pub fn match_one(slot: &mut WallContact, hit: Option<&WallHit>) -> Vec3 {
    let Some(h) = hit else {
        *slot = WallContact::EMPTY;
        return Vec3::ZERO;
    };
    let same = slot.wall == h.wall && slot.normal.dot(h.contact.normal) > 0.5;
    let history = if same { slot.history } else { Vec3::ZERO };
    // Field by field: a whole slot built aside and copied in was loaded back in wider pieces
    // than it was stored in, which stalls the store forwarding (B1: 9 % of the wall kernel).
    slot.wall = h.wall;
    slot.normal = h.contact.normal;
    slot.history = history;
    history
}

/// `match_history` for any number of contacts.
fn match_any(slots: &mut WallSlots, hits: &Hits, out: &mut [Vec3; WALL_SLOTS]) {
    let old = *slots;
    let mut used = [false; WALL_SLOTS];
    *slots = [WallContact::EMPTY; WALL_SLOTS];
    for (k, h) in hits.iter().enumerate() {
        let mut best = None;
        let mut best_dot = 0.5;
        for (m, o) in old.iter().enumerate() {
            if o.wall == h.wall && !used[m] {
                let dot = o.normal.dot(h.contact.normal);
                if dot > best_dot {
                    best_dot = dot;
                    best = Some(m);
                }
            }
        }
        out[k] = match best {
            Some(m) => {
                used[m] = true;
                old[m].history
            }
            None => Vec3::ZERO,
        };
        slots[k] = WallContact {
            wall: h.wall,
            normal: h.contact.normal,
            history: out[k],
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::SurfaceContact;

    fn hit(wall: u32, normal: Vec3) -> WallHit {
        WallHit {
            wall,
            contact: SurfaceContact {
                point: Vec3::ZERO,
                normal,
                overlap: 1e-4,
                element: 0,
            },
            velocity: Vec3::ZERO,
        }
    }

    /// The path for one contact gives what the general matching gives, slots and histories,
    /// for every case it takes: no contact now, a new one, the same wall (normal within and
    /// beyond 60°), another wall.
    #[test]
    fn one_contact_matches_as_the_general_rule() {
        let old = WallContact {
            wall: 2,
            normal: Vec3::Z,
            history: Vec3::new(1e-6, -2e-6, 0.0),
        };
        let tilted = Vec3::new(0.0, 0.6, 0.8);
        let turned = Vec3::new(0.0, 0.9, 0.1).normalize();
        let mut cases = Vec::new();
        for before in [None, Some(old)] {
            for now in [
                None,
                Some(hit(2, tilted)),
                Some(hit(2, turned)),
                Some(hit(5, Vec3::Z)),
            ] {
                cases.push((before, now));
            }
        }
        let mut inherited = 0;
        for (before, now) in cases {
            let mut slots = [WallContact::EMPTY; WALL_SLOTS];
            if let Some(o) = before {
                slots[0] = o;
            }
            let mut hits = Hits::default();
            if let Some(h) = now {
                hits.push(h);
            }
            let (mut fast, mut general) = (slots, slots);
            let (mut out_fast, mut out_general) =
                ([Vec3::NAN; WALL_SLOTS], [Vec3::NAN; WALL_SLOTS]);
            match_history(&mut fast, &hits, &mut out_fast);
            match_any(&mut general, &hits, &mut out_general);
            assert_eq!(fast, general, "{before:?} {now:?}");
            assert_eq!(out_fast[..hits.len], out_general[..hits.len]);
            inherited += usize::from(hits.len == 1 && out_fast[0] == old.history);
        }
        // Only the same wall with the normal within 60° inherits.
        assert_eq!(inherited, 1);
    }
}
