//! Sphere-wall contacts between rebuilds: which walls each sphere can reach, and the history of
//! its wall contacts.
//!
//! At each neighbour rebuild the walls within r + skin of every sphere are listed (for a mesh,
//! with the triangles within reach). Until the next rebuild every wall moves less than skin/2
//! (`stale` forces a rebuild otherwise) and each sphere stays in a room that keeps it from the
//! walls left out (`rebuild`, `neighbor::Room`), so no other wall can touch it. Most spheres reach no wall: they have no entry and cost nothing per step. Spheres that
//! do have an entry, and history slots for their wall contacts (`walls::match_history`),
//! carried over from one build to the next by sphere. The slots are kept apart from the
//! entries (16 bytes each), so that the many spheres near a wall and touching none read
//! nothing else; and the first slot apart from the others, so that a sphere touching one wall,
//! the common case, reads 56 bytes of history, not the 336 of all its slots (B1: the slots of
//! the ~20,000 spheres on the floor were streamed whole at every step).

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::neighbor::{Room, NONE};
use super::par::MIN_SPHERES_PER_TASK;
use super::spheres::{SphereId, Spheres};
use super::walls::{Motion, Shape, Wall, WallContact, WallSlots, WALL_SLOTS};
use crate::geometry::ContactBuf;
use crate::math::Vec3;

/// Spheres per parallel work item of the per-sphere force pass and of the wall lists' build
/// (fixed, so that results do not depend on the thread count); `WallContacts::chunk_start` is
/// kept for the first, and the build's join relies on each chunk holding these slots.
pub const CHUNK: usize = 2048;

/// History slots 1.. of an entry (`WallContacts::more`; slot 0 is in `WallContacts::first`).
pub type MoreSlots = [WallContact; WALL_SLOTS - 1];

/// Slots 1.. of a sphere that touches at most one wall.
const MORE_EMPTY: MoreSlots = [WallContact::EMPTY; WALL_SLOTS - 1];

/// An entry's slots, from its first slot and the others.
pub fn join(first: WallContact, more: &MoreSlots) -> WallSlots {
    std::array::from_fn(|k| if k == 0 { first } else { more[k - 1] })
}

/// An entry's slots as its first slot and the others (the inverse of `join`).
pub fn split(slots: &WallSlots) -> (WallContact, MoreSlots) {
    (slots[0], std::array::from_fn(|k| slots[k + 1]))
}

/// A sphere with walls within reach.
#[derive(Clone, Copy, Debug)]
pub struct WallEntry {
    /// Its slot.
    pub sphere: u32,
    /// Its reachable walls: `near[near.0..near.1]` of `WallContacts`.
    pub near: (u32, u32),
    /// How many of its history slots hold a contact (they fill from the front).
    pub used: u32,
}

/// A wall within reach of a sphere.
#[derive(Clone, Copy, Debug)]
pub struct NearWall {
    /// Index of the wall.
    pub wall: u32,
    /// For a mesh, its triangles within reach: `triangles[tri.0..tri.1]` of `WallContacts`.
    pub tri: (u32, u32),
}

/// The wall-contact history of one sphere, as saved in checkpoints.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SavedWallContacts {
    /// Sphere id.
    pub id: SphereId,
    /// Its history slots.
    pub slots: WallSlots,
}

/// The sphere-wall contact lists of the last build.
#[derive(Clone, Debug, Default)]
pub struct WallContacts {
    /// For each sphere slot, its entry in `entries`, or `NONE`.
    pub entry_of: Vec<u32>,
    /// Spheres with walls within reach, by ascending slot.
    pub entries: Vec<WallEntry>,
    /// History slot 0 of each entry's wall contacts (slots fill from the front).
    pub first: Vec<WallContact>,
    /// History slots 1.. of each entry, read only when its sphere touches more than one wall
    /// now or before.
    pub more: Vec<MoreSlots>,
    /// Reachable walls of the entries.
    pub near: Vec<NearWall>,
    /// Reachable mesh triangles.
    pub triangles: Vec<u32>,
    /// For each chunk of `CHUNK` slots (and one past the last), its first entry.
    pub chunk_start: Vec<u32>,
    /// Each wall's displacement at the build [m].
    pub displacement: Vec<Vec3>,
    /// Time of the build [s].
    pub built_at: f64,
    old_entry_of: Vec<u32>,
    old_entries: Vec<WallEntry>,
    old_first: Vec<WallContact>,
    old_more: Vec<MoreSlots>,
    chunks: Vec<ChunkLists>,
}

/// What a chunk of the wall lists' build reads.
struct Reach<'a> {
    walls: &'a [Wall],
    /// Each wall's displacement at the build [m].
    displacement: &'a [Vec3],
    radius: &'a [f64],
    /// Fixed spheres get no entry: like two fixed spheres (`neighbor`), a fixed sphere and a
    /// wall move nothing, and their law would divide by the infinite mass of both (m* = ∞/∞).
    fixed: &'a [bool],
    skin: f64,
}

/// One chunk's part of the lists (indices into its own `near` and `triangles`), kept from
/// build to build so that it does not allocate once grown.
#[derive(Clone, Debug, Default)]
struct ChunkLists {
    entries: Vec<WallEntry>,
    near: Vec<NearWall>,
    triangles: Vec<u32>,
    tri_buf: Vec<u32>,
}

impl Reach<'_> {
    /// Lists the walls within reach of the spheres `i0..i0 + room.len()` (positions `pos`
    /// from i0 on) in `out` and narrows their rooms.
    fn chunk(&self, i0: usize, pos: &[Vec3], room: &mut [Room], out: &mut ChunkLists) {
        out.entries.clear();
        out.near.clear();
        out.triangles.clear();
        let mut buf = ContactBuf::new();
        let skin = self.skin;
        for (k, (&x, room)) in pos.iter().zip(room).enumerate() {
            let i = i0 + k;
            if self.fixed[i] {
                continue;
            }
            let first = out.near.len() as u32;
            let r = self.radius[i];
            let reach = r + skin;
            // A plane farther than this cannot narrow a room (`Room::FARTHEST`).
            let far = r + 3f64.sqrt() * Room::FARTHEST * skin + skin;
            for (w, wall) in self.walls.iter().enumerate() {
                let q = x - self.displacement[w];
                let tri0 = out.triangles.len() as u32;
                // A moving wall may come skin/2 closer before `stale` asks for a rebuild.
                let coming = match wall.motion {
                    Motion::Fixed => 0.0,
                    _ => 0.5 * skin,
                };
                let near = match &wall.shape {
                    Shape::Plane(p) => {
                        let s = p.signed_distance(q);
                        if s >= reach && s < far {
                            room.keep_off(p.normal, s - r - coming);
                        }
                        s < reach
                    }
                    Shape::Cuboid(c) => {
                        buf.clear();
                        c.sphere_contacts(q, reach, &mut buf);
                        !buf.as_slice().is_empty()
                    }
                    Shape::Cylinder(c) => {
                        buf.clear();
                        c.sphere_contacts(q, reach, &mut buf);
                        !buf.as_slice().is_empty()
                    }
                    Shape::Mesh(m) => {
                        m.candidates(q, reach, &mut out.tri_buf);
                        out.triangles.extend_from_slice(&out.tri_buf);
                        // The triangles left out are a skin away or more, listed or not.
                        room.within(skin - coming);
                        !out.tri_buf.is_empty()
                    }
                };
                // A box or cylinder left out is a skin away or more, in no known direction.
                if !near && matches!(wall.shape, Shape::Cuboid(_) | Shape::Cylinder(_)) {
                    room.within(skin - coming);
                }
                if near {
                    out.near.push(NearWall {
                        wall: w as u32,
                        tri: (tri0, out.triangles.len() as u32),
                    });
                }
            }
            let last = out.near.len() as u32;
            if last > first {
                out.entries.push(WallEntry {
                    sphere: i as u32,
                    near: (first, last),
                    used: 0,
                });
            }
        }
    }
}

impl WallContacts {
    /// True when a wall has moved more than skin/2 since the build, so that the lists must be
    /// rebuilt.
    pub fn stale(&self, walls: &[Wall], t: f64, skin: f64) -> bool {
        walls.iter().enumerate().any(|(w, wall)| {
            !matches!(wall.motion, super::walls::Motion::Fixed)
                && (w >= self.displacement.len()
                    || (wall.motion.displacement(t) - self.displacement[w]).length() > 0.5 * skin)
        })
    }

    /// Lists the walls within reach of each sphere, at the positions `pos` (by slot) and time
    /// `t`, and carries the history over from the previous lists through `previous_slot` (the
    /// slot each sphere had at the previous build, or `NONE`).
    ///
    /// Narrows each sphere's `room` so that no wall left out reaches it before the next build:
    /// a plane by its gap (signed distance − r), in the directions against its normal; any
    /// other shape, and the triangles of a mesh left out, by the skin in every direction.
    #[allow(clippy::too_many_arguments)]
    pub fn rebuild(
        &mut self,
        walls: &[Wall],
        spheres: &Spheres,
        pos: &[Vec3],
        previous_slot: &[u32],
        room: &mut [Room],
        t: f64,
        skin: f64,
    ) {
        std::mem::swap(&mut self.entry_of, &mut self.old_entry_of);
        std::mem::swap(&mut self.entries, &mut self.old_entries);
        std::mem::swap(&mut self.first, &mut self.old_first);
        std::mem::swap(&mut self.more, &mut self.old_more);
        self.displacement.clear();
        self.displacement
            .extend(walls.iter().map(|w| w.motion.displacement(t)));
        self.built_at = t;
        // The walls within reach, chunk by chunk in parallel (fixed chunks: the lists do not
        // depend on the thread count), then joined in chunk order.
        let n = spheres.len().min(pos.len());
        let reach = Reach {
            walls,
            displacement: &self.displacement,
            radius: &spheres.radius,
            fixed: &spheres.fixed,
            skin,
        };
        assert!(room.len() >= n, "rebuild: rooms of the wrong length");
        self.chunks
            .resize_with(n.div_ceil(CHUNK), ChunkLists::default);
        self.chunks
            .par_iter_mut()
            .zip(room[..n].par_chunks_mut(CHUNK))
            .enumerate()
            .for_each(|(c, (out, room))| reach.chunk(c * CHUNK, &pos[c * CHUNK..], room, out));
        self.join(n);
        // Each entry's history from its sphere's entry at the previous build.
        let (old_of, old_entries) = (&self.old_entry_of, &self.old_entries);
        let (old_first, old_more) = (&self.old_first, &self.old_more);
        let carried = |e: &mut WallEntry| {
            let prev = previous_slot
                .get(e.sphere as usize)
                .copied()
                .unwrap_or(NONE);
            match old_of.get(prev as usize) {
                Some(&o) if o != NONE && old_entries[o as usize].used > 0 => {
                    let o = o as usize;
                    e.used = old_entries[o].used;
                    let more = if e.used > 1 { old_more[o] } else { MORE_EMPTY };
                    (old_first[o], more)
                }
                _ => (WallContact::EMPTY, MORE_EMPTY),
            }
        };
        self.entries
            .par_iter_mut()
            .with_min_len(MIN_SPHERES_PER_TASK)
            .map(carried)
            .unzip_into_vecs(&mut self.first, &mut self.more);
    }

    /// Puts the chunks' lists end to end: entries, reachable walls and triangles with their
    /// indices shifted, the first entry of each chunk, and each slot's entry.
    fn join(&mut self, n: usize) {
        self.entries.clear();
        self.near.clear();
        self.triangles.clear();
        self.chunk_start.clear();
        self.entry_of.clear();
        self.entry_of.resize(n, NONE);
        for (c, ch) in self.chunks.iter().enumerate() {
            let (e0, w0) = (self.entries.len(), self.near.len() as u32);
            let t0 = self.triangles.len() as u32;
            self.chunk_start.push(e0 as u32);
            self.entries.extend(ch.entries.iter().map(|e| WallEntry {
                near: (e.near.0 + w0, e.near.1 + w0),
                ..*e
            }));
            self.near.extend(ch.near.iter().map(|w| NearWall {
                tri: (w.tri.0 + t0, w.tri.1 + t0),
                ..*w
            }));
            self.triangles.extend_from_slice(&ch.triangles);
            debug_assert!(ch.entries.iter().all(|e| (e.sphere as usize) / CHUNK == c));
            for (k, e) in ch.entries.iter().enumerate() {
                self.entry_of[e.sphere as usize] = (e0 + k) as u32;
            }
        }
        self.chunk_start.push(self.entries.len() as u32);
    }

    /// The spheres with wall contacts and their history, for a checkpoint.
    pub fn save(&self, spheres: &Spheres) -> Vec<SavedWallContacts> {
        (self.entries.iter().zip(&self.first).zip(&self.more))
            .filter(|((e, _), _)| e.used > 0)
            .map(|((e, &first), more)| SavedWallContacts {
                id: spheres.id[e.sphere as usize],
                slots: join(first, more),
            })
            .collect()
    }

    /// Puts saved history back into lists built at the saved run's build positions.
    pub fn restore(&mut self, saved: &[SavedWallContacts], spheres: &Spheres) {
        for e in &mut self.entries {
            e.used = 0;
        }
        self.first.fill(WallContact::EMPTY);
        self.more.fill(MORE_EMPTY);
        for s in saved {
            if let Some(i) = spheres.slot_of(s.id) {
                let e = self.entry_of[i];
                if e != NONE {
                    (self.first[e as usize], self.more[e as usize]) = split(&s.slots);
                    let used = s.slots.iter().filter(|c| c.wall != u32::MAX).count();
                    self.entries[e as usize].used = used as u32;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::domain::Domain;
    use crate::dem::neighbor::NeighborList;
    use crate::dem::spheres::NewSphere;
    use crate::dem::walls::Motion;
    use crate::geometry::Plane;

    /// The lists built chunk by chunk and joined are those of each sphere on its own: the same
    /// walls, mesh triangles and rooms, each entry found through its slot and its chunk, and the
    /// history carried over from the build before (over 5,000 spheres, three chunks, with a
    /// mesh whose triangle indices must be shifted at the join).
    #[test]
    fn lists_joined_from_chunks_are_those_of_each_sphere() {
        use crate::dem::neighbor::tests::uniform;
        use crate::geometry::TriMesh;
        let d = Domain {
            min: Vec3::splat(-1.0),
            max: Vec3::splat(1.0),
            periodic: [false; 3],
        };
        let wall = |name: &str, shape: Shape| Wall {
            name: name.into(),
            shape,
            material: 0,
            motion: Motion::Fixed,
        };
        // A floor of 8 x 8 squares (128 triangles) at z = 0.
        let mut soup = Vec::new();
        for (a, b) in (0..64).map(|k| (k % 8, k / 8)) {
            let p = |i: i32, j: i32| Vec3::new(-0.8 + 0.2 * i as f64, -0.8 + 0.2 * j as f64, 0.0);
            soup.push([p(a, b), p(a + 1, b), p(a + 1, b + 1)]);
            soup.push([p(a, b), p(a + 1, b + 1), p(a, b + 1)]);
        }
        let mut mesh = TriMesh::from_triangle_soup(&soup).unwrap();
        mesh.build_bins(0.1);
        let walls = [
            wall(
                "plane",
                Shape::Plane(Plane::new(Vec3::new(-0.5, 0.0, 0.0), Vec3::X)),
            ),
            wall("mesh", Shape::Mesh(mesh)),
        ];
        let mut seed = 7u64;
        let mut s = Spheres::default();
        for _ in 0..5000 {
            let mut u = || uniform(&mut seed);
            s.push(NewSphere {
                position: Vec3::new(1.4 * u() - 0.7, 1.4 * u() - 0.7, 0.03 * u()),
                velocity: Vec3::ZERO,
                angular_velocity: Vec3::ZERO,
                radius: 0.005,
                material: 0,
                density: 1000.0,
                fixed: false,
            });
        }
        let mut nl = NeighborList::new(0.002);
        let mut wc = WallContacts::default();
        nl.build(&mut s, &d, None);
        let (pos, prev, room) = nl.for_walls();
        wc.rebuild(&walls, &s, pos, prev, room, 0.0, 0.002);
        // Give every entry a contact, then build again from the same positions.
        for (e, first) in wc.entries.iter_mut().zip(&mut wc.first) {
            e.used = 1;
            first.wall = 1;
            first.history = Vec3::new(e.sphere as f64, 0.0, 0.0);
        }
        let old = wc.entries.clone();
        nl.build(&mut s, &d, None);
        let (pos, prev, room) = nl.for_walls();
        wc.rebuild(&walls, &s, pos, prev, room, 0.0, 0.002);
        let (pos, prev, room) = nl.for_walls();
        assert!(wc.entries.len() > 1000 && s.len() > 2 * CHUNK);
        let reach = Reach {
            walls: &walls,
            displacement: &[Vec3::ZERO; 2],
            radius: &s.radius,
            fixed: &s.fixed,
            skin: 0.002,
        };
        let mut one = ChunkLists::default();
        let mut triangles = 0;
        for i in 0..s.len() {
            // The room the neighbour list gives before the walls narrow it (no periodic axis).
            let far = Vec3::splat(Room::FARTHEST * 0.002);
            let mut r = Room::between(-far, far);
            reach.chunk(i, &pos[i..], std::slice::from_mut(&mut r), &mut one);
            assert_eq!(r, room[i], "room of {i}");
            let e = wc.entry_of[i];
            if e == NONE {
                assert!(one.entries.is_empty(), "{i} reaches a wall, has no entry");
                continue;
            }
            let (e, c) = (e as usize, i / CHUNK);
            assert!((wc.chunk_start[c] as usize..wc.chunk_start[c + 1] as usize).contains(&e));
            let entry = wc.entries[e];
            assert_eq!(entry.sphere as usize, i);
            let near = &wc.near[entry.near.0 as usize..entry.near.1 as usize];
            assert_eq!(near.len(), one.near.len(), "walls of {i}");
            for (a, b) in near.iter().zip(&one.near) {
                assert_eq!(a.wall, b.wall);
                let (ta, tb) = (
                    a.tri.0 as usize..a.tri.1 as usize,
                    b.tri.0 as usize..b.tri.1 as usize,
                );
                assert_eq!(wc.triangles[ta], one.triangles[tb], "triangles of {i}");
                triangles += b.tri.1 - b.tri.0;
            }
            // Carried over: the sphere kept its slot (same positions), so its own history.
            assert_eq!(prev[i] as usize, i);
            assert_eq!((entry.used, wc.first[e].history.x), (1, i as f64));
        }
        assert_eq!(old.len(), wc.entries.len());
        assert!(triangles > 1000, "{triangles} listed triangles");
    }

    /// A block of spheres falling together past a floor, a side wall and an oblique plane (and
    /// through them: nothing pushes here): at every step each sphere touching a wall has it
    /// listed, while the lists outlive the skin/2 rule (the block hardly spreads, and the walls
    /// bound each sphere only in the directions against their normals).
    #[test]
    fn no_wall_contact_is_missed() {
        let d = Domain {
            min: Vec3::splat(-1.0),
            max: Vec3::splat(1.0),
            periodic: [false; 3],
        };
        let plane = |name: &str, p: Vec3, n: Vec3| Wall {
            name: name.into(),
            shape: Shape::Plane(Plane::new(p, n)),
            material: 0,
            motion: Motion::Fixed,
        };
        let walls = [
            plane("floor", Vec3::ZERO, Vec3::Z),
            plane("side", Vec3::ZERO, Vec3::X),
            plane("ramp", Vec3::new(0.3, 0.0, 0.0), Vec3::new(-1.0, 0.0, 1.0)),
        ];
        let mut s = Spheres::default();
        for k in 0..250 {
            let (i, j, l) = (k % 10, (k / 10) % 5, k / 50);
            let c = Vec3::new(i as f64, j as f64, l as f64) * 0.03;
            s.push(NewSphere {
                position: c + Vec3::new(0.012, 0.0, 0.05),
                velocity: Vec3::new(-0.1, 0.0, -1.0) + 0.01 * Vec3::new(0.0, (k % 3) as f64, 0.0),
                angular_velocity: Vec3::ZERO,
                radius: 0.01,
                material: 0,
                density: 1000.0,
                fixed: false,
            });
        }
        let mut nl = NeighborList::new(0.002);
        let mut wc = WallContacts::default();
        let (dt, skin) = (1e-4, nl.skin);
        let (mut builds, mut past_half_skin) = (0, 0);
        for step in 0..1500 {
            if step == 0 || nl.needs_rebuild(&s, &d) {
                nl.build(&mut s, &d, None);
                let (pos, prev, room) = nl.for_walls();
                wc.rebuild(&walls, &s, pos, prev, room, 0.0, skin);
                builds += 1;
            } else {
                past_half_skin += usize::from(
                    (s.position.iter().zip(nl.reference()))
                        .any(|(&x, &x0)| (x - x0).length() > 0.5 * skin),
                );
            }
            for (i, &x) in s.position.iter().enumerate() {
                for (w, wall) in walls.iter().enumerate() {
                    let Shape::Plane(p) = &wall.shape else {
                        unreachable!()
                    };
                    if p.signed_distance(x) >= s.radius[i] {
                        continue;
                    }
                    let e = wc.entry_of[i];
                    assert_ne!(e, NONE, "step {step}: sphere {i} touches {w}, lists none");
                    let (a, b) = wc.entries[e as usize].near;
                    let near = &wc.near[a as usize..b as usize];
                    assert!(
                        near.iter().any(|n| n.wall == w as u32),
                        "step {step}: {i}, {w}"
                    );
                }
            }
            let mut max_drift: f64 = 0.0;
            for (x, v) in s.position.iter_mut().zip(&s.velocity) {
                max_drift = max_drift.max((dt * *v).length());
                *x += dt * *v;
            }
            nl.note_drift(max_drift);
        }
        assert!(
            builds > 10 && past_half_skin > 500,
            "{builds} builds, {past_half_skin} steps past skin/2"
        );
    }
}
