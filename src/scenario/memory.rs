//! The memory a scenario will need, estimated from its numbers before anything is allocated,
//! and refused with the key that drives it when the machine does not have it: a lattice of
//! micrometre spacing, a feed of 10¹¹ spheres or a grid of 1500³ cells would otherwise abort
//! the process, or grind for minutes, without naming the cause.

use std::fmt::Write as _;

use super::schema::{BlockSet, SizeSection, SphereSet};
use super::text::{bytes, count};
use super::{ScenarioError, Source};
use crate::dem::material::Material;
use crate::fluid::diagnostics::memory_for_cells;
use crate::rigid::templates::BlockTemplate;

/// DEM memory per sphere [bytes] (ARCHITECTURE.md, "Performance and memory": state, neighbour
/// list and sorting, listed pairs with their history, wall lists; 7.2 GB for 10 million).
pub const BYTES_PER_SPHERE: f64 = 718.0;

/// What a scenario needs, and what drives it.
#[derive(Clone, Debug, Default)]
pub struct MemoryEstimate {
    /// Spheres at the start and fed, block members included.
    pub spheres: f64,
    /// Cells of the flow grid.
    pub cells: f64,
    /// The DEM's share [bytes].
    pub dem_bytes: f64,
    /// The flow's share [bytes].
    pub fluid_bytes: f64,
    /// Per key that adds memory: (key, what it asks for in words, bytes).
    pub drivers: Vec<(String, String, f64)>,
    /// Memory the machine has for it [bytes] and where that figure comes from, when known.
    pub available: Option<(f64, &'static str)>,
}

impl MemoryEstimate {
    /// Total [bytes].
    pub fn total(&self) -> f64 {
        self.dem_bytes + self.fluid_bytes
    }

    /// The line `riprap check` prints.
    pub fn report(&self) -> String {
        let mut parts = Vec::new();
        if self.spheres > 0.0 {
            parts.push(format!(
                "{} for {} at {BYTES_PER_SPHERE:.0} B each",
                bytes(self.dem_bytes),
                count(self.spheres.round(), "sphere")
            ));
        }
        if self.cells > 0.0 {
            parts.push(format!(
                "{} for {}",
                bytes(self.fluid_bytes),
                count(self.cells, "fluid cell")
            ));
        }
        let mut s = format!("memory estimate: {}", bytes(self.total()));
        if !parts.is_empty() {
            let _ = write!(s, " ({})", parts.join(", "));
        }
        match self.available {
            Some((b, from)) => {
                let _ = write!(s, "; this machine has {} ({from})", bytes(b));
            }
            None => s.push_str("; this machine's free memory is unknown (not checked)"),
        }
        s.push('\n');
        s
    }

    fn add(&mut self, key: String, what: String, b: f64) {
        if b > 0.0 {
            self.drivers.push((key, what, b));
        }
    }
}

/// Memory free for a new process [bytes]: MemAvailable (else MemTotal) of /proc/meminfo, on
/// Linux; `None` elsewhere.
pub fn machine_memory() -> Option<(f64, &'static str)> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let field = |name: &str| {
        text.lines()
            .find_map(|l| l.strip_prefix(name))
            .and_then(|rest| {
                rest.trim()
                    .trim_end_matches("kB")
                    .trim()
                    .parse::<f64>()
                    .ok()
            })
            .map(|kb| kb * 1024.0)
    };
    field("MemAvailable:")
        .map(|b| (b, "MemAvailable in /proc/meminfo"))
        .or_else(|| field("MemTotal:").map(|b| (b, "MemTotal in /proc/meminfo")))
}

/// Sites of `lattice(lo, hi, s)` without making them (the same count, in f64 so that it cannot
/// overflow).
pub(super) fn lattice_sites(lo: [f64; 3], hi: [f64; 3], s: f64) -> f64 {
    if !(s.is_finite() && s > 0.0) {
        return 0.0;
    }
    (0..3)
        .map(|k| ((hi[k] - lo[k]) / s + 1e-9).floor().max(0.0))
        .product()
}

/// Spheres of a random fill's size classes: counts, or mass fractions of the total mass.
fn class_spheres(
    sizes: &[SizeSection],
    total_mass: Option<f64>,
    density: &dyn Fn(Option<&str>) -> Option<f64>,
) -> f64 {
    let sum: f64 = sizes.iter().filter_map(|c| c.mass_fraction).sum();
    sizes
        .iter()
        .map(|c| match (c.count, c.mass_fraction, total_mass) {
            (Some(n), _, _) => n as f64,
            (None, Some(f), Some(m)) if sum > 0.0 => {
                let rho = density(c.material.as_deref()).unwrap_or(f64::NAN);
                let one = rho * std::f64::consts::PI / 6.0 * c.diameter.powi(3);
                let n = m * f / sum / one;
                if n.is_finite() {
                    n.max(0.0)
                } else {
                    0.0
                }
            }
            _ => 0.0,
        })
        .sum()
}

/// Rows of a sphere file (lines that are neither blank nor comments), 0 when unreadable (the
/// set's checks then say why).
fn file_rows(path: &std::path::Path) -> f64 {
    std::fs::read_to_string(path).map_or(0.0, |t| {
        t.lines()
            .filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
            .count() as f64
    })
}

/// f64 fields per padded cell that the coupling adds to the flow's (`coupling::Coupling`).
const COUPLING_FIELDS: f64 = 14.0;

/// Estimates the scenario's memory from its numbers, allocating nothing in proportion to them.
/// `templates` are the block templates, built where they could be (they are small).
pub(super) fn estimate(
    src: &Source,
    names: &[String],
    materials: &[Material],
    templates: &[Option<BlockTemplate>],
) -> MemoryEstimate {
    let sc = &src.scenario;
    let mut est = MemoryEstimate {
        available: machine_memory(),
        ..MemoryEstimate::default()
    };
    let density_of = |name: Option<&str>| {
        let i = names.iter().position(|n| Some(n.as_str()) == name)?;
        Some(materials[i].density)
    };
    for (i, set) in sc.spheres.iter().enumerate() {
        let key = format!("spheres[{i}]");
        let (key, n) = match set {
            SphereSet::List(l) => (format!("{key}.spheres"), l.spheres.len() as f64),
            SphereSet::Lattice(l) => (
                format!("{key}.spacing"),
                lattice_sites(l.min, l.max, l.spacing),
            ),
            SphereSet::Random(r) => {
                let density = |m: Option<&str>| density_of(m.or(r.material.as_deref()));
                (
                    format!("{key}.sizes"),
                    class_spheres(&r.sizes, r.total_mass, &density),
                )
            }
            SphereSet::Feed(f) => (format!("{key}.total"), f.total as f64),
            SphereSet::File(f) => (format!("{key}.file"), file_rows(&src.dir.join(&f.file))),
        };
        est.spheres += n;
        est.add(key, count(n.round(), "sphere"), n * BYTES_PER_SPHERE);
    }
    let template_of = |name: &str| {
        let t = sc.block_templates.iter().position(|t| t.name == name)?;
        templates.get(t)?.as_ref()
    };
    for (i, set) in sc.blocks.iter().enumerate() {
        let key = format!("blocks[{i}]");
        let (key, blocks, template) = match set {
            BlockSet::List(l) => (
                format!("{key}.blocks"),
                l.blocks.len() as f64,
                template_of(&l.template),
            ),
            BlockSet::Lattice(l) => {
                let t = template_of(&l.template);
                let s = l.spacing.or_else(|| t.map(|t| 2.0 * t.bounding_radius()));
                let n = s.map_or(0.0, |s| lattice_sites(l.min, l.max, s));
                (format!("{key}.spacing"), n, t)
            }
            BlockSet::Random(r) => {
                let t = template_of(&r.template);
                let n = match (r.count, r.layer_thickness, t) {
                    (Some(n), _, _) => n as f64,
                    (None, Some(h), Some(t)) => {
                        let area = (r.max[0] - r.min[0]) * (r.max[1] - r.min[1]);
                        let n = h * area * (1.0 - r.porosity.unwrap_or(0.5)) / t.volume;
                        if n.is_finite() {
                            n.max(0.0)
                        } else {
                            0.0
                        }
                    }
                    _ => 0.0,
                };
                let by = if r.count.is_some() {
                    "count"
                } else {
                    "layer_thickness"
                };
                (format!("{key}.{by}"), n, t)
            }
        };
        let members = template.map_or(1.0, |t| t.members.len() as f64);
        let n = blocks * members;
        est.spheres += n;
        est.add(
            key,
            format!(
                "{} of {}",
                count(blocks.round(), "block"),
                count(members, "sphere")
            ),
            n * BYTES_PER_SPHERE,
        );
    }
    est.dem_bytes = est.spheres * BYTES_PER_SPHERE;
    if let Some(f) = &sc.fluid {
        let (lo, hi) = match (f.min, f.max) {
            (Some(lo), Some(hi)) => (lo, hi),
            _ => (sc.domain.min, sc.domain.max),
        };
        let (key, n) = match (f.cells, f.cell_size) {
            (Some(n), _) => ("fluid.cells", n.map(|c| c as f64)),
            (None, Some(h)) => (
                "fluid.cell_size",
                std::array::from_fn(|a| ((hi[a] - lo[a]) / h).round().max(0.0)),
            ),
            (None, None) => ("fluid.cells", [0.0; 3]),
        };
        let n = n.map(|c| if c.is_finite() { c } else { 0.0 });
        est.cells = n.iter().product();
        est.fluid_bytes = memory_for_cells(n);
        if sc.coupling.is_some() {
            // The coupling's own fields per padded cell (`Coupling::new`): weights 3 × 2,
            // face loads 3, cell fractions 2, interaction force 3.
            let padded: f64 = n.iter().map(|c| c + 2.0).product();
            est.fluid_bytes += COUPLING_FIELDS * 8.0 * padded;
        }
        est.add(
            key.into(),
            format!("{} × {} × {} cells", n[0], n[1], n[2]),
            est.fluid_bytes,
        );
    }
    est
}

/// Refuses a scenario that needs more memory than the machine has, naming the key that asks
/// for the most.
pub(super) fn refuse_if_too_big(src: &Source, est: &MemoryEstimate) -> Result<(), ScenarioError> {
    let Some((have, from)) = est.available else {
        return Ok(());
    };
    if est.total() <= have {
        return Ok(());
    }
    let Some((key, what, b)) = est
        .drivers
        .iter()
        .max_by(|a, b| a.2.total_cmp(&b.2))
        .cloned()
    else {
        return Ok(());
    };
    Err(src.invalid(
        &key,
        format!(
            "asks for {what}, about {} of memory ({} for the whole scenario: {BYTES_PER_SPHERE:.0} \
             B per sphere, and the flow's fields per cell), but this machine has {} ({from}); \
             make the scenario smaller",
            bytes(b),
            bytes(est.total()),
            bytes(have)
        ),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lattice_sites_match_the_lattice() {
        let (lo, hi) = ([0.0; 3], [0.3, 0.25, 0.1]);
        let made = crate::dem::insertion::lattice(
            crate::math::Vec3::from_array(lo),
            crate::math::Vec3::from_array(hi),
            0.05,
        );
        assert_eq!(lattice_sites(lo, hi, 0.05), made.len() as f64);
    }
}
