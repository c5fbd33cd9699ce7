//! The checks of single values that every part of a scenario makes: each returns the value
//! or an error naming the file, the line, the key and the reason. This file uses no other
//! scenario file, so that all of them may use it.

use super::{ScenarioError, Source};

/// `v` if finite and above zero.
pub(super) fn positive(src: &Source, key: &str, v: f64) -> Result<f64, ScenarioError> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(src.invalid(key, format!("must be a positive number, got {v}")))
    }
}

/// Ok if every component of `v` is finite.
pub(super) fn finite(src: &Source, key: &str, v: &[f64]) -> Result<(), ScenarioError> {
    match v.iter().find(|x| !x.is_finite()) {
        Some(x) => Err(src.invalid(key, format!("must be finite, got {x}"))),
        None => Ok(()),
    }
}

/// `v` if finite and not below zero.
pub(super) fn non_negative(src: &Source, key: &str, v: f64) -> Result<f64, ScenarioError> {
    if v.is_finite() && v >= 0.0 {
        Ok(v)
    } else {
        Err(src.invalid(key, format!("must be zero or positive, got {v}")))
    }
}

/// A coefficient of restitution `e` in (0, 1].
pub(super) fn restitution(src: &Source, key: &str, e: f64) -> Result<f64, ScenarioError> {
    if e > 0.0 && e <= 1.0 {
        Ok(e)
    } else {
        Err(src.invalid(
            key,
            format!("must lie in (0, 1] (1 = elastic, small = very dissipative), got {e}"),
        ))
    }
}

/// The index of material `name` among `names` (`None`: no material given).
pub(super) fn material_of(
    src: &Source,
    names: &[String],
    key: &str,
    name: Option<&str>,
) -> Result<u16, ScenarioError> {
    let name =
        name.ok_or_else(|| src.invalid(key, "no material given (here or for the whole set)"))?;
    names
        .iter()
        .position(|n| n == name)
        .map(|i| i as u16)
        .ok_or_else(|| {
            src.invalid(
                key,
                format!(
                    "unknown material `{name}`; the [[material]] tables define: {}",
                    names.join(", ")
                ),
            )
        })
}

/// The material of a sphere or size class: its own (`key`) or else its set's (`set_key`).
pub(super) fn material_or_default(
    src: &Source,
    names: &[String],
    key: &str,
    own: Option<&str>,
    set_key: &str,
    set: Option<&str>,
) -> Result<u16, ScenarioError> {
    match (own, set) {
        (Some(_), _) => material_of(src, names, key, own),
        (None, Some(_)) => material_of(src, names, set_key, set),
        (None, None) => Err(src.invalid(
            key,
            format!("no material given, here or for the whole set (`{set_key}`)"),
        )),
    }
}
