//! What the water does to one box-shaped piece of debris, from the flow at its centre: the
//! hydrostatic balance (floating, grounded, sunk), the Morison drag and inertia, the bed's
//! Coulomb friction and the flooding of a container. Pure functions of scalars, so that each
//! law is tested alone against its closed form (`super::tests`).
//!
//! Symbols: ρ water density [kg m⁻³], g gravity [m s⁻²], L, B, H the box's length, width and
//! height [m], A = L B its plan area [m²], M its mass [kg] (flooding water included), h the
//! local depth [m], u the depth-averaged velocity [m s⁻¹], v the box's velocity [m s⁻¹].

use serde::{Deserialize, Serialize};

/// Where a piece of debris stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Phase {
    /// Afloat: the free draft M/(ρA) is below the local depth.
    Floating,
    /// On the bed, with the buoyancy of the local depth only (it would float in deeper water).
    Grounded,
    /// Flooded beyond floating at any depth (M ≥ ρ L B H): on the bed for good.
    Sunk,
    /// Left the flow's domain (or stands among solid cells only): frozen where it left.
    Out,
}

impl Phase {
    /// The word in the tracks' CSV.
    pub fn name(self) -> &'static str {
        match self {
            Phase::Floating => "floating",
            Phase::Grounded => "grounded",
            Phase::Sunk => "sunk",
            Phase::Out => "out",
        }
    }

    /// The number in the tracks' CSV (0 floating, 1 grounded, 2 sunk, 3 out).
    pub fn code(self) -> f64 {
        match self {
            Phase::Floating => 0.0,
            Phase::Grounded => 1.0,
            Phase::Sunk => 2.0,
            Phase::Out => 3.0,
        }
    }
}

/// The hydrostatic balance of a box (Archimedes):
///
/// ```text
/// d  = M / (ρ A)                                  free draft [m]
/// floating  if d < h and d < H:   wet height w = d,            N = 0
/// otherwise (on the bed):          w = min(h, H),  N = g (M − ρ A w) ≥ 0
/// ```
///
/// with N the bed's normal reaction [N] (the buoyancy-reduced weight) and w the wet height
/// [m] on which the flow acts (the draft capped by the local depth).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Balance {
    /// Wet height w [m].
    pub wet_height: f64,
    /// Normal reaction of the bed N [N].
    pub normal: f64,
    /// The phase the balance puts the box in.
    pub phase: Phase,
}

/// The balance of a box of `mass` [kg], plan `area` [m²] and `height` [m] in water of
/// `depth` [m] (see [`Balance`]).
pub fn balance(mass: f64, area: f64, height: f64, depth: f64, rho: f64, g: f64) -> Balance {
    let d = mass / (rho * area);
    let h = depth.max(0.0);
    if d < h && d < height {
        return Balance {
            wet_height: d,
            normal: 0.0,
            phase: Phase::Floating,
        };
    }
    let w = h.min(height);
    Balance {
        wet_height: w,
        normal: (g * (mass - rho * area * w)).max(0.0),
        phase: if d >= height {
            Phase::Sunk
        } else {
            Phase::Grounded
        },
    }
}

/// The drag coefficient k [kg s⁻¹] of the Morison drag F = k u_r on a box of wet height
/// `w` [m], length `l` and width `b` [m] whose long axis points along the unit vector `e`,
/// in a flow `u_r` = u − v [m s⁻¹] relative to it:
///
/// ```text
/// F_D = ½ ρ C_D A_wet |u_r| u_r,    A_wet = w (L |u_r × e| + B |u_r · e|) / |u_r|
/// k   = ½ ρ C_D w (L |u_r × e| + B |u_r · e|)
/// ```
///
/// A_wet is the wetted frontal area: the box's width seen across the relative flow times the
/// wet height (Morison et al. 1950, "The force exerted by surface waves on piles", Petroleum
/// Trans. AIME 189, 149-154, with the frontal area of a box at an angle).
pub fn drag_factor(rho: f64, cd: f64, w: f64, l: f64, b: f64, e: [f64; 2], ur: [f64; 2]) -> f64 {
    let along = (ur[0] * e[0] + ur[1] * e[1]).abs();
    let across = (ur[0] * e[1] - ur[1] * e[0]).abs();
    0.5 * rho * cd * w * (l * across + b * along)
}

/// The horizontal velocity after a step `dt` [s] of a box of effective mass `m` [kg] (its
/// own plus the added mass) at velocity `v`, in a flow `u` [m s⁻¹], under the explicit force
/// `f` [N] (the Morison inertia and the contacts), the drag factor `k` [kg s⁻¹] of
/// [`drag_factor`] taken implicitly, and the bed's Coulomb friction with normal reaction `n`
/// [N] (static `mu_s`, kinetic `mu_k`). `stuck` says whether the box was held by static
/// friction; it is updated. Returns the new velocity.
///
/// ```text
/// drag, implicit in v:   v* = (m v + Δt (f + k u)) / (m + Δt k)
/// held (v = 0):          stays held while |f + k u| ≤ μ_s N, else slides
/// sliding:               v = v* − Δt μ_k N v̂* / (m + Δt k),  held when that would reverse v*
/// ```
///
/// The friction thus never reverses the motion, and a box at rest starts to slide exactly
/// when the force on it exceeds μ_s N (backward-Euler treatment of Coulomb friction, as in
/// the event-free schemes of Moreau 1988, "Unilateral contact and dry friction in finite
/// freedom dynamics", CISM 302).
#[allow(clippy::too_many_arguments)]
pub fn slide(
    m: f64,
    v: [f64; 2],
    u: [f64; 2],
    f: [f64; 2],
    k: f64,
    n: f64,
    mu_s: f64,
    mu_k: f64,
    dt: f64,
    stuck: &mut bool,
) -> [f64; 2] {
    let drive = [f[0] + k * u[0], f[1] + k * u[1]];
    if n > 0.0 && *stuck {
        if drive[0].hypot(drive[1]) <= mu_s * n {
            return [0.0, 0.0];
        }
        *stuck = false;
    }
    let den = m + dt * k;
    let vs = [
        (m * v[0] + dt * drive[0]) / den,
        (m * v[1] + dt * drive[1]) / den,
    ];
    if n <= 0.0 {
        *stuck = false;
        return vs;
    }
    let speed = vs[0].hypot(vs[1]);
    let dv = dt * mu_k * n / den;
    if speed <= dv {
        *stuck = true;
        return [0.0, 0.0];
    }
    let s = 1.0 - dv / speed;
    [vs[0] * s, vs[1] * s]
}

/// The mass [kg] of a container of dry mass `m0` [kg] and outer volume `v` [m³] that has
/// floated for `t` [s], flooding with time constant `tau` [s] up to the fraction `phi` of its
/// volume (the voids a leak can fill):
///
/// ```text
/// M(t) = M₀ + ρ φ V (1 − e^(−t/τ))
/// ```
///
/// (the first-order filling of a leaking hull: the inflow proportional to the volume left to
/// fill). It sinks when M reaches ρ V, at [`sinking_time`]. `tau` = ∞: watertight.
pub fn flooded_mass(m0: f64, v: f64, phi: f64, tau: f64, rho: f64, t: f64) -> f64 {
    if !tau.is_finite() {
        return m0;
    }
    m0 + rho * phi * v * (-(-t / tau).exp_m1())
}

/// The floating time [s] after which [`flooded_mass`] reaches ρ V, the mass at which the box
/// floats no more: t_s = −τ ln(1 − (ρ V − M₀)/(ρ φ V)); `None` if it never does (watertight,
/// or voids too small).
pub fn sinking_time(m0: f64, v: f64, phi: f64, tau: f64, rho: f64) -> Option<f64> {
    let need = (rho * v - m0) / (rho * phi * v);
    if !tau.is_finite() || need.is_nan() || need >= 1.0 {
        return None;
    }
    Some(-tau * (-need.max(0.0)).ln_1p())
}
