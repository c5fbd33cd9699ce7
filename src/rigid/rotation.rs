//! Rotations by quaternions (METHOD.md [37]-[49]).
//!
//! A block's orientation is the unit quaternion Q that turns body-frame vectors into world
//! vectors: q = Q (0, q⁰) Q* [43]-[45], or q = R q⁰ with the rotation matrix R of Q [47][48].
//! A step of angular velocity ω [rad s⁻¹] held for Δt [s] is the rotation by θ = |ω| Δt [rad]
//! about ψ = ω / |ω| [41]:
//!
//!   ΔQ = (cos θ/2, ψ sin θ/2),   Q ← ΔQ Q   (ω in the world frame, so ΔQ multiplies on the left).
//!
//! The inertia tensor follows the body [49]: I_g = R I_g0 Rᵀ with I_g0 = diag(I₁, I₂, I₃) the
//! principal moments [kg m²]. Quaternions are renormalised after every product, so that round-off
//! never accumulates into a scaling of the block.

use crate::math::{Mat3, Quat, Vec3};

/// The rotation of one step, ΔQ = (cos θ/2, ψ sin θ/2), θ = |ω| Δt, ψ = ω/|ω| [41].
/// `omega` [rad s⁻¹] (any frame; the result acts in the same frame), `dt` [s].
///
/// Implements [41].
pub fn step_rotation(omega: Vec3, dt: f64) -> Quat {
    let w = omega.length();
    if w == 0.0 {
        return Quat::IDENTITY;
    }
    let half = 0.5 * w * dt;
    let s = half.sin() / w; // ψ sin θ/2 = ω sin(θ/2) / |ω|
    Quat::from_xyzw(omega.x * s, omega.y * s, omega.z * s, half.cos())
}

/// The orientation after turning for Δt [s] at the world-frame angular velocity ω [rad s⁻¹]:
/// normalise(ΔQ Q) [41][45].
pub fn advance_orientation(q: Quat, omega: Vec3, dt: f64) -> Quat {
    normalise(step_rotation(omega, dt) * q)
}

/// The unit quaternion of q (q / |q|), with the scalar part made non-negative (Q and −Q are the
/// same rotation; a fixed sign keeps checkpoints and outputs comparable).
pub fn normalise(q: Quat) -> Quat {
    let q = q / q.length();
    if q.w < 0.0 {
        -q
    } else {
        q
    }
}

/// The rotation matrix R of the unit quaternion Q = (q₀, q_x, q_y, q_z) [47].
///
/// Implements [47].
pub fn rotation_matrix(q: Quat) -> Mat3 {
    let (q0, qx, qy, qz) = (q.w, q.x, q.y, q.z);
    Mat3::from_cols(
        Vec3::new(
            1.0 - 2.0 * (qy * qy + qz * qz),
            2.0 * (qx * qy + q0 * qz),
            2.0 * (qx * qz - q0 * qy),
        ),
        Vec3::new(
            2.0 * (qx * qy - q0 * qz),
            1.0 - 2.0 * (qx * qx + qz * qz),
            2.0 * (qy * qz + q0 * qx),
        ),
        Vec3::new(
            2.0 * (qx * qz + q0 * qy),
            2.0 * (qy * qz - q0 * qx),
            1.0 - 2.0 * (qx * qx + qy * qy),
        ),
    )
}

/// The vector v turned by the unit quaternion Q as the sandwich product Q (0, v) Q* [43]-[45],
/// written with the multiplication rules [38] (Hamilton product), not through the matrix.
///
/// Implements [38], [43], [44], [45].
pub fn rotate_by_sandwich(q: Quat, v: Vec3) -> Vec3 {
    // (s1, u1)(s2, u2) = (s1 s2 − u1·u2, s1 u2 + s2 u1 + u1 × u2)
    let mul = |s1: f64, u1: Vec3, s2: f64, u2: Vec3| {
        (s1 * s2 - u1.dot(u2), s1 * u2 + s2 * u1 + u1.cross(u2))
    };
    let u = Vec3::new(q.x, q.y, q.z);
    let (s, t) = mul(q.w, u, 0.0, v);
    let (_, r) = mul(s, t, q.w, -u);
    r
}

/// World-frame inertia I_g = R diag(I₁, I₂, I₃) Rᵀ [kg m²] [49].
///
/// Implements [49].
pub fn world_inertia(q: Quat, principal: Vec3) -> Mat3 {
    let r = rotation_matrix(q);
    r * Mat3::from_diagonal(principal) * r.transpose()
}

/// World-frame inverse inertia I_g⁻¹ = R diag(1/I₁, 1/I₂, 1/I₃) Rᵀ [kg⁻¹ m⁻²].
pub fn world_inverse_inertia(q: Quat, principal: Vec3) -> Mat3 {
    let r = rotation_matrix(q);
    r * Mat3::from_diagonal(principal.recip()) * r.transpose()
}

/// Angular velocity ω = I_g⁻¹ L [rad s⁻¹] from the world angular momentum L [kg m² s⁻¹] [35].
pub fn angular_velocity(q: Quat, principal: Vec3, l: Vec3) -> Vec3 {
    let b = q.inverse() * l; // body frame
    q * (b / principal)
}

/// Angular momentum L = I_g ω [kg m² s⁻¹] from the world angular velocity ω [rad s⁻¹].
pub fn angular_momentum(q: Quat, principal: Vec3, omega: Vec3) -> Vec3 {
    q * (principal * (q.inverse() * omega))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn some_rotation() -> Quat {
        normalise(Quat::from_xyzw(0.3, -0.5, 0.2, 0.8))
    }

    #[test]
    fn the_source_matrix_matches_the_sandwich_product_and_glam() {
        let q = some_rotation();
        let v = Vec3::new(0.7, -1.1, 2.3);
        let a = rotation_matrix(q) * v;
        let b = rotate_by_sandwich(q, v);
        let c = q * v;
        assert!((a - b).length() < 1e-15 && (a - c).length() < 1e-15);
        let r = rotation_matrix(q);
        assert!((r * r.transpose() - Mat3::IDENTITY)
            .to_cols_array()
            .iter()
            .all(|x| x.abs() < 1e-15));
    }

    #[test]
    fn a_step_turns_by_omega_dt_about_omega() {
        let w = Vec3::new(0.0, 0.0, 2.0);
        let q = step_rotation(w, 0.25 * std::f64::consts::PI); // θ = π/2 about z
        let x = rotation_matrix(q) * Vec3::X;
        assert!((x - Vec3::Y).length() < 1e-15);
        // The axis is left alone, for any axis.
        let w = Vec3::new(1.0, -2.0, 0.5);
        assert!((step_rotation(w, 0.3) * w - w).length() < 1e-14);
        assert_eq!(step_rotation(Vec3::ZERO, 1.0), Quat::IDENTITY);
    }

    #[test]
    fn inertia_follows_the_body() {
        let q = some_rotation();
        let p = Vec3::new(1.0, 2.0, 3.0);
        let w = Vec3::new(0.4, 0.1, -0.9);
        let l = world_inertia(q, p) * w;
        assert!((angular_momentum(q, p, w) - l).length() < 1e-14);
        assert!((angular_velocity(q, p, l) - w).length() < 1e-14);
        assert!((world_inverse_inertia(q, p) * l - w).length() < 1e-14);
    }

    #[test]
    fn normalise_gives_a_unit_quaternion_with_nonnegative_scalar() {
        let q = normalise(Quat::from_xyzw(1.0, 2.0, 3.0, -4.0));
        assert!((q.length() - 1.0).abs() < 1e-15 && q.w > 0.0);
    }
}
