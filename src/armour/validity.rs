//! Where each formula was fitted: the ranges of the tests as data, and the list of ranges an
//! input leaves, as sentences for a report.
//!
//! The shallow-foreshore form (Van Gent et al. 2003, h/H_s < 3) is not implemented: the deep
//! water range h/H_s ≥ 3 below flags the inputs that would need it.

use super::formulas::{iribarren_number, RockSlope, SeaState};

/// An input quantity of the formulas.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// notional permeability P [-]
    Permeability,
    /// cot α [-]
    CotAlpha,
    /// s_m = 2π H_s/(g T_m²) [-]
    Steepness,
    /// ξ_m [-]
    Iribarren,
    /// N [-]
    NumberOfWaves,
    /// Δ = ρ_r/ρ_w − 1 [-]
    RelativeDensity,
    /// h/H_s, water depth at the toe over H_s [-]
    DepthOverWaveHeight,
    /// S [-]
    Damage,
}

impl Quantity {
    /// The symbol in messages.
    pub fn symbol(self) -> &'static str {
        match self {
            Quantity::Permeability => "P",
            Quantity::CotAlpha => "cot α",
            Quantity::Steepness => "s_m",
            Quantity::Iribarren => "ξ_m",
            Quantity::NumberOfWaves => "N",
            Quantity::RelativeDensity => "Δ",
            Quantity::DepthOverWaveHeight => "h/H_s",
            Quantity::Damage => "S",
        }
    }
}

/// A tested range min ≤ value ≤ max (either end may be infinite), with its source.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ValidityRange {
    /// the quantity
    pub quantity: Quantity,
    /// lower end, in the quantity's unit
    pub min: f64,
    /// upper end, in the quantity's unit
    pub max: f64,
    /// where the range comes from
    pub source: &'static str,
}

const fn range(quantity: Quantity, min: f64, max: f64, source: &'static str) -> ValidityRange {
    ValidityRange {
        quantity,
        min,
        max,
        source,
    }
}

const VDM_1988: &str = "Van der Meer 1988";
const RM_2007: &str = "Van der Meer 1988; Rock Manual 2007 §5.2.2.2";

/// Van der Meer (1988), rock, deep water. The ranges of his tests (thesis; Rock Manual 2007
/// §5.2.2.2; TU Delft breakwater design notes): s_m from 0.005 as in the Deltares toolbox (the
/// TU Delft notes give 0.01), S up to 20 (beyond, failure: see
/// [`super::coefficients::damage_levels`]).
pub const VAN_DER_MEER_ROCK_RANGES: [ValidityRange; 8] = [
    range(Quantity::Permeability, 0.1, 0.6, VDM_1988),
    range(Quantity::CotAlpha, 1.5, 6.0, VDM_1988),
    range(Quantity::Steepness, 0.005, 0.06, VDM_1988),
    range(Quantity::Iribarren, 0.7, 7.0, RM_2007),
    range(Quantity::NumberOfWaves, 0.0, 7500.0, VDM_1988),
    range(Quantity::RelativeDensity, 1.0, 2.1, VDM_1988),
    range(
        Quantity::DepthOverWaveHeight,
        3.0,
        f64::INFINITY,
        "deep water, Van der Meer 1988; shallow: Van Gent et al. 2003",
    ),
    range(Quantity::Damage, 1.0, 20.0, RM_2007),
];

/// Van der Meer (1988), concrete cubes: one slope, 1:1.5, was tested; s_om and N as checked by
/// the Deltares coastal-structures-toolbox.
pub const VAN_DER_MEER_CUBE_RANGES: [ValidityRange; 3] = [
    range(Quantity::CotAlpha, 1.5, 1.5, VDM_1988),
    range(Quantity::Steepness, 0.005, 0.07, VDM_1988),
    range(Quantity::NumberOfWaves, 0.0, 7500.0, VDM_1988),
];

/// Van der Meer (1988), tetrapods: one slope, 1:1.5, was tested.
pub const VAN_DER_MEER_TETRAPOD_RANGES: [ValidityRange; 1] =
    [range(Quantity::CotAlpha, 1.5, 1.5, VDM_1988)];

/// Hudson (1959): the K_D of SPM 1984 Table 7-8 hold for slopes 1:1.5 to 1:5 and non-overtopped
/// trunks.
pub const HUDSON_RANGES: [ValidityRange; 1] =
    [range(Quantity::CotAlpha, 1.5, 5.0, "SPM 1984 Table 7-8")];

/// The ranges of `ranges` that the given values leave, each as "s_m = 0.07 outside 0.005..0.06
/// (Van der Meer 1988)". A quantity without a value is not checked.
pub fn violations(ranges: &[ValidityRange], values: &[(Quantity, f64)]) -> Vec<String> {
    let mut found = Vec::new();
    for r in ranges {
        for &(quantity, value) in values.iter().filter(|(q, _)| *q == r.quantity) {
            // NaN is outside every range.
            if !(r.min <= value && value <= r.max) {
                let upper = if r.max.is_finite() {
                    r.max.to_string()
                } else {
                    String::new()
                };
                found.push(format!(
                    "{} = {} outside {}..{} ({})",
                    quantity.symbol(),
                    short(value),
                    r.min,
                    upper,
                    r.source
                ));
            }
        }
    }
    found
}

/// A value as a sentence shows it: four decimals without trailing zeros (0.07, 2.5, 8000),
/// or two significant digits in e-notation below 10⁻³ (5.62e-4).
fn short(v: f64) -> String {
    if v != 0.0 && v.abs() < 1e-3 {
        return format!("{v:.2e}");
    }
    let s = format!("{v:.4}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// The violated ranges of [`VAN_DER_MEER_ROCK_RANGES`] for a slope, Δ [-], a storm, the water
/// depth at the toe h [m] and the damage S [-] asked for or predicted.
pub fn van_der_meer_rock_violations(
    slope: RockSlope,
    relative_density: f64,
    sea: SeaState,
    water_depth: f64,
    damage: f64,
) -> Vec<String> {
    let steepness = sea.steepness();
    let values = [
        (Quantity::Permeability, slope.permeability),
        (Quantity::CotAlpha, slope.cot_alpha),
        (Quantity::Steepness, steepness),
        (
            Quantity::Iribarren,
            iribarren_number(slope.cot_alpha, steepness),
        ),
        (Quantity::NumberOfWaves, sea.number_of_waves),
        (Quantity::RelativeDensity, relative_density),
        (
            Quantity::DepthOverWaveHeight,
            water_depth / sea.significant_wave_height,
        ),
        (Quantity::Damage, damage),
    ];
    violations(&VAN_DER_MEER_ROCK_RANGES, &values)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steep_waves_are_flagged_with_their_range_and_source() {
        let found = violations(&VAN_DER_MEER_ROCK_RANGES, &[(Quantity::Steepness, 0.07)]);
        assert_eq!(
            found,
            vec!["s_m = 0.07 outside 0.005..0.06 (Van der Meer 1988)".to_string()]
        );
    }

    #[test]
    fn a_design_inside_every_range_passes() {
        let slope = RockSlope {
            cot_alpha: 3.0,
            permeability: 0.4,
        };
        let sea = SeaState {
            significant_wave_height: 2.0,
            mean_period: 6.0,
            number_of_waves: 3000.0,
        };
        assert!(van_der_meer_rock_violations(slope, 1.585, sea, 10.0, 2.0).is_empty());
    }

    #[test]
    fn every_rock_range_is_checked() {
        let slope = RockSlope {
            cot_alpha: 7.0,
            permeability: 0.7,
        };
        // T_m = 3 s with H_s = 2 m: s_m = 0.142, ξ_m = 0.38; h/H_s = 2.5.
        let sea = SeaState {
            significant_wave_height: 2.0,
            mean_period: 3.0,
            number_of_waves: 8000.0,
        };
        let found = van_der_meer_rock_violations(slope, 2.5, sea, 5.0, 25.0);
        let symbols: Vec<&str> = found
            .iter()
            .map(|s| s.split(" = ").next().unwrap())
            .collect();
        assert_eq!(
            symbols,
            ["P", "cot α", "s_m", "ξ_m", "N", "Δ", "h/H_s", "S"]
        );
        assert!(found.contains(&"h/H_s = 2.5 outside 3.. (deep water, Van der Meer 1988; shallow: Van Gent et al. 2003)".to_string()));
        assert!(found.contains(&"N = 8000 outside 0..7500 (Van der Meer 1988)".to_string()));
    }

    #[test]
    fn concrete_units_off_the_tested_slope_are_flagged() {
        assert_eq!(
            violations(&VAN_DER_MEER_TETRAPOD_RANGES, &[(Quantity::CotAlpha, 1.5)]),
            Vec::<String>::new()
        );
        assert_eq!(
            violations(&VAN_DER_MEER_CUBE_RANGES, &[(Quantity::CotAlpha, 2.0)]).len(),
            1
        );
        assert_eq!(
            violations(&HUDSON_RANGES, &[(Quantity::CotAlpha, f64::NAN)]).len(),
            1
        );
    }
}
