//! The pair kernel of `forces`: for a range of owners, the distance filter over their
//! candidates, then the contact law on batches of close pairs (`PairContext::run`).

use super::super::contact::lanes::{self, get, put, Lanes};
use super::super::contact::{dispatch, Law, WithLaw};
use super::super::isa::{on_isa, Isa, AVX2, AVX512, GENERIC};
use super::super::material::PairLaw;
use super::kernel::uniform_kind;
use super::{larger, Out, Tally};
use crate::math::Vec3;

/// What the pair kernel reads.
pub(super) struct PairContext<'a> {
    pub(super) pos: &'a [Vec3],
    pub(super) vel: &'a [Vec3],
    pub(super) ang: &'a [Vec3],
    pub(super) rad: &'a [f64],
    pub(super) mass: &'a [f64],
    pub(super) material: &'a [u16],
    pub(super) fixed: &'a [bool],
    pub(super) offsets: &'a [u32],
    pub(super) partner: &'a [u32],
    pub(super) owner: &'a [u32],
    pub(super) plain: &'a [bool],
    pub(super) laws: &'a [PairLaw],
    pub(super) n_mat: usize,
    pub(super) domain: super::super::domain::Domain,
    pub(super) dt: f64,
    /// The instructions the kernel runs with (`dem::isa`).
    pub(super) isa: Isa,
}

impl PairContext<'_> {
    /// The pairs of the owners `owners`, whose history and touch flags start at `hist[0]`,
    /// `touch[0]`.
    pub(super) fn run(
        &self,
        owners: std::ops::Range<usize>,
        out: &mut Out,
        hist: &mut [Vec3],
        touch: &mut [u8],
    ) -> Tally {
        struct Run<'r, 'c, 'o>(&'r PairContext<'c>, Args<'r, 'o>);
        impl WithLaw for Run<'_, '_, '_> {
            type Out = Tally;
            fn run<L: Law>(self) -> Tally {
                let Run(ctx, args) = self;
                match ctx.domain.periodic.iter().any(|&p| p) {
                    true => ctx.run_on::<true, L>(args),
                    false => ctx.run_on::<false, L>(args),
                }
            }
        }
        let args = (owners, out, hist, touch);
        dispatch(uniform_kind(self.laws), Run(self, args))
    }

    /// `run_with` compiled for the kernel's instruction set (`dem::isa`).
    #[inline(always)]
    fn run_on<const PERIODIC: bool, K: Law>(&self, args: Args) -> Tally {
        on_isa!(
            self.isa,
            self.run_with::<PERIODIC, K, GENERIC>(args),
            self.run_avx2::<PERIODIC, K>(args),
            self.run_avx512::<PERIODIC, K>(args)
        )
    }

    /// `run_with` compiled for AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn run_avx2<const PERIODIC: bool, K: Law>(&self, args: Args) -> Tally {
        self.run_with::<PERIODIC, K, AVX2>(args)
    }

    /// `run_with` compiled for AVX-512.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx512f")]
    fn run_avx512<const PERIODIC: bool, K: Law>(&self, args: Args) -> Tally {
        self.run_with::<PERIODIC, K, AVX512>(args)
    }

    /// `run` for a domain with (`PERIODIC`) or without periodic axes and the contact law `K`.
    ///
    /// Three stages, on batches of up to `BATCH` contacts in pair order:
    ///
    /// 1. *Filter*: every candidate (i, j) has its distance tested, |x_j - x_i|² < (r_i + r_j)²
    ///    (x_j - x_i taken to its nearest periodic image only for owners near a periodic
    ///    face); those closer join the batch (its touch flag with it), every touch flag is
    ///    cleared. Most candidates leave here, in a loop over pairs small enough to keep
    ///    everything in registers.
    /// 2. *Geometry*: for the batch, d = |x_j - x_i|, δ = r_i + r_j - d, n = (x_j - x_i)/d,
    ///    R* = r_i r_j/(r_i + r_j), m* = m_i m_j/(m_i + m_j) and the law's square roots
    ///    (`Law::prepare`). The contacts are independent here, so the processor overlaps their
    ///    square roots and divisions instead of waiting on each chain d → δ → a → √(m* a).
    /// 3. *Forces*: (a) the velocities and histories gathered into the lanes, (b) the law on
    ///    all lanes at once (`lanes::run`), (c) the scatter in pair order: i receives F and
    ///    T_i, j receives −F and T_j, at once.
    ///
    /// The order in which each sphere receives its terms is the pair order, as if each pair
    /// were done from start to end before the next.
    ///
    /// `I` is the copy it is compiled into (`run_on`), whose batches it runs (`batch`).
    #[inline(always)]
    fn run_with<const PERIODIC: bool, K: Law, const I: u8>(
        &self,
        (owners, out, hist, touch): Args,
    ) -> Tally {
        let Some(first) = owners.clone().next() else {
            return Tally::ZERO;
        };
        let base = self.offsets[first] as usize;
        let im = self.domain.images();
        let n = self.pos.len();
        let mut batch = Batch {
            base,
            ..Batch::default()
        };
        if self.n_mat == 1 {
            let l = &mut batch.lanes;
            for (c, v) in self.laws[0].k.into_iter().enumerate() {
                l.params[c] = [v; BATCH];
            }
        }
        // The batch's length, held apart so that it stays in a register in the filter.
        let mut len = 0;
        let mut s = Sweep {
            batch,
            tally: Tally::ZERO,
            out,
        };
        let c = Candidates {
            pos: &self.pos[..n],
            rad: &self.rad[..n],
            offsets: self.offsets,
            partner: self.partner,
            owner: self.owner,
            im,
            base,
        };
        // Runs of owners that need no periodic image (`NeighborList::plain`, most of them)
        // or may need one: the filter of the first kind skips the image's compares and
        // selects, a third of its instructions.
        let plain = &self.plain[..n];
        let mut i0 = owners.start;
        while i0 < owners.end {
            let flag = plain[i0];
            let i1 = i0
                + plain[i0..owners.end]
                    .iter()
                    .take_while(|&&p| p == flag)
                    .count();
            len = if PERIODIC && !flag {
                self.filter::<PERIODIC, true, K, I>(c, i0..i1, len, &mut s, hist, touch)
            } else {
                self.filter::<PERIODIC, false, K, I>(c, i0..i1, len, &mut s, hist, touch)
            };
            i0 = i1;
        }
        s.batch.len = len;
        self.batch::<PERIODIC, K, I>(&mut s, hist, touch);
        s.tally
    }

    /// Stage 1 of `run_with` for the pairs of the owners `owners`, `len` contacts already in
    /// the batch; returns the new length. `IMAGES`: whether x_j - x_i may need a periodic
    /// image (stage 2 takes the image whenever the domain is `PERIODIC`, which changes nothing
    /// for the others).
    ///
    /// The loop runs over pairs, each reading its owner from `owner`, not over owners: B2's
    /// owners have 3.5 candidates on average, and a loop per owner would end at an
    /// unpredictable count every few candidates (B2, 1 thread: forces -8 %; B1: -9 %).
    #[inline(always)]
    fn filter<const PERIODIC: bool, const IMAGES: bool, K: Law, const I: u8>(
        &self,
        c: Candidates,
        owners: std::ops::Range<usize>,
        mut len: usize,
        s: &mut Sweep,
        hist: &mut [Vec3],
        touch: &mut [u8],
    ) -> usize {
        let Candidates { pos, rad, im, .. } = c;
        let (p0, p1) = (
            c.offsets[owners.start] as usize,
            c.offsets[owners.end] as usize,
        );
        let pairs = (p0 - c.base..p1 - c.base).zip(&c.partner[p0..p1]);
        for ((p, &j), &i) in pairs.zip(&c.owner[p0..p1]) {
            let (i, j) = (i as usize, j as usize);
            let (xi, ri) = (pos[i], rad[i]);
            let mut d = pos[j] - xi;
            if IMAGES {
                d = im.nearest(d);
            }
            let r_sum = ri + rad[j];
            // Every candidate is written to the batch's next place, which only a close one
            // keeps: no branch on the distance, which the processor could not predict
            // (contacts and near misses are interleaved).
            let close = d.length_squared() < r_sum * r_sum;
            len = s.batch.offer(len, p, touch[p], close);
            touch[p] = 0;
            // Stage 3 reads this contact's history when the batch is full: ask for it now
            // (the history, one of the largest arrays, missed the cache in 17 % of B2's pair
            // loop).
            prefetch_at(hist.as_ptr().wrapping_add(p));
            if len == BATCH {
                s.batch.len = len;
                self.batch::<PERIODIC, K, I>(s, hist, touch);
                len = 0;
            }
        }
        len
    }

    /// Stages 2 and 3 of `run_with` for the contacts in `s.batch`, which it empties.
    ///
    /// Never inlined: called once per `BATCH` close pairs, it would otherwise crowd the filter
    /// loop's registers and make it reload its constants from the stack at every candidate
    /// (B2, 1 thread: forces 1.00 -> 0.89 s).
    /// The copy is `I`'s, the one `run_with` runs in: chosen once per call of `run`
    /// (`run_on`), not per batch.
    #[inline(always)]
    fn batch<const PERIODIC: bool, K: Law, const I: u8>(
        &self,
        s: &mut Sweep,
        hist: &mut [Vec3],
        touch: &mut [u8],
    ) {
        match I {
            // SAFETY: `I` is AVX2 or AVX512 only inside `run_avx2` or `run_avx512`, which
            // `run_on` calls only where the processor has those instructions.
            #[cfg(target_arch = "x86_64")]
            AVX2 => unsafe { self.batch_avx2::<PERIODIC, K>(s, hist, touch) },
            #[cfg(target_arch = "x86_64")]
            AVX512 => unsafe { self.batch_avx512::<PERIODIC, K>(s, hist, touch) },
            _ => self.batch_generic::<PERIODIC, K>(s, hist, touch),
        }
    }

    /// `batch_body`, compiled for the generic instructions.
    #[inline(never)]
    fn batch_generic<const PERIODIC: bool, K: Law>(
        &self,
        s: &mut Sweep,
        hist: &mut [Vec3],
        touch: &mut [u8],
    ) {
        self.batch_body::<PERIODIC, K>(s, hist, touch);
    }

    /// `batch_body`, compiled for AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline(never)]
    fn batch_avx2<const PERIODIC: bool, K: Law>(
        &self,
        s: &mut Sweep,
        hist: &mut [Vec3],
        touch: &mut [u8],
    ) {
        self.batch_body::<PERIODIC, K>(s, hist, touch);
    }

    /// `batch_body`, compiled for AVX-512.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx512f")]
    #[inline(never)]
    fn batch_avx512<const PERIODIC: bool, K: Law>(
        &self,
        s: &mut Sweep,
        hist: &mut [Vec3],
        touch: &mut [u8],
    ) {
        self.batch_body::<PERIODIC, K>(s, hist, touch);
    }

    /// The work of `batch`.
    #[inline(always)]
    fn batch_body<const PERIODIC: bool, K: Law>(
        &self,
        s: &mut Sweep,
        hist: &mut [Vec3],
        touch: &mut [u8],
    ) {
        let Sweep {
            batch: b,
            tally,
            out,
            ..
        } = s;
        let len = b.len.min(BATCH);
        b.len = 0;
        // Columns cut to one length n, so that a single test j < n covers every access below.
        let n = self.pos.len();
        let (pos, rad, vel, ang) = (
            &self.pos[..n],
            &self.rad[..n],
            &self.vel[..n],
            &self.ang[..n],
        );
        let (mass, fixed, material) = (&self.mass[..n], &self.fixed[..n], &self.material[..n]);
        // Stage 2a: the close pairs' spheres, separations, radii and masses.
        let im = self.domain.images();
        let (owner, partner) = (&self.owner[b.base..], &self.partner[b.base..]);
        let l = &mut b.lanes;
        for k in 0..len {
            let p = b.p[k] as usize >> 1;
            b.touched[k] = b.p[k] as u8 & 1;
            b.p[k] = p as u32;
            (b.i[k], b.j[k]) = (owner[p], partner[p]);
            let (i, j) = (b.i[k] as usize, b.j[k] as usize);
            assert!(i < n && j < n);
            // Stage 3 reads j's velocity and spin and adds to its force and torque: ask for
            // them now, so that they arrive while the geometry is computed.
            prefetch(&vel[j]);
            prefetch(&ang[j]);
            out.prefetch(j);
            let mut d = pos[j] - pos[i];
            if PERIODIC {
                d = im.nearest(d);
            }
            put(&mut l.n, k, d);
            b.d2[k] = d.length_squared();
            (l.r_i[k], l.r_j[k]) = (rad[i], rad[j]);
            // m* = m_num / m_den; a fixed sphere counts as infinitely heavy.
            (b.m_num[k], b.m_den[k]) = match (fixed[i], fixed[j]) {
                (false, false) => (mass[i] * mass[j], mass[i] + mass[j]),
                (true, _) => (mass[j], 1.0),
                (false, true) => (mass[i], 1.0),
            };
            // With one material the law's constants were set once for all lanes.
            if self.n_mat > 1 {
                let law = material[i] as usize * self.n_mat + material[j] as usize;
                for (c, v) in self.laws[law].k.into_iter().enumerate() {
                    l.params[c][k] = v;
                }
            }
        }
        geometry::<K>(b, len);
        // Stage 3a: gather each contact's state and history into the lanes.
        let l = &mut b.lanes;
        for k in 0..len {
            let (i, j, p) = (b.i[k] as usize, b.j[k] as usize, b.p[k] as usize);
            assert!(i < n && j < n);
            let h = if b.touched[k] & 1 == 0 {
                Vec3::ZERO
            } else {
                hist[p]
            };
            put(&mut l.dv, k, vel[i] - vel[j]);
            put(&mut l.w_i, k, ang[i]);
            put(&mut l.w_j, k, ang[j]);
            put(&mut l.hist, k, h);
        }
        // Stage 3b: the law, on all lanes at once.
        lanes::run::<K>(l, self.dt);
        // Stage 3c: the scatter, in pair order. i's terms go straight to its force and torque,
        // as j's do: summing them per owner first costs a branch on each change of owner, which
        // the processor cannot predict where owners have one contact or none (B2, 1 thread:
        // 1.729 -> 1.683 s, medians of 6).
        let l = &b.lanes;
        for k in 0..len {
            let (i, j, p) = (b.i[k] as usize, b.j[k] as usize, b.p[k] as usize);
            let delta = l.delta[k];
            touch[p] = 0;
            if delta <= 0.0 || b.d2[k] == 0.0 {
                continue;
            }
            hist[p] = get(&l.hist, k);
            touch[p] = 1;
            let force = get(&l.force, k);
            out.add(i, force, get(&l.torque_i, k));
            out.add(j, -force, get(&l.torque_j, k));
            tally.contacts += 1;
            // Overlap ratio δ / min(r_i, r_j), divided out only when it may be the largest.
            let r_min = l.r_i[k].min(l.r_j[k]);
            if delta >= tally.worst.0 * r_min {
                tally.worst = larger(tally.worst, (delta / r_min, i));
            }
        }
    }
}

/// Asks the processor to bring `x` into the cache; changes nothing else.
#[inline(always)]
pub(super) fn prefetch<T>(x: &T) {
    prefetch_at(x as *const T);
}

/// Asks the processor to bring the memory at `x` into the cache; changes nothing else, and is
/// harmless for any address (so a column's element k can be asked for without a bounds test).
#[inline(always)]
pub(super) fn prefetch_at<T>(x: *const T) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: a prefetch reads nothing the program sees and cannot fault, whatever the address.
    unsafe {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        _mm_prefetch::<_MM_HINT_T0>(x.cast::<i8>());
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = x;
}

/// What the pair loop carries from batch to batch: the batch, the counters, and where the
/// forces go.
struct Sweep<'s, 'o> {
    batch: Batch,
    tally: Tally,
    out: &'s mut Out<'o>,
}

/// What the filter reads, passed by value so that it stays in registers: positions and
/// radii cut to one length (one bounds test covers both), the list, the periodic images, and
/// the index of the task's first pair (its histories and touch flags start there).
#[derive(Clone, Copy)]
struct Candidates<'a> {
    pos: &'a [Vec3],
    rad: &'a [f64],
    offsets: &'a [u32],
    partner: &'a [u32],
    owner: &'a [u32],
    im: super::super::domain::Images,
    base: usize,
}

/// What `PairContext::run_with` takes: the owners, where the forces go, and the task's
/// histories and touch flags.
type Args<'r, 'o> = (
    std::ops::Range<usize>,
    &'r mut Out<'o>,
    &'r mut [Vec3],
    &'r mut [u8],
);

/// Contacts per batch of the pair loop (`lanes::LANES`).
const BATCH: usize = lanes::LANES;

/// The close pairs waiting for stages 2 and 3 of the pair loop, as columns (so that stages 2
/// and 3b run on several contacts per instruction).
struct Batch {
    len: usize,
    /// The list's index of the task's first pair.
    base: usize,
    /// Owner i, partner j, pair index p (from the task's first pair; stage 1 writes 2 p + the
    /// touch flag, stage 2 unpacks it and looks up i and j).
    i: [u32; BATCH],
    j: [u32; BATCH],
    p: [u32; BATCH],
    /// The pair's touch flag before this evaluation.
    touched: [u8; BATCH],
    /// |x_j - x_i|² [m²].
    d2: [f64; BATCH],
    /// m* = m_num / m_den [kg] (m_i m_j / (m_i + m_j), or the free sphere's mass over 1).
    m_num: [f64; BATCH],
    m_den: [f64; BATCH],
    /// The contacts as the law sees them (`lanes.n` holds x_j - x_i until stage 2).
    lanes: Lanes,
}

impl Default for Batch {
    fn default() -> Self {
        let one = [1.0; BATCH];
        Batch {
            len: 0,
            base: 0,
            i: [0; BATCH],
            j: [0; BATCH],
            p: [0; BATCH],
            touched: [0; BATCH],
            d2: one,
            m_num: one,
            m_den: one,
            lanes: Lanes::default(),
        }
    }
}

impl Batch {
    /// Writes the candidate p (pair index, with its touch flag `touched`, 0 or 1) to place
    /// k < `BATCH` and returns the length of the batch: k + 1 if `close` (the batch keeps
    /// it), else k. One store per candidate: stage 2 looks up its spheres.
    #[inline(always)]
    fn offer(&mut self, k: usize, p: usize, touched: u8, close: bool) -> usize {
        // k < BATCH already; the mask only lets the compiler drop the bounds tests.
        const { assert!(BATCH.is_power_of_two()) };
        let k = k & (BATCH - 1);
        // A task's pairs are far fewer than 2^31 (each takes over 60 bytes).
        self.p[k] = (p as u32) << 1 | u32::from(touched & 1);
        k + usize::from(close)
    }
}

/// Stage 2 of the pair loop for the first `len` contacts of `b`:
///
/// |d| = √(d²), n = d / |d|, δ = r_i + r_j - |d|, R* = r_i r_j / (r_i + r_j),
/// m* = m_num / m_den, and the law's square roots (`Law::prepare`, from δ clamped at 0).
///
/// The contacts are independent: the loop runs on whole vectors of them, as wide as the
/// instructions `batch` is compiled for (`dem::isa`; the same bits with any, as every
/// operation is IEEE-exact).
///
/// Implements [6].
#[inline(always)]
fn geometry<K: Law>(b: &mut Batch, len: usize) {
    let len = len.min(BATCH);
    let (d2, m_num, m_den) = (&b.d2[..len], &b.m_num[..len], &b.m_den[..len]);
    let l = &mut b.lanes;
    let [nx, ny, nz] = &mut l.n;
    let (nx, ny, nz) = (&mut nx[..len], &mut ny[..len], &mut nz[..len]);
    let (r_i, r_j, delta) = (&l.r_i[..len], &l.r_j[..len], &mut l.delta[..len]);
    let (r_star, m_star) = (&mut l.r_star[..len], &mut l.m_star[..len]);
    let params = &l.params;
    let [pre_a, pre_b] = &mut l.pre;
    let (pre_a, pre_b) = (&mut pre_a[..len], &mut pre_b[..len]);
    for k in 0..len {
        let dist = d2[k].sqrt();
        let r_sum = r_i[k] + r_j[k];
        let dl = r_sum - dist;
        let rs = r_i[k] * r_j[k] / r_sum;
        let ms = m_num[k] / m_den[k];
        let constants = params.each_ref().map(|c| c[k]);
        let [pa, pb] = K::prepare(&K::unpack(constants), rs, ms, dl.max(0.0));
        let inv_dist = 1.0 / dist;
        nx[k] *= inv_dist;
        ny[k] *= inv_dist;
        nz[k] *= inv_dist;
        delta[k] = dl;
        r_star[k] = rs;
        m_star[k] = ms;
        pre_a[k] = pa;
        pre_b[k] = pb;
    }
}
