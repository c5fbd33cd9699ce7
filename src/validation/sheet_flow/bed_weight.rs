//! How much of the resting bed's submerged weight the water's pressure p̄ carries (README.md,
//! "A defect this case found"): after 0.004 s of the base case, the flow barely started, the
//! mean vertical [59] force (the held load less buoyancy) on the spheres whose centre lies
//! 1.5 to 3.5 cm up, per size class, in units of their submerged weight (ρ_p − ρ_w) V g.
//! Near 0 when the bed rests on its contacts; a third with the defect. Run by
//! `riprap validate --only sheet_flow_bed_weight`; reported, no verdict (the regression test
//! is `tests/coupling.rs::a_resting_bed_rests_on_its_contacts_not_on_the_pressure`).

use std::path::Path;

use super::{class_of, scenario, Level, BED};
use crate::scenario::{build, Source};

/// Simulated time of the measurement [s].
pub const END_TIME: f64 = 0.004;

/// Per size class: the mean vertical [59] force over the submerged weight [–] and the number
/// of spheres in the 1.5-3.5 cm band. `work` is a folder for the bed file.
pub fn bed_weight_carried_by_the_pressure(work: &Path) -> anyhow::Result<[(f64, usize); 3]> {
    std::fs::create_dir_all(work)?;
    std::fs::write(work.join("bed.csv"), BED)?;
    let text = scenario(&Level {
        end_time: END_TIME,
        ..Level::QUICK
    });
    let src = Source::from_str(&text, "scenario.toml", work.to_path_buf())?;
    let mut sim = build(&src)?.simulation;
    while sim.time < END_TIME - 1e-9 {
        sim.step_towards(END_TIME)?;
    }
    let s = &sim.dem.spheres;
    let (rho_w, g) = (1000.0, 9.81);
    let mut by_class = [(0.0, 0); 3];
    for i in 0..s.len() {
        let z = s.position[i].z;
        if !(0.015..=0.035).contains(&z) {
            continue;
        }
        let v = 4.0 / 3.0 * std::f64::consts::PI * s.radius[i].powi(3);
        let submerged = (s.mass[i] / v - rho_w) * v * g;
        let lift = s.fluid[i].force.z - rho_w * v * g;
        let c = class_of(s.radius[i]);
        by_class[c].0 += lift / submerged;
        by_class[c].1 += 1;
    }
    Ok(by_class.map(|(sum, n)| (sum / n.max(1) as f64, n)))
}
