//! Links between bodies: tension-only wires between blocks, and breakable bonds between spheres.
//!
//! The source reviews both (METHOD.md §1, item 3): armour blocks joined by wires so that a unit
//! cannot be plucked out alone (Gotoh et al. 2010), and walls of elements joined by breakable
//! "bonds" broken by a bore (Arikawa et al.). Neither law is printed in the source; these are
//! the standard forms, as force functions with explicit history so that the caller owns the
//! state (and checkpoints it).
//!
//! **Wire** between anchor points a and b (world position x [m], velocity v [m s⁻¹]):
//!
//! ```text
//! l = |x_b − x_a|,  n = (x_b − x_a) / l,  l̇ = (v_b − v_a) · n
//! T = max(0, k (l − l₀) + c l̇)   if l > l₀,  else 0        (a wire cannot push)
//! F_a = T n,  F_b = −T n;  the wire breaks, for good, once T ≥ F_break
//! ```
//!
//! with l₀ the slack length [m], k the axial stiffness [N m⁻¹] (E A / l₀ of the rope), c a
//! damping coefficient [N s m⁻¹] and F_break the breaking force [N].
//!
//! **Bond** between spheres i and j, glued at the point between them, in the vector form of the
//! contact law (METHOD.md §2):
//!
//! ```text
//! n = (x_j − x_i)/L,  L = |x_j − x_i|,  F_n = k_n (L − L₀) + c_n L̇           (tension > 0)
//! u = (v_j + ω_j × (−r_j n)) − (v_i + ω_i × (r_i n)),  u_t = u − (u·n) n
//! s ← |s| · (s − (s·n) n)/|s − (s·n) n|  (kept in the current tangent plane), s += k_s u_t Δt
//! F_i = F_n n + s + c_s u_t,  F_j = −F_i,  T_i = r_i n × F_i^t,  T_j = r_j n × F_i^t
//! broken, for good, once F_n > tensile strength or |s| > shear strength
//! ```
//!
//! with L₀ the length when bonded [m], k_n, k_s normal and shear stiffness [N m⁻¹], c_n, c_s
//! dashpots [N s m⁻¹], s the shear spring force [N] (the bond's history), strengths in [N]. The
//! bond resists tension and compression; bending is carried through the shear springs at the
//! glued point, so a single file of bonded spheres still hinges: build beams two or more
//! spheres deep.

use serde::{Deserialize, Serialize};

use crate::math::Vec3;

use super::blocks::RigidState;

/// A tension-only wire (rope, chain, cable) between two anchor points.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Wire {
    /// Length l₀ at which the wire becomes taut [m].
    pub slack_length: f64,
    /// Axial stiffness k, E A / l₀ of the rope [N m⁻¹].
    pub stiffness: f64,
    /// Damping coefficient c of the stretching [N s m⁻¹].
    pub damping: f64,
    /// Breaking force F_break [N].
    pub breaking_force: f64,
}

/// Where a link end is and how it moves.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Anchor {
    /// World position [m].
    pub position: Vec3,
    /// World velocity [m s⁻¹].
    pub velocity: Vec3,
}

impl Anchor {
    /// A fixed point [m].
    pub fn fixed(position: Vec3) -> Anchor {
        Anchor {
            position,
            velocity: Vec3::ZERO,
        }
    }

    /// The point of a block at body-frame offset `p` [m] from its centre, in state `s`:
    /// x = x_g + R p, v = v_g + ω × R p.
    pub fn on_block(s: &RigidState, p: Vec3) -> Anchor {
        let q = s.orientation * p;
        Anchor {
            position: s.centre + q,
            velocity: s.velocity + s.angular_velocity.cross(q),
        }
    }
}

/// The pull of a wire on its first end [N] (the second gets the opposite), and whether it broke
/// now. A broken wire (`*broken` true) pulls nothing and never mends.
pub fn wire_force(w: &Wire, a: &Anchor, b: &Anchor, broken: &mut bool) -> Vec3 {
    if *broken {
        return Vec3::ZERO;
    }
    let d = b.position - a.position;
    let l = d.length();
    if l <= w.slack_length || l == 0.0 {
        return Vec3::ZERO;
    }
    let n = d / l;
    let l_dot = (b.velocity - a.velocity).dot(n);
    let tension = (w.stiffness * (l - w.slack_length) + w.damping * l_dot).max(0.0);
    if tension >= w.breaking_force {
        *broken = true;
        return Vec3::ZERO;
    }
    tension * n
}

/// A breakable bond between two spheres.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Bond {
    /// Normal stiffness k_n [N m⁻¹].
    pub normal_stiffness: f64,
    /// Shear stiffness k_s [N m⁻¹].
    pub shear_stiffness: f64,
    /// Normal dashpot c_n [N s m⁻¹].
    pub normal_damping: f64,
    /// Shear dashpot c_s [N s m⁻¹].
    pub shear_damping: f64,
    /// Largest tensile normal force before breaking [N].
    pub tensile_strength: f64,
    /// Largest shear spring force before breaking [N].
    pub shear_strength: f64,
}

/// The state of one bond: its history.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct BondState {
    /// Length L₀ when bonded [m].
    pub rest_length: f64,
    /// Shear spring force s, world frame, on the first sphere [N].
    pub shear: Vec3,
    /// True once broken.
    pub broken: bool,
}

/// The two spheres of a bond: centres [m], velocities [m s⁻¹], angular velocities [rad s⁻¹],
/// radii [m].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BondPair {
    /// Centres x_i, x_j.
    pub position: [Vec3; 2],
    /// Velocities v_i, v_j.
    pub velocity: [Vec3; 2],
    /// Angular velocities ω_i, ω_j.
    pub angular_velocity: [Vec3; 2],
    /// Radii r_i, r_j.
    pub radius: [f64; 2],
}

/// Force and torques of a bond.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BondReaction {
    /// Force on sphere i [N]; sphere j gets the opposite.
    pub force_i: Vec3,
    /// Torque on sphere i [N m].
    pub torque_i: Vec3,
    /// Torque on sphere j [N m].
    pub torque_j: Vec3,
}

/// Advances the bond over Δt [s] and returns its reaction (module doc). A broken bond returns
/// nothing; the spheres then only touch through the ordinary contact law.
pub fn bond_force(law: &Bond, state: &mut BondState, p: &BondPair, dt: f64) -> BondReaction {
    if state.broken {
        return BondReaction::default();
    }
    let d = p.position[1] - p.position[0];
    let l = d.length();
    let n = d / l;
    let [ri, rj] = p.radius;
    let u = (p.velocity[1] + p.angular_velocity[1].cross(-rj * n))
        - (p.velocity[0] + p.angular_velocity[0].cross(ri * n));
    let u_n = u.dot(n);
    let u_t = u - u_n * n;
    let f_n = law.normal_stiffness * (l - state.rest_length) + law.normal_damping * u_n;

    // The shear spring turns with the pair: keep its length, drop its normal part.
    let s = state.shear;
    let s_t = s - s.dot(n) * n;
    let s_t = if s_t.length_squared() > 0.0 {
        s_t * (s.length() / s_t.length())
    } else {
        s_t
    };
    state.shear = s_t + law.shear_stiffness * dt * u_t;

    if f_n > law.tensile_strength || state.shear.length() > law.shear_strength {
        state.broken = true;
        state.shear = Vec3::ZERO;
        return BondReaction::default();
    }
    let f_t = state.shear + law.shear_damping * u_t;
    BondReaction {
        force_i: f_n * n + f_t,
        torque_i: (ri * n).cross(f_t),
        torque_j: (rj * n).cross(f_t),
    }
}
