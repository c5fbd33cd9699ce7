//! The `[[material]]` tables and the `[contact]` section: the materials, checked, and the law
//! of every pairing of two of them.

use serde::Deserialize;

use super::checks::{material_of, non_negative, positive, restitution};
use super::schema::{ContactSection, MaterialSection};
use super::{ScenarioError, Source};
use crate::dem::contact::ScenarioValues;
use crate::dem::material::{ContactModel, Material, PairLaw, PairOverride};

/// The scenario's materials, by index, and their names (for look-ups and messages).
pub(super) struct Materials {
    /// In the order of the `[[material]]` tables.
    pub list: Vec<Material>,
    /// `list[i].name`, for `checks::material_of`.
    pub names: Vec<String>,
}

/// Checks the `[[material]]` tables (at least one unless the scenario is flow only).
pub(super) fn materials(src: &Source) -> Result<Materials, ScenarioError> {
    let sc = &src.scenario;
    if sc.materials.is_empty() && sc.fluid.is_none() {
        return Err(src.invalid("material", "at least one [[material]] is needed"));
    }
    let mut out = Materials {
        list: Vec::new(),
        names: Vec::new(),
    };
    for (i, m) in sc.materials.iter().enumerate() {
        if out.names.contains(&m.name) {
            return Err(src.invalid(
                &format!("material[{i}].name"),
                format!("material `{}` is defined twice", m.name),
            ));
        }
        out.list.push(material(src, i, m)?);
        out.names.push(m.name.clone());
    }
    Ok(out)
}

/// Checks `[[material]]` table `i`.
fn material(src: &Source, i: usize, m: &MaterialSection) -> Result<Material, ScenarioError> {
    let key = |k: &str| format!("material[{i}].{k}");
    positive(src, &key("density"), m.density)?;
    positive(src, &key("young_modulus"), m.young_modulus)?;
    if !(0.0..0.5).contains(&m.poisson_ratio) {
        return Err(src.invalid(
            &key("poisson_ratio"),
            format!(
                "must lie in [0, 0.5) (0.5 would be incompressible), got {}",
                m.poisson_ratio
            ),
        ));
    }
    non_negative(src, &key("friction_coefficient"), m.friction_coefficient)?;
    let e = restitution(
        src,
        &key("restitution_coefficient"),
        m.restitution_coefficient.unwrap_or(0.5),
    )?;
    Ok(Material {
        name: m.name.clone(),
        density: m.density,
        young_modulus: m.young_modulus,
        poisson_ratio: m.poisson_ratio,
        friction_coefficient: m.friction_coefficient,
        restitution_coefficient: e,
    })
}

/// The law of every pairing of materials `a`, `b`, at `a * n + b` (n materials): the
/// `[contact]` model with the materials' values, or a `[[contact.pair]]`'s. `v_ref` is the
/// reference impact velocity [m s⁻¹] (the apparent linear Hertz spring is set for it).
pub(super) fn contact_laws(
    src: &Source,
    materials: &Materials,
    v_ref: f64,
) -> Result<Vec<PairLaw>, ScenarioError> {
    let model = contact_model(src, &src.scenario.contact, v_ref)?;
    let overrides = pair_overrides(src, &materials.names)?;
    let m = &materials.list;
    let n = m.len();
    let mut laws = Vec::with_capacity(n * n);
    for a in 0..n {
        for b in 0..n {
            laws.push(PairLaw::new(&model, &m[a], &m[b], overrides[a * n + b]));
        }
    }
    Ok(laws)
}

/// The `[[contact.pair]]` tables, checked, at `a * n + b` and `b * n + a` (n materials).
fn pair_overrides(src: &Source, names: &[String]) -> Result<Vec<PairOverride>, ScenarioError> {
    let n = names.len();
    let mut overrides = vec![PairOverride::default(); n * n];
    for (p, pair) in src.scenario.contact.pairs.iter().enumerate() {
        let key = format!("contact.pair[{p}].materials");
        let a = material_of(src, names, &key, Some(&pair.materials[0]))? as usize;
        let b = material_of(src, names, &key, Some(&pair.materials[1]))? as usize;
        if let Some(f) = pair.friction_coefficient {
            non_negative(src, &format!("contact.pair[{p}].friction_coefficient"), f)?;
        }
        if let Some(e) = pair.restitution_coefficient {
            restitution(
                src,
                &format!("contact.pair[{p}].restitution_coefficient"),
                e,
            )?;
        }
        let o = PairOverride {
            friction_coefficient: pair.friction_coefficient,
            restitution_coefficient: pair.restitution_coefficient,
        };
        overrides[a * n + b] = o;
        overrides[b * n + a] = o;
    }
    Ok(overrides)
}

/// The `[contact]` section's law: `model` names it, and the keys beside it are read as its
/// options (each law's own struct, `dem::contact`), checked by the law.
fn contact_model(
    src: &Source,
    c: &ContactSection,
    v_ref: f64,
) -> Result<ContactModel, ScenarioError> {
    let mut table = c.options.clone();
    table.insert("model".into(), toml::Value::String(c.model.clone()));
    let mut model = ContactModel::deserialize(toml::Value::Table(table)).map_err(|e| {
        let msg = e.to_string();
        let msg = msg.trim_end();
        // serde names an unknown or missing key between backticks: point at it.
        let key = c
            .options
            .keys()
            .find(|k| msg.contains(&format!("`{k}`")))
            .map_or("contact.model".to_string(), |k| format!("contact.{k}"));
        if msg.contains("unknown variant") {
            return src.invalid("contact.model", msg.to_string());
        }
        src.invalid_at(&key, &key, format!("the `{}` model: {msg}", c.model))
    })?;
    model.complete(&ScenarioValues {
        reference_velocity: v_ref,
    });
    model.check().map_err(|e| {
        let key = format!("contact.{}", e.key);
        let at = if c.options.contains_key(e.key) {
            key.clone()
        } else {
            "contact.model".into()
        };
        src.invalid_at(&key, &at, e.reason)
    })?;
    Ok(model)
}
