//! Discrete element method for spheres (METHOD.md §2).
//!
//! `Dem` holds the state of the granular phase: spheres, walls, materials and the laws between
//! them, contact history and the neighbour list. The order of the phases of a step lives in
//! `crate::simulation`; this module provides the phases.

pub mod contact;
pub mod contacts;
pub mod domain;
pub mod fluid_load;
pub mod forces;
pub mod insertion;
pub mod integrate;
pub mod isa;
pub mod material;
pub mod neighbor;
pub mod par;
pub mod probe;
pub mod spheres;
pub mod timestep;
pub mod wall_contacts;
pub mod walls;

use serde::{Deserialize, Serialize};

use crate::math::Vec3;
use contacts::{PairContacts, SavedContact};
use domain::Domain;
use material::{Material, PairLaw};
use neighbor::NeighborList;
use spheres::Spheres;
use wall_contacts::{SavedWallContacts, WallContacts};
use walls::Wall;

/// Bounds beyond which a run is declared unstable.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Limits {
    /// Largest plausible sphere speed [m s⁻¹].
    pub max_speed: f64,
    /// Largest plausible overlap as a fraction of the smaller radius [-].
    pub max_overlap_ratio: f64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_speed: 100.0,
            max_overlap_ratio: 0.5,
        }
    }
}

/// Counters of the last force evaluation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Stats {
    /// Touching sphere-sphere pairs.
    pub pair_contacts: usize,
    /// Sphere-wall contacts.
    pub wall_contacts: usize,
    /// Largest overlap / smaller radius [-].
    pub max_overlap_ratio: f64,
    /// Slot of the sphere with the largest overlap ratio (`usize::MAX` if none).
    pub max_overlap_slot: usize,
    /// Wall contacts dropped because a sphere touched more than `WALL_SLOTS` surfaces.
    pub dropped_wall_contacts: usize,
    /// Spheres removed so far because they left the domain (members of lost blocks included).
    pub spheres_lost: usize,
    /// Blocks removed so far because a member left the domain.
    pub blocks_lost: usize,
}

/// The granular phase.
#[derive(Clone, Debug)]
pub struct Dem {
    /// All spheres.
    pub spheres: Spheres,
    /// Materials, indexed by `MaterialIndex`.
    pub materials: Vec<Material>,
    /// Contact laws, `laws[a * n + b]` for materials a, b.
    pub laws: Vec<PairLaw>,
    /// Walls.
    pub walls: Vec<Wall>,
    /// The box, with its periodic axes.
    pub domain: Domain,
    /// Gravitational acceleration [m s⁻²].
    pub gravity: Vec3,
    /// Time step Δt [s].
    pub dt: f64,
    /// Instability bounds.
    pub limits: Limits,
    /// Verlet list (which also keeps the spheres sorted by cell).
    pub neighbors: NeighborList,
    /// Pair history, aligned with the neighbour list.
    pub contacts: PairContacts,
    /// Walls within reach of each sphere and the wall-contact history.
    pub wall_contacts: WallContacts,
    /// Counters of the last force evaluation.
    pub stats: Stats,
    /// The vector instructions the force kernels run with (`isa`; the same bits with any).
    pub isa: isa::Isa,
}

impl Dem {
    /// The law between materials a and b.
    #[inline]
    pub fn law(&self, a: u16, b: u16) -> &PairLaw {
        &self.laws[a as usize * self.materials.len() + b as usize]
    }

    /// Index of the material with this name.
    pub fn material_index(&self, name: &str) -> Option<u16> {
        self.materials
            .iter()
            .position(|m| m.name == name)
            .map(|i| i as u16)
    }
}

impl Dem {
    /// Rebuilds the neighbour list at the current positions (which sorts the spheres by cell),
    /// carries the pair history over, and lists the walls within reach of each sphere at time
    /// `t`.
    pub fn rebuild_lists(&mut self, t: f64) {
        self.neighbors.band_axis = self.gravity.abs().max_position();
        self.neighbors.build(&mut self.spheres, &self.domain, None);
        self.contacts.rebuild(&self.neighbors, &self.spheres);
        self.rebuild_wall_lists(t);
    }

    /// Rebuilds the lists as a saved run had them: at the positions `reference` of its last
    /// neighbour build (by slot, with the spheres in the saved storage order) and the time
    /// `built_at` of that build, then puts the saved history back. The run then continues
    /// with the same lists, storage order and rebuild schedule, hence bit for bit.
    pub fn restore_lists(
        &mut self,
        reference: &[Vec3],
        built_at: f64,
        contacts: &[SavedContact],
        walls: &[SavedWallContacts],
    ) {
        self.neighbors.forget();
        self.neighbors.band_axis = self.gravity.abs().max_position();
        self.neighbors
            .build(&mut self.spheres, &self.domain, Some(reference));
        self.contacts.rebuild(&self.neighbors, &self.spheres);
        self.contacts
            .restore(contacts, &self.neighbors, &self.spheres);
        self.wall_contacts = WallContacts::default();
        self.rebuild_wall_lists(built_at);
        self.wall_contacts.restore(walls, &self.spheres);
    }

    fn rebuild_wall_lists(&mut self, t: f64) {
        let skin = self.neighbors.skin;
        let (pos, previous_slot, room) = self.neighbors.for_walls();
        self.wall_contacts.rebuild(
            &self.walls,
            &self.spheres,
            pos,
            previous_slot,
            room,
            t,
            skin,
        );
    }

    /// True when a moving wall has gone more than skin/2 since the last build.
    pub fn walls_moved(&self, t: f64) -> bool {
        self.wall_contacts
            .stale(&self.walls, t, self.neighbors.skin)
    }
}

impl Dem {
    /// A granular phase with no spheres nor walls, for research code and tests: the laws
    /// between all pairs of `materials` follow `model`. Gravity is (0, 0, -9.81) m s⁻²; the
    /// neighbour skin is set to `neighbor::DEFAULT_SKIN_FRACTION` of the largest diameter when
    /// the simulation starts, unless set before.
    pub fn new(
        materials: Vec<Material>,
        model: material::ContactModel,
        domain: Domain,
        dt: f64,
    ) -> Dem {
        let n = materials.len();
        let mut laws = Vec::with_capacity(n * n);
        for a in &materials {
            for b in &materials {
                laws.push(PairLaw::new(
                    &model,
                    a,
                    b,
                    material::PairOverride::default(),
                ));
            }
        }
        Dem {
            spheres: Spheres::default(),
            materials,
            laws,
            walls: Vec::new(),
            domain,
            gravity: Vec3::new(0.0, 0.0, -9.81),
            dt,
            limits: Limits::default(),
            neighbors: NeighborList::new(0.0),
            contacts: PairContacts::default(),
            wall_contacts: WallContacts::default(),
            stats: Stats::default(),
            isa: isa::Isa::chosen(),
        }
    }

    /// Adds a sphere of material `material` (density taken from it); returns its id.
    pub fn add_sphere(
        &mut self,
        position: Vec3,
        velocity: Vec3,
        angular_velocity: Vec3,
        radius: f64,
        material: u16,
    ) -> spheres::SphereId {
        let density = self.materials[material as usize].density;
        self.spheres.push(spheres::NewSphere {
            position,
            velocity,
            angular_velocity,
            radius,
            material,
            density,
            fixed: false,
        })
    }
}
