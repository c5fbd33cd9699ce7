//! Closest point of a triangle to a point (Ericson, *Real-Time Collision Detection*, 5.1.5).

use glam::DVec3;

/// Which part of a triangle `(a, b, c)` the closest point lies on.
///
/// Edges are numbered `0: a→b`, `1: b→c`, `2: c→a`; vertices `0: a`, `1: b`, `2: c`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Feature {
    /// The interior of the face.
    Face,
    /// The interior of an edge.
    Edge(u8),
    /// A corner.
    Vertex(u8),
}

/// A triangle with |(b-a)×(c-a)|² below this times (longest edge)⁴ counts as degenerate and is
/// treated as its three edges: its face normal would be mostly rounding (the cross product has
/// an absolute error of ~1e-16 (longest edge)²).
const DEGENERATE_SIN2: f64 = 1e-18;

/// Closest point [m] of the triangle `(a, b, c)` to `p`, and the feature it lies on.
///
/// Uses Ericson's Voronoi-region method. Edge parameters are computed directly from the
/// edge vector (never from differences that can vanish), and a face point is the projection
/// along the unit normal, so slivers give accurate points. Degenerate triangles (collinear or
/// coincident corners) have no face: the answer is then the closest of the three edges, and
/// never [`Feature::Face`].
pub fn closest_point_on_triangle(p: DVec3, a: DVec3, b: DVec3, c: DVec3) -> (DVec3, Feature) {
    let ab = b - a;
    let ac = c - a;
    let n = ab.cross(ac);
    let lmax2 = ab
        .length_squared()
        .max(ac.length_squared())
        .max((c - b).length_squared());
    if !(n.length_squared() > DEGENERATE_SIN2 * lmax2 * lmax2) {
        return closest_on_edges(p, [a, b, c]);
    }

    let ap = p - a;
    let d1 = ab.dot(ap);
    let d2 = ac.dot(ap);
    if d1 <= 0.0 && d2 <= 0.0 {
        return (a, Feature::Vertex(0));
    }
    let bp = p - b;
    let d3 = ab.dot(bp);
    let d4 = ac.dot(bp);
    if d3 >= 0.0 && d4 <= d3 {
        return (b, Feature::Vertex(1));
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return (on_segment(p, a, b), Feature::Edge(0));
    }
    let cp = p - c;
    let d5 = ab.dot(cp);
    let d6 = ac.dot(cp);
    if d6 >= 0.0 && d5 <= d6 {
        return (c, Feature::Vertex(2));
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return (on_segment(p, c, a), Feature::Edge(2));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 {
        return (on_segment(p, b, c), Feature::Edge(1));
    }
    // Projection along the normal: exact in the plane, unlike barycentrics from va, vb, vc,
    // which lose all accuracy on slivers.
    let nu = n.normalize();
    (p - ap.dot(nu) * nu, Feature::Face)
}

/// Closest point of the segment `[a, b]` to `p` (the parameter clamped to the segment).
#[inline]
fn on_segment(p: DVec3, a: DVec3, b: DVec3) -> DVec3 {
    let ab = b - a;
    let l2 = ab.length_squared();
    if l2 > 0.0 {
        a + ((p - a).dot(ab) / l2).clamp(0.0, 1.0) * ab
    } else {
        a
    }
}

/// Closest point of the three edges of a (degenerate) triangle.
fn closest_on_edges(p: DVec3, v: [DVec3; 3]) -> (DVec3, Feature) {
    let mut best = (v[0], Feature::Vertex(0));
    let mut best_d2 = f64::INFINITY;
    for i in 0..3u8 {
        let (s, e) = (v[i as usize], v[(i as usize + 1) % 3]);
        let q = on_segment(p, s, e);
        let d2 = (q - p).length_squared();
        if d2 < best_d2 {
            best_d2 = d2;
            let f = if q == s {
                Feature::Vertex(i)
            } else if q == e {
                Feature::Vertex((i + 1) % 3)
            } else {
                Feature::Edge(i)
            };
            best = (q, f);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::test_util::Rng;

    /// Minimum distance over a dense barycentric grid of the triangle, and the grid spacing.
    fn brute(p: DVec3, a: DVec3, b: DVec3, c: DVec3, n: usize) -> (f64, f64) {
        let mut best = f64::INFINITY;
        for i in 0..=n {
            for j in 0..=n - i {
                let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
                let q = a + u * (b - a) + v * (c - a);
                best = best.min((q - p).length());
            }
        }
        let h = (b - a).length().max((c - a).length()).max((c - b).length()) / n as f64;
        (best, h)
    }

    #[test]
    fn matches_brute_force() {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        for k in 0..400 {
            let (a, b, c) = (rng.vec(2.0), rng.vec(2.0), rng.vec(2.0));
            // Every fifth triangle a sliver: c almost on the line ab.
            let c = if k % 5 == 0 { a + 0.3 * (b - a) + 1e-7 * c } else { c };
            let p = rng.vec(4.0);
            let (q, f) = closest_point_on_triangle(p, a, b, c);
            let d = (q - p).length();
            let (db, h) = brute(p, a, b, c, 300);
            // The exact minimum is below every sample and within one grid step of the best.
            assert!(d <= db + 1e-12, "case {k}: {d} > brute {db}");
            assert!(d >= db - h, "case {k}: {d} < brute {db} - {h}");
            // The point lies on the triangle: its distance to it (from itself) is zero.
            let (q2, _) = closest_point_on_triangle(q, a, b, c);
            let tol = if k % 5 == 0 { 1e-6 } else { 1e-12 };
            assert!((q2 - q).length() < tol, "case {k}: point off the triangle");
            match f {
                Feature::Vertex(i) => assert_eq!(q, [a, b, c][i as usize]),
                Feature::Edge(i) => {
                    let (s, e) = ([a, b, c][i as usize], [a, b, c][(i as usize + 1) % 3]);
                    let t = (q - s).cross(e - s).length() / (e - s).length_squared();
                    assert!(t < 1e-9, "case {k}: edge point off edge {i}");
                }
                Feature::Face => {
                    let n = (b - a).cross(c - a).normalize();
                    assert!((p - q).cross(n).length() < 1e-9, "case {k}: not a projection");
                }
            }
        }
    }

    #[test]
    fn regions_of_unit_triangle() {
        let (a, b, c) = (DVec3::ZERO, DVec3::X, DVec3::Y);
        let cases = [
            (DVec3::new(0.2, 0.2, 1.0), DVec3::new(0.2, 0.2, 0.0), Feature::Face),
            (DVec3::new(-1.0, -1.0, 0.5), a, Feature::Vertex(0)),
            (DVec3::new(2.0, -0.5, 0.0), b, Feature::Vertex(1)),
            (DVec3::new(-0.1, 3.0, 0.0), c, Feature::Vertex(2)),
            (DVec3::new(0.5, -1.0, 0.0), DVec3::new(0.5, 0.0, 0.0), Feature::Edge(0)),
            (DVec3::new(1.0, 1.0, -2.0), DVec3::new(0.5, 0.5, 0.0), Feature::Edge(1)),
            (DVec3::new(-1.0, 0.25, 0.0), DVec3::new(0.0, 0.25, 0.0), Feature::Edge(2)),
        ];
        for (p, q, f) in cases {
            let (q2, f2) = closest_point_on_triangle(p, a, b, c);
            assert!((q2 - q).length() < 1e-15, "{p}: {q2} != {q}");
            assert_eq!(f2, f, "{p}");
        }
    }

    #[test]
    fn degenerate_triangles() {
        let p = DVec3::new(0.5, 1.0, 0.0);
        // Collinear corners: the closest point of the segment, never a face.
        let (q, f) = closest_point_on_triangle(p, DVec3::ZERO, DVec3::X, 2.0 * DVec3::X);
        assert_eq!(q, DVec3::new(0.5, 0.0, 0.0));
        assert_eq!(f, Feature::Edge(0));
        // All corners equal: that point, as a vertex.
        let (q, f) = closest_point_on_triangle(p, DVec3::X, DVec3::X, DVec3::X);
        assert_eq!(q, DVec3::X);
        assert!(matches!(f, Feature::Vertex(_)));
        // Two corners equal.
        let (q, f) = closest_point_on_triangle(p, DVec3::ZERO, DVec3::ZERO, DVec3::X);
        assert_eq!(q, DVec3::new(0.5, 0.0, 0.0));
        assert!(matches!(f, Feature::Edge(_)));
        assert!(q.is_finite());
    }
}
