//! The geometry of a plane surface in a cell (PLIC: piecewise-linear interface calculation),
//! for [`super::interface`]: how much of a cell lies behind a plane, where the plane lies for
//! a given water fraction, and how much water a split sweep moves through a face.
//!
//! In a cell's own coordinates ξ ∈ [0, 1]³ (index space, so that a cell is a unit cube
//! whatever its Δx, Δy, Δz) the water is the region m · ξ ≤ a, the normal m pointing into
//! the air. Its volume, for m ≥ 0 (reflect the axes whose m is negative), by inclusion and
//! exclusion of the cube's corners (Scardovelli & Zaleski 2000):
//!
//! ```text
//! V(m, a) = [ a³ − Σ_i (a − m_i)₊³ + Σ_i (a − s + m_i)₊³ − (a − s)₊³ ] / (6 m₁ m₂ m₃),   s = Σ m_i
//! ```
//!
//! evaluated for a ≤ s/2 and by V(m, a) = 1 − V(m, s − a) above (the cancellation is smaller
//! near the corner it starts from). A normal with a component below 1e-7 of the others' sum
//! is treated as parallel to that axis (the area of a line in the square, or a depth), which
//! errs by less than that fraction.
//!
//! The normal is Youngs' (1982): −∇α from the 27 cells around the cell, each difference along
//! an axis weighted (1, 2, 1) ⊗ (1, 2, 1) across it.

/// Below this fraction of the normal's sum a component counts as zero [-].
const FLAT: f64 = 1e-7;

/// The area of {m₁ ξ + m₂ η ≤ a} in the unit square [-], m₁, m₂ ≥ 0.
fn area(m1: f64, m2: f64, a: f64) -> f64 {
    let s = m1 + m2;
    if s <= 0.0 {
        return if a >= 0.0 { 1.0 } else { 0.0 };
    }
    let (m1, m2, a) = (m1 / s, m2 / s, a / s);
    if a <= 0.0 {
        return 0.0;
    }
    if a >= 1.0 {
        return 1.0;
    }
    let (lo, hi) = if m1 < m2 { (m1, m2) } else { (m2, m1) };
    if lo < FLAT {
        return a;
    }
    if a < lo {
        a * a / (2.0 * m1 * m2)
    } else if a <= hi {
        (a - 0.5 * lo) / hi
    } else {
        1.0 - (1.0 - a) * (1.0 - a) / (2.0 * m1 * m2)
    }
}

/// The volume of {m · ξ ≤ a} in the unit cube [-], m ≥ 0 (module docs).
pub fn volume(m: [f64; 3], a: f64) -> f64 {
    let s = m[0] + m[1] + m[2];
    if s <= 0.0 {
        return if a >= 0.0 { 1.0 } else { 0.0 };
    }
    let mut n = m.map(|x| x / s);
    let a = a / s;
    if a <= 0.0 {
        return 0.0;
    }
    if a >= 1.0 {
        return 1.0;
    }
    n.sort_by(|x, y| x.total_cmp(y));
    if n[0] < FLAT {
        return area(n[1], n[2], a);
    }
    let corner = |a: f64| {
        let c = |x: f64| if x > 0.0 { x * x * x } else { 0.0 };
        let mut v = c(a);
        for &mi in &n {
            v += c(a - 1.0 + mi) - c(a - mi);
        }
        (v - c(a - 1.0)) / (6.0 * n[0] * n[1] * n[2])
    };
    if a <= 0.5 {
        corner(a)
    } else {
        1.0 - corner(1.0 - a)
    }
}

/// The plane constant a with [`volume`]`(m, a) = f` [-], m ≥ 0 not all zero, f ∈ [0, 1]: by
/// bisection (V grows monotonically with a, from 0 at a = 0 to 1 at a = Σ m).
pub fn plane(m: [f64; 3], f: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, m[0] + m[1] + m[2]);
    for _ in 0..64 {
        let mid = 0.5 * (lo + hi);
        if volume(m, mid) < f {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The water [cell volumes] in the slab [x0, x0 + w] along `axis` of a cell holding `f` of
/// water behind the plane of normal `m` (any signs; pointing into the air): the flux of a split
/// sweep through the face the slab touches, w being the face's Courant number.
pub fn slab(m: [f64; 3], f: f64, axis: usize, x0: f64, w: f64) -> f64 {
    let abs = m.map(f64::abs);
    if abs == [0.0; 3] {
        return f * w;
    }
    let a = plane(abs, f);
    // Reflected along the axis if its component is negative, so that m ≥ 0; reflections
    // across it leave the slab whole.
    let x0 = if m[axis] < 0.0 { 1.0 - x0 - w } else { x0 };
    let mut scaled = abs;
    scaled[axis] *= w;
    w * volume(scaled, a - abs[axis] * x0)
}

/// Youngs' normal −∇α [-] (index space) of the cell at storage index `c`, from `alpha` with
/// filled ghosts and the storage `strides` of x, y, z. Components along axes whose neighbours
/// are ghost copies of the cell come out zero.
pub fn youngs_normal(alpha: &[f64], c: usize, strides: [usize; 3]) -> [f64; 3] {
    let w = [1.0, 2.0, 1.0];
    std::array::from_fn(|d| {
        let (b1, b2) = ((d + 1) % 3, (d + 2) % 3);
        let mut g = 0.0;
        for (i, wi) in w.iter().enumerate() {
            for (j, wj) in w.iter().enumerate() {
                let q = (c + i * strides[b1] + j * strides[b2]) - strides[b1] - strides[b2];
                g += wi * wj * (alpha[q + strides[d]] - alpha[q - strides[d]]);
            }
        }
        -g
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The volume against counting points of a fine lattice, for planes in general position,
    /// parallel to one axis and to two; the plane constant inverts the volume.
    #[test]
    fn the_volume_behind_a_plane_is_the_counted_one_and_inverts() {
        let n = 60;
        let count = |m: [f64; 3], a: f64| {
            let mut inside = 0;
            for i in 0..n {
                for j in 0..n {
                    for k in 0..n {
                        let x = [i, j, k].map(|q| (q as f64 + 0.5) / n as f64);
                        if m[0] * x[0] + m[1] * x[1] + m[2] * x[2] <= a {
                            inside += 1;
                        }
                    }
                }
            }
            inside as f64 / (n * n * n) as f64
        };
        for m in [
            [0.2, 0.3, 0.5],
            [0.7, 0.1, 0.2],
            [0.0, 0.4, 0.6],
            [0.0, 0.0, 1.0],
            [1.0, 1.0, 1.0],
        ] {
            for a in [0.05, 0.2, 0.4, 0.5, 0.63, 0.9] {
                let a = a * (m[0] + m[1] + m[2]);
                let v = volume(m, a);
                // The lattice resolves a plane to about 1/n of a cell.
                assert!((v - count(m, a)).abs() < 2.0 / n as f64, "{m:?} {a}: {v}");
                assert!((volume(m, plane(m, v)) - v).abs() < 1e-12, "{m:?} {a}");
            }
        }
    }

    /// A level surface at 0.3 of the cell: a slab along x holds 0.3 of its width; a vertical
    /// one with water below x = 0.3: the slab at the high face is dry, at the low face full;
    /// the same surface seen from the other side (normal reversed, water above x = 0.7).
    #[test]
    fn slabs_of_level_and_upright_surfaces() {
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
        assert!(close(slab([0.0, 0.0, 1.0], 0.3, 0, 0.8, 0.2), 0.06));
        assert!(close(slab([1.0, 0.0, 0.0], 0.3, 0, 0.8, 0.2), 0.0));
        assert!(close(slab([1.0, 0.0, 0.0], 0.3, 0, 0.0, 0.2), 0.2));
        assert!(close(slab([-1.0, 0.0, 0.0], 0.3, 0, 0.8, 0.2), 0.2));
        assert!(close(slab([0.0, 0.0, 1.0], 0.3, 2, 0.8, 0.2), 0.0));
        assert!(close(slab([0.0, 0.0, 1.0], 0.3, 2, 0.0, 0.2), 0.2));
        // A slab the whole cell wide holds the cell's water.
        assert!(close(slab([0.3, -0.5, 0.8], 0.37, 1, 0.0, 1.0), 0.37));
    }
}
