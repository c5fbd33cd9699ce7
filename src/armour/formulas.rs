//! Design formulas for armour layers: Hudson (1959) and Van der Meer (1988).
//!
//! Symbols and units (all formulas below):
//! * H_s significant wave height at the toe [m]; H design wave height of Hudson's formula [m]
//! * T_m mean wave period [s]; N number of waves in the storm [-]
//! * ρ_r, ρ_w densities of the armour and of the water [kg/m³]; Δ = ρ_r/ρ_w − 1 [-]
//! * D_n50 nominal diameter, the side of the cube of the median mass [m]; W50 = ρ_r D_n50³
//!   median mass [kg]; D_n the same for a concrete unit [m]
//! * cot α the front slope, horizontal over vertical [-]
//! * P notional permeability [-] (0.1 impermeable core … 0.6 homogeneous rock)
//! * S damage level A_e/D_n50², A_e the eroded cross-section area [m²] [-]
//! * N_od displaced units per width D_n across the slope [-]
//! * s_m = 2π H_s/(g T_m²) fictitious wave steepness [-], g = [`GRAVITY`] [m/s²]
//! * ξ_m = tan α / √s_m Iribarren (surf similarity) number [-]
//! * N_s = H_s/(Δ D_n50) stability number [-]

use std::f64::consts::PI;

/// Acceleration of gravity g [m/s²] in the deep-water wave length g T_m²/2π.
pub const GRAVITY: f64 = 9.81;

/// H_1/10 / H_s [-] for Rayleigh-distributed heights. SPM 1984 (p. 7-203) designs with
/// H = H_1/10 in Hudson's formula, with the K_D of its Table 7-8.
pub const H_TENTH_OVER_SIGNIFICANT: f64 = 1.27;

/// Relative buoyant density Δ = ρ_r/ρ_w − 1 [-], ρ_r and ρ_w in [kg/m³].
pub fn relative_buoyant_density(armour_density: f64, water_density: f64) -> f64 {
    armour_density / water_density - 1.0
}

/// Nominal diameter D_n50 = (W50/ρ_r)^(1/3) [m] of median mass W50 [kg], ρ_r [kg/m³].
pub fn nominal_diameter_from_mass(median_mass: f64, armour_density: f64) -> f64 {
    (median_mass / armour_density).cbrt()
}

/// Median mass W50 = ρ_r D_n50³ [kg] of nominal diameter D_n50 [m], ρ_r [kg/m³].
pub fn median_mass_from_nominal_diameter(nominal_diameter: f64, armour_density: f64) -> f64 {
    armour_density * nominal_diameter.powi(3)
}

/// Fictitious deep-water steepness s_m = 2π H_s/(g T_m²) [-] (s_om of Van der Meer 1988), from
/// H_s [m] and T_m [s].
pub fn mean_wave_steepness(significant_wave_height: f64, mean_period: f64) -> f64 {
    2.0 * PI * significant_wave_height / (GRAVITY * mean_period * mean_period)
}

/// Iribarren number ξ_m = tan α / √s_m [-], from cot α [-] and s_m [-].
pub fn iribarren_number(cot_alpha: f64, steepness: f64) -> f64 {
    1.0 / (cot_alpha * steepness.sqrt())
}

// ---------------------------------------------------------------------------------------
// Hudson (1959), in the form of the Shore Protection Manual (CERC 1984, ch. 7)
// ---------------------------------------------------------------------------------------

/// Hudson's stability number (Hudson 1959; SPM 1984 ch. 7; Rock Manual 2007 eq. 5.133):
///
/// N_s = H/(Δ D_n50) = (K_D cot α)^(1/3)
///
/// H design wave height [m] (H_1/10 in SPM 1984, see [`H_TENTH_OVER_SIGNIFICANT`]), K_D [-]
/// from [`super::coefficients::hudson_kd`], cot α [-].
pub fn hudson_stability_number(kd: f64, cot_alpha: f64) -> f64 {
    (kd * cot_alpha).cbrt()
}

/// Required nominal diameter D_n50 = H/(Δ (K_D cot α)^(1/3)) [m] (Hudson 1959, SPM 1984), for
/// the design wave height H [m], Δ [-], K_D [-], cot α [-].
pub fn hudson_nominal_diameter(
    wave_height: f64,
    relative_density: f64,
    kd: f64,
    cot_alpha: f64,
) -> f64 {
    wave_height / (relative_density * hudson_stability_number(kd, cot_alpha))
}

/// Required median mass (Hudson 1959; SPM 1984 ch. 7, with ρ_r for the unit weight):
///
/// W50 = ρ_r D_n50³ = ρ_r H³ / (K_D Δ³ cot α)   [kg]
///
/// H [m], ρ_r and ρ_w [kg/m³], K_D [-], cot α [-].
pub fn hudson_median_mass(
    wave_height: f64,
    armour_density: f64,
    water_density: f64,
    kd: f64,
    cot_alpha: f64,
) -> f64 {
    let delta = relative_buoyant_density(armour_density, water_density);
    let diameter = hudson_nominal_diameter(wave_height, delta, kd, cot_alpha);
    median_mass_from_nominal_diameter(diameter, armour_density)
}

/// Allowable design wave height H = Δ D_n50 (K_D cot α)^(1/3) [m] for armour of nominal diameter
/// D_n50 [m] (Hudson 1959, SPM 1984); Δ [-], K_D [-], cot α [-].
pub fn hudson_allowable_wave_height(
    nominal_diameter: f64,
    relative_density: f64,
    kd: f64,
    cot_alpha: f64,
) -> f64 {
    relative_density * nominal_diameter * hudson_stability_number(kd, cot_alpha)
}

// ---------------------------------------------------------------------------------------
// Van der Meer (1988), rock, deep water
// ---------------------------------------------------------------------------------------

/// c_pl [-] of the plunging formula: the mean fit of Van der Meer (1988), σ = 0.4.
pub const VAN_DER_MEER_PLUNGING_COEFFICIENT: f64 = 6.2;
/// c_s [-] of the surging formula: the mean fit of Van der Meer (1988), σ = 0.08.
pub const VAN_DER_MEER_SURGING_COEFFICIENT: f64 = 1.0;
/// From this cot α [-] on only the plunging formula holds (Van der Meer 1993, "Conceptual
/// design of rubble mound breakwaters", §4.2; Rock Manual 2007 §5.2.2.2): on such gentle
/// slopes the surging branch was not seen in the tests.
pub const PLUNGING_ONLY_FROM_COT_ALPHA: f64 = 4.0;

/// Which of Van der Meer's two formulas applies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BreakerType {
    /// ξ_m < ξ_mc, or cot α ≥ 4
    Plunging,
    /// ξ_m ≥ ξ_mc and cot α < 4
    Surging,
}

/// The structure in Van der Meer's rock formula.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RockSlope {
    /// cot α, horizontal over vertical [-]
    pub cot_alpha: f64,
    /// notional permeability P [-]
    pub permeability: f64,
}

/// A storm at the toe of the structure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeaState {
    /// H_s [m]
    pub significant_wave_height: f64,
    /// T_m [s]
    pub mean_period: f64,
    /// N [-]
    pub number_of_waves: f64,
}

impl SeaState {
    /// s_m = 2π H_s/(g T_m²) [-]
    pub fn steepness(&self) -> f64 {
        mean_wave_steepness(self.significant_wave_height, self.mean_period)
    }
}

/// Transition between plunging and surging (Van der Meer 1988; Rock Manual 2007 §5.2.2.2),
/// where the two formulas give the same N_s:
///
/// ξ_mc = (c_pl/c_s P^0.31 √tan α)^(1/(P+0.5))   [-]
pub fn van_der_meer_transition_iribarren(slope: RockSlope) -> f64 {
    let ratio = VAN_DER_MEER_PLUNGING_COEFFICIENT / VAN_DER_MEER_SURGING_COEFFICIENT;
    (ratio * slope.permeability.powf(0.31) * (1.0 / slope.cot_alpha).sqrt())
        .powf(1.0 / (slope.permeability + 0.5))
}

/// Plunging for ξ_m < ξ_mc, surging above, and plunging only for cot α ≥ 4
/// ([`PLUNGING_ONLY_FROM_COT_ALPHA`]); ξ_m [-].
pub fn van_der_meer_breaker_type(slope: RockSlope, iribarren: f64) -> BreakerType {
    if slope.cot_alpha >= PLUNGING_ONLY_FROM_COT_ALPHA
        || iribarren < van_der_meer_transition_iribarren(slope)
    {
        BreakerType::Plunging
    } else {
        BreakerType::Surging
    }
}

/// N_s at S/√N = 1, one of the two formulas (Van der Meer 1988; Rock Manual 2007 §5.2.2.2):
///
/// plunging: H_s/(Δ D_n50) = c_pl P^0.18 (S/√N)^0.2 ξ_m^-0.5
/// surging:  H_s/(Δ D_n50) = c_s P^-0.13 (S/√N)^0.2 √cot α ξ_m^P
pub fn van_der_meer_rock_formula(breaker: BreakerType, slope: RockSlope, iribarren: f64) -> f64 {
    let p = slope.permeability;
    match breaker {
        BreakerType::Plunging => {
            VAN_DER_MEER_PLUNGING_COEFFICIENT * p.powf(0.18) * iribarren.powf(-0.5)
        }
        BreakerType::Surging => {
            VAN_DER_MEER_SURGING_COEFFICIENT
                * p.powf(-0.13)
                * slope.cot_alpha.sqrt()
                * iribarren.powf(p)
        }
    }
}

/// Stability number N_s = H_s/(Δ D_n50) [-] at which the damage after N waves is S (Van der
/// Meer 1988, deep water, the formula chosen by [`van_der_meer_breaker_type`]):
///
/// N_s = F(ξ_m) (S/√N)^0.2, F of [`van_der_meer_rock_formula`]
///
/// s_m [-], S [-], N [-].
pub fn van_der_meer_rock_stability_number(
    slope: RockSlope,
    steepness: f64,
    damage: f64,
    number_of_waves: f64,
) -> f64 {
    let xi = iribarren_number(slope.cot_alpha, steepness);
    let breaker = van_der_meer_breaker_type(slope, xi);
    van_der_meer_rock_formula(breaker, slope, xi) * (damage / number_of_waves.sqrt()).powf(0.2)
}

/// Damage level after N waves, the inverse of [`van_der_meer_rock_stability_number`] (the
/// breaker type depends on ξ_m alone, so the inverse is exact):
///
/// S = √N (N_s / F(ξ_m))^5   [-]
///
/// N_s [-], s_m [-], N [-].
pub fn van_der_meer_rock_damage(
    slope: RockSlope,
    steepness: f64,
    stability_number: f64,
    number_of_waves: f64,
) -> f64 {
    let xi = iribarren_number(slope.cot_alpha, steepness);
    let breaker = van_der_meer_breaker_type(slope, xi);
    number_of_waves.sqrt()
        * (stability_number / van_der_meer_rock_formula(breaker, slope, xi)).powi(5)
}

/// Damage S [-] of rock of nominal diameter D_n50 [m] and Δ [-] under a storm: the curve of S
/// against the number of waves the damage report draws (Van der Meer 1988, as
/// [`van_der_meer_rock_damage`] with N_s = H_s/(Δ D_n50)).
pub fn van_der_meer_rock_damage_in_storm(
    slope: RockSlope,
    relative_density: f64,
    nominal_diameter: f64,
    sea: SeaState,
) -> f64 {
    let stability_number = sea.significant_wave_height / (relative_density * nominal_diameter);
    van_der_meer_rock_damage(
        slope,
        sea.steepness(),
        stability_number,
        sea.number_of_waves,
    )
}

/// Required nominal diameter D_n50 = H_s/(Δ N_s) [m] for damage S [-] after the storm (Van der
/// Meer 1988); Δ [-].
pub fn van_der_meer_rock_nominal_diameter(
    slope: RockSlope,
    relative_density: f64,
    sea: SeaState,
    damage: f64,
) -> f64 {
    let ns =
        van_der_meer_rock_stability_number(slope, sea.steepness(), damage, sea.number_of_waves);
    sea.significant_wave_height / (relative_density * ns)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::armour::coefficients::{hudson_kd, HudsonArmour, WaveCondition};

    /// A published figure given to `decimals` places is the exact value rounded: the two differ
    /// by at most half a unit of the last digit (1e-12 for the round-off of f64).
    pub(crate) fn assert_rounds_to(computed: f64, published: f64, decimals: i32) {
        let half_unit = 0.5 * 10f64.powi(-decimals);
        assert!(
            (computed - published).abs() <= half_unit + 1e-12,
            "computed {computed} does not round to the published {published} ({decimals} places)"
        );
    }

    pub(crate) fn assert_relative(a: f64, b: f64, tolerance: f64) {
        assert!(
            (a - b).abs() <= tolerance * b.abs(),
            "{a} vs {b}: relative {}",
            (a - b).abs() / b.abs()
        );
    }

    /// Hudson: published worked example (arizval.app, "Breakwaters and coastal structures",
    /// example 1): H = 4.5 m, rough angular quarrystone γ_r = 26.0 kN/m³, S_r = 2.65, K_D = 4.0,
    /// cot θ = 2 → W = 65.9 kN. Weights are g times masses, so ρ = γ/g gives W = g W50.
    #[test]
    fn hudson_weight_matches_the_worked_quarrystone_example() {
        let kd = hudson_kd(
            HudsonArmour::RoughAngularQuarryStone,
            WaveCondition::NonBreaking,
        );
        let rock = 26.0e3 / GRAVITY;
        let mass = hudson_median_mass(4.5, rock, rock / 2.65, kd, 2.0);
        assert_rounds_to(GRAVITY * mass / 1e3, 65.9, 1);
    }

    /// Hudson: published worked example (reuven.tools, breakwater armor calculator): H = 3 m,
    /// γ_r = 25.5 kN/m³, γ_w = 10.05 kN/m³, K_D = 4, cot θ = 2 → W = 23.7 kN.
    #[test]
    fn hudson_weight_matches_the_worked_calculator_example() {
        let mass = hudson_median_mass(3.0, 25.5e3 / GRAVITY, 10.05e3 / GRAVITY, 4.0, 2.0);
        assert_rounds_to(GRAVITY * mass / 1e3, 23.7, 1);
    }

    #[test]
    fn hudson_height_and_size_round_trip() {
        for (height, kd, cot) in [(4.5, 4.0, 2.0), (2.0, 2.0, 1.5), (7.3, 8.0, 3.0)] {
            let delta = relative_buoyant_density(2650.0, 1025.0);
            let diameter = hudson_nominal_diameter(height, delta, kd, cot);
            assert_relative(
                hudson_allowable_wave_height(diameter, delta, kd, cot),
                height,
                1e-12,
            );
            let mass = hudson_median_mass(height, 2650.0, 1025.0, kd, cot);
            assert_relative(nominal_diameter_from_mass(mass, 2650.0), diameter, 1e-12);
        }
    }

    /// One case of the Deltares coastal-structures-toolbox table for Van der Meer (1988)
    /// (tests/structural/stability_rock_armour/vandermeer1988_test.py): ρ_w = 1025 kg/m³,
    /// N = 3000; its form with H_2% = 1.4 H_s and c_pl = 8.68, c_s = 1.4 is 6.2 and 1.0 on H_s.
    struct RockCase {
        cot_alpha: f64,
        permeability: f64,
        rock_density: f64,
        mean_period: f64,
        significant_wave_height: f64,
    }

    fn rock_case(c: &RockCase) -> (RockSlope, f64, SeaState) {
        let slope = RockSlope {
            cot_alpha: c.cot_alpha,
            permeability: c.permeability,
        };
        let delta = relative_buoyant_density(c.rock_density, 1025.0);
        let sea = SeaState {
            significant_wave_height: c.significant_wave_height,
            mean_period: c.mean_period,
            number_of_waves: 3000.0,
        };
        (slope, delta, sea)
    }

    fn case(
        cot_alpha: f64,
        permeability: f64,
        rock_density: f64,
        mean_period: f64,
        hs: f64,
    ) -> RockCase {
        RockCase {
            cot_alpha,
            permeability,
            rock_density,
            mean_period,
            significant_wave_height: hs,
        }
    }

    /// S for M50 = 1000 or 1200 kg against the Deltares table (given to 3 significant digits;
    /// tolerance half a unit of the last digit). The T_m = 12 s row is surging (ξ_m = 3.53 >
    /// ξ_mc = 3.01), the others plunging.
    #[test]
    fn rock_damage_matches_the_tabulated_values() {
        let rows = [
            (
                case(3.0, 0.4, 2650.0, 6.0, 2.0),
                1000.0,
                0.918,
                3,
                BreakerType::Plunging,
            ),
            (
                case(2.0, 0.4, 2650.0, 6.0, 2.0),
                1000.0,
                2.53,
                2,
                BreakerType::Plunging,
            ),
            (
                case(3.0, 0.5, 2650.0, 6.0, 2.0),
                1000.0,
                0.751,
                3,
                BreakerType::Plunging,
            ),
            (
                case(3.0, 0.4, 2850.0, 6.0, 2.0),
                1000.0,
                0.580,
                3,
                BreakerType::Plunging,
            ),
            (
                case(3.0, 0.4, 2650.0, 12.0, 2.0),
                1000.0,
                2.51,
                2,
                BreakerType::Surging,
            ),
            (
                case(3.0, 0.4, 2650.0, 6.0, 2.5),
                1000.0,
                2.12,
                2,
                BreakerType::Plunging,
            ),
            (
                case(3.0, 0.4, 2650.0, 6.0, 2.0),
                1200.0,
                0.677,
                3,
                BreakerType::Plunging,
            ),
        ];
        for (c, mass, published, decimals, breaker) in rows {
            let (slope, delta, sea) = rock_case(&c);
            let xi = iribarren_number(slope.cot_alpha, sea.steepness());
            assert_eq!(van_der_meer_breaker_type(slope, xi), breaker);
            let diameter = nominal_diameter_from_mass(mass, c.rock_density);
            let damage = van_der_meer_rock_damage_in_storm(slope, delta, diameter, sea);
            assert_rounds_to(damage, published, decimals);
        }
    }

    /// D_n50 for S = 2 or 3 against the same Deltares table (3 decimals).
    #[test]
    fn rock_nominal_diameter_matches_the_tabulated_values() {
        let rows = [
            (case(3.0, 0.4, 2650.0, 6.0, 2.0), 2.0, 0.618),
            (case(2.0, 0.4, 2650.0, 6.0, 2.0), 2.0, 0.757),
            (case(3.0, 0.4, 2650.0, 12.0, 2.0), 2.0, 0.756),
            (case(3.0, 0.4, 2650.0, 6.0, 2.0), 3.0, 0.570),
        ];
        for (c, damage, published) in rows {
            let (slope, delta, sea) = rock_case(&c);
            assert_rounds_to(
                van_der_meer_rock_nominal_diameter(slope, delta, sea, damage),
                published,
                3,
            );
        }
    }

    /// At ξ_mc the two formulas agree: the definition of ξ_mc, checked analytically.
    #[test]
    fn plunging_and_surging_agree_at_the_transition() {
        for permeability in [0.1, 0.4, 0.5, 0.6] {
            for cot_alpha in [1.5, 2.0, 3.0, 6.0] {
                let slope = RockSlope {
                    cot_alpha,
                    permeability,
                };
                let xi = van_der_meer_transition_iribarren(slope);
                let plunging = van_der_meer_rock_formula(BreakerType::Plunging, slope, xi);
                let surging = van_der_meer_rock_formula(BreakerType::Surging, slope, xi);
                assert_relative(plunging, surging, 1e-12);
            }
        }
    }

    /// Above ξ_mc the surging branch holds on 1:3.9, never on 1:4 and milder.
    #[test]
    fn gentle_slopes_use_the_plunging_formula_only() {
        for (cot_alpha, expected) in [
            (3.9, BreakerType::Surging),
            (4.0, BreakerType::Plunging),
            (6.0, BreakerType::Plunging),
        ] {
            let slope = RockSlope {
                cot_alpha,
                permeability: 0.5,
            };
            let xi = 1.5 * van_der_meer_transition_iribarren(slope);
            assert_eq!(
                van_der_meer_breaker_type(slope, xi),
                expected,
                "cot α = {cot_alpha}"
            );
        }
    }

    #[test]
    fn rock_damage_and_stability_number_round_trip() {
        for (cot_alpha, permeability, steepness) in [
            (3.0, 0.4, 0.036),
            (3.0, 0.4, 0.009),
            (1.5, 0.1, 0.02),
            (5.0, 0.6, 0.005),
        ] {
            let slope = RockSlope {
                cot_alpha,
                permeability,
            };
            for damage in [1.0, 2.0, 8.0, 17.0] {
                for number_of_waves in [500.0, 3000.0, 7500.0] {
                    let ns = van_der_meer_rock_stability_number(
                        slope,
                        steepness,
                        damage,
                        number_of_waves,
                    );
                    let back = van_der_meer_rock_damage(slope, steepness, ns, number_of_waves);
                    assert_relative(back, damage, 1e-12);
                }
            }
        }
    }

    /// S grows with N (as √N) and with H_s, across the plunging-surging switch too (T_m = 12 s:
    /// ξ_m falls through ξ_mc = 3.01 as H_s grows from 1 to 4 m).
    #[test]
    fn rock_damage_grows_with_wave_height_and_number_of_waves() {
        let slope = RockSlope {
            cot_alpha: 3.0,
            permeability: 0.4,
        };
        let delta = relative_buoyant_density(2650.0, 1025.0);
        for mean_period in [6.0, 12.0] {
            let mut previous_height = 0.0;
            for i in 0..=30 {
                let sea = SeaState {
                    significant_wave_height: 1.0 + 0.1 * i as f64,
                    mean_period,
                    number_of_waves: 3000.0,
                };
                let damage = van_der_meer_rock_damage_in_storm(slope, delta, 0.7, sea);
                assert!(
                    damage > previous_height,
                    "H_s = {}",
                    sea.significant_wave_height
                );
                previous_height = damage;
                let mut previous_count = 0.0;
                for number_of_waves in [100.0, 1000.0, 3000.0, 7500.0] {
                    let damage = van_der_meer_rock_damage_in_storm(
                        slope,
                        delta,
                        0.7,
                        SeaState {
                            number_of_waves,
                            ..sea
                        },
                    );
                    assert!(damage > previous_count);
                    previous_count = damage;
                }
            }
        }
    }
}
