//! Materials and the contact law between each pair of them.
//!
//! A `Material` holds what an engineer looks up in a table (density, Young's modulus, Poisson's
//! ratio, friction and restitution). `ContactModel` is the choice of law made once per scenario;
//! `PairLaw` is what the contact kernel needs for one pair of materials, derived once at set-up.

use serde::{Deserialize, Serialize};

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

pub use super::contact::hooke::HookeOptions;
pub use super::contact::voigt::{Damping, NormalSpring, TangentialStiffness, VoigtOptions};
pub use super::contact::{ContactModel, LawKind, NoOptions};

/// The constants of a pair of materials after the mixing rules, from which each law derives
/// its own (`contact::Law::params`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Mixed {
    /// Effective modulus E* with 1/E* = (1-ν_i²)/E_i + (1-ν_j²)/E_j [Pa].
    pub e_star: f64,
    /// Effective shear modulus G* with 1/G* = 2(2-ν_i)(1+ν_i)/E_i + 2(2-ν_j)(1+ν_j)/E_j [Pa].
    pub g_star: f64,
    /// Poisson's ratio ν, the mean of the pair's [-].
    pub poisson_ratio: f64,
    /// Friction coefficient μ [-]: the mean of the pair's unless overridden.
    pub friction: f64,
    /// Target restitution e [-]: the mean of the pair's unless overridden.
    pub restitution: f64,
}

impl Mixed {
    /// The constants of materials `a` and `b`. Friction and restitution default to the mean of
    /// the two materials' values unless `over` sets them.
    pub fn new(a: &Material, b: &Material, over: PairOverride) -> Mixed {
        let inv_e = (1.0 - a.poisson_ratio.powi(2)) / a.young_modulus
            + (1.0 - b.poisson_ratio.powi(2)) / b.young_modulus;
        let inv_g = 2.0 * (2.0 - a.poisson_ratio) * (1.0 + a.poisson_ratio) / a.young_modulus
            + 2.0 * (2.0 - b.poisson_ratio) * (1.0 + b.poisson_ratio) / b.young_modulus;
        Mixed {
            e_star: 1.0 / inv_e,
            g_star: 1.0 / inv_g,
            poisson_ratio: 0.5 * (a.poisson_ratio + b.poisson_ratio),
            friction: over
                .friction_coefficient
                .unwrap_or(0.5 * (a.friction_coefficient + b.friction_coefficient)),
            restitution: over
                .restitution_coefficient
                .unwrap_or(0.5 * (a.restitution_coefficient + b.restitution_coefficient)),
        }
    }

    /// The Hertz coefficient K in s_n = K δ^{3/2}: K = (4/3) E* √R* [N m^{-3/2}].
    ///
    /// Implements [16], [17].
    pub fn hertz_coefficient(&self, r_star: f64) -> f64 {
        4.0 / 3.0 * self.e_star * r_star.sqrt()
    }
}

/// Everything the contact kernel needs for one pair of materials.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PairLaw {
    /// The law and its options.
    pub model: ContactModel,
    /// The pair's mixed material constants.
    pub mixed: Mixed,
    /// The law's constants of the pair, derived once (`contact::Law::params`).
    pub k: super::contact::Constants,
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
    /// The law `model` between materials `a` and `b` (see [`Mixed::new`]).
    pub fn new(model: &ContactModel, a: &Material, b: &Material, over: PairOverride) -> PairLaw {
        let mixed = Mixed::new(a, b, over);
        PairLaw {
            model: *model,
            mixed,
            k: model.constants(&mixed),
        }
    }

    /// The law's kernel.
    pub fn kind(&self) -> LawKind {
        self.model.kind()
    }

    /// The friction coefficient μ of the pair [-].
    pub fn friction(&self) -> f64 {
        self.mixed.friction
    }

    /// A head-on impact of a pairing with R* [m] and m* [kg] at `v` [m s⁻¹], and its overlap
    /// at rest under `load` [N] (`contact::Law::scales`).
    pub fn scales(
        &self,
        r_star: f64,
        m_star: f64,
        v: f64,
        load: f64,
    ) -> super::contact::scales::Scales {
        self.model.scales(&self.mixed, r_star, m_star, v, load)
    }

    /// The restitution of a head-on impact in continuous time of a pairing with m* [kg] [-]
    /// (`contact::Law::restitution`).
    pub fn restitution(&self, m_star: f64) -> f64 {
        self.model.restitution(&self.mixed, m_star)
    }

    /// What `riprap check` says of the law (`contact::Law::describe`).
    pub fn describe(&self) -> String {
        self.model.describe(&self.mixed)
    }
}
