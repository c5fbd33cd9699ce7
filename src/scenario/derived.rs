//! What `riprap check` prints: the quantities an expert computes by hand before a run, and
//! their report.

use std::fmt::Write as _;

use super::fluid::FluidDerived;
use super::memory::MemoryEstimate;
use crate::dem::material::PairLaw;
use crate::dem::timestep::ContactScales;

/// Quantities an expert computes by hand before a run.
#[derive(Clone, Debug)]
pub struct Derived {
    /// Reference impact velocity [m s⁻¹].
    pub reference_velocity: f64,
    /// Shortest spring period T over the pairings present [s].
    pub min_period: f64,
    /// Largest stable step T/10 [s].
    pub max_time_step: f64,
    /// The step used [s].
    pub time_step: f64,
    /// Number of steps to the end.
    pub steps: u64,
    /// Spheres at the start, and to be fed.
    pub spheres: (usize, usize),
    /// One line per pairing: description and scales.
    pub pairings: Vec<(String, ContactScales)>,
    /// Memory estimate, made before anything was allocated.
    pub memory: MemoryEstimate,
    /// Per pairing: (restitution a run at this step shows, steps in contact), from
    /// `timestep::discrete_impact` at the reference velocity.
    pub at_step: Vec<(f64, u64)>,
    /// One line per block template (count, size, mass), and the links.
    pub block_lines: Vec<String>,
    /// The flow, if the scenario has one.
    pub fluid: Option<FluidDerived>,
    /// The coupling's line of the report, if the scenario couples spheres and water.
    pub coupling: Option<String>,
    /// One line per mesh wall: its triangles, so that a file cut short shows.
    pub mesh_lines: Vec<String>,
    /// The armour layer's line (`scenario::armour`), with `[armour]`.
    pub armour: Option<String>,
    /// What `[breakwater]` made (`scenario::breakwater`).
    pub breakwater: Option<String>,
    /// The line estimating the output's size (`output_size`).
    pub output: String,
}

impl Derived {
    /// The report printed by `riprap check`: the spheres' part (unless there are none and a
    /// fluid), then the fluid's.
    pub fn report(&self) -> String {
        let mut s = match &self.fluid {
            Some(_) if self.spheres == (0, 0) => "spheres: none (a flow-only scenario)\n".into(),
            _ => self.sphere_report(),
        };
        if let Some(f) = &self.fluid {
            s.push_str(&f.report());
        }
        if let Some(c) = &self.coupling {
            s.push_str(c);
        }
        for l in &self.mesh_lines {
            let _ = writeln!(s, "{l}");
        }
        if let Some(b) = &self.breakwater {
            s.push_str(b);
        }
        if let Some(a) = &self.armour {
            s.push_str(a);
        }
        s.push_str(&self.memory.report());
        s.push_str(&self.output);
        s
    }

    /// The spheres' part of the report.
    fn sphere_report(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "spheres: {} at the start, {} fed during the run",
            self.spheres.0, self.spheres.1
        );
        if !self.block_lines.is_empty() {
            let _ = writeln!(s, "rigid blocks:");
            for l in &self.block_lines {
                let _ = writeln!(s, "  {l}");
            }
        }
        let _ = writeln!(
            s,
            "reference impact velocity: {:.3} m/s",
            self.reference_velocity
        );
        self.pairing_table(&mut s);
        self.restitution_lines(&mut s);
        let _ = writeln!(
            s,
            "shortest spring period T [22]: {:.4e} s",
            self.min_period
        );
        let _ = writeln!(
            s,
            "largest stable time step T/10: {:.4e} s",
            self.max_time_step
        );
        let _ = writeln!(
            s,
            "time step: {:.4e} s (T/{:.1}), {} steps to the end",
            self.time_step,
            self.min_period / self.time_step,
            self.steps
        );
        s
    }

    /// The pairings' scales, then their friction, restitution and moduli.
    fn pairing_table(&self, s: &mut String) {
        if let Some((_, c)) = self.pairings.first() {
            let _ = writeln!(s, "{}", law_line(&c.law));
        }
        let _ = writeln!(
            s,
            "contact pairings (head-on impact at the reference velocity):"
        );
        let _ = writeln!(
            s,
            "  {:<34} {:>10} {:>10} {:>11} {:>11} {:>11} {:>11}",
            "pairing", "R* [m]", "m* [kg]", "T [s]", "t_c [s]", "δmax/R*", "δrest/R*"
        );
        for (name, c) in &self.pairings {
            let _ = writeln!(
                s,
                "  {:<34} {:>10.3e} {:>10.3e} {:>11.3e} {:>11.3e} {:>11.3e} {:>11.3e}",
                name,
                c.r_star,
                c.m_star,
                c.period,
                c.duration,
                c.max_overlap / c.r_star,
                c.rest_overlap / c.r_star
            );
        }
        let _ = writeln!(
            s,
            "friction μ and restitution e of each pairing: the mean of the two materials' \
             values unless a [[contact.pair]] sets them (a material's restitution_coefficient \
             is 0.5 when not given); E* and G* from both materials, 1/E* = Σ (1 − ν²)/E, \
             1/G* = Σ 2 (2 − ν)(1 + ν)/E:"
        );
        for (name, c) in &self.pairings {
            let _ = writeln!(
                s,
                "  {:<34} μ {:.3}, e {:.3}, E* {:.3e} Pa, G* {:.3e} Pa",
                name,
                c.law.mixed.friction,
                c.law.mixed.restitution,
                c.law.mixed.e_star,
                c.law.mixed.g_star
            );
        }
    }

    /// Per pairing, the restitution aimed at and the one a run at this step shows.
    fn restitution_lines(&self, s: &mut String) {
        let _ = writeln!(
            s,
            "restitution a run at this time step shows (head-on, reference velocity):"
        );
        for ((name, c), (e, n)) in self.pairings.iter().zip(&self.at_step) {
            let target = ideal_restitution(&c.law, c.m_star);
            let _ = writeln!(
                s,
                "  {:<34} target {:.3}, at Δt {:.3} ({:+.1} %), {} steps in contact",
                name,
                target,
                e,
                100.0 * (e - target) / target,
                n
            );
        }
    }
}

/// The restitution of a head-on impact in continuous time: what the dashpots were chosen for.
fn ideal_restitution(law: &PairLaw, m_star: f64) -> f64 {
    law.restitution(m_star)
}

/// What `check` says of the contact law: which law, and the choices that change results.
fn law_line(law: &PairLaw) -> String {
    law.describe()
}
