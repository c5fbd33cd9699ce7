//! The design formulas for one structure and one sea state, side by side, as a damage report
//! sets them beside a simulated damage: the stability number, the breaker type, Hudson's
//! allowable height, Van der Meer's expected damage after N waves, and the ranges the inputs
//! leave.

use super::coefficients::{damage_levels, hudson_kd, DamageLevels, HudsonArmour, WaveCondition};
use super::concrete::{van_der_meer_concrete_damage_in_storm, ConcreteUnit};
use super::formulas::{
    hudson_allowable_wave_height, iribarren_number, van_der_meer_breaker_type,
    van_der_meer_rock_damage_in_storm, BreakerType, RockSlope, SeaState,
};
use super::validity::{
    van_der_meer_rock_violations, violations, Quantity, HUDSON_RANGES, VAN_DER_MEER_CUBE_RANGES,
    VAN_DER_MEER_TETRAPOD_RANGES,
};

/// The kind of armour unit, which picks the formulas (`[armour] unit`, by [`ArmourUnit::name`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ArmourUnit {
    /// Quarry stone: Van der Meer's rock formula (damage S) and Hudson's rough angular stone.
    Rock,
    /// Concrete cubes: Van der Meer's cube formula (N_od) and Hudson's cubes.
    Cube,
    /// Tetrapods: Van der Meer's tetrapod formula (N_od) and Hudson's tetrapods.
    Tetrapod,
}

impl ArmourUnit {
    /// The name as a scenario writes it.
    pub fn name(self) -> &'static str {
        match self {
            ArmourUnit::Rock => "rock",
            ArmourUnit::Cube => "cube",
            ArmourUnit::Tetrapod => "tetrapod",
        }
    }

    fn hudson(self) -> HudsonArmour {
        match self {
            ArmourUnit::Rock => HudsonArmour::RoughAngularQuarryStone,
            ArmourUnit::Cube => HudsonArmour::Cube,
            ArmourUnit::Tetrapod => HudsonArmour::Tetrapod,
        }
    }

    fn concrete(self) -> Option<ConcreteUnit> {
        match self {
            ArmourUnit::Rock => None,
            ArmourUnit::Cube => Some(ConcreteUnit::Cube),
            ArmourUnit::Tetrapod => Some(ConcreteUnit::Tetrapod),
        }
    }
}

/// The structure the formulas see.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Structure {
    /// The unit.
    pub unit: ArmourUnit,
    /// cot α and the notional permeability P [-].
    pub slope: RockSlope,
    /// Δ = ρ_s/ρ_w − 1 [-].
    pub relative_density: f64,
    /// D_n [m].
    pub nominal_diameter: f64,
    /// h, the water depth at the toe [m].
    pub depth: f64,
}

/// The formulas' answers for a structure under a sea state.
#[derive(Debug, Clone, PartialEq)]
pub struct DesignCheck {
    /// N_s = H_s/(Δ D_n) [-].
    pub stability_number: f64,
    /// s_m = 2π H_s/(g T_m²) [-].
    pub steepness: f64,
    /// ξ_m = tan α/√s_m [-].
    pub iribarren: f64,
    /// Plunging or surging (Van der Meer 1988), for rock.
    pub breaker: BreakerType,
    /// Hudson's allowable H [m] for K_D of breaking and of non-breaking waves (SPM 1984:
    /// H = H_1/10 ≈ 1.27 H_s), and those K_D [-].
    pub hudson: [(f64, f64); 2],
    /// Van der Meer's rock damage S [-] after the N waves (also given for concrete units as
    /// a yardstick of the profile's change).
    pub rock_damage: f64,
    /// Van der Meer's N_od [-] after the N waves, for cubes and tetrapods.
    pub displaced: Option<f64>,
    /// The damage levels of two-layer rock on this slope (None outside 1:1.5 … 1:6).
    pub levels: Option<DamageLevels>,
    /// The validity ranges the inputs leave, as sentences.
    pub outside: Vec<String>,
}

/// The formulas for `s` under `sea`.
pub fn design_check(s: &Structure, sea: SeaState) -> DesignCheck {
    let (delta, dn) = (s.relative_density, s.nominal_diameter);
    let steepness = sea.steepness();
    let iribarren = iribarren_number(s.slope.cot_alpha, steepness);
    let hudson = [WaveCondition::Breaking, WaveCondition::NonBreaking].map(|w| {
        let kd = hudson_kd(s.unit.hudson(), w);
        (
            hudson_allowable_wave_height(dn, delta, kd, s.slope.cot_alpha),
            kd,
        )
    });
    let rock_damage = van_der_meer_rock_damage_in_storm(s.slope, delta, dn, sea);
    let displaced =
        (s.unit.concrete()).map(|u| van_der_meer_concrete_damage_in_storm(u, delta, dn, sea));
    let mut outside = match s.unit.concrete() {
        None => van_der_meer_rock_violations(s.slope, delta, sea, s.depth, rock_damage),
        Some(u) => {
            let ranges: &[_] = match u {
                ConcreteUnit::Cube => &VAN_DER_MEER_CUBE_RANGES,
                ConcreteUnit::Tetrapod => &VAN_DER_MEER_TETRAPOD_RANGES,
            };
            let values = [
                (Quantity::CotAlpha, s.slope.cot_alpha),
                (Quantity::Steepness, steepness),
                (Quantity::NumberOfWaves, sea.number_of_waves),
            ];
            violations(ranges, &values)
        }
    };
    outside.extend(
        violations(&HUDSON_RANGES, &[(Quantity::CotAlpha, s.slope.cot_alpha)])
            .into_iter()
            .map(|v| format!("Hudson: {v}")),
    );
    DesignCheck {
        stability_number: sea.significant_wave_height / (delta * dn),
        steepness,
        iribarren,
        breaker: van_der_meer_breaker_type(s.slope, iribarren),
        hudson,
        rock_damage,
        displaced,
        levels: damage_levels(s.slope.cot_alpha),
        outside,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::armour::formulas::van_der_meer_rock_damage;

    fn structure(unit: ArmourUnit) -> Structure {
        Structure {
            unit,
            slope: RockSlope {
                cot_alpha: 2.0,
                permeability: 0.4,
            },
            relative_density: 1.65,
            nominal_diameter: 0.04,
            depth: 0.4,
        }
    }

    /// The check repeats the formulas it gathers: N_s, ξ_m, Van der Meer's S for the same
    /// input, and Hudson's H = Δ D_n (K_D cot α)^⅓ with K_D = 2 and 4 for rock.
    #[test]
    fn the_check_gathers_the_formulas_for_one_storm() {
        let s = structure(ArmourUnit::Rock);
        let sea = SeaState {
            significant_wave_height: 0.1,
            mean_period: 1.2,
            number_of_waves: 1000.0,
        };
        let c = design_check(&s, sea);
        assert!((c.stability_number - 0.1 / (1.65 * 0.04)).abs() < 1e-12);
        let sm = sea.steepness();
        assert!((c.iribarren - 0.5 / sm.sqrt()).abs() < 1e-12);
        let n_s = c.stability_number;
        let want = van_der_meer_rock_damage(s.slope, sm, n_s, 1000.0);
        assert_eq!(c.rock_damage, want);
        assert!((c.hudson[0].0 - 1.65 * 0.04 * 4.0_f64.cbrt()).abs() < 1e-12);
        assert_eq!((c.hudson[0].1, c.hudson[1].1), (2.0, 4.0));
        assert_eq!(c.displaced, None);
        assert_eq!(c.levels.unwrap().start, 2.0);
        // h/H_s = 4: deep water, and every other input in range but S (0.54 < 1).
        assert_eq!(c.outside.len(), 1, "{:?}", c.outside);
    }

    /// Cubes get N_od and the cube ranges: a 1:2 slope is outside the one slope tested.
    #[test]
    fn cubes_get_displaced_units_and_their_ranges() {
        let sea = SeaState {
            significant_wave_height: 0.1,
            mean_period: 1.2,
            number_of_waves: 1000.0,
        };
        let c = design_check(&structure(ArmourUnit::Cube), sea);
        assert!(c.displaced.unwrap() > 0.0);
        assert!(
            c.outside.iter().any(|v| v.contains("cot α")),
            "{:?}",
            c.outside
        );
        // Far below the design wave the cubes stay: N_od = 0.
        let calm = SeaState {
            significant_wave_height: 0.01,
            ..sea
        };
        assert_eq!(
            design_check(&structure(ArmourUnit::Cube), calm).displaced,
            Some(0.0)
        );
    }

    /// Regular waves at the rubble-mound example's N_s = 0.6 break the deep-water and damage
    /// ranges: the check lists them rather than hiding them.
    #[test]
    fn inputs_outside_the_tests_are_listed() {
        let sea = SeaState {
            significant_wave_height: 0.04,
            mean_period: 0.8,
            number_of_waves: 6.0,
        };
        let mut s = structure(ArmourUnit::Rock);
        s.depth = 0.1;
        let c = design_check(&s, sea);
        assert!(
            c.outside.iter().any(|v| v.starts_with("S =")),
            "{:?}",
            c.outside
        );
        assert!(
            c.outside.iter().any(|v| v.starts_with("h/H_s")),
            "{:?}",
            c.outside
        );
    }
}
