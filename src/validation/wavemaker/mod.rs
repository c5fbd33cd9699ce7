//! Validation of the wavemaker paddles (issue 28): the wave a piston or a flap makes, one
//! wavelength from it, against the height its first-order transfer function promises (Biesel &
//! Suquet 1951; `fluid::wavemaker`), for kh from 0.5 to 2. Set-up, criteria and cost:
//! `README.md`.

pub mod report;

use crate::fluid::wavemaker::{transfer, PaddleKind};

pub use super::flume_case::{FlumeCase, Resolution, Run, Theory};

/// Still-water depth h [m].
pub const DEPTH: f64 = 0.4;
/// Wave height H [m]: H/h = 0.05, steepness H/L from 0.004 (kh = 0.5) to 0.016 (kh = 2).
pub const HEIGHT: f64 = 0.02;
/// The largest departure of the incident height from H allowed [-] (`README.md`).
pub const TOLERANCE: f64 = 0.03;

/// The flume for a paddle of `kind` at kh: the paddle at x = 0, a test section of 3 L with one
/// gauge array 1 L from the paddle (past the evanescent modes, which die out within about
/// 3 h), an absorbing zone of 1.5 L; 0.1 m of air; a ramp of 2 periods; the last 3 periods
/// analysed.
pub fn flume(kind: PaddleKind, kh: f64) -> FlumeCase {
    FlumeCase {
        theory: Theory::Linear,
        height: HEIGHT,
        period: FlumeCase::period_for(kh, DEPTH),
        depth: DEPTH,
        air: 0.1,
        generation: 0.0,
        section: 3.0,
        absorption: 1.5,
        ramp: 2.0,
        window: 3.0,
        stations: &[1.0],
        paddle: Some(kind),
    }
}

/// The cases of a level. Quick: the piston at kh = 1; full: the piston and the flap at kh =
/// 0.5, 1 and 2. Always L/Δx = 40 and H/Δz = 4, the resolution of `regular_waves`'
/// linear wave at its quick level.
pub fn levels(quick: bool) -> Vec<(PaddleKind, f64, Resolution)> {
    let res = Resolution {
        per_wavelength: 40,
        per_height: 4,
    };
    if quick {
        return vec![(PaddleKind::Piston, 1.0, res)];
    }
    [PaddleKind::Piston, PaddleKind::Flap]
        .into_iter()
        .flat_map(|k| [0.5, 1.0, 2.0].map(|kh| (k, kh, res)))
        .collect()
}

/// One case's measured figures.
#[derive(Clone, Debug)]
pub struct Measured {
    /// The paddle.
    pub kind: PaddleKind,
    /// kh [-].
    pub kh: f64,
    /// The paddle's stroke S [m].
    pub stroke: f64,
    /// The run.
    pub run: Run,
    /// The incident wave's height over H [-].
    pub incident: f64,
    /// The reflection coefficient at the array [-] (the absorbing zone's, seen through the
    /// test section).
    pub reflection: f64,
}

impl Measured {
    /// The incident height within [`TOLERANCE`] of H.
    pub fn passes(&self) -> bool {
        (self.incident - 1.0).abs() <= TOLERANCE
    }
}

/// Runs the flume for the paddle at kh and `res`, and separates the waves at its array.
pub fn measure(kind: PaddleKind, kh: f64, res: Resolution) -> Measured {
    let f = flume(kind, kh);
    let run = f.run(res);
    let s = f.separate(&run)[0];
    Measured {
        kind,
        kh,
        stroke: HEIGHT / transfer(kind, kh),
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
    fn every_flume_keeps_mansard_and_funkes_spacing_past_the_evanescent_modes() {
        for (kind, kh, _) in levels(false) {
            let f = flume(kind, kh);
            let l = f.wavelength();
            let x = f.station_gauges(f.stations[0]);
            assert_eq!(
                spacing_problem(x[1] - x[0], x[2] - x[0], l),
                None,
                "kh {kh}"
            );
            assert!(
                x[0] >= 3.0 * DEPTH,
                "kh {kh}: the array starts at {} m",
                x[0]
            );
            assert!(x[2] < f.section * l, "kh {kh}");
        }
    }
}
