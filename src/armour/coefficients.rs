//! Tables beside the formulas: Hudson's stability coefficient K_D and the damage levels S of
//! rock slopes.

/// Source of [`HUDSON_KD_TRUNK`].
pub const HUDSON_KD_SOURCE: &str = "SPM 1984 Table 7-8 (trunk, no damage, minor overtopping; \
                                    design wave H_1/10); Rock Manual 2007 §5.2.2.2";

/// Armour of Hudson's K_D table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HudsonArmour {
    /// rough angular quarry stone, two layers, random placement
    RoughAngularQuarryStone,
    /// (modified) concrete cubes, two layers, random placement
    Cube,
    /// tetrapods, two layers, random placement
    Tetrapod,
}

/// Whether the waves break on the foreshore in front of the structure (depth-limited) or not.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WaveCondition {
    /// waves breaking on the foreshore
    Breaking,
    /// non-breaking waves
    NonBreaking,
}

/// One row of the K_D table: the trunk of the structure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HudsonCoefficient {
    /// the armour
    pub armour: HudsonArmour,
    /// number of layers [-]
    pub layers: u32,
    /// K_D for breaking waves [-]
    pub breaking: f64,
    /// K_D for non-breaking waves [-]
    pub non_breaking: f64,
}

/// K_D [-] for the trunk, randomly placed double layers ([`HUDSON_KD_SOURCE`]). They are for
/// "no damage" (0–5 % of the units displaced) and, in SPM 1984, H = H_1/10.
pub const HUDSON_KD_TRUNK: [HudsonCoefficient; 3] = [
    HudsonCoefficient {
        armour: HudsonArmour::RoughAngularQuarryStone,
        layers: 2,
        breaking: 2.0,
        non_breaking: 4.0,
    },
    HudsonCoefficient {
        armour: HudsonArmour::Cube,
        layers: 2,
        breaking: 6.5,
        non_breaking: 7.5,
    },
    HudsonCoefficient {
        armour: HudsonArmour::Tetrapod,
        layers: 2,
        breaking: 7.0,
        non_breaking: 8.0,
    },
];

/// K_D [-] of [`HUDSON_KD_TRUNK`] for an armour and wave condition.
pub fn hudson_kd(armour: HudsonArmour, waves: WaveCondition) -> f64 {
    let row = HUDSON_KD_TRUNK
        .iter()
        .find(|row| row.armour == armour)
        .expect("every HudsonArmour has a row");
    match waves {
        WaveCondition::Breaking => row.breaking,
        WaveCondition::NonBreaking => row.non_breaking,
    }
}

/// Source of [`damage_levels`].
pub const DAMAGE_LEVELS_SOURCE: &str = "Van der Meer 1988; Rock Manual 2007 §5.2.2.2; CEM VI-5";

/// Damage levels S [-] of a two-layer rock armour (S = A_e/D_n50², A_e the eroded area [m²]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DamageLevels {
    /// start of damage, the design value for no damage [-]
    pub start: f64,
    /// intermediate damage, repair needed: the range [-]
    pub intermediate: (f64, f64),
    /// failure: the filter layer shows through the armour [-]
    pub failure: f64,
}

/// The table of [`DAMAGE_LEVELS_SOURCE`], by cot α [-].
const DAMAGE_LEVEL_TABLE: [(f64, DamageLevels); 5] = [
    (
        1.5,
        DamageLevels {
            start: 2.0,
            intermediate: (3.0, 5.0),
            failure: 8.0,
        },
    ),
    (
        2.0,
        DamageLevels {
            start: 2.0,
            intermediate: (4.0, 6.0),
            failure: 8.0,
        },
    ),
    (
        3.0,
        DamageLevels {
            start: 2.0,
            intermediate: (6.0, 9.0),
            failure: 12.0,
        },
    ),
    (
        4.0,
        DamageLevels {
            start: 3.0,
            intermediate: (8.0, 12.0),
            failure: 17.0,
        },
    ),
    (
        6.0,
        DamageLevels {
            start: 3.0,
            intermediate: (8.0, 12.0),
            failure: 17.0,
        },
    ),
];

/// Damage levels for a slope cot α [-] ([`DAMAGE_LEVELS_SOURCE`]). The table has rows for
/// 1:1.5, 1:2, 1:3, 1:4 and 1:6; between rows this takes the steeper one, whose levels are
/// lower (on the safe side) rather than interpolating numbers the tests never gave. None
/// outside 1:1.5 … 1:6.
pub fn damage_levels(cot_alpha: f64) -> Option<DamageLevels> {
    if !(1.5..=6.0).contains(&cot_alpha) {
        return None;
    }
    DAMAGE_LEVEL_TABLE
        .iter()
        .rev()
        .find(|(row_cot, _)| *row_cot <= cot_alpha)
        .map(|(_, levels)| *levels)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rows of Van der Meer (1988) as reprinted in the Rock Manual and on
    /// Wikipedia "Van der Meer formula": 1:2 → 2, 4–6, 8; 1:3 → 2, 6–9, 12.
    #[test]
    fn damage_levels_read_the_published_rows() {
        let row = damage_levels(2.0).unwrap();
        assert_eq!(
            (row.start, row.intermediate, row.failure),
            (2.0, (4.0, 6.0), 8.0)
        );
        let row = damage_levels(3.0).unwrap();
        assert_eq!(
            (row.start, row.intermediate, row.failure),
            (2.0, (6.0, 9.0), 12.0)
        );
        assert_eq!(damage_levels(6.0).unwrap().failure, 17.0);
    }

    #[test]
    fn damage_levels_between_rows_take_the_steeper_slope() {
        assert_eq!(damage_levels(2.5), damage_levels(2.0));
        assert_eq!(damage_levels(5.0), damage_levels(4.0));
        assert_eq!(damage_levels(1.7), damage_levels(1.5));
        assert_eq!(damage_levels(1.4), None);
        assert_eq!(damage_levels(6.5), None);
    }

    /// SPM 1984 Table 7-8, trunk: rough angular stone 2.0/4.0, cubes 6.5/7.5, tetrapods 7.0/8.0.
    #[test]
    fn hudson_kd_reads_the_published_table() {
        use HudsonArmour::*;
        use WaveCondition::*;
        assert_eq!(hudson_kd(RoughAngularQuarryStone, Breaking), 2.0);
        assert_eq!(hudson_kd(RoughAngularQuarryStone, NonBreaking), 4.0);
        assert_eq!(hudson_kd(Cube, Breaking), 6.5);
        assert_eq!(hudson_kd(Cube, NonBreaking), 7.5);
        assert_eq!(hudson_kd(Tetrapod, Breaking), 7.0);
        assert_eq!(hudson_kd(Tetrapod, NonBreaking), 8.0);
    }
}
