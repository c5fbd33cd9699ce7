//! Van der Meer (1988) for concrete cubes and tetrapods, two layers on a 1:1.5 slope, in both
//! directions: damage N_od from a storm, and the allowable H_s for a damage. Symbols and units
//! as in [`super::formulas`]; N_od is the number of displaced units per width D_n [-].

use super::formulas::{mean_wave_steepness, SeaState};

/// A concrete unit of Van der Meer's (1988) tests, two layers on a 1:1.5 slope.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ConcreteUnit {
    /// H_s/(Δ D_n) = (6.7 N_od^0.4/N^0.3 + 1.0) s_m^-0.1
    Cube,
    /// H_s/(Δ D_n) = (3.75 N_od^0.5/N^0.25 + 0.85) s_m^-0.2
    Tetrapod,
}

/// (a, k, m, b, c) of N_s = (a N_od^k / N^m + b) s_m^-c.
fn concrete_coefficients(unit: ConcreteUnit) -> (f64, f64, f64, f64, f64) {
    match unit {
        ConcreteUnit::Cube => (6.7, 0.4, 0.3, 1.0, 0.1),
        ConcreteUnit::Tetrapod => (3.75, 0.5, 0.25, 0.85, 0.2),
    }
}

/// Stability number of concrete units (Van der Meer 1988, thesis; Rock Manual 2007
/// ch. 5, concrete armour units), s_m = s_om from T_m as in [`mean_wave_steepness`]:
///
/// cubes:     H_s/(Δ D_n) = (6.7 N_od^0.4 / N^0.3 + 1.0) s_m^-0.1
/// tetrapods: H_s/(Δ D_n) = (3.75 N_od^0.5 / N^0.25 + 0.85) s_m^-0.2
///
/// N_od [-], N [-], s_m [-]; returns N_s [-].
pub fn van_der_meer_concrete_stability_number(
    unit: ConcreteUnit,
    displaced_units: f64,
    number_of_waves: f64,
    steepness: f64,
) -> f64 {
    let (a, k, m, b, c) = concrete_coefficients(unit);
    (a * displaced_units.powf(k) / number_of_waves.powf(m) + b) * steepness.powf(-c)
}

/// Displaced units N_od [-] for a stability number N_s [-], the inverse of
/// [`van_der_meer_concrete_stability_number`]:
///
/// N_od = ((N_s s_m^c − b) N^m / a)^(1/k)
///
/// and 0 where N_s s_m^c ≤ b: below the formula's no-damage line.
pub fn van_der_meer_concrete_displaced_units(
    unit: ConcreteUnit,
    stability_number: f64,
    number_of_waves: f64,
    steepness: f64,
) -> f64 {
    let (a, k, m, b, c) = concrete_coefficients(unit);
    let excess = stability_number * steepness.powf(c) - b;
    if excess <= 0.0 {
        return 0.0;
    }
    (excess * number_of_waves.powf(m) / a).powf(1.0 / k)
}

/// N_od [-] of units of D_n [m] and Δ [-] under a storm (Van der Meer 1988), s_m from H_s, T_m.
pub fn van_der_meer_concrete_damage_in_storm(
    unit: ConcreteUnit,
    relative_density: f64,
    nominal_diameter: f64,
    sea: SeaState,
) -> f64 {
    let stability_number = sea.significant_wave_height / (relative_density * nominal_diameter);
    van_der_meer_concrete_displaced_units(
        unit,
        stability_number,
        sea.number_of_waves,
        sea.steepness(),
    )
}

/// Allowable H_s [m] for N_od [-] after N waves of mean period T_m [s], units of D_n [m] and
/// Δ [-]. With F = a N_od^k/N^m + b and s_m = 2π H_s/(g T_m²) the formula
/// H_s = Δ D_n F s_m^-c solves in closed form:
///
/// H_s = (Δ D_n F (2π/(g T_m²))^-c)^(1/(1+c))
pub fn van_der_meer_concrete_allowable_wave_height(
    unit: ConcreteUnit,
    relative_density: f64,
    nominal_diameter: f64,
    displaced_units: f64,
    number_of_waves: f64,
    mean_period: f64,
) -> f64 {
    let (_, _, _, _, c) = concrete_coefficients(unit);
    // N_s at unit steepness is F; s_m = H_s · (2π/(g T_m²)).
    let f = van_der_meer_concrete_stability_number(unit, displaced_units, number_of_waves, 1.0);
    let steepness_per_metre = mean_wave_steepness(1.0, mean_period);
    (relative_density * nominal_diameter * f * steepness_per_metre.powf(-c)).powf(1.0 / (1.0 + c))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::armour::formulas::relative_buoyant_density;
    use crate::armour::formulas::tests::{assert_relative, assert_rounds_to};
    /// Cubes against the Deltares table for Van der Meer (1988) cubes
    /// (tests/structural/stability_concrete_armour/cubes_double_layer_vandermeer1988_test.py),
    /// ρ_c = 2400 kg/m³, ρ_w = 1025 kg/m³, N = 3000; published to 3 decimals (D_n) or 2 (H_s,
    /// N_od), tolerance half a unit of the last digit. Its T_m = 15 s row (0.772) is left out:
    /// the formula gives 0.7714, which its own tolerance of 1e-3 admits but rounding does not.
    #[test]
    fn cubes_match_the_tabulated_values() {
        let delta = relative_buoyant_density(2400.0, 1025.0);
        let n = 3000.0;
        for (height, period, displaced, published) in
            [(3.0, 8.0, 2.0, 0.875), (3.0, 8.0, 4.0, 0.766)]
        {
            let ns = van_der_meer_concrete_stability_number(
                ConcreteUnit::Cube,
                displaced,
                n,
                mean_wave_steepness(height, period),
            );
            assert_rounds_to(height / (delta * ns), published, 3);
        }
        // H_s for D_n = 1.5 m and N_od = 2 at a given s_om.
        for (steepness, published) in [(0.05, 4.89), (0.03, 5.14)] {
            let ns = van_der_meer_concrete_stability_number(ConcreteUnit::Cube, 2.0, n, steepness);
            assert_rounds_to(delta * 1.5 * ns, published, 2);
        }
        // N_od for H_s = 5 m, D_n = 1.5 m.
        for (steepness, published, decimals) in [(0.05, 2.27, 2), (0.03, 1.7, 1)] {
            let ns = 5.0 / (delta * 1.5);
            assert_rounds_to(
                van_der_meer_concrete_displaced_units(ConcreteUnit::Cube, ns, n, steepness),
                published,
                decimals,
            );
        }
    }

    #[test]
    fn concrete_damage_and_wave_height_round_trip() {
        for unit in [ConcreteUnit::Cube, ConcreteUnit::Tetrapod] {
            for (displaced, number_of_waves, mean_period) in
                [(0.5, 1000.0, 7.0), (2.0, 3000.0, 10.0), (4.0, 7000.0, 14.0)]
            {
                let delta = relative_buoyant_density(2400.0, 1025.0);
                let height = van_der_meer_concrete_allowable_wave_height(
                    unit,
                    delta,
                    1.6,
                    displaced,
                    number_of_waves,
                    mean_period,
                );
                let sea = SeaState {
                    significant_wave_height: height,
                    mean_period,
                    number_of_waves,
                };
                assert_relative(
                    van_der_meer_concrete_damage_in_storm(unit, delta, 1.6, sea),
                    displaced,
                    1e-12,
                );
                let ns = van_der_meer_concrete_stability_number(
                    unit,
                    displaced,
                    number_of_waves,
                    sea.steepness(),
                );
                assert_relative(height / (delta * 1.6), ns, 1e-12);
            }
        }
    }

    #[test]
    fn concrete_damage_grows_with_wave_height_and_number_of_waves() {
        let delta = relative_buoyant_density(2400.0, 1025.0);
        for unit in [ConcreteUnit::Cube, ConcreteUnit::Tetrapod] {
            let mut previous = 0.0;
            // From above the no-damage line (N_s s_m^c > b) up.
            for i in 0..=20 {
                let sea = SeaState {
                    significant_wave_height: 4.0 + 0.2 * i as f64,
                    mean_period: 10.0,
                    number_of_waves: 3000.0,
                };
                let displaced = van_der_meer_concrete_damage_in_storm(unit, delta, 1.5, sea);
                assert!(
                    displaced > previous,
                    "{unit:?} H_s = {}",
                    sea.significant_wave_height
                );
                previous = displaced;
            }
            let sea = SeaState {
                significant_wave_height: 5.0,
                mean_period: 10.0,
                number_of_waves: 1000.0,
            };
            let few = van_der_meer_concrete_damage_in_storm(unit, delta, 1.5, sea);
            let many = van_der_meer_concrete_damage_in_storm(
                unit,
                delta,
                1.5,
                SeaState {
                    number_of_waves: 5000.0,
                    ..sea
                },
            );
            assert!(many > few && few > 0.0, "{unit:?}");
        }
    }

    /// Below the no-damage line the inverse returns 0 rather than the power of a negative number.
    #[test]
    fn small_waves_displace_no_concrete_units() {
        let ns =
            0.5 * van_der_meer_concrete_stability_number(ConcreteUnit::Tetrapod, 0.0, 3000.0, 0.04);
        assert_eq!(
            van_der_meer_concrete_displaced_units(ConcreteUnit::Tetrapod, ns, 3000.0, 0.04),
            0.0
        );
    }
}
