//! The statistics an ensemble of beds is judged by: the mean of a quantity over the members
//! with its standard error, and a one-sided 95 % Student-t bound that decides a criterion
//! (or leaves it undecided when the bound straddles the threshold).

/// The mean of a quantity over `n` independent members and its standard error,
///
/// ```text
/// x̄ = Σ x_i / n ,   SE = s / √n ,   s² = Σ (x_i − x̄)² / (n − 1)
/// ```
///
/// (SE is NaN for one member: one realisation says nothing about the spread).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate {
    /// x̄.
    pub mean: f64,
    /// SE = s/√n.
    pub se: f64,
    /// Members n.
    pub n: usize,
}

impl Estimate {
    /// The estimate from the members' values, summed in their order (members are in seed
    /// order, so the result does not depend on which finished first).
    pub fn of(xs: &[f64]) -> Estimate {
        let n = xs.len();
        let mean = xs.iter().sum::<f64>() / n as f64;
        let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n as f64 - 1.0);
        Estimate {
            mean,
            se: (var / n as f64).sqrt(),
            n,
        }
    }

    /// The standard deviation of the members, s = SE √n.
    pub fn spread(&self) -> f64 {
        self.se * (self.n as f64).sqrt()
    }

    /// The one-sided 95 % bound above the mean, x̄ + t₀.₉₅(n − 1) SE.
    pub fn upper(&self) -> f64 {
        self.mean + t95(self.n.saturating_sub(1)) * self.se
    }

    /// The one-sided 95 % bound below the mean, x̄ − t₀.₉₅(n − 1) SE.
    pub fn lower(&self) -> f64 {
        self.mean - t95(self.n.saturating_sub(1)) * self.se
    }

    /// Whether the mean lies below `threshold` with 95 % confidence: holds when the upper
    /// bound is below it, fails when the lower bound is above it, undecided otherwise.
    pub fn below(&self, threshold: f64) -> Verdict {
        if self.upper() < threshold {
            Verdict::Holds
        } else if self.lower() > threshold {
            Verdict::Fails
        } else {
            Verdict::Undecided
        }
    }

    /// Members needed for [`Estimate::below`] to decide at this mean and spread: the
    /// smallest n with t₀.₉₅(n − 1) s/√n < |x̄ − threshold| (None beyond 1000, or with no
    /// spread measured).
    pub fn members_to_decide(&self, threshold: f64) -> Option<usize> {
        let (gap, s) = ((self.mean - threshold).abs(), self.spread());
        if !s.is_finite() {
            return None;
        }
        (2..=1000).find(|&n| t95(n - 1) * s / (n as f64).sqrt() < gap)
    }

    /// `x̄ ± SE` with three decimals.
    pub fn text(&self) -> String {
        format!("{:.3} ± {:.3}", self.mean, self.se)
    }

    /// `x̄ ± SE` with three decimals and the sign of x̄ always written (for changes).
    pub fn signed(&self) -> String {
        format!("{:+.3} ± {:.3}", self.mean, self.se)
    }
}

/// Whether a criterion holds on an ensemble at 95 % confidence.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// It holds with 95 % confidence.
    Holds,
    /// It fails with 95 % confidence.
    Fails,
    /// The ensemble is too small to tell.
    Undecided,
}

impl Verdict {
    /// Both must hold; either failing fails.
    pub fn and(self, other: Verdict) -> Verdict {
        use Verdict::*;
        match (self, other) {
            (Fails, _) | (_, Fails) => Fails,
            (Holds, Holds) => Holds,
            _ => Undecided,
        }
    }

    /// `pass`, `FAIL` or `UNDECIDED`.
    pub fn text(self) -> &'static str {
        match self {
            Verdict::Holds => "pass",
            Verdict::Fails => "FAIL",
            Verdict::Undecided => "UNDECIDED",
        }
    }
}

/// The one-sided 95 % quantile of Student's t with `df` degrees of freedom (the standard
/// table to 30; beyond, t ≈ z (1 + (z² + 1)/(4 df)) with z = 1.645, within 0.2 % there).
/// Infinite for df = 0.
pub fn t95(df: usize) -> f64 {
    const TABLE: [f64; 30] = [
        6.314, 2.920, 2.353, 2.132, 2.015, 1.943, 1.895, 1.860, 1.833, 1.812, 1.796, 1.782, 1.771,
        1.761, 1.753, 1.746, 1.740, 1.734, 1.729, 1.725, 1.721, 1.717, 1.714, 1.711, 1.708, 1.706,
        1.703, 1.701, 1.699, 1.697,
    ];
    match df {
        0 => f64::INFINITY,
        1..=30 => TABLE[df - 1],
        _ => {
            let z = 1.645_f64;
            z * (1.0 + (z * z + 1.0) / (4.0 * df as f64))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mean_and_standard_error_of_a_known_sample() {
        // 2, 4, 4, 4, 5, 5, 7, 9: mean 5, s² = 32/7.
        let e = Estimate::of(&[2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0]);
        assert_eq!(e.mean, 5.0);
        assert!((e.se - (32.0f64 / 7.0 / 8.0).sqrt()).abs() < 1e-15);
        assert!((e.spread() - (32.0f64 / 7.0).sqrt()).abs() < 1e-14);
        assert!(Estimate::of(&[1.0]).se.is_nan());
    }

    #[test]
    fn t_quantiles_match_the_table_and_join_it_smoothly() {
        assert_eq!(t95(1), 6.314);
        assert_eq!(t95(5), 2.015);
        assert!(t95(0).is_infinite());
        // Beyond the table: t(40) = 1.684, t(60) = 1.671, t(120) = 1.658 (standard table).
        for (df, t) in [(40, 1.684), (60, 1.671), (120, 1.658)] {
            assert!((t95(df) - t).abs() < 0.003, "df {df}: {}", t95(df));
        }
    }

    #[test]
    fn a_criterion_is_decided_only_when_the_bound_clears_the_threshold() {
        // Mean −0.15 with SE 0.01 over 6 members: upper bound −0.15 + 2.015 × 0.01 < −0.1.
        let sure = Estimate {
            mean: -0.15,
            se: 0.01,
            n: 6,
        };
        assert_eq!(sure.below(-0.1), Verdict::Holds);
        assert_eq!(sure.below(-0.2), Verdict::Fails);
        let unsure = Estimate { se: 0.04, ..sure };
        assert_eq!(unsure.below(-0.1), Verdict::Undecided);
        // s = 0.098; the gap 0.05 needs t s/√n < 0.05: n = 13 (t = 1.782, 0.0484).
        assert_eq!(unsure.members_to_decide(-0.1), Some(13));
        assert_eq!(Verdict::Holds.and(Verdict::Undecided), Verdict::Undecided);
        assert_eq!(Verdict::Undecided.and(Verdict::Fails), Verdict::Fails);
    }
}
