//! Materials and the contact law between each pair of them.
//!
//! A `Material` holds what an engineer looks up in a table (density, Young's modulus, Poisson's
//! ratio, friction and restitution). `ContactModel` is the choice of law made once per scenario;
//! `PairLaw` is what the contact kernel needs for one pair of materials, derived once at set-up.

use serde::{Deserialize, Serialize};

use super::contact::damping;

/// A solid material.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Material {
    /// Name used in scenario files.
    pub name: String,
    /// Density ρ [kg m⁻³].
    pub density: f64,
    /// Young's modulus E [Pa].
    pub young_modulus: f64,
    /// Poisson's ratio ν [-].
    pub poisson_ratio: f64,
    /// Coulomb friction coefficient μ [-] (METHOD.md [11]).
    pub friction_coefficient: f64,
    /// Target normal coefficient of restitution e [-], used when damping is chosen from it.
    pub restitution_coefficient: f64,
}

impl Material {
    /// E / (1 - ν²) [Pa], the plane-strain modulus of [15]-[19].
    pub fn plane_strain_modulus(&self) -> f64 {
        self.young_modulus / (1.0 - self.poisson_ratio * self.poisson_ratio)
    }
}

/// The normal spring of the source's Voigt model (METHOD.md [15]-[19]).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum NormalSpring {
    /// s_n = k_n δ with a given k_n [N m⁻¹].
    Linear {
        /// Normal stiffness k_n [N m⁻¹].
        stiffness: f64,
    },
    /// Hertz: s_n = k_n δ^{3/2}, k_n = (2/3) E/(1-ν²) √(r_i r_j/(r_i+r_j)) [15]-[17].
    Hertz,
    /// The apparent linear Hertz spring [18][19]: s_n = k_n δ with
    /// k_n = {(4/9) r_i r_j/(r_i+r_j) (E/(1-ν²))² s_ref}^{1/3}, the secant of the Hertz curve at the
    /// force s_ref. s_ref is the peak Hertz force of a head-on impact at `reference_velocity`.
    ApparentLinearHertz {
        /// Impact velocity that sets the representative force [m s⁻¹].
        reference_velocity: f64,
    },
}

/// How the dashpots of the Voigt model are chosen.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Damping {
    /// Critical damping, c = 2 √(m* k) [21] (k the tangent stiffness for Hertz springs).
    Critical,
    /// Damping ratio chosen so that a head-on impact rebounds with the pair's restitution
    /// coefficient (calibrated exactly for the clamped law, linear and Hertz alike).
    Restitution,
}

/// The contact law of a scenario.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum ContactModel {
    /// The source's Voigt spring-dashpot with a no-tension joint and a Coulomb slider [9]-[14].
    Voigt {
        /// Normal spring.
        spring: NormalSpring,
        /// Dashpot choice.
        damping: Damping,
        /// Tangential spring against the normal one.
        tangential: TangentialStiffness,
    },
    /// LIGGGHTS `model hertz tangential history` (= LAMMPS `hertz/material` + `mindlin`), exactly
    /// as `bench/peers/README.md` specifies it, for users coming from those codes.
    HertzMindlin,
    /// Hertz-Mindlin with the Coulomb limit kept (`contact::hertz_mindlin_coulomb`): the
    /// same springs and dashpots, but the whole tangential force within μ F_n and no tension,
    /// so that a sliding contact's tangential impulse is exactly μ times its normal one.
    HertzMindlinCoulomb,
    /// LAMMPS `pair_style gran/hooke/history k_n k_t γ_n γ_t xmu dampflag` (`contact::hooke`):
    /// a linear spring-dashpot with tangential history, for users of LAMMPS and its chute
    /// benchmark (B2). The friction coefficient (LAMMPS xmu) is the pair's.
    HookeHistory {
        /// Normal stiffness k_n [N m⁻¹].
        normal_stiffness: f64,
        /// Tangential stiffness k_t [N m⁻¹] (LAMMPS's default: 2/7 k_n).
        tangential_stiffness: f64,
        /// Normal damping γ_n [s⁻¹]: the dashpot is m* γ_n.
        normal_damping: f64,
        /// Tangential damping γ_t [s⁻¹] (LAMMPS's default γ_n/2; 0 with dampflag 0).
        tangential_damping: f64,
    },
}

/// The ratio of the tangential to the normal spring of the Voigt laws, k_t/k_n (for Hertz,
/// of the tangent stiffnesses).
///
/// The source's [20] gives 1/(2(1 + ν)) (0.38 at ν = 0.3), the ratio of the shear to the
/// Young's modulus. For Hertz contacts Mindlin's theory gives 2(1 − ν)/(2 − ν) (0.82 at
/// ν = 0.3): with [20] a sphere striking a wall obliquely without sliding stores half the
/// tangential energy it should, and rebounds with about half the tangential velocity that
/// experiments (Kharaz, Gorham & Salman 2001) show at small incidence.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum TangentialStiffness {
    /// k_t/k_n = 1/(2(1 + ν)), the source's [20] (the default: faithful to the source).
    #[default]
    Source,
    /// k_t/k_n = 2(1 − ν)/(2 − ν), Mindlin's ratio for elastic spheres in contact.
    Mindlin,
}

impl TangentialStiffness {
    /// k_t/k_n for Poisson's ratio `nu` (the mean of the two materials').
    ///
    /// Implements [20].
    pub fn ratio(self, nu: f64) -> f64 {
        match self {
            TangentialStiffness::Source => 1.0 / (2.0 * (1.0 + nu)),
            TangentialStiffness::Mindlin => 2.0 * (1.0 - nu) / (2.0 - nu),
        }
    }
}

/// Which kernel a pair uses.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum LawKind {
    /// Voigt with s_n = k δ, k fixed.
    Linear,
    /// Voigt with s_n = K δ^{3/2}.
    Hertz,
    /// Voigt with s_n = k δ, k from [19] for each pair of radii.
    ApparentLinear,
    /// LIGGGHTS/LAMMPS Hertz-Mindlin.
    HertzMindlin,
    /// Hertz-Mindlin with the Coulomb limit on the whole tangential force, no tension.
    HertzMindlinCoulomb,
    /// LAMMPS Hooke with history.
    HookeHistory,
}

/// Everything the contact kernel needs for one pair of materials.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PairLaw {
    /// Kernel.
    pub kind: LawKind,
    /// Linear stiffness k_n [N m⁻¹] (`Linear` and `HookeHistory`).
    pub stiffness: f64,
    /// Tangential stiffness k_t [N m⁻¹] (`HookeHistory` only).
    pub tangential_stiffness: f64,
    /// Normal and tangential damping rates γ_n, γ_t [s⁻¹] (`HookeHistory` only).
    pub gamma: (f64, f64),
    /// Reference impact velocity for [19] [m s⁻¹] (`ApparentLinear` only).
    pub reference_velocity: f64,
    /// Effective modulus E* with 1/E* = (1-ν_i²)/E_i + (1-ν_j²)/E_j [Pa].
    pub e_star: f64,
    /// Effective shear modulus G* with 1/G* = 2(2-ν_i)(1+ν_i)/E_i + 2(2-ν_j)(1+ν_j)/E_j [Pa].
    pub g_star: f64,
    /// k_t / k_n = G/E = 1/(2(1+ν)) [20], ν the mean of the pair.
    pub tangential_ratio: f64,
    /// Friction coefficient μ [-].
    pub friction: f64,
    /// Target restitution e [-].
    pub restitution: f64,
    /// Damping ratio ζ of the Voigt dashpots: c = 2 ζ √(m* k) [-].
    pub damping_ratio: f64,
    /// LIGGGHTS β = ln e / √(ln² e + π²) [-] (`HertzMindlin` only).
    pub beta: f64,
    /// Hertz-Mindlin factors, derived once (`HertzMindlin` only): k_n = c.0 a, k_t = c.1 a
    /// [Pa], γ_n = c.2 √(m* a), γ_t = c.3 √(m* a) [Pa^½], with a = √(R* δ) (see
    /// `contact::hertz_mindlin`).
    pub hertz_mindlin: (f64, f64, f64, f64),
}

/// Per-pair overrides of the mixing rules.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct PairOverride {
    /// Friction coefficient [-].
    pub friction_coefficient: Option<f64>,
    /// Restitution coefficient [-].
    pub restitution_coefficient: Option<f64>,
}

impl PairLaw {
    /// The law between materials `a` and `b`. Friction and restitution default to the mean of the
    /// two materials' values unless `over` sets them; the tangential spring of the Voigt laws
    /// from [`TangentialStiffness::ratio`] [20].
    pub fn new(model: &ContactModel, a: &Material, b: &Material, over: PairOverride) -> PairLaw {
        let inv_e = (1.0 - a.poisson_ratio.powi(2)) / a.young_modulus
            + (1.0 - b.poisson_ratio.powi(2)) / b.young_modulus;
        let inv_g = 2.0 * (2.0 - a.poisson_ratio) * (1.0 + a.poisson_ratio) / a.young_modulus
            + 2.0 * (2.0 - b.poisson_ratio) * (1.0 + b.poisson_ratio) / b.young_modulus;
        let nu = 0.5 * (a.poisson_ratio + b.poisson_ratio);
        let friction = over
            .friction_coefficient
            .unwrap_or(0.5 * (a.friction_coefficient + b.friction_coefficient));
        let e = over
            .restitution_coefficient
            .unwrap_or(0.5 * (a.restitution_coefficient + b.restitution_coefficient));
        let mut law = PairLaw {
            kind: LawKind::Linear,
            stiffness: 0.0,
            tangential_stiffness: 0.0,
            gamma: (0.0, 0.0),
            reference_velocity: 0.0,
            e_star: 1.0 / inv_e,
            g_star: 1.0 / inv_g,
            tangential_ratio: TangentialStiffness::Source.ratio(nu),
            friction,
            restitution: e,
            damping_ratio: 0.0,
            beta: 0.0,
            hertz_mindlin: (0.0, 0.0, 0.0, 0.0),
        };
        match *model {
            ContactModel::HookeHistory {
                normal_stiffness,
                tangential_stiffness,
                normal_damping,
                tangential_damping,
            } => {
                law.kind = LawKind::HookeHistory;
                law.stiffness = normal_stiffness;
                law.tangential_stiffness = tangential_stiffness;
                law.gamma = (normal_damping, tangential_damping);
            }
            ContactModel::HertzMindlin | ContactModel::HertzMindlinCoulomb => {
                law.kind = match model {
                    ContactModel::HertzMindlin => LawKind::HertzMindlin,
                    _ => LawKind::HertzMindlinCoulomb,
                };
                let ln_e = e.max(1e-12).ln();
                law.beta = ln_e / (ln_e * ln_e + std::f64::consts::PI.powi(2)).sqrt();
                // γ = -2 √(5/6) β √(S m*), S = 2 E* a (normal) or 8 G* a (tangential): LIGGGHTS's
                // damping, which gives e for a law that may pull. Without tension the contact
                // ends sooner and rebounds faster, so the Coulomb variant takes the damping ratio
                // of the clamped Hertz law instead (its S_n is the Hertz tangent stiffness):
                // γ = 2 ζ √(S m*), ζ from `damping::damping_ratio_for_restitution`.
                let c = match law.kind {
                    LawKind::HertzMindlin => -2.0 * (5.0f64 / 6.0).sqrt() * law.beta,
                    _ => {
                        law.damping_ratio =
                            damping::damping_ratio_for_restitution(e, damping::Spring::Hertz);
                        2.0 * law.damping_ratio
                    }
                };
                law.hertz_mindlin = (
                    4.0 / 3.0 * law.e_star,
                    8.0 * law.g_star,
                    c * (2.0 * law.e_star).sqrt(),
                    c * (8.0 * law.g_star).sqrt(),
                );
            }
            ContactModel::Voigt {
                spring,
                damping,
                tangential,
            } => {
                law.tangential_ratio = tangential.ratio(nu);
                let shape = match spring {
                    NormalSpring::Linear { stiffness } => {
                        law.kind = LawKind::Linear;
                        law.stiffness = stiffness;
                        damping::Spring::Linear
                    }
                    NormalSpring::ApparentLinearHertz { reference_velocity } => {
                        law.kind = LawKind::ApparentLinear;
                        law.reference_velocity = reference_velocity;
                        damping::Spring::Linear
                    }
                    NormalSpring::Hertz => {
                        law.kind = LawKind::Hertz;
                        damping::Spring::Hertz
                    }
                };
                law.damping_ratio = match damping {
                    Damping::Critical => 1.0,
                    Damping::Restitution => damping::damping_ratio_for_restitution(e, shape),
                };
            }
        }
        law
    }

    /// The Hertz coefficient K in s_n = K δ^{3/2}: K = (4/3) E* √R* [15]-[17] [N m^{-3/2}].
    ///
    /// Implements [16], [17].
    pub fn hertz_coefficient(&self, r_star: f64) -> f64 {
        4.0 / 3.0 * self.e_star * r_star.sqrt()
    }

    /// The linear stiffness of `Linear` and `ApparentLinear` springs for a pair [N m⁻¹] (the
    /// apparent one from [19], `contact::voigt::apparent_stiffness`).
    pub fn linear_stiffness(&self, r_star: f64, m_star: f64) -> f64 {
        match self.kind {
            LawKind::ApparentLinear => super::contact::voigt::apparent_stiffness(
                4.0 / 3.0 * self.e_star,
                self.reference_velocity,
                r_star,
                m_star,
            ),
            _ => self.stiffness,
        }
    }
}
