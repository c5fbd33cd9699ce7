//! The `[run]` and `[domain]` sections: the run's name and end, the box and gravity, the
//! reference impact velocity, the Verlet skin and the limits past which a run has failed.

use super::checks::{finite, positive};
use super::pairings::Kind;
use super::schema::v3;
use super::{ScenarioError, Source};
use crate::dem::domain::Domain;
use crate::dem::neighbor::DEFAULT_SKIN_FRACTION;
use crate::dem::Limits;
use crate::math::Vec3;

/// Checks the run's name and end time and the domain; returns the domain and gravity.
pub(super) fn run_and_domain(src: &Source) -> Result<(Domain, Vec3), ScenarioError> {
    let sc = &src.scenario;
    run_name(src, &sc.run.name)?;
    positive(src, "run.end_time", sc.run.end_time)?;
    finite(src, "domain.min", &sc.domain.min)?;
    finite(src, "domain.max", &sc.domain.max)?;
    for k in 0..3 {
        if sc.domain.min[k].partial_cmp(&sc.domain.max[k]) != Some(std::cmp::Ordering::Less) {
            return Err(src.invalid("domain.max", "must exceed domain.min along every axis"));
        }
    }
    let domain = Domain {
        min: v3(sc.domain.min),
        max: v3(sc.domain.max),
        periodic: sc.domain.periodic,
    };
    let gravity = sc.domain.gravity.unwrap_or([0.0, 0.0, -9.81]);
    finite(src, "domain.gravity", &gravity)?;
    Ok((domain, v3(gravity)))
}

/// Refuses a run name that is not one plain folder name: the results go to `output/<name>`,
/// and a `/`, `\` or `..` there would write elsewhere.
fn run_name(src: &Source, name: &str) -> Result<(), ScenarioError> {
    let why = if name.trim().is_empty() {
        Some("is empty")
    } else if name.contains(['/', '\\']) {
        Some("contains a path separator (`/` or `\\`)")
    } else if name.starts_with('.') {
        Some("starts with a dot (`..` would leave the output folder, `.` hides it)")
    } else if name.chars().any(char::is_control) {
        Some("contains a control character")
    } else {
        None
    };
    match why {
        Some(why) => Err(src.invalid(
            "run.name",
            format!(
                "`{name}` {why}; the results go to the folder output/<name>, so the name must be \
                 a single plain folder name such as \"dam_break\""
            ),
        )),
        None => Ok(()),
    }
}

/// The reference impact velocity [m s⁻¹]: `run.reference_velocity`, or else √(2 g H) over the
/// domain's height H along gravity (at least 0.5 m/s).
pub(super) fn reference_velocity(
    src: &Source,
    domain: &Domain,
    gravity: Vec3,
) -> Result<f64, ScenarioError> {
    let height = (domain.max - domain.min)
        .dot(-gravity.normalize_or_zero())
        .abs();
    match src.scenario.run.reference_velocity {
        Some(v) => positive(src, "run.reference_velocity", v),
        None => Ok((2.0 * gravity.length() * height).sqrt().max(0.5)),
    }
}

/// The Verlet skin [m]: `run.skin_fraction` (default `DEFAULT_SKIN_FRACTION`) of the largest
/// diameter among the kinds of spheres.
pub(super) fn skin(src: &Source, kinds: &[Kind]) -> Result<f64, ScenarioError> {
    let skin_fraction = src
        .scenario
        .run
        .skin_fraction
        .unwrap_or(DEFAULT_SKIN_FRACTION);
    positive(src, "run.skin_fraction", skin_fraction)?;
    let d_max = kinds.iter().map(|k| 2.0 * k.radius).fold(0.0, f64::max);
    Ok(skin_fraction * d_max.max(1e-9))
}

/// The speed and overlap past which a run is declared unstable (`run.max_speed`, default 20
/// `v_ref`; `run.max_overlap_ratio`, default 0.5).
pub(super) fn limits(src: &Source, v_ref: f64) -> Result<Limits, ScenarioError> {
    let run = &src.scenario.run;
    Ok(Limits {
        // An impact at 20 times the expected speed means the integration has failed.
        max_speed: positive(src, "run.max_speed", run.max_speed.unwrap_or(20.0 * v_ref))?,
        max_overlap_ratio: positive(
            src,
            "run.max_overlap_ratio",
            run.max_overlap_ratio.unwrap_or(0.5),
        )?,
    })
}
