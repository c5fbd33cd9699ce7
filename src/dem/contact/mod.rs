//! Contact forces between two spheres, or a sphere and a wall (METHOD.md [6]-[22]).
//!
//! Conventions: sphere i is the first of the pair, j the second (or the wall, a sphere of infinite
//! radius and mass). The unit normal n points from i to j. The kernel returns the force on i; j
//! receives its opposite. The per-contact history (`hist`) is a world-frame vector whose meaning
//! depends on the law: the tangential spring force s_t [N] for the Voigt laws (METHOD.md [9]),
//! the tangential displacement ξ [m] for Hertz-Mindlin (as LIGGGHTS stores it) and for LAMMPS's
//! Hooke law. Whatever the law, the history of the pair (j, i) is the opposite of that of (i, j).
//!
//! A law is one file: its options (what a user writes in `[contact]` besides `model`), its
//! constants derived from them and the pair's mixed material constants, and its one
//! formulation, in one `impl Law`. Adding one touches that file and this one (its `mod` line
//! and its line in `registry!`); the scenario, the kernels, the lanes and `check` take it from
//! there.

pub mod damping;
pub mod hertz_mindlin;
pub mod hertz_mindlin_coulomb;
pub mod hooke;
pub mod lanes;
pub mod real;
pub mod scales;
pub mod voigt;

#[cfg(test)]
mod local_frame;

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

use crate::dem::material::{Mixed, PairLaw};
use crate::math::Vec3;
use real::{Real, V3};
use scales::Scales;

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

/// One contact as a law sees it, in numbers `T` (one contact, or eight: `real::Real`). For a
/// wall, r_j and ω_j hold the law's [`Law::WALL`].
#[derive(Clone, Copy)]
pub struct Contact<T> {
    /// Unit normal from i to j [-].
    pub n: V3<T>,
    /// Overlap δ [m].
    pub delta: T,
    /// v_i − v_j [m s⁻¹].
    pub dv: V3<T>,
    /// ω_i, ω_j [rad s⁻¹].
    pub w_i: V3<T>,
    /// See [`Contact::w_i`].
    pub w_j: V3<T>,
    /// r_i, r_j [m].
    pub r_i: T,
    /// See [`Contact::r_i`].
    pub r_j: T,
    /// Effective mass m* [kg].
    pub m_star: T,
    /// The law's values of this contact from [`Law::prepare`].
    pub pre: [T; 2],
}

/// What a law returns for one contact: the new history, the force on i and the torques.
#[derive(Clone, Copy)]
pub struct Response<T> {
    /// The contact's history after the step.
    pub hist: V3<T>,
    /// Force on i [N]; j receives its opposite.
    pub force: V3<T>,
    /// Torque on i [N m].
    pub torque_i: V3<T>,
    /// Torque on j [N m].
    pub torque_j: V3<T>,
}

/// The constants of a law for one pair of materials as the lanes carry them, one column each
/// ([`Columns`]).
pub type Constants = [f64; 5];

/// A law's constants laid out as the lanes' columns, one constant each.
pub trait Columns<T>: Copy {
    /// The constants from the columns.
    fn from_columns(k: [T; 5]) -> Self;
    /// The constants as the columns hold them.
    fn to_columns(self) -> [T; 5];
}

/// An option of a law refused by [`Law::check`]: the key (as the scenario's `[contact]` table
/// names it) and why.
#[derive(Clone, Debug, PartialEq)]
pub struct Invalid {
    /// The option's key.
    pub key: &'static str,
    /// Why it is refused.
    pub reason: String,
}

/// What a scenario gives every law besides its own options ([`Law::complete`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScenarioValues {
    /// The reference impact velocity of the scenario [m s⁻¹] (`run.reference_velocity`).
    pub reference_velocity: f64,
}

/// Options of a law that takes none (an empty `[contact]` table besides `model`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NoOptions {}

/// A contact law: its options, the constants it derives from them and the materials, one
/// formulation ([`Law::force`]) run one contact at a time ([`contact_force`]) and on columns
/// of contacts (`lanes::run`) with the same bits, and what `check` says of it. A law is one
/// file with one `impl Law`, named in the registry at the end of this file.
pub trait Law {
    /// What a user chooses for the law (the keys of `[contact]` besides `model`).
    type Options: Copy + std::fmt::Debug + PartialEq + Serialize + DeserializeOwned;
    /// The law's constants for one pair of materials, named and with their units, in numbers
    /// `T` (one pair, or eight contacts' pairs).
    type Params<T: Real>: Columns<T>;
    /// The radius r_j [m] and the spin ω_j (each component) [rad s⁻¹] a wall takes in
    /// [`Contact`]: values whose terms change no sum, so that a wall gives what a sphere of
    /// infinite radius and mass would (signed zeros; each law says why its pair works).
    const WALL: (f64, f64);
    /// The law's constants for a pair of materials, derived once from its options and the
    /// pair's mixed material constants.
    fn params(o: &Self::Options, m: &Mixed) -> Self::Params<f64>;
    /// Refuses options out of range.
    fn check(_o: &Self::Options) -> Result<(), Invalid> {
        Ok(())
    }
    /// Fills the options a scenario gives rather than `[contact]` (none by default).
    fn complete(_o: &mut Self::Options, _s: &ScenarioValues) {}
    /// The constants from the lanes' columns.
    #[inline(always)]
    fn unpack<T: Real>(k: [T; 5]) -> Self::Params<T> {
        Columns::from_columns(k)
    }
    /// Values of one contact that need more than IEEE-exact arithmetic, or that the kernels
    /// take early so that the processor overlaps their square roots (R* [m], m* [kg], δ ≥ 0
    /// [m]); zeros when the law has none.
    #[inline(always)]
    fn prepare(_p: &Self::Params<f64>, _r_star: f64, _m_star: f64, _delta: f64) -> [f64; 2] {
        [0.0; 2]
    }
    /// One step of the contact: `hist` is its history before the step.
    fn force<T: Real>(p: &Self::Params<T>, c: &Contact<T>, hist: V3<T>, dt: T) -> Response<T>;
    /// A head-on impact of a pairing with R* [m] and m* [kg] at `v` [m s⁻¹], and its overlap
    /// at rest under `load` [N].
    fn scales(o: &Self::Options, m: &Mixed, r_star: f64, m_star: f64, v: f64, load: f64) -> Scales;
    /// The restitution of a head-on impact in continuous time of a pairing with m* [kg] [-]:
    /// what the dashpots were chosen for.
    fn restitution(o: &Self::Options, m: &Mixed, m_star: f64) -> f64;
    /// What `riprap check` says of the law: which law, and the choices that change results.
    fn describe(o: &Self::Options, m: &Mixed) -> String;
}

/// Something to do with the law of a kind (`dispatch`).
pub trait WithLaw {
    /// The result.
    type Out;
    /// Does it with the law `L`.
    fn run<L: Law>(self) -> Self::Out;
}

/// The registry of laws: from one line per law (its kind, its name in scenario files, its
/// type) it makes [`LawKind`], [`ContactModel`] (the law and its options, `[contact] model =
/// "name"` in TOML), [`dispatch`] and the model's methods. Adding a law is its file and one
/// line here.
macro_rules! registry {
    ($($(#[doc = $doc:literal])* $kind:ident = $name:literal => $law:ty;)*) => {
        /// Which law a pair uses.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
        pub enum LawKind {
            $($(#[doc = $doc])* $kind,)*
        }

        /// The contact law of a scenario with its options: in TOML, `[contact] model =
        /// "name"` and the options' keys beside it.
        #[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
        #[serde(tag = "model")]
        pub enum ContactModel {
            $($(#[doc = $doc])* #[serde(rename = $name)] $kind(<$law as Law>::Options),)*
        }

        /// The one place that maps a pair's kind to its law.
        #[inline(always)]
        pub fn dispatch<W: WithLaw>(kind: LawKind, w: W) -> W::Out {
            match kind {
                $(LawKind::$kind => w.run::<$law>(),)*
            }
        }

        impl ContactModel {
            /// The names of the laws in scenario files.
            pub const NAMES: &'static [&'static str] = &[$($name),*];

            /// The law's kind.
            pub fn kind(&self) -> LawKind {
                match self {
                    $(Self::$kind(_) => LawKind::$kind,)*
                }
            }
            /// The law's name in scenario files.
            pub fn name(&self) -> &'static str {
                match self {
                    $(Self::$kind(_) => $name,)*
                }
            }
            /// [`Law::params`] as the lanes' columns hold them.
            pub fn constants(&self, m: &Mixed) -> Constants {
                match self {
                    $(Self::$kind(o) => <$law as Law>::params(o, m).to_columns(),)*
                }
            }
            /// [`Law::check`].
            pub fn check(&self) -> Result<(), Invalid> {
                match self {
                    $(Self::$kind(o) => <$law as Law>::check(o),)*
                }
            }
            /// [`Law::complete`].
            pub fn complete(&mut self, s: &ScenarioValues) {
                match self {
                    $(Self::$kind(o) => <$law as Law>::complete(o, s),)*
                }
            }
            /// [`Law::scales`].
            pub fn scales(&self, m: &Mixed, r_star: f64, m_star: f64, v: f64, load: f64)
                -> Scales {
                match self {
                    $(Self::$kind(o) => <$law as Law>::scales(o, m, r_star, m_star, v, load),)*
                }
            }
            /// [`Law::restitution`].
            pub fn restitution(&self, m: &Mixed, m_star: f64) -> f64 {
                match self {
                    $(Self::$kind(o) => <$law as Law>::restitution(o, m, m_star),)*
                }
            }
            /// [`Law::describe`].
            pub fn describe(&self, m: &Mixed) -> String {
                match self {
                    $(Self::$kind(o) => <$law as Law>::describe(o, m),)*
                }
            }
        }
    };
}

registry! {
    /// The source's Voigt law with the Hertz spring s_n = K δ^{3/2} [15]-[17].
    Hertz = "hertz" => voigt::Hertz;
    /// The source's Voigt law with a linear spring s_n = k_n δ, k_n given [18].
    Linear = "linear" => voigt::Linear;
    /// The source's Voigt law with the apparent linear Hertz spring [18][19].
    ApparentLinear = "apparent_linear_hertz" => voigt::ApparentLinear;
    /// Hertz-Mindlin with the Coulomb limit on the whole tangential force, no tension.
    HertzMindlinCoulomb = "hertz_mindlin" => hertz_mindlin_coulomb::HertzMindlinCoulomb;
    /// LIGGGHTS `model hertz tangential history` (= LAMMPS `hertz/material` + `mindlin`).
    HertzMindlin = "hertz_mindlin_liggghts" => hertz_mindlin::HertzMindlin;
    /// LAMMPS `pair_style gran/hooke/history`.
    HookeHistory = "hooke_history" => hooke::Hooke;
}

impl Default for ContactModel {
    /// The source's Voigt law with the Hertz spring and the default options.
    fn default() -> ContactModel {
        ContactModel::Hertz(Default::default())
    }
}

/// The force of one contact under the law `L`; `hist` is updated in place. A wall (r_j
/// infinite) receives nothing: `torque_j` is zero.
#[inline(always)]
pub fn force_of<L: Law>(law: &PairLaw, p: &Pair, hist: &mut Vec3, dt: f64) -> Reaction {
    force_with::<L>(law.k, p, hist, dt)
}

/// [`force_of`] given the law's constants.
#[inline(always)]
pub fn force_with<L: Law>(k: Constants, p: &Pair, hist: &mut Vec3, dt: f64) -> Reaction {
    let params = L::unpack(k);
    let wall = !p.r_j.is_finite();
    let (r_j, w_j) = if wall {
        (L::WALL.0, Vec3::splat(L::WALL.1))
    } else {
        (p.r_j, p.w_j)
    };
    let c = Contact {
        n: p.n.into(),
        delta: p.delta,
        dv: p.dv.into(),
        w_i: p.w_i.into(),
        w_j: w_j.into(),
        r_i: p.r_i,
        r_j,
        m_star: p.m_star,
        pre: L::prepare(&params, p.r_star, p.m_star, p.delta),
    };
    let r = L::force(&params, &c, (*hist).into(), dt);
    *hist = r.hist.into();
    Reaction {
        force: r.force.into(),
        torque_i: r.torque_i.into(),
        torque_j: if wall { Vec3::ZERO } else { r.torque_j.into() },
    }
}

/// The force of one contact under the pair's law; `hist` is updated in place.
pub fn contact_force(law: &PairLaw, p: &Pair, hist: &mut Vec3, dt: f64) -> Reaction {
    struct One<'a>(&'a PairLaw, &'a Pair, &'a mut Vec3, f64);
    impl WithLaw for One<'_> {
        type Out = Reaction;
        fn run<L: Law>(self) -> Reaction {
            force_of::<L>(self.0, self.1, self.2, self.3)
        }
    }
    dispatch(law.kind(), One(law, p, hist, dt))
}
