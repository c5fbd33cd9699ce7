//! The wave-flume cases' set-up: a linear wave generated in a relaxation zone at x = 0,
//! a test section with arrays of three gauges, and an absorbing zone at the far end, in a 2D
//! slice with a free-slip bed and ends and a top open to the atmosphere; its records, and the
//! incident and reflected wave at each array (Mansard & Funke 1980, `fluid::reflection`).

use std::f64::consts::PI;

use crate::fluid::flume::Flume;
use crate::fluid::interface::Reconstruction;
use crate::fluid::reflection::{gauge_array, harmonic, separate, Separation};
use crate::fluid::wavemaker::{Paddle, PaddleKind};
use crate::fluid::waves::{Regular, RelaxationZone, Wave};
use crate::fluid::{Boundary, Fluid};
use crate::math::Vec3;

/// Gravity [m s⁻²].
pub const G: f64 = 9.81;

/// A flume for a linear wave. Lengths along the flume in wavelengths, times in periods.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearFlume {
    /// H [m].
    pub height: f64,
    /// T [s].
    pub period: f64,
    /// h, the still water's depth [m].
    pub depth: f64,
    /// The air above the still water [m].
    pub air: f64,
    /// The generating zone [L].
    pub generation: f64,
    /// The test section between the zones [L].
    pub section: f64,
    /// The absorbing zone [L].
    pub absorption: f64,
    /// The ramp-up from rest [T].
    pub ramp: f64,
    /// The records analysed, ending at the run's end [T].
    pub window: f64,
    /// The arrays' first gauges, from the generating zone's inner edge [L].
    pub stations: &'static [f64],
    /// A wavemaker paddle at x = 0 instead of the generating zone (then `generation` is 0),
    /// driven with the stroke of its transfer function (`fluid::wavemaker`).
    pub paddle: Option<PaddleKind>,
}

/// The resolution of a run: cells per wavelength along x, and per wave height along z.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Resolution {
    /// L/Δx.
    pub per_wavelength: usize,
    /// H/Δz.
    pub per_height: usize,
}

/// One run of a flume.
#[derive(Clone, Debug)]
pub struct Run {
    /// The resolution.
    pub resolution: Resolution,
    /// The gauges along the flume, three per station [m].
    pub gauges: Vec<f64>,
    /// Per gauge, (t [s], η [m]) after every step.
    pub records: Vec<Vec<(f64, f64)>>,
    /// Fluid steps.
    pub steps: u64,
    /// Cells of the grid.
    pub cells: usize,
    /// Wall-clock time [s].
    pub seconds: f64,
}

impl LinearFlume {
    /// The wave: linear theory at h, H, T.
    pub fn wave(&self) -> Regular {
        Regular::new(self.height, self.period, self.depth, G)
    }

    /// The wavelength L [m].
    pub fn wavelength(&self) -> f64 {
        2.0 * PI / self.wave().k
    }

    /// The group velocity c_g = (c/2)(1 + 2kh/sinh 2kh) [m s⁻¹].
    pub fn group_velocity(&self) -> f64 {
        let w = self.wave();
        let kh = w.k * self.depth;
        0.5 * (w.omega / w.k) * (1.0 + 2.0 * kh / (2.0 * kh).sinh())
    }

    /// The flow at `res`: generating zone, test section, absorbing zone along x.
    pub fn fluid(&self, res: Resolution) -> Fluid {
        let l = self.wavelength();
        let zones = self.generation + self.section + self.absorption;
        let length = zones * l;
        let nx = (zones * res.per_wavelength as f64).round() as usize;
        let dz = self.height / res.per_height as f64;
        let nz = ((self.depth + self.air) / dz).round() as usize;
        let dx = length / nx as f64;
        let size = Vec3::new(length, dx, nz as f64 * dz);
        // Planes: THINC's profile feeds the waves energy (`fluid::interface`).
        let planes = Reconstruction::Plane;
        let h = self.depth;
        let w = self.wave();
        let start = match self.paddle {
            Some(kind) => {
                let ramp = self.ramp * self.period;
                let p = Paddle::for_wave(kind, self.height, self.period, w.k, 0.0, h, ramp);
                Boundary::Wavemaker(p)
            }
            None => Boundary::FreeSlip,
        };
        let mut f = super::slice_under_air([nx, 1, nz], size, G, start, Boundary::Open, planes);
        f.set_water_fraction(|lo, hi| ((h - lo[2]) / (hi[2] - lo[2])).clamp(0.0, 1.0))
            .expect("the flume has air");
        f.set_flume(Flume {
            wave: Wave::Linear(self.wave()),
            still_water_level: h,
            generation: self.paddle.is_none().then_some(RelaxationZone {
                inner: self.generation * l,
                outer: 0.0,
            }),
            absorption: Some(RelaxationZone {
                inner: (self.generation + self.section) * l,
                outer: length,
            }),
            ramp_time: self.ramp * self.period,
            current: 0.0,
        })
        .expect("the flume has air");
        f
    }

    /// The gauges of the array at station `s` [L from the generating zone] [m].
    pub fn station_gauges(&self, s: f64) -> [f64; 3] {
        let l = self.wavelength();
        gauge_array((self.generation + s) * l, l)
    }

    /// The run's end [s]: the ramp; the wave's front (at the group velocity) to the absorbing
    /// zone, half a wavelength into it and back to the first station, so that the reflected
    /// wave has reached every gauge; one period to settle; and the window.
    pub fn duration(&self) -> f64 {
        let there = self.generation + self.section + 0.5;
        let back = self.section + 0.5 - self.stations[0];
        (self.ramp + 1.0 + self.window) * self.period
            + (there + back) * self.wavelength() / self.group_velocity()
    }

    /// Runs the flume at `res` for [`LinearFlume::duration`], recording every gauge after
    /// every step.
    pub fn run(&self, res: Resolution) -> Run {
        let start = std::time::Instant::now();
        let mut f = self.fluid(res);
        let xs: Vec<f64> = self
            .stations
            .iter()
            .flat_map(|&s| self.station_gauges(s))
            .collect();
        let y = 0.5 * f.grid().spacing.y;
        let mut records: Vec<Vec<(f64, f64)>> = vec![Vec::new(); xs.len()];
        let t_end = self.duration();
        while f.time() < t_end {
            f.step_adaptive(t_end);
            for (r, &x) in records.iter_mut().zip(&xs) {
                r.push((f.time(), f.surface_height(x, y) - self.depth));
            }
        }
        Run {
            resolution: res,
            gauges: xs,
            records,
            steps: f.steps(),
            cells: f.grid().cell_count(),
            seconds: start.elapsed().as_secs_f64(),
        }
    }

    /// Writes the run's records to `path` as CSV: t [s], then η [m] at each gauge (named by
    /// its x [m]), one row per step ([`write_gauges`]).
    pub fn write_records(run: &Run, path: &std::path::Path) -> std::io::Result<()> {
        write_gauges(&run.gauges, &run.records, path)
    }

    /// Per station, the incident and the reflected wave over the run's last window.
    pub fn separate(&self, run: &Run) -> Vec<Separation> {
        let w = self.wave();
        let t1 = self.duration();
        let t0 = t1 - self.window * self.period;
        run.records
            .chunks(3)
            .zip(run.gauges.chunks(3))
            .map(|(recs, xs)| {
                let b: Vec<_> = recs.iter().map(|r| harmonic(r, w.omega, t0, t1)).collect();
                separate(&b, xs, w.k).expect("the arrays keep Mansard & Funke's spacing")
            })
            .collect()
    }

    /// The period of the wave with kh = `kh` in this flume's depth, from ω² = g k tanh kh [s].
    pub fn period_for(kh: f64, depth: f64) -> f64 {
        let k = kh / depth;
        2.0 * PI / (G * k * kh.tanh()).sqrt()
    }
}

/// Writes gauge records to `path` as CSV: t [s], then η [m] at each gauge of `gauges` (named
/// by its x [m]), one row per sample of the records (all sampled at the same times).
pub fn write_gauges(
    gauges: &[f64],
    records: &[Vec<(f64, f64)>],
    path: &std::path::Path,
) -> std::io::Result<()> {
    use std::io::Write as _;
    let mut w = std::io::BufWriter::new(std::fs::File::create(path)?);
    write!(w, "t")?;
    for x in gauges {
        write!(w, ",eta_x{x:.4}")?;
    }
    writeln!(w)?;
    for (q, &(t, _)) in records[0].iter().enumerate() {
        write!(w, "{t:.6}")?;
        for r in records {
            write!(w, ",{:.7e}", r[q].1)?;
        }
        writeln!(w)?;
    }
    w.flush()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_period_for_kh_gives_that_kh_back() {
        for kh in [0.5, 1.0, 2.0, 3.0] {
            let t = LinearFlume::period_for(kh, 0.4);
            let w = Regular::new(0.02, t, 0.4, G);
            assert!((w.k * 0.4 - kh).abs() < 1e-10, "{kh}");
        }
    }
}
