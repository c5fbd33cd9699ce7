//! Validation of the wave flume's absorbing zone (issue 28): how much of a regular wave a
//! relaxation zone 1.5 wavelengths long sends back, for kh from 0.5 to 3, from three gauges
//! in front of it (Mansard & Funke 1980). Set-up, criteria and cost: `README.md`.

pub mod report;

pub use super::flume_case::{FlumeCase, Resolution, Run, Theory};

/// Still-water depth h [m].
pub const DEPTH: f64 = 0.4;
/// Wave height H [m]: H/h = 0.05, steepness H/L from 0.004 (kh = 0.5) to 0.024 (kh = 3).
pub const HEIGHT: f64 = 0.02;
/// The largest reflection coefficient allowed (the criterion).
pub const LIMIT: f64 = 0.05;

/// The flume for kh: a generating zone of 1 L, a test section of 2 L with one gauge array
/// 0.75 L from the generating zone, an absorbing zone of 1.5 L; 0.1 m of air; a ramp of 2
/// periods; the last 3 periods analysed.
pub fn flume(kh: f64) -> FlumeCase {
    FlumeCase {
        theory: Theory::Linear,
        height: HEIGHT,
        period: FlumeCase::period_for(kh, DEPTH),
        depth: DEPTH,
        air: 0.1,
        generation: 1.0,
        section: 2.0,
        absorption: 1.5,
        ramp: 2.0,
        window: 3.0,
        stations: &[0.75],
        paddle: None,
    }
}

/// The cases of a level: kh and the resolution. Quick: kh = 2; full: 0.5, 1, 2 and 3. Always
/// L/Δx = 40 and H/Δz = 4, the resolution of `regular_waves`'
/// linear wave at its quick level.
pub fn levels(quick: bool) -> Vec<(f64, Resolution)> {
    let res = Resolution {
        per_wavelength: 40,
        per_height: 4,
    };
    let khs: &[f64] = if quick { &[2.0] } else { &[0.5, 1.0, 2.0, 3.0] };
    khs.iter().map(|&kh| (kh, res)).collect()
}

/// One case's measured figures.
#[derive(Clone, Debug)]
pub struct Measured {
    /// kh [-].
    pub kh: f64,
    /// The run.
    pub run: Run,
    /// The reflection coefficient K_r [-].
    pub reflection: f64,
    /// The incident wave's height over H [-].
    pub incident: f64,
}

impl Measured {
    /// K_r within [`LIMIT`].
    pub fn passes(&self) -> bool {
        self.reflection <= LIMIT
    }
}

/// Runs the flume for `kh` at `res` and separates the waves at its array.
pub fn measure(kh: f64, res: Resolution) -> Measured {
    let f = flume(kh);
    let run = f.run(res);
    let s = f.separate(&run)[0];
    Measured {
        kh,
        reflection: s.reflection_coefficient(),
        incident: s.incident_height() / HEIGHT,
        run,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fluid::reflection::spacing_problem;

    #[test]
    fn every_flume_keeps_mansard_and_funkes_spacing() {
        for (kh, _) in levels(false) {
            let f = flume(kh);
            let l = f.wavelength();
            let x = f.station_gauges(f.stations[0]);
            assert_eq!(
                spacing_problem(x[1] - x[0], x[2] - x[0], l),
                None,
                "kh {kh}"
            );
            assert!(x[2] < (f.generation + f.section) * l, "kh {kh}");
        }
    }
}
