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
//! At a rebuild the history is carried over without hashing: for a new pair (i, j) it is looked
//! up in the old list's (short) partner lists of i and of j, found through the slots the spheres
//! had at the previous build (`NeighborList::previous_slot`) and the partners' ids.

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::neighbor::{NeighborList, NONE};
use super::par::for_chunks;
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

/// Per-pair state aligned with the neighbour list.
#[derive(Clone, Debug, Default)]
pub struct PairContacts {
    /// History of each pair of the list (meaningful while `touch` is set).
    pub history: Vec<Vec3>,
    /// 1 while the pair touched at the last force evaluation, else 0.
    pub touch: Vec<u8>,
    old_history: Vec<Vec3>,
    old_touch: Vec<u8>,
}

impl PairContacts {
    /// Adopts the list just built by `nl`, carrying the history of the pairs that touched.
    pub fn rebuild(&mut self, nl: &NeighborList, spheres: &Spheres) {
        std::mem::swap(&mut self.history, &mut self.old_history);
        std::mem::swap(&mut self.touch, &mut self.old_touch);
        let n_pairs = nl.partner.len();
        self.history.clear();
        self.history.resize(n_pairs, Vec3::ZERO);
        self.touch.clear();
        self.touch.resize(n_pairs, 0);
        if nl.old_offsets.is_empty() || self.old_touch.len() != nl.old_partner_id.len() {
            return;
        }
        let n = spheres.len();
        let ids = &spheres.id;
        let (old_h, old_t) = (&self.old_history, &self.old_touch);
        // The touching old pair (a, b), by a's old slot and b's id.
        let find = |a_old: u32, b: SphereId| -> Option<Vec3> {
            if a_old == NONE {
                return None;
            }
            let a_old = a_old as usize;
            let seg = nl.old_offsets[a_old] as usize..nl.old_offsets[a_old + 1] as usize;
            seg.clone()
                .zip(&nl.old_partner_id[seg])
                .find(|&(q, &id)| id == b && old_t[q] != 0)
                .map(|(q, _)| old_h[q])
        };
        let offsets = &nl.offsets;
        let bounds = |c: usize| (offsets[(c * CHUNK).min(n)] as usize, 0);
        for_chunks(
            0..n.div_ceil(CHUNK),
            (&mut self.history[..], &mut self.touch[..]),
            (),
            &bounds,
            &|c, (hist, touch): (&mut [Vec3], &mut [u8]), ()| {
                let base = offsets[c * CHUNK] as usize;
                for i in c * CHUNK..((c + 1) * CHUNK).min(n) {
                    for p in offsets[i] as usize..offsets[i + 1] as usize {
                        let j = nl.partner[p] as usize;
                        let carried = find(nl.previous_slot[i], ids[j])
                            .or_else(|| find(nl.previous_slot[j], ids[i]).map(|h| -h));
                        if let Some(h) = carried {
                            hist[p - base] = h;
                            touch[p - base] = 1;
                        }
                    }
                }
            },
            &|(), ()| (),
        );
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
        let find = |a: SphereId, b: SphereId| -> Option<usize> {
            let i = spheres.slot_of(a)?;
            let j = spheres.slot_of(b)? as u32;
            (nl.offsets[i] as usize..nl.offsets[i + 1] as usize).find(|&p| nl.partner[p] == j)
        };
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
