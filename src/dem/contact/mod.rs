//! Contact forces between two spheres, or a sphere and a wall (METHOD.md [6]-[22]).
//!
//! Conventions: sphere i is the first of the pair, j the second (or the wall, a sphere of infinite
//! radius and mass). The unit normal n points from i to j. The kernel returns the force on i; j
//! receives its opposite. The per-contact history (`hist`) is a world-frame vector whose meaning
//! depends on the law: the tangential spring force s_t [N] for the Voigt laws (METHOD.md [9]),
//! the tangential displacement ξ [m] for Hertz-Mindlin (as LIGGGHTS stores it) and for LAMMPS's
//! Hooke law. Whatever the law, the history of the pair (j, i) is the opposite of that of (i, j).

pub mod damping;
pub mod hertz_mindlin;
pub mod hooke;
pub mod lanes;
pub mod voigt;

#[cfg(test)]
mod local_frame;

use crate::dem::material::{LawKind, PairLaw};
use crate::math::Vec3;

/// The state of the two bodies at a contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pair {
    /// Unit normal from i to j.
    pub n: Vec3,
    /// Overlap δ = r_i + r_j - |x_j - x_i| > 0 [m] (walls: r_i - distance) [6].
    pub delta: f64,
    /// Velocity of i's centre minus j's (for a wall, minus the wall's velocity at the contact) [m s⁻¹].
    pub dv: Vec3,
    /// Angular velocity of i [rad s⁻¹].
    pub w_i: Vec3,
    /// Angular velocity of j [rad s⁻¹] (zero for walls).
    pub w_j: Vec3,
    /// Radius of i [m].
    pub r_i: f64,
    /// Radius of j [m]; `f64::INFINITY` for a wall.
    pub r_j: f64,
    /// Effective radius R* = r_i r_j / (r_i + r_j) [m] (= r_i against a wall).
    pub r_star: f64,
    /// Effective mass m* = m_i m_j / (m_i + m_j) [kg] (= m_i against a wall or a fixed
    /// sphere, which count as infinitely heavy).
    pub m_star: f64,
}

impl Pair {
    /// The pair state from the normal, overlap, relative velocity v_i - v_j, angular velocities
    /// (ω_i, ω_j), radii (r_i, r_j) and masses (m_i, m_j), with `f64::INFINITY` for the radius
    /// of a wall and the mass of a wall or a fixed sphere.
    #[inline]
    pub fn new(
        n: Vec3,
        delta: f64,
        dv: Vec3,
        w: (Vec3, Vec3),
        r: (f64, f64),
        m: (f64, f64),
    ) -> Pair {
        Pair {
            n,
            delta,
            dv,
            w_i: w.0,
            w_j: w.1,
            r_i: r.0,
            r_j: r.1,
            r_star: harmonic(r.0, r.1),
            m_star: harmonic(m.0, m.1),
        }
    }

    /// Effective radius R* [m].
    #[inline]
    pub fn r_star(&self) -> f64 {
        self.r_star
    }

    /// Effective mass m* [kg].
    #[inline]
    pub fn m_star(&self) -> f64 {
        self.m_star
    }

    /// Relative velocity of i's contact point with respect to j's, with lever arms l_i, l_j:
    /// v_r = v_i - v_j + (l_i ω_i + l_j ω_j) × n  ([7], with r = l n on i and -l n on j).
    ///
    /// Implements [7].
    #[inline]
    pub fn contact_velocity(&self, l_i: f64, l_j: f64) -> Vec3 {
        let mut spin = l_i * self.w_i;
        if l_j.is_finite() {
            spin += l_j * self.w_j;
        }
        self.dv + spin.cross(self.n)
    }
}

/// a b / (a + b), with an infinite partner giving the finite one.
#[inline]
fn harmonic(a: f64, b: f64) -> f64 {
    if !b.is_finite() {
        a
    } else if !a.is_finite() {
        b
    } else {
        a * b / (a + b)
    }
}

/// What a contact does to its two bodies.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Reaction {
    /// Force on i [N]; j receives -force.
    pub force: Vec3,
    /// Torque on i [N m].
    pub torque_i: Vec3,
    /// Torque on j [N m].
    pub torque_j: Vec3,
}

/// The force of one contact, dispatching on the pair's law. `hist` is updated in place.
#[inline(always)]
pub fn contact_force(law: &PairLaw, p: &Pair, hist: &mut Vec3, dt: f64) -> Reaction {
    match law.kind {
        LawKind::HertzMindlin => hertz_mindlin::force(law, p, hist, dt),
        LawKind::HertzMindlinCoulomb => hertz_mindlin::coulomb_force(law, p, hist, dt),
        LawKind::HookeHistory => hooke::force(law, p, hist, dt),
        _ => voigt::force(law, p, hist, dt),
    }
}
