//! Tests of the neighbour list: against a brute-force search, its slabs, plain owners and
//! previous slots, and its rebuild test (no touching pair missed, lists that outlive half a skin).

use super::*;
use crate::dem::spheres::NewSphere;

fn brute(s: &Spheres, d: &Domain, skin: f64) -> Vec<(u32, u32)> {
    let mut v = vec![];
    for i in 0..s.len() {
        for j in i + 1..s.len() {
            let cut = s.radius[i] + s.radius[j] + skin;
            if d.minimum_image(s.position[j] - s.position[i]).length() < cut {
                v.push((i as u32, j as u32));
            }
        }
    }
    v
}

/// Uniform in [0, 1) from the xorshift state `seed` (deterministic, for tests).
pub(crate) fn uniform(seed: &mut u64) -> f64 {
    *seed ^= *seed << 13;
    *seed ^= *seed >> 7;
    *seed ^= *seed << 17;
    (*seed >> 11) as f64 / (1u64 << 53) as f64
}

fn random_spheres(periodic: [bool; 3], size: f64, seed: u64) -> (Spheres, Domain) {
    let mut seed = seed;
    let mut rnd = || uniform(&mut seed);
    let d = Domain {
        min: Vec3::ZERO,
        max: Vec3::new(size, 0.5 * size, 0.8 * size),
        periodic,
    };
    let mut s = Spheres::default();
    for _ in 0..600 {
        let r = if rnd() < 0.2 { 0.03 } else { 0.01 };
        s.push(NewSphere {
            position: Vec3::new(rnd(), 0.5 * rnd(), 0.8 * rnd()) * size,
            velocity: Vec3::ZERO,
            angular_velocity: Vec3::ZERO,
            radius: r,
            material: 0,
            density: 1000.0,
            fixed: false,
        });
    }
    (s, d)
}

/// Slabs group whole layers to about `SLAB_SPHERES` spheres, but stay at least `MIN_SLABS`
/// (or one per layer when there are fewer layers).
#[test]
fn slabs_group_layers() {
    assert_eq!(slab_count(155, 100_000), 38); // B1 100k: 646 a layer, 4 layers a slab
    assert_eq!(slab_count(36, 32_000), 12); // B2: 889 a layer, 3 layers a slab
    assert_eq!(slab_count(40, 1_000), 8); // few spheres: still 8 slabs
    assert_eq!(slab_count(5, 1_000), 5);
    assert_eq!(slab_count(1000, 10_000_000), 1000); // thick layers: one a slab
    assert_eq!(slab_count(0, 0), 1);
}

/// The list holds exactly the brute-force pairs (mixed sizes, periodic axes, boxes only a
/// few cells wide), each once, under an owner that respects the slab rule, and the spheres
/// end up sorted with ids and the id → slot table consistent.
#[test]
fn matches_brute_force() {
    for (periodic, size) in [
        ([false; 3], 1.0),
        ([true, false, true], 1.0),
        ([true; 3], 0.1),
        ([true; 3], 0.5),
    ] {
        let (mut s, d) = random_spheres(periodic, size, 12345);
        let ids_before = s.id.clone();
        let mut nl = NeighborList::new(0.005);
        nl.build(&mut s, &d, None);
        for (k, &id) in s.id.iter().enumerate() {
            assert_eq!(s.slot_of(id), Some(k));
        }
        let mut ids = s.id.clone();
        ids.sort_unstable();
        assert_eq!(ids, ids_before);
        let mut got = vec![];
        let slab_of = |k: u32| nl.slabs().partition_point(|&b| b <= k) - 1;
        let last = nl.slabs().len() - 2;
        assert_eq!(nl.owner.len(), nl.partner.len());
        for i in 0..s.len() {
            let pairs = nl.offsets[i] as usize..nl.offsets[i + 1] as usize;
            assert!(nl.owner[pairs.clone()].iter().all(|&o| o as usize == i));
            let own = &nl.partner[pairs];
            assert!(own.windows(2).all(|w| w[0] < w[1]), "partners ascending");
            for &j in own {
                let (si, sj) = (slab_of(i as u32), slab_of(j));
                let wraps = nl.slab_wraps() && si == last && sj == 0;
                assert!(
                    wraps || (j as usize > i && sj <= si + 1),
                    "{periodic:?}: owner {i} (slab {si}) of {j} (slab {sj})"
                );
                got.push((i.min(j as usize) as u32, i.max(j as usize) as u32));
            }
        }
        got.sort_unstable();
        assert_eq!(got, brute(&s, &d, 0.005), "periodic {periodic:?}");
        assert_eq!(close_pairs(&s, &d, 0.005), brute(&s, &d, 0.005));
    }
}

/// With the drift bound, `needs_rebuild` answers as measuring the displacements at every
/// step does (spheres drifting at different speeds across a periodic face), and the bound
/// keeps it from measuring in most steps.
#[test]
fn drift_bound_gives_the_exact_answer() {
    let (mut s, d) = random_spheres([true, false, false], 1.0, 4242);
    let dt = 1e-3;
    for (k, v) in s.velocity.iter_mut().enumerate() {
        *v = Vec3::new(
            0.3 + 0.1 * (k % 5) as f64,
            0.05 * ((k % 3) as f64 - 1.0),
            0.0,
        );
    }
    let mut nl = NeighborList::new(0.005);
    nl.build(&mut s, &d, None);
    let (mut builds, mut skipped) = (0, 0);
    for _ in 0..300 {
        let mut max_drift: f64 = 0.0;
        for (x, v) in s.position.iter_mut().zip(&s.velocity) {
            max_drift = max_drift.max((dt * *v).length());
            *x = d.wrap(*x + dt * *v);
        }
        nl.note_drift(max_drift);
        let exact = Moves::measure(
            &s.position,
            &nl.reference,
            &nl.room,
            &mut nl.bands,
            &d,
            nl.skin,
        )
        .verdict(nl.skin)
        .is_err();
        skipped += usize::from(nl.drift < nl.next_check);
        assert_eq!(nl.needs_rebuild(&s, &d), exact);
        if exact {
            nl.build(&mut s, &d, None);
            builds += 1;
        }
    }
    assert!(
        builds > 20 && skipped > 100,
        "{builds} builds, {skipped} steps skipped"
    );
}

/// Moves the spheres `steps` steps of `dt` at their velocities, rebuilding the list when
/// `needs_rebuild` says so, and checks at every other step that each touching pair is
/// listed. Returns the builds and the steps at which some sphere was farther than skin/2
/// from its build position.
fn follow(s: &mut Spheres, d: &Domain, dt: f64, steps: usize) -> (usize, usize) {
    let mut nl = NeighborList::new(0.005);
    nl.build(s, d, None);
    let (mut builds, mut past_half_skin) = (0, 0);
    for _ in 0..steps {
        let mut max_drift: f64 = 0.0;
        for (x, v) in s.position.iter_mut().zip(&s.velocity) {
            max_drift = max_drift.max((dt * *v).length());
            *x = d.wrap(*x + dt * *v);
        }
        nl.note_drift(max_drift);
        if nl.needs_rebuild(s, d) {
            nl.build(s, d, None);
            builds += 1;
            continue;
        }
        past_half_skin += usize::from(
            (s.position.iter().zip(&nl.reference))
                .any(|(&x, &x0)| d.minimum_image(x - x0).length() > 0.5 * nl.skin),
        );
        let mut listed: Vec<(u32, u32)> = (0..s.len())
            .flat_map(|i| {
                let p = nl.offsets[i] as usize..nl.offsets[i + 1] as usize;
                nl.partner[p]
                    .iter()
                    .map(move |&j| (j.min(i as u32), j.max(i as u32)))
            })
            .collect();
        listed.sort_unstable();
        for pair in brute(s, d, 0.0) {
            assert!(listed.binary_search(&pair).is_ok(), "{pair:?} not listed");
        }
    }
    (builds, past_half_skin)
}

/// In a shear flow over a fixed base (a chute), the list lives until the spheres'
/// displacements differ by a skin, well past the step where the fastest has moved skin/2,
/// and holds every touching pair. Spheres cross both periodic faces.
#[test]
fn lists_outlive_half_a_skin_in_a_shear_flow() {
    let (mut s, d) = random_spheres([true, true, false], 0.3, 99);
    let height = d.max.z;
    for (k, (v, x)) in s.velocity.iter_mut().zip(&s.position).enumerate() {
        let noise = 0.1 * Vec3::new((k % 7) as f64 - 3.0, (k % 5) as f64 - 2.0, 0.0);
        *v = if x.z < 0.1 * height {
            Vec3::ZERO
        } else {
            Vec3::new(2.0 * x.z / height, 0.0, 0.0) + noise
        };
    }
    let (builds, past_half_skin) = follow(&mut s, &d, 1e-4, 300);
    assert!(
        builds > 5 && past_half_skin > 100,
        "{builds} builds, {past_half_skin} steps past skin/2"
    );
}

/// A list of no spheres stays valid (regression: the rebuild test split its per-band
/// boxes of no part).
#[test]
fn an_empty_list_stays_valid() {
    let (_, d) = random_spheres([true, false, false], 1.0, 1);
    let mut s = Spheres::default();
    let mut nl = NeighborList::new(0.005);
    nl.build(&mut s, &d, None);
    nl.note_drift(1.0);
    assert!(!nl.needs_rebuild(&s, &d));
}

/// Two layers sliding past each other, each moving as a block: the bands (two cells of
/// z each, here z < 0.16 m and above) hardly spread inside, but pairs across the two are
/// compared, and no touching pair is missed.
#[test]
fn no_touching_pair_is_missed_between_sliding_layers() {
    let (mut s, d) = random_spheres([true, false, false], 0.3, 8);
    for (v, x) in s.velocity.iter_mut().zip(&s.position) {
        *v = Vec3::new(if x.z < 0.16 { 0.5 } else { -0.5 }, 0.0, 0.0);
    }
    // 1 m/s against each other: a build every skin, 50 steps.
    let (builds, _) = follow(&mut s, &d, 1e-4, 300);
    assert!(builds >= 5, "{builds} builds");
}

/// Spheres moving every way in a dense cloud approach each other as fast as the spread
/// of their displacements grows: no touching pair is missed.
#[test]
fn no_touching_pair_is_missed_in_random_motion() {
    let (mut s, d) = random_spheres([true, false, false], 0.3, 5);
    let mut seed = 17;
    for v in s.velocity.iter_mut() {
        let mut rnd = || 2.0 * uniform(&mut seed) - 1.0;
        *v = Vec3::new(rnd(), rnd(), rnd());
    }
    let (builds, _) = follow(&mut s, &d, 1e-4, 300);
    assert!(builds > 10, "{builds} builds");
}

/// For a plain owner, x_j - x_i is its own nearest image at every step until the next
/// build, while spheres drift across both periodic faces, all alike (so that their rooms at
/// the faces, not their spread, end the lists); near the faces owners are not plain.
#[test]
fn plain_owners_need_no_image() {
    let (mut s, d) = random_spheres([true, true, false], 0.8, 777);
    let dt = 1e-3;
    for (k, v) in s.velocity.iter_mut().enumerate() {
        let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
        *v = Vec3::new(0.5, 0.3, 0.0) + sign * 0.001 * Vec3::new((k % 5) as f64, 0.0, 0.0);
    }
    let mut nl = NeighborList::new(0.005);
    nl.build(&mut s, &d, None);
    let (mut builds, mut plain, mut owners) = (0, 0, 0);
    for _ in 0..400 {
        let mut max_drift: f64 = 0.0;
        for (x, v) in s.position.iter_mut().zip(&s.velocity) {
            max_drift = max_drift.max((dt * *v).length());
            *x = d.wrap(*x + dt * *v);
        }
        nl.note_drift(max_drift);
        if nl.needs_rebuild(&s, &d) {
            nl.build(&mut s, &d, None);
            builds += 1;
        }
        let x = &s.position;
        for i in 0..s.len() {
            owners += 1;
            if !nl.plain[i] {
                continue;
            }
            plain += 1;
            for &j in &nl.partner[nl.offsets[i] as usize..nl.offsets[i + 1] as usize] {
                let dx = x[j as usize] - x[i];
                assert_eq!(d.minimum_image(dx), dx, "owner {i}, partner {j}");
            }
        }
    }
    let share = plain as f64 / owners as f64;
    assert!(
        builds > 10 && share > 0.3 && share < 0.9,
        "{builds} builds, {share} plain"
    );
}

/// A second build after small moves maps every slot to its previous one.
#[test]
fn previous_slots_follow_the_spheres() {
    let (mut s, d) = random_spheres([true, false, false], 1.0, 777);
    let mut nl = NeighborList::new(0.005);
    nl.build(&mut s, &d, None);
    let before = s.id.clone();
    for (k, x) in s.position.iter_mut().enumerate() {
        *x += Vec3::new(0.02 * ((k % 7) as f64 - 3.0), 0.0, 0.0);
        *x = d.wrap(*x);
    }
    nl.build(&mut s, &d, None);
    for k in 0..s.len() {
        assert_eq!(before[nl.previous_slot[k] as usize], s.id[k]);
    }
    let total = nl.old_partner_id.len();
    assert_eq!(*nl.old_offsets.last().unwrap() as usize, total);
}
