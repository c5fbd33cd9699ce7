//! Sphere-sphere contact history and the deterministic force reduction.
//!
//! The history lives beside the candidate pairs, keyed by the pair's ids. At each neighbour
//! rebuild the new (sorted) pair list is merged with the old one in one pass: values carry over
//! for pairs present in both, new pairs start at zero (METHOD.md [10]: the history of a contact
//! starts when it forms). Forces are computed per pair in parallel, then summed per sphere in
//! pair order through a CSR index, so that the result does not depend on the number of threads.

use serde::{Deserialize, Serialize};

use super::contact::Reaction;
use super::spheres::{SphereId, Spheres};
use crate::math::Vec3;

/// History of one touching pair, as saved in checkpoints.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SavedContact {
    /// Ids of the two spheres, smaller first.
    pub ids: (SphereId, SphereId),
    /// The contact's history vector (see `contact`).
    pub history: Vec3,
}

/// Per-pair state aligned with the neighbour list.
#[derive(Clone, Debug, Default)]
pub struct PairContacts {
    /// Ids of each candidate pair, smaller first (sorted, since slots follow ids).
    pub ids: Vec<(SphereId, SphereId)>,
    /// History of each pair (zero while not touching).
    pub history: Vec<Vec3>,
    /// This step's reaction of each pair.
    pub reaction: Vec<Reaction>,
    /// Whether the pair touches this step.
    pub touching: Vec<bool>,
    /// CSR index: the pairs of sphere i are `members[offsets[i]..offsets[i + 1]]`, ascending.
    pub offsets: Vec<u32>,
    /// See `offsets`.
    pub members: Vec<u32>,
    old_ids: Vec<(SphereId, SphereId)>,
    old_history: Vec<Vec3>,
}

impl PairContacts {
    /// Adopts a new candidate list, carrying the history of pairs that persist.
    pub fn rebuild(&mut self, pairs: &[(u32, u32)], spheres: &Spheres) {
        std::mem::swap(&mut self.ids, &mut self.old_ids);
        std::mem::swap(&mut self.history, &mut self.old_history);
        self.ids.clear();
        self.history.clear();
        let mut k = 0;
        for &(i, j) in pairs {
            let key = (spheres.id[i as usize], spheres.id[j as usize]);
            while k < self.old_ids.len() && self.old_ids[k] < key {
                k += 1;
            }
            let h = if k < self.old_ids.len() && self.old_ids[k] == key {
                self.old_history[k]
            } else {
                Vec3::ZERO
            };
            self.ids.push(key);
            self.history.push(h);
        }
        self.reaction.clear();
        self.reaction.resize(pairs.len(), Reaction::default());
        self.touching.clear();
        self.touching.resize(pairs.len(), false);
        self.build_index(pairs, spheres.len());
    }

    fn build_index(&mut self, pairs: &[(u32, u32)], n: usize) {
        self.offsets.clear();
        self.offsets.resize(n + 1, 0);
        for &(i, j) in pairs {
            self.offsets[i as usize + 1] += 1;
            self.offsets[j as usize + 1] += 1;
        }
        for i in 0..n {
            self.offsets[i + 1] += self.offsets[i];
        }
        self.members.clear();
        self.members.resize(2 * pairs.len(), 0);
        let mut fill: Vec<u32> = self.offsets[..n].to_vec();
        for (p, &(i, j)) in pairs.iter().enumerate() {
            for s in [i as usize, j as usize] {
                self.members[fill[s] as usize] = p as u32;
                fill[s] += 1;
            }
        }
    }

    /// The touching pairs with their history, for a checkpoint.
    pub fn save(&self) -> Vec<SavedContact> {
        (0..self.ids.len())
            .filter(|&p| self.history[p] != Vec3::ZERO)
            .map(|p| SavedContact {
                ids: self.ids[p],
                history: self.history[p],
            })
            .collect()
    }

    /// Restores history from a checkpoint; call `rebuild` afterwards to align it with new pairs.
    pub fn load(&mut self, saved: &[SavedContact]) {
        self.ids = saved.iter().map(|c| c.ids).collect();
        self.history = saved.iter().map(|c| c.history).collect();
    }

    /// Sum of the pair reactions on sphere `i` (force, torque), in pair order.
    #[inline]
    pub fn gather(&self, pairs: &[(u32, u32)], i: usize) -> (Vec3, Vec3) {
        let (mut f, mut t) = (Vec3::ZERO, Vec3::ZERO);
        for &p in &self.members[self.offsets[i] as usize..self.offsets[i + 1] as usize] {
            let p = p as usize;
            if !self.touching[p] {
                continue;
            }
            let r = &self.reaction[p];
            if pairs[p].0 as usize == i {
                f += r.force;
                t += r.torque_i;
            } else {
                f -= r.force;
                t += r.torque_j;
            }
        }
        (f, t)
    }
}
