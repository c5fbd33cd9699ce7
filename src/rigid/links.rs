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
//! **Bond** between spheres i and j: a parallel bond (Potyondy & Cundall 2004, "A bonded-particle
//! model for rock", Int. J. Rock Mech. Min. Sci. 41, 1329-1364), a short elastic cylinder
//! glued at the bond point c between the spheres, in the incremental vector form of the contact
//! law (METHOD.md §2). With x, v, ω, r the spheres' centres, velocities, angular velocities and
//! radii:
//!
//! ```text
//! l = |x_j − x_i|,  n = (x_j − x_i)/l,  g = l − r_i − r_j          (gap > 0, overlap < 0)
//! a_i = r_i + g/2,  a_j = r_j + g/2,  c = x_i + a_i n             (c midway across the gap)
//! u = (v_j + ω_j × (−a_j n)) − (v_i + ω_i × (a_i n)),  u_n = u·n,  u_t = u − u_n n
//! w = ω_j − ω_i,  w_n = (w·n) n,  w_t = w − w_n                   (relative rotation rate)
//!
//! history turned with the pair (s, M_b ⊥ n; the twist M_τ is a scalar about n):
//!   tilt:  s ← |s| (s − (s·n) n)/|s − (s·n) n|,  same for M_b
//!   spin:  s, M_b turned about n by φ = ½ (ω_i + ω_j)·n Δt
//! increments over the step (Δθ = w Δt, the relative rotation of j to i):
//!   s   += k_s u_t Δt                                             shear force [N]
//!   M_b += k_b w_t Δt                                             bending moment [N m]
//!   M_τ += k_τ (w·n) Δt                                           twisting moment [N m]
//! broken, for good, once k_n (l − L₀) > tensile strength, |s| > shear strength or
//! |M_b| > bending strength (spring parts only)
//!
//! F_n = k_n (l − L₀) + c_n u_n                                    (tension > 0)
//! F_t = s + c_s u_t,   M = M_b + M_τ n + c_b w_t + c_τ w_n
//! F_i = F_n n + F_t,   F_j = −F_i
//! T_i = a_i n × F_t + M,   T_j = a_j n × F_t − M
//! ```
//!
//! with L₀ the length when bonded [m]; k_n, k_s normal and shear stiffness [N m⁻¹]; k_b, k_τ
//! bending and twisting stiffness [N m rad⁻¹]; c_n, c_s dashpots [N s m⁻¹]; c_b, c_τ rotational
//! dashpots [N m s rad⁻¹]; s, M_b, M_τ the bond's history, all acting on sphere i (j gets the
//! opposite); strengths in [N] and [N m], one per mode (simpler than Potyondy and Cundall's
//! largest tensile and shear stresses on the cylinder's section).
//!
//! Signs: a relative rotation of j drags i along (+M) and holds j back (−M), so the moment
//! restores. Both spheres' forces act at the one point c (a_i + a_j = l), so the bond's forces
//! and torques sum to zero force and zero moment about any point: it conserves the pair's
//! momentum and angular momentum. The spin turn is the part of a rigid rotation of the pair
//! that the tilt projection misses (rotation about n); together they turn the history with the
//! pair to first order in the angle turned per step.
//!
//! **A bonded chain as a beam.** `Bond::beam` makes each bond the exact Timoshenko beam element
//! of a cylinder of radius R̄ and length L = L₀ between the two centres (A = π R̄², I = π R̄⁴/4,
//! J = 2 I, shear coefficient κ): k_n = E A/L, k_b = E I/L, k_τ = G J/L and
//! 1/k_s = L³/(12 E I) + L/(κ G A). For equal spheres (a_i = a_j = L/2) the bond's response to
//! the end displacements and rotations of the element is then that of the element: the relative
//! rotation Δθ meets E I/L, and the turn of the chord against the mean end rotation,
//! γ = Δw − (L/2)(θ_i + θ_j), meets the series compliance of the element's bending with its end
//! rotations held (L³/(12 E I), which k_b does not see) and of its shear. A straight file of
//! spheres spaced L is therefore the standard beam finite-element model, exact at the spheres
//! under loads applied to them: a Timoshenko beam of rigidities E I and κ G A, an
//! Euler-Bernoulli one as G → ∞ (`tests/rigid_beam.rs`).

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

/// A breakable parallel bond between two spheres (module doc).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Bond {
    /// Normal stiffness k_n [N m⁻¹].
    pub normal_stiffness: f64,
    /// Shear stiffness k_s [N m⁻¹].
    pub shear_stiffness: f64,
    /// Bending stiffness k_b [N m rad⁻¹].
    pub bending_stiffness: f64,
    /// Twisting stiffness k_τ [N m rad⁻¹].
    pub twisting_stiffness: f64,
    /// Normal dashpot c_n [N s m⁻¹].
    pub normal_damping: f64,
    /// Shear dashpot c_s [N s m⁻¹].
    pub shear_damping: f64,
    /// Bending dashpot c_b [N m s rad⁻¹].
    pub bending_damping: f64,
    /// Twisting dashpot c_τ [N m s rad⁻¹].
    pub twisting_damping: f64,
    /// Largest tensile normal spring force before breaking [N].
    pub tensile_strength: f64,
    /// Largest shear spring force |s| before breaking [N].
    pub shear_strength: f64,
    /// Largest bending spring moment |M_b| before breaking [N m] (`f64::INFINITY`: never).
    pub bending_strength: f64,
}

/// Shear coefficient κ of the bond cylinder's solid circular section [–] (`Bond::beam`).
pub const SHEAR_COEFFICIENT: f64 = 0.9;

impl Bond {
    /// The springs that make the bond the Timoshenko beam element of an elastic cylinder of
    /// radius R̄ = `bond_radius` [m] and length L = `length` [m] (the spacing of the spheres it
    /// joins), of Young's modulus E = `young_modulus` [Pa] and shear modulus
    /// G = `shear_modulus` [Pa] (module doc):
    ///
    /// ```text
    /// A = π R̄²,  I = π R̄⁴/4,  J = 2 I,  κ = 0.9
    /// k_n = E A/L,  k_b = E I/L,  k_τ = G J/L,  1/k_s = L³/(12 E I) + L/(κ G A)
    /// ```
    ///
    /// κ = `SHEAR_COEFFICIENT` is the shear coefficient of a solid circular section (Cowper
    /// 1966: 6(1 + ν)/(7 + 6ν), 0.86 to 0.90 for ν = 0 to 0.5). Why k_s is not
    /// simply the cylinder's shear stiffness G A/L: the joint's bending spring sees only the
    /// relative rotation of the spheres, and a beam segment whose chord turns against its end
    /// rotations also bends (stiffness 12 E I/L³); leaving that out makes a chain of N bonds
    /// too stiff by 1/(4N²) under an end load (its deflection becomes the trapezoidal sum of
    /// the joint rotations). With both compliances in series the chain is exact at the spheres.
    ///
    /// No damping, and unbreakable (infinite strengths); see `with_damping_ratio` and
    /// `with_strengths`. A zero modulus gives zero springs.
    ///
    /// ```
    /// use riprap::rigid::links::Bond;
    /// let b = Bond::beam(1.0e8, 4.0e7, 0.005, 0.01);
    /// let i = std::f64::consts::PI * 0.005f64.powi(4) / 4.0;
    /// assert!((b.bending_stiffness - 1.0e8 * i / 0.01).abs() < 1e-12);
    /// assert!((b.twisting_stiffness - 4.0e7 * 2.0 * i / 0.01).abs() < 1e-12);
    /// // Without shear (G → ∞), the Euler-Bernoulli element: k_s = 12 E I/L³.
    /// let eb = Bond::beam(1.0e8, f64::INFINITY, 0.005, 0.01);
    /// assert!((eb.shear_stiffness * 0.01f64.powi(3) / (12.0 * 1.0e8 * i) - 1.0).abs() < 1e-12);
    /// ```
    pub fn beam(young_modulus: f64, shear_modulus: f64, bond_radius: f64, length: f64) -> Bond {
        let (e, g, l) = (young_modulus, shear_modulus, length);
        let area = std::f64::consts::PI * bond_radius * bond_radius;
        let second_moment = 0.25 * area * bond_radius * bond_radius;
        let polar_moment = 2.0 * second_moment;
        let compliance =
            l.powi(3) / (12.0 * e * second_moment) + l / (SHEAR_COEFFICIENT * g * area);
        Bond {
            normal_stiffness: e * area / l,
            shear_stiffness: 1.0 / compliance,
            bending_stiffness: e * second_moment / l,
            twisting_stiffness: g * polar_moment / l,
            normal_damping: 0.0,
            shear_damping: 0.0,
            bending_damping: 0.0,
            twisting_damping: 0.0,
            tensile_strength: f64::INFINITY,
            shear_strength: f64::INFINITY,
            bending_strength: f64::INFINITY,
        }
    }

    /// The same springs with dashpots at damping ratio ζ = `ratio` [–] of each spring acting
    /// alone on the pair's reduced mass m* = m_i m_j/(m_i + m_j) = `reduced_mass` [kg] and
    /// reduced moment of inertia I* = `reduced_inertia` [kg m²]:
    /// c = 2 ζ √(k m*) for the normal and shear springs, c = 2 ζ √(k I*) for bending and twist.
    /// (In a chain the modes mix, so ζ is a guide, not the damping ratio of any one mode.)
    pub fn with_damping_ratio(self, ratio: f64, reduced_mass: f64, reduced_inertia: f64) -> Bond {
        let c = |k: f64, m: f64| 2.0 * ratio * (k * m).sqrt();
        Bond {
            normal_damping: c(self.normal_stiffness, reduced_mass),
            shear_damping: c(self.shear_stiffness, reduced_mass),
            bending_damping: c(self.bending_stiffness, reduced_inertia),
            twisting_damping: c(self.twisting_stiffness, reduced_inertia),
            ..self
        }
    }

    /// The same bond with strengths: tensile and shear [N], bending [N m].
    pub fn with_strengths(self, tensile: f64, shear: f64, bending: f64) -> Bond {
        Bond {
            tensile_strength: tensile,
            shear_strength: shear,
            bending_strength: bending,
            ..self
        }
    }
}

/// The state of one bond: its history.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct BondState {
    /// Length L₀ when bonded [m].
    pub rest_length: f64,
    /// Shear spring force s, world frame, on the first sphere [N].
    pub shear: Vec3,
    /// Bending spring moment M_b (perpendicular to the bond axis), world frame, on the first
    /// sphere [N m].
    pub bending: Vec3,
    /// Twisting spring moment M_τ about the bond axis n (from the first sphere to the second),
    /// on the first sphere [N m].
    pub twisting: f64,
    /// True once broken.
    pub broken: bool,
}

impl BondState {
    /// A bond glued now, at length `rest_length` [m], with no load.
    pub fn new(rest_length: f64) -> BondState {
        BondState {
            rest_length,
            ..Default::default()
        }
    }
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
    /// Torque on sphere i [N m]: a_i n × F_t + M.
    pub torque_i: Vec3,
    /// Torque on sphere j [N m]: a_j n × F_t − M.
    pub torque_j: Vec3,
}

/// A vector of the bond's history turned with the pair (module doc): projected onto the plane
/// normal to the current axis `n` at its old length (the tilt of n), then turned about n by
/// `spin` [rad] (the pair's rotation about its own axis).
fn turn_with_pair(h: Vec3, n: Vec3, spin: f64) -> Vec3 {
    let t = h - h.dot(n) * n;
    let t = if t.length_squared() > 0.0 {
        t * (h.length() / t.length())
    } else {
        t
    };
    let (sin, cos) = spin.sin_cos();
    cos * t + sin * n.cross(t)
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
    let [wi, wj] = p.angular_velocity;

    // The bond point c, midway across the gap g: arms a_i + a_j = L.
    let g = l - ri - rj;
    let (a_i, a_j) = (ri + 0.5 * g, rj + 0.5 * g);
    let u = (p.velocity[1] + wj.cross(-a_j * n)) - (p.velocity[0] + wi.cross(a_i * n));
    let u_n = u.dot(n);
    let u_t = u - u_n * n;
    let w = wj - wi;
    let w_n = w.dot(n);
    let w_t = w - w_n * n;

    // The history turns with the pair, then takes this step's increments.
    let spin = 0.5 * (wi + wj).dot(n) * dt;
    state.shear = turn_with_pair(state.shear, n, spin) + law.shear_stiffness * dt * u_t;
    state.bending = turn_with_pair(state.bending, n, spin) + law.bending_stiffness * dt * w_t;
    state.twisting += law.twisting_stiffness * dt * w_n;

    let f_spring = law.normal_stiffness * (l - state.rest_length);
    if f_spring > law.tensile_strength
        || state.shear.length() > law.shear_strength
        || state.bending.length() > law.bending_strength
    {
        *state = BondState {
            broken: true,
            ..BondState::new(state.rest_length)
        };
        return BondReaction::default();
    }
    let f_n = f_spring + law.normal_damping * u_n;
    let f_t = state.shear + law.shear_damping * u_t;
    let m = state.bending
        + state.twisting * n
        + law.bending_damping * w_t
        + law.twisting_damping * w_n * n;
    BondReaction {
        force_i: f_n * n + f_t,
        torque_i: (a_i * n).cross(f_t) + m,
        torque_j: (a_j * n).cross(f_t) - m,
    }
}
