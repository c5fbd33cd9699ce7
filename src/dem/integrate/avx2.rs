//! `close_and_open` four spheres at a time, with AVX2.
//!
//! The columns hold x y z of each sphere one after the other, so four spheres are twelve
//! numbers, three registers of four: [x₀ y₀ z₀ x₁] [y₁ z₁ x₂ y₂] [z₂ x₃ y₃ z₃]. A vector
//! operation such as v + (Δt/2)/m F runs register by register, with the per-sphere factor
//! spread to the same layout (`spread`) and the per-axis constants laid out alike (`pattern`);
//! a per-sphere sum such as |v|² gathers the three terms of each sphere into one lane per
//! sphere (`sums`). Every number goes through the operations of `close_and_open_one`, in its
//! order, so the bits are the same (there is no fused multiply-add here). The stability check
//! reads per-sphere flags off the lanes; the rare outflow is counted one sphere at a time.
//!
//! One sphere at a time, the loop waited on chains of some 40 dependent operations with only
//! two or three spheres in flight: B2 on 1 thread spent 0.42 s in the closing pass (14 ns a
//! sphere; not memory: doing it twice on a chunk in cache took twice as long), 0.22 s now.

use std::arch::x86_64::*;

use super::{close_and_open_one, Inertia, Motion, Opener, Opening};
use crate::math::{is_finite, Vec3};

// The loads and stores take a sphere as three f64 in a row.
const _: () = assert!(std::mem::size_of::<Vec3>() == 3 * std::mem::size_of::<f64>());

/// A per-axis vector laid out as the three registers of four spheres.
#[inline(always)]
unsafe fn pattern(a: Vec3) -> [__m256d; 3] {
    [
        _mm256_setr_pd(a.x, a.y, a.z, a.x),
        _mm256_setr_pd(a.y, a.z, a.x, a.y),
        _mm256_setr_pd(a.z, a.x, a.y, a.z),
    ]
}

/// `a`, but opaque to the compiler. A blend of a value with the number just loaded from where
/// the result is stored would otherwise become a masked store, which AMD Zen processors run in
/// microcode (B2, 1 thread: twice as long for this loop).
///
/// The `ymm` register class needs AVX where the `asm!` is written, not only in the caller:
/// without it a build that does not target this processor (`RUSTFLAGS=""`, or riprap as a
/// dependency of another crate) does not compile. `#[inline]` still inlines it into
/// `close_and_open`, whose AVX2 includes AVX.
///
/// # Safety
/// The processor must have AVX.
#[inline]
#[target_feature(enable = "avx")]
unsafe fn opaque(mut a: __m256d) -> __m256d {
    std::arch::asm!("/* {0} */", inout(ymm_reg) a, options(pure, nomem, nostack, preserves_flags));
    a
}

/// Register c of per-sphere values [s₀ s₁ s₂ s₃] spread to the layout: [s₀ s₀ s₀ s₁],
/// [s₁ s₁ s₂ s₂] or [s₂ s₃ s₃ s₃].
#[inline(always)]
unsafe fn spread(s: __m256d, c: usize) -> __m256d {
    match c {
        0 => _mm256_permute4x64_pd::<0b01_00_00_00>(s),
        1 => _mm256_permute4x64_pd::<0b10_10_01_01>(s),
        _ => _mm256_permute4x64_pd::<0b11_11_11_10>(s),
    }
}

/// The per-sphere sums (a_x + a_y) + a_z of the layout `a` (as `Vec3::length_squared` adds
/// the squares), one sphere per lane.
#[inline(always)]
unsafe fn sums(a: [__m256d; 3]) -> __m256d {
    let [a0, a1, a2] = a;
    // x: numbers 0, 3, 6, 9; y: 1, 4, 7, 10; z: 2, 5, 8, 11.
    let x = _mm256_blend_pd::<0b0010>(_mm256_blend_pd::<0b0100>(a0, a1), a2);
    let x = _mm256_permute4x64_pd::<0b01_10_11_00>(x);
    let y = _mm256_blend_pd::<0b0100>(_mm256_blend_pd::<0b1001>(a0, a1), a2);
    let y = _mm256_permute4x64_pd::<0b10_11_00_01>(y);
    let z = _mm256_blend_pd::<0b1001>(_mm256_blend_pd::<0b0010>(a0, a1), a2);
    let z = _mm256_permute4x64_pd::<0b11_00_01_10>(z);
    _mm256_add_pd(_mm256_add_pd(x, y), z)
}

/// `close_and_open`, four spheres at a time (the last few one at a time).
///
/// # Safety
/// The processor must have AVX2.
#[target_feature(enable = "avx2")]
pub(super) unsafe fn close_and_open(
    op: &Opener,
    max_speed2: f64,
    first: usize,
    Motion { x, v, w, f, t }: Motion,
    Inertia {
        mass,
        inertia,
        fixed,
    }: Inertia,
) -> (Option<usize>, Opening) {
    let n = x.len();
    let (v, w, f, t) = (&mut v[..n], &mut w[..n], &mut f[..n], &mut t[..n]);
    let (mass, inertia, fixed) = (&mass[..n], &inertia[..n], &fixed[..n]);
    let zero = _mm256_setzero_pd();
    let h = _mm256_set1_pd(0.5 * op.dt);
    let dt = _mm256_set1_pd(op.dt);
    let max2 = _mm256_set1_pd(max_speed2);
    let (wrap_lo, wrap_hi, period) = op.images.wrap_box();
    let (wrap_lo, wrap_hi) = (pattern(wrap_lo), pattern(wrap_hi));
    let (period, minus_period) = (pattern(period), pattern(-period));
    let (lo, hi) = op.images.open_box();
    let (lo, hi) = (pattern(lo), pattern(hi));
    let gravity = pattern(op.gravity);
    let mut bad = None;
    let mut outside = 0;
    let mut max_drift = zero;
    let groups = n / 4;
    for q in 0..groups {
        let k = 4 * q;
        // SAFETY (the loads and stores below): spheres k..k + 4 <= n of columns of length n,
        // each sphere three f64 in a row (`Vec3` is `repr(C)` of three f64); register c of
        // the four is the numbers 4c..4c + 4 from the first.
        let at = |col: &[Vec3], c: usize| col.as_ptr().add(k).cast::<f64>().add(4 * c);
        let at_mut = |col: &mut [Vec3], c: usize| col.as_mut_ptr().add(k).cast::<f64>().add(4 * c);
        let get = |col: &[Vec3], c: usize| _mm256_loadu_pd(at(col, c));
        let m = _mm256_loadu_pd(mass.as_ptr().add(k));
        let i = _mm256_loadu_pd(inertia.as_ptr().add(k));
        let held = |s: usize| -i64::from(fixed[k + s]);
        let held = _mm256_castsi256_pd(_mm256_setr_epi64x(held(0), held(1), held(2), held(3)));
        let (rate_v, rate_w) = (_mm256_div_pd(h, m), _mm256_div_pd(h, i));
        // Per register c of the four spheres: the closing half kick, then the next step's
        // opening: half kick, drift, wrap, F = m g, T = 0 (a fixed sphere keeps x, v and ω,
        // and gets F = 0). On the way, what the checks need: x - x + ω - ω (0 when both are
        // finite), v² and the drift squared after each kick, and whether x is in the box.
        let mut infinite = 0;
        let mut v_sq = [zero; 3];
        let mut drift_sq = [zero; 3];
        let mut inside = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
        for c in 0..3 {
            let (fx, rv, rw) = (spread(held, c), spread(rate_v, c), spread(rate_w, c));
            let (x0, v0, w0) = (opaque(get(x, c)), opaque(get(v, c)), opaque(get(w, c)));
            let (f0, t0) = (get(f, c), get(t, c));
            let v1 = _mm256_blendv_pd(_mm256_add_pd(v0, _mm256_mul_pd(rv, f0)), v0, fx);
            let w1 = _mm256_blendv_pd(_mm256_add_pd(w0, _mm256_mul_pd(rw, t0)), w0, fx);
            let z = _mm256_add_pd(_mm256_sub_pd(x0, x0), _mm256_sub_pd(w1, w1));
            infinite |= _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_NEQ_UQ>(z, zero)) << (4 * c);
            v_sq[c] = _mm256_mul_pd(v1, v1);
            let v2 = _mm256_add_pd(v1, _mm256_mul_pd(rv, f0));
            let w2 = _mm256_add_pd(w1, _mm256_mul_pd(rw, t0));
            let drift = _mm256_mul_pd(dt, v2);
            drift_sq[c] = _mm256_mul_pd(drift, drift);
            let p = _mm256_add_pd(x0, drift);
            let below = _mm256_cmp_pd::<_CMP_LT_OQ>(p, wrap_lo[c]);
            let above = _mm256_cmp_pd::<_CMP_GE_OQ>(p, wrap_hi[c]);
            let shift = _mm256_blendv_pd(zero, period[c], above);
            let shift = _mm256_blendv_pd(shift, minus_period[c], below);
            let x2 = _mm256_blendv_pd(_mm256_sub_pd(p, shift), x0, fx);
            let g = _mm256_mul_pd(spread(m, c), gravity[c]);
            _mm256_storeu_pd(at_mut(x, c), x2);
            _mm256_storeu_pd(at_mut(v, c), _mm256_blendv_pd(v2, v0, fx));
            _mm256_storeu_pd(at_mut(w, c), _mm256_blendv_pd(w2, w0, fx));
            _mm256_storeu_pd(at_mut(f, c), _mm256_blendv_pd(g, zero, fx));
            _mm256_storeu_pd(at_mut(t, c), zero);
            let ge = _mm256_cmp_pd::<_CMP_GE_OQ>(x2, lo[c]);
            let le = _mm256_cmp_pd::<_CMP_LE_OQ>(x2, hi[c]);
            inside = _mm256_and_pd(inside, _mm256_and_pd(ge, le));
        }
        // The check after the closing kick: the lowest of the four with a number of x or ω
        // not finite (bits 3s..3s + 3 of `infinite`) or |v|² above max².
        if bad.is_none() {
            let slow = !_mm256_movemask_pd(_mm256_cmp_pd::<_CMP_LE_OQ>(sums(v_sq), max2));
            bad = (0..4)
                .find(|&s| (infinite >> (3 * s)) & 0b111 != 0 || (slow >> s) & 1 != 0)
                .map(|s| first + k + s);
        }
        // The largest drift of a free sphere: max(d², m) is d² where d² > m, else m, so a NaN
        // d² leaves m, as in `Opener::open_at`.
        let d2 = _mm256_blendv_pd(sums(drift_sq), zero, held);
        max_drift = _mm256_max_pd(d2, max_drift);
        // Outflow: only when some sphere is outside along an open axis, one at a time.
        if _mm256_movemask_pd(inside) != 0b1111 {
            outside += (k..k + 4)
                .filter(|&j| {
                    !op.images.contains(x[j])
                        && is_finite(x[j])
                        && v[j].length_squared() <= op.max_speed2
                })
                .count();
        }
    }
    let mut drifts = [0.0; 4];
    _mm256_storeu_pd(drifts.as_mut_ptr(), max_drift);
    let mut o = Opening {
        max_drift: drifts.into_iter().fold(0.0, f64::max),
        outside,
    };
    let k = 4 * groups;
    let (bad_rest, rest) = close_and_open_one(
        op,
        max_speed2,
        first + k,
        Motion {
            x: &mut x[k..],
            v: &mut v[k..],
            w: &mut w[k..],
            f: &mut f[k..],
            t: &mut t[k..],
        },
        Inertia {
            mass: &mass[k..],
            inertia: &inertia[k..],
            fixed: &fixed[k..],
        },
    );
    o = Opening::merge(o, rest);
    (bad.or(bad_rest), o)
}
