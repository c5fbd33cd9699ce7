//! Sphere-sphere contact history, aligned with the neighbour list.
//!
//! Each candidate pair p of the list has a history vector `history[p]` and a flag `touch[p]`,
//! set while the pair touched at the last force evaluation. The history of a pair that did not
//! touch is not read (it counts as zero: METHOD.md [10], the history of a contact starts when it
//! forms), so a pair that is apart costs one byte of writing per step.
//!
//! The history is a vector attached to the pair (i, j) in that order: the law's tangential
//! spring or displacement of i relative to j (see `contact`). Seen from j it is its opposite, so
//! when a rebuild lists the pair the other way round, the carried history changes sign.
//!
//! At a rebuild the history is carried over without hashing: each old pair that touched, (a, b),
//! is looked up in the new list's (short) partner lists of a and of b, found through the slots
//! the spheres had at the previous build (`NeighborList::previous_slot`) and the partners' ids.
//! Only the touching pairs are looked up (in B2 one in seven).

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::neighbor::{NeighborList, NONE};
use super::spheres::{SphereId, Spheres};
use crate::math::Vec3;

/// Owners per parallel work item; fixed, so the result is thread-count independent.
const CHUNK: usize = 2048;

/// History of one touching pair, as saved in checkpoints.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SavedContact {
    /// Ids of the two spheres (i, j), in the orientation of `history`.
    pub ids: (SphereId, SphereId),
    /// The contact's history vector for the pair (i, j) (see `contact`).
    pub history: Vec3,
}

/// Sets `v` to `n` copies of `x`, in parallel (B1 refills 400,000 histories at each build).
fn filled<T: Copy + Send + Sync>(v: &mut Vec<T>, n: usize, x: T) {
    v.truncate(n);
    v.par_iter_mut().with_min_len(1 << 14).for_each(|y| *y = x);
    v.resize(n, x);
}

/// Per-pair state aligned with the neighbour list.
#[derive(Clone, Debug, Default)]
pub struct PairContacts {
    /// History of each pair of the list (meaningful while `touch` is set).
    pub history: Vec<Vec3>,
    /// 1 while the pair touched at the last force evaluation, else 0.
    pub touch: Vec<u8>,
    old_history: Vec<Vec3>,
    old_touch: Vec<u8>,
    /// Scratch of `rebuild`: the slot now of each slot of the previous build.
    new_slot: Vec<u32>,
    /// Scratch of `rebuild`: (pair, history) carried over, by chunk of old owners.
    found: Vec<Vec<(u32, Vec3)>>,
}

impl PairContacts {
    /// Adopts the list just built by `nl`, carrying the history of the pairs that touched.
    pub fn rebuild(&mut self, nl: &NeighborList, spheres: &Spheres) {
        std::mem::swap(&mut self.history, &mut self.old_history);
        std::mem::swap(&mut self.touch, &mut self.old_touch);
        let n_pairs = nl.partner.len();
        filled(&mut self.history, n_pairs, Vec3::ZERO);
        filled(&mut self.touch, n_pairs, 0);
        if nl.old_offsets.is_empty() || self.old_touch.len() != nl.old_partner_id.len() {
            return;
        }
        let n_old = nl.old_offsets.len() - 1;
        // The slot of each old slot's sphere now (`NONE` for a sphere gone since).
        self.new_slot.clear();
        self.new_slot.resize(n_old, NONE);
        for (k, &o) in nl.previous_slot.iter().enumerate() {
            if let Some(s) = self.new_slot.get_mut(o as usize) {
                *s = k as u32;
            }
        }
        // Each touching old pair (a, b) is listed now as (a, b) or as (b, a) (then its
        // history changes sign): found by old owners in parallel, put in place in chunk order.
        let (old_h, old_t) = (&self.old_history, &self.old_touch);
        let new_slot = &self.new_slot;
        self.found.resize_with(n_old.div_ceil(CHUNK), Vec::new);
        self.found.par_iter_mut().enumerate().for_each(|(c, out)| {
            out.clear();
            let owners = c * CHUNK..((c + 1) * CHUNK).min(n_old);
            for (a_old, &a) in owners.clone().zip(&new_slot[owners]) {
                if a == NONE {
                    continue;
                }
                let seg = nl.old_offsets[a_old] as usize..nl.old_offsets[a_old + 1] as usize;
                for q in seg {
                    if old_t[q] == 0 {
                        continue;
                    }
                    let Some(b) = spheres.slot_of(nl.old_partner_id[q]) else {
                        continue;
                    };
                    let a = a as usize;
                    if let Some(p) = nl.pair_index(a, b) {
                        out.push((p as u32, old_h[q]));
                    } else if let Some(p) = nl.pair_index(b, a) {
                        out.push((p as u32, -old_h[q]));
                    }
                }
            }
        });
        for &(p, h) in self.found.iter().flatten() {
            self.history[p as usize] = h;
            self.touch[p as usize] = 1;
        }
    }

    /// The touching pairs with their history, for a checkpoint.
    pub fn save(&self, nl: &NeighborList, spheres: &Spheres) -> Vec<SavedContact> {
        let mut out = Vec::new();
        for i in 0..nl.offsets.len().saturating_sub(1) {
            for p in nl.offsets[i] as usize..nl.offsets[i + 1] as usize {
                if self.touch[p] != 0 {
                    let j = nl.partner[p] as usize;
                    out.push(SavedContact {
                        ids: (spheres.id[i], spheres.id[j]),
                        history: self.history[p],
                    });
                }
            }
        }
        out
    }

    /// Restores saved history into the list just built by `nl` (at the saved run's build
    /// positions, so that it holds every saved pair). Every other pair starts apart.
    pub fn restore(&mut self, saved: &[SavedContact], nl: &NeighborList, spheres: &Spheres) {
        let n_pairs = nl.partner.len();
        self.history.clear();
        self.history.resize(n_pairs, Vec3::ZERO);
        self.touch.clear();
        self.touch.resize(n_pairs, 0);
        let find =
            |a: SphereId, b: SphereId| nl.pair_index(spheres.slot_of(a)?, spheres.slot_of(b)?);
        for c in saved {
            let (a, b) = c.ids;
            if let Some(p) = find(a, b) {
                self.history[p] = c.history;
                self.touch[p] = 1;
            } else if let Some(p) = find(b, a) {
                self.history[p] = -c.history;
                self.touch[p] = 1;
            }
        }
    }

    /// Number of pairs that touched at the last force evaluation.
    pub fn touching(&self) -> usize {
        self.touch.par_iter().map(|&t| t as usize).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::domain::Domain;
    use crate::dem::neighbor::tests::uniform;
    use crate::dem::spheres::NewSphere;
    use std::collections::HashMap;

    /// The touching pairs as (id, id) → history, oriented as listed.
    fn touching(c: &PairContacts, nl: &NeighborList, s: &Spheres) -> HashMap<(u64, u64), Vec3> {
        c.save(nl, s)
            .into_iter()
            .map(|p| ((p.ids.0 as u64, p.ids.1 as u64), p.history))
            .collect()
    }

    /// Spheres moved, reordered, one removed and one added between two builds: every pair
    /// that touched and is still listed keeps its history (with the sign flipped when the new
    /// list names it the other way round), and no other pair touches.
    #[test]
    fn history_follows_the_pairs_across_a_rebuild() {
        let mut seed = 99u64;
        let mut rnd = || uniform(&mut seed);
        let d = Domain {
            min: Vec3::ZERO,
            max: Vec3::new(0.4, 0.2, 0.3),
            periodic: [true, false, false],
        };
        let mut s = Spheres::default();
        for _ in 0..800 {
            s.push(NewSphere {
                position: Vec3::new(0.4 * rnd(), 0.2 * rnd(), 0.3 * rnd()),
                velocity: Vec3::ZERO,
                angular_velocity: Vec3::ZERO,
                radius: if rnd() < 0.3 { 0.02 } else { 0.01 },
                material: 0,
                density: 1000.0,
                fixed: false,
            });
        }
        let mut nl = NeighborList::new(0.01);
        let mut c = PairContacts::default();
        nl.build(&mut s, &d, None);
        c.rebuild(&nl, &s);
        for p in 0..c.touch.len() {
            if rnd() < 0.4 {
                c.touch[p] = 1;
                c.history[p] = Vec3::new(rnd(), rnd(), rnd()) - 0.5;
            }
        }
        let before = touching(&c, &nl, &s);
        // Moves of up to 0.03 m (three skins) reorder the slots, turn pairs round and take
        // some out of reach; one sphere goes, one comes.
        for x in s.position.iter_mut() {
            *x = d.wrap(*x + Vec3::new(rnd() - 0.5, rnd() - 0.5, rnd() - 0.5) * 0.06);
        }
        let mut keep = vec![true; s.len()];
        keep[17] = false;
        let gone = s.id[17] as u64;
        s.retain(&keep);
        s.push(NewSphere {
            position: Vec3::splat(0.1),
            velocity: Vec3::ZERO,
            angular_velocity: Vec3::ZERO,
            radius: 0.01,
            material: 0,
            density: 1000.0,
            fixed: false,
        });
        nl.build(&mut s, &d, None);
        c.rebuild(&nl, &s);
        let after = touching(&c, &nl, &s);
        let mut listed = std::collections::HashSet::new();
        for i in 0..s.len() {
            for p in nl.offsets[i] as usize..nl.offsets[i + 1] as usize {
                let j = nl.partner[p] as usize;
                listed.insert((s.id[i] as u64, s.id[j] as u64));
            }
        }
        let mut kept = 0;
        for (&(a, b), &h) in &before {
            let want = if listed.contains(&(a, b)) {
                Some(((a, b), h))
            } else if listed.contains(&(b, a)) {
                Some(((b, a), -h))
            } else {
                None
            };
            if let Some((key, h)) = want {
                assert_eq!(after.get(&key), Some(&h), "pair {key:?}");
                kept += 1;
            }
        }
        assert_eq!(after.len(), kept, "only carried pairs touch");
        let flipped = before
            .keys()
            .filter(|&&(a, b)| listed.contains(&(b, a)))
            .count();
        assert!(
            kept > 100 && flipped > 10 && kept < before.len(),
            "{kept} kept, {flipped} flipped of {}",
            before.len()
        );
        assert!(before.keys().any(|&(a, b)| a == gone || b == gone));
    }
}
