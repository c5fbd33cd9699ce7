//! Validation of wet contacts (beyond the source's cases): a sphere falling onto a wall in a viscous liquid and rebounding, its
//! restitution against the Stokes number of the impact, with and without the lubrication film
//! (`crate::coupling::lubrication`), beside the measurements of Gondret, Lance & Petit (2002)
//! as Legendre et al. (2006) fitted them. Set-up, reference and tolerances: `README.md`.

pub mod report;

use std::path::PathBuf;

use crate::scenario::{build, Source};

/// The case's scenario (one member of the sweep, ν to be replaced).
pub const SCENARIO: &str = include_str!("scenario.toml");

/// Sphere diameter d [m], density ρ_p and the liquid's ρ_f [kg m⁻³].
pub const D: f64 = 0.01;
const RHO_P: f64 = 7800.0;
const RHO_F: f64 = 1000.0;
/// The dry restitution of the contact law [-] (the scenario's steel).
pub const E_DRY: f64 = 0.97;

/// The viscosities of the sweep [m² s⁻¹]: impact Stokes numbers from about 3 to 400.
pub fn viscosities(quick: bool) -> Vec<f64> {
    if quick {
        vec![1.0e-3, 1.0e-4]
    } else {
        vec![1.0e-3, 5.0e-4, 2.5e-4, 1.0e-4, 5.0e-5, 2.0e-5]
    }
}

/// Legendre, Zenit, Daniel & Guiraud (2006, Chem. Eng. Sci. 61, 3543): e/e_dry = exp(−β/St)
/// with β = 35, their fit to the measurements of Gondret et al. (2002) and Joseph et al.
/// (2001) for spheres rebounding on a wall in liquids, St = ρ_p d U/(9 μ).
pub fn legendre_2006(stokes: f64) -> f64 {
    (-35.0 / stokes).exp()
}

/// One fall and rebound.
#[derive(Clone, Debug)]
pub struct Member {
    /// Kinematic viscosity ν [m² s⁻¹].
    pub nu: f64,
    /// Whether the film force was on.
    pub lubrication: bool,
    /// Largest downward speed before the first contact U [m s⁻¹].
    pub impact_speed: f64,
    /// Largest upward speed after it [m s⁻¹] (zero: no rebound).
    pub rebound_speed: f64,
    /// St = ρ_p d U/(9 μ) [-].
    pub stokes: f64,
    /// (t [s], gap to the floor [m], vertical velocity [m s⁻¹]), one per fluid step.
    pub samples: Vec<(f64, f64, f64)>,
    /// Wall-clock time [s].
    pub seconds: f64,
}

impl Member {
    /// e/e_dry, the measured restitution over the dry one [-].
    pub fn ratio(&self) -> f64 {
        self.rebound_speed / self.impact_speed / E_DRY
    }
}

/// The scenario of one member.
pub fn scenario(nu: f64, lubrication: bool) -> String {
    let s = SCENARIO.replace(
        "kinematic_viscosity = 1.0e-4 ",
        &format!("kinematic_viscosity = {nu:e} "),
    );
    if lubrication {
        s
    } else {
        // The film's keys go with it.
        let dry: Vec<&str> = s
            .lines()
            .filter(|l| !l.starts_with("lubrication"))
            .collect();
        dry.join("\n")
    }
}

/// Runs one member: the sphere falls from rest, touches the floor and rebounds; the run
/// stops at the top of the rebound, or when the sphere has lain on the floor for 0.05 s
/// without rising, or at the scenario's end.
pub fn run_member(nu: f64, lubrication: bool) -> anyhow::Result<Member> {
    let start = std::time::Instant::now();
    let text = scenario(nu, lubrication);
    let src = Source::from_str(&text, "wet_rebound/scenario.toml", PathBuf::from("."))?;
    let t_end = src.scenario.run.end_time;
    let mut sim = build(&src)?.simulation;
    let r = 0.5 * D;
    let (mut impact, mut rebound) = (0.0f64, 0.0f64);
    let mut rose = false;
    let mut resting_since = None;
    let mut samples = Vec::new();
    while sim.time < t_end {
        sim.step()?;
        let s = &sim.dem.spheres;
        let (gap, w) = (s.position[0].z - r, s.velocity[0].z);
        samples.push((sim.time, gap, w));
        if !rose && w > 0.0 {
            rose = true;
        }
        if !rose {
            impact = impact.max(-w);
        } else {
            rebound = rebound.max(w);
            if w < 0.0 {
                break; // the top of the rebound
            }
        }
        // On the floor and not moving up: no rebound.
        if gap < 0.01 * D && w.abs() < 0.01 * impact {
            let since = *resting_since.get_or_insert(sim.time);
            if sim.time - since > 0.05 {
                break;
            }
        } else {
            resting_since = None;
        }
    }
    let mu = RHO_F * nu;
    Ok(Member {
        nu,
        lubrication,
        impact_speed: impact,
        rebound_speed: rebound,
        stokes: RHO_P * D * impact / (9.0 * mu),
        samples,
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// The case's verdict on the members with the film: no rebound (e/e_dry < 0.1) below
/// St = 10, and within 0.2 of [`legendre_2006`] from there up (`README.md`).
pub fn passes(members: &[Member]) -> bool {
    members.iter().filter(|m| m.lubrication).all(check)
}

/// Whether a member meets the criterion at its St (`README.md`).
pub fn check(m: &Member) -> bool {
    if m.stokes < 10.0 {
        m.ratio() < 0.1
    } else {
        (m.ratio() - legendre_2006(m.stokes)).abs() <= 0.2
    }
}
