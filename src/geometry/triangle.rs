//! Closest point of a triangle to a point (Ericson, *Real-Time Collision Detection*, 5.1.5),
//! and the contacts of a sphere with a set of triangles forming one surface.

use crate::math::Vec3;

use super::SurfaceContact;

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
pub fn closest_point_on_triangle(p: Vec3, a: Vec3, b: Vec3, c: Vec3) -> (Vec3, Feature) {
    let ab = b - a;
    let ac = c - a;
    let n = ab.cross(ac);
    let lmax2 = ab
        .length_squared()
        .max(ac.length_squared())
        .max((c - b).length_squared());
    let area2 = n.length_squared();
    if area2.is_nan() || area2 <= DEGENERATE_SIN2 * lmax2 * lmax2 {
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
fn on_segment(p: Vec3, a: Vec3, b: Vec3) -> Vec3 {
    let ab = b - a;
    let l2 = ab.length_squared();
    if l2 > 0.0 {
        a + ((p - a).dot(ab) / l2).clamp(0.0, 1.0) * ab
    } else {
        a
    }
}

/// Closest point of the three edges of a (degenerate) triangle.
fn closest_on_edges(p: Vec3, v: [Vec3; 3]) -> (Vec3, Feature) {
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

/// Hits held on the stack in [`sphere_triangle_contacts`]; more take a slower path.
const HIT_CAP: usize = 16;

/// One triangle's answer in [`sphere_triangle_contacts`].
#[derive(Clone, Copy, Default)]
struct Hit {
    tri: u32,
    face: bool,
    point: Vec3,
    normal: Vec3,
    overlap: f64,
}

/// `(e_i × (p - v_i))·n` for the three edges `e_i = v_{i+1} - v_i`: |e_i| times the signed
/// distance of `p` from the edge line, positive on the inner side; None if `n` is zero.
#[inline]
fn edge_functions(p: Vec3, [a, b, c]: [Vec3; 3], n: Vec3) -> Option<[f64; 3]> {
    (n != Vec3::ZERO).then(|| [(a, b), (b, c), (c, a)].map(|(v, w)| (w - v).cross(p - v).dot(n)))
}

/// The answer of triangle `id` (corners [m], unit normal along (b-a)×(c-a) or zero) to a
/// sphere, if it touches.
fn hit(id: u32, (t, n): ([Vec3; 3], Vec3), centre: Vec3, radius: f64, tol: f64) -> Option<Hit> {
    let [a, b, c] = t;
    let s = (centre - a).dot(n);
    // Cheap rejections: too far from the plane (never for degenerate triangles: n = 0) or
    // from the bounding box.
    let gap = (a.min(b).min(c) - centre).max(centre - a.max(b).max(c));
    if s.abs() >= radius || gap.max(Vec3::ZERO).length_squared() >= radius * radius {
        return None;
    }
    let side = if s >= 0.0 { -n } else { n };
    // The common case first: the centre straight above the face (no need for Ericson's test).
    let (p, feature) = match edge_functions(centre, t, n) {
        Some(f) if f.iter().all(|&x| x >= 0.0) => (centre - s * n, Feature::Face),
        _ => closest_point_on_triangle(centre, a, b, c),
    };
    // An edge or vertex straight below the centre (within rounding) counts as the face, so
    // that the normal comes from the plane, not from a tiny, noisy offset.
    let above = n != Vec3::ZERO && (centre - s * n - p).length() <= tol;
    let (point, normal, dist, face) = if feature == Feature::Face || above {
        // From the plane equation, as for a plane wall: coplanar triangles agree exactly.
        (centre - s * n, side, s.abs(), true)
    } else {
        let dist = (p - centre).length();
        let normal = if dist > 0.0 {
            (p - centre) / dist
        } else {
            side
        };
        (p, normal, dist, false)
    };
    let overlap = radius - dist;
    (overlap > 0.0 && normal != Vec3::ZERO).then_some(Hit {
        tri: id,
        face,
        point,
        normal,
        overlap,
    })
}

/// Appends to `out` the contacts of a sphere (centre [m], radius [m]) with the triangles `ids`
/// of one surface (two-sided), in the order of `ids`; `triangle(id)` gives the corners
/// `[a, b, c]` [m] of triangle `id` and its unit normal, which must be `(b - a) × (c - a)`
/// normalised (zero if degenerate), as [`TriMesh::normals`](super::TriMesh::normals) holds;
/// `id` becomes the contact's `element`. Allocates nothing.
///
/// Triangles sharing a plane must act exactly as that plane, so per-triangle closest points
/// are merged, keeping only local minima of the distance over the surface: face contacts are
/// kept (once per point); an edge or vertex contact is dropped if its point lies on another
/// triangle (within 1e-9 radius) that gave a face contact or whose own closest point is
/// elsewhere (hence closer), and edge or vertex contacts at the same point are reported once,
/// by the first in `ids`. A convex edge or corner thus gives one contact, a concave crease one
/// per face, and a flat region of any number of triangles one. Containment is tested
/// geometrically, so unmerged vertices and T-junctions behave too. Every triangle containing a
/// contact point must be in `ids`, as it is when `ids` holds all within `radius`.
pub fn sphere_triangle_contacts(
    centre: Vec3,
    radius: f64,
    ids: &[u32],
    triangle: impl Fn(u32) -> ([Vec3; 3], Vec3),
    out: &mut impl Extend<SurfaceContact>,
) {
    let tol = 1e-9 * radius + 1e-14 * centre.abs().max_element();
    let mut buf = [Hit::default(); HIT_CAP];
    let mut n = 0;
    for &id in ids {
        if let Some(h) = hit(id, triangle(id), centre, radius, tol) {
            if n == HIT_CAP {
                // Rare (a sphere much larger than the triangles): recompute instead of storing.
                let get = |i: usize| hit(ids[i], triangle(ids[i]), centre, radius, tol);
                return resolve(ids.len(), get, &triangle, tol, out);
            }
            buf[n] = h;
            n += 1;
        }
    }
    resolve(n, |i| Some(buf[i]), &triangle, tol, out);
}

/// The merging rule of [`sphere_triangle_contacts`] over the hits `get(0..n)`.
fn resolve(
    n: usize,
    get: impl Fn(usize) -> Option<Hit>,
    triangle: &impl Fn(u32) -> ([Vec3; 3], Vec3),
    tol: f64,
    out: &mut impl Extend<SurfaceContact>,
) {
    let same = |p: Vec3, q: Vec3| (p - q).length() <= tol;
    let on_triangle = |p: Vec3, id: u32| {
        let (t @ [a, b, c], n) = triangle(id);
        if (a.min(b).min(c) - p).max(p - a.max(b).max(c)).max_element() > tol {
            return false;
        }
        // Decide from the plane and the edge lines where that is clear-cut, else exactly.
        if let Some(f) = edge_functions(p, t, n) {
            if (p - a).dot(n).abs() > tol {
                return false;
            }
            if f.iter().all(|&x| x >= 0.0) {
                return true;
            }
            let edges = [b - a, c - b, a - c];
            if (0..3).any(|i| f[i] < 0.0 && f[i] * f[i] > tol * tol * edges[i].length_squared()) {
                return false;
            }
        }
        same(closest_point_on_triangle(p, a, b, c).0, p)
    };
    for i in 0..n {
        let Some(h) = get(i) else { continue };
        let dropped = if h.face {
            (0..i)
                .filter_map(&get)
                .any(|g| g.face && same(g.point, h.point))
        } else {
            // Not a local minimum of the distance if another triangle contains the point and
            // its own closest point is elsewhere (closest points on a triangle are unique).
            // Comparing points, not distances, leaves no tolerance gap near a vertex, where
            // distances differ only to second order.
            (0..n).any(|j| {
                get(j).is_some_and(|g| {
                    g.tri != h.tri
                        && (g.face || j < i || !same(g.point, h.point))
                        && on_triangle(h.point, g.tri)
                })
            })
        };
        if !dropped {
            out.extend(Some(SurfaceContact {
                point: h.point,
                normal: h.normal,
                overlap: h.overlap,
                element: h.tri,
            }));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::test_util::Rng;
    use crate::geometry::TriMesh;

    /// Minimum distance over a dense barycentric grid of the triangle, and the grid spacing.
    fn brute(p: Vec3, a: Vec3, b: Vec3, c: Vec3, n: usize) -> (f64, f64) {
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
            let c = if k % 5 == 0 {
                a + 0.3 * (b - a) + 1e-7 * c
            } else {
                c
            };
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
                    assert!(
                        (p - q).cross(n).length() < 1e-9,
                        "case {k}: not a projection"
                    );
                }
            }
        }
    }

    #[test]
    fn regions_of_unit_triangle() {
        let (a, b, c) = (Vec3::ZERO, Vec3::X, Vec3::Y);
        let cases = [
            ([0.2, 0.2, 1.0], [0.2, 0.2, 0.0], Feature::Face),
            ([-1.0, -1.0, 0.5], [0.0; 3], Feature::Vertex(0)),
            ([2.0, -0.5, 0.0], [1.0, 0.0, 0.0], Feature::Vertex(1)),
            ([-0.1, 3.0, 0.0], [0.0, 1.0, 0.0], Feature::Vertex(2)),
            ([0.5, -1.0, 0.0], [0.5, 0.0, 0.0], Feature::Edge(0)),
            ([1.0, 1.0, -2.0], [0.5, 0.5, 0.0], Feature::Edge(1)),
            ([-1.0, 0.25, 0.0], [0.0, 0.25, 0.0], Feature::Edge(2)),
        ];
        for (p, q, f) in cases {
            let (p, q) = (Vec3::from_array(p), Vec3::from_array(q));
            let (q2, f2) = closest_point_on_triangle(p, a, b, c);
            assert!((q2 - q).length() < 1e-15, "{p}: {q2} != {q}");
            assert_eq!(f2, f, "{p}");
        }
    }

    #[test]
    fn degenerate_triangles() {
        let p = Vec3::new(0.5, 1.0, 0.0);
        // Collinear corners: the closest point of the segment, never a face.
        let (q, f) = closest_point_on_triangle(p, Vec3::ZERO, Vec3::X, 2.0 * Vec3::X);
        assert_eq!(q, Vec3::new(0.5, 0.0, 0.0));
        assert_eq!(f, Feature::Edge(0));
        // All corners equal: that point, as a vertex.
        let (q, f) = closest_point_on_triangle(p, Vec3::X, Vec3::X, Vec3::X);
        assert_eq!(q, Vec3::X);
        assert!(matches!(f, Feature::Vertex(_)));
        // Two corners equal.
        let (q, f) = closest_point_on_triangle(p, Vec3::ZERO, Vec3::ZERO, Vec3::X);
        assert_eq!(q, Vec3::new(0.5, 0.0, 0.0));
        assert!(matches!(f, Feature::Edge(_)));
        assert!(q.is_finite());
    }

    fn all(mesh: &TriMesh, c: Vec3, r: f64) -> Vec<SurfaceContact> {
        let cand: Vec<u32> = (0..mesh.triangles().len() as u32).collect();
        let mut v = Vec::new();
        mesh.sphere_contacts(c, r, &cand, &mut v);
        v
    }

    #[test]
    fn convex_ridge_gives_one_contact() {
        // Roof along y with the ridge at x = 0, z = 1 and 45° slopes; rolling over it.
        let (l0, l1) = (Vec3::new(-1.0, 0.0, 0.0), Vec3::new(-1.0, 2.0, 0.0));
        let (t0, t1) = (Vec3::new(0.0, 0.0, 1.0), Vec3::new(0.0, 2.0, 1.0));
        let (r0, r1) = (Vec3::new(1.0, 0.0, 0.0), Vec3::new(1.0, 2.0, 0.0));
        let mesh =
            TriMesh::from_triangle_soup(&[[l0, t0, t1], [l0, t1, l1], [t0, r0, r1], [t0, r1, t1]])
                .unwrap();
        let (r, d) = (0.3, 0.2);
        for k in -160..=160 {
            let th = (k as f64 * 0.5).to_radians();
            let c = t0 + Vec3::new(0.0, 1.0, 0.0) + d * Vec3::new(th.sin(), 0.0, th.cos());
            let v = all(&mesh, c, r);
            assert_eq!(v.len(), 1, "angle {}: {v:?}", k as f64 * 0.5);
            let off = th.abs() - std::f64::consts::FRAC_PI_4;
            let dist = if off <= 0.0 { d } else { d * off.cos() };
            assert!(
                (v[0].overlap - (r - dist)).abs() < 1e-12,
                "angle {}: {v:?}",
                k as f64 * 0.5
            );
        }
    }

    #[test]
    fn concave_crease_gives_two_contacts() {
        let (a0, a1) = (Vec3::new(-1.0, 0.0, 1.0), Vec3::new(-1.0, 2.0, 1.0));
        let (m0, m1) = (Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 2.0, 0.0));
        let (b0, b1) = (Vec3::new(1.0, 0.0, 1.0), Vec3::new(1.0, 2.0, 1.0));
        let mesh =
            TriMesh::from_triangle_soup(&[[a0, m0, m1], [a0, m1, a1], [m0, b0, b1], [m0, b1, m1]])
                .unwrap();
        let v = all(&mesh, Vec3::new(0.0, 1.0, 0.3), 0.3);
        assert_eq!(v.len(), 2, "{v:?}");
        let d = 0.3 / 2f64.sqrt();
        for c in &v {
            assert!((c.overlap - (0.3 - d)).abs() < 1e-12);
        }
        let s = 0.5f64.sqrt();
        assert!((v[0].normal - Vec3::new(-s, 0.0, -s)).length() < 1e-12);
        assert!((v[1].normal - Vec3::new(s, 0.0, -s)).length() < 1e-12);
        assert!(v[0].element < v[1].element);
    }

    /// A fan of `n` triangles around the origin, flat or (tip > 0) a cone.
    fn fan(n: usize, tip: f64) -> TriMesh {
        let p = |i: usize| {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            Vec3::new(a.cos(), a.sin(), 0.0)
        };
        let soup: Vec<_> = (0..n)
            .map(|i| [Vec3::new(0.0, 0.0, tip), p(i), p(i + 1)])
            .collect();
        TriMesh::from_triangle_soup(&soup).unwrap()
    }

    #[test]
    fn shared_vertex_of_many_triangles() {
        // 12 hits fit the stack buffer, 40 take the recomputing path: same answer.
        for n in [12, 40] {
            for c in [Vec3::new(0.0, 0.0, 0.05), Vec3::new(0.03, 0.01, 0.05)] {
                let v = all(&fan(n, 0.0), c, 0.1);
                assert_eq!(v.len(), 1, "{n} triangles: {v:?}");
                assert!(
                    (v[0].overlap - 0.05).abs() < 1e-12 && (v[0].normal + Vec3::Z).length() < 1e-12
                );
            }
            // Convex cone tip: one vertex contact.
            let v = all(&fan(n, 0.5), Vec3::new(0.0, 0.0, 0.55), 0.1);
            assert_eq!(v.len(), 1, "{n}-cone: {v:?}");
            assert_eq!(v[0].point, Vec3::new(0.0, 0.0, 0.5));
            assert_eq!(v[0].element, 0);
        }
    }
}
