//! Validation of the free surface (issue 28): the first sloshing mode of a closed tank, its
//! period against linear theory. Set-up, reference, criteria and cost: `README.md`.

pub mod report;

use std::f64::consts::PI;

use crate::fluid::interface::Reconstruction;
use crate::fluid::{Boundary, Fluid};
use crate::math::Vec3;

/// The tank's length L [m] (half the wavelength: k = π/L).
pub const LENGTH: f64 = 1.0;
/// The still water's depth h [m].
pub const DEPTH: f64 = 0.5;
/// The tank's height [m] (air above the water: 0.25 m).
pub const HEIGHT: f64 = 0.75;
/// The initial amplitude A of η = A cos(k x) [m] (k A = 0.063).
pub const AMPLITUDE: f64 = 0.02;
/// Gravity [m s⁻²].
pub const G: f64 = 9.81;
/// Periods simulated: enough for three up-crossings of the mode (at ¾, 1¾ and 2¾ periods).
pub const PERIODS: f64 = 2.9;

/// k = π/L [m⁻¹].
pub fn wavenumber() -> f64 {
    PI / LENGTH
}

/// The linear period T = 2π/ω, ω² = g k tanh(k h) [s].
pub fn linear_period() -> f64 {
    let k = wavenumber();
    2.0 * PI / (G * k * (k * DEPTH).tanh()).sqrt()
}

/// One run of the tank.
#[derive(Clone, Debug)]
pub struct Run {
    /// Cells along the tank L/Δ.
    pub cells_per_length: usize,
    /// (t [s], a [m]): the first mode's amplitude after every step.
    pub mode: Vec<(f64, f64)>,
    /// The fastest air (α < 0.01) and water (α > 0.99, 0.1 m or more below the still surface)
    /// over the run [m s⁻¹].
    pub max_air_speed: f64,
    /// See [`Run::max_air_speed`].
    pub max_water_speed: f64,
    /// Relative change of the water's volume over the run [-].
    pub volume_change: f64,
    /// What the interface scheme clipped, summed [cell volumes].
    pub clipped: f64,
    /// Fluid steps.
    pub steps: u64,
    /// Wall-clock time [s].
    pub seconds: f64,
}

impl Run {
    /// The mode's up-crossings of zero [s].
    pub fn crossings(&self) -> Vec<f64> {
        super::up_crossings(&self.mode, f64::NEG_INFINITY)
    }

    /// The period: the mean interval between the first and the last up-crossing [s].
    pub fn period(&self) -> Option<f64> {
        let c = self.crossings();
        let n = c.len().checked_sub(1).filter(|&n| n > 0)?;
        Some((c[n] - c[0]) / n as f64)
    }

    /// The mode's largest |a| over the last period simulated, over A [-].
    pub fn amplitude_kept(&self) -> f64 {
        let t_end = self.mode.last().map_or(0.0, |m| m.0);
        let late = self.mode.iter().filter(|m| m.0 >= t_end - linear_period());
        late.fold(0.0f64, |m, &(_, a)| m.max(a.abs())) / AMPLITUDE
    }
}

/// The 2D tank (two cells across, periodic in y; free-slip walls) at L/Δ = `n`, water
/// under a cosine surface (each cell's fraction the mean over its width).
pub fn tank(n: usize) -> Fluid {
    let dx = LENGTH / n as f64;
    let nz = (HEIGHT / dx).round() as usize;
    let size = Vec3::new(LENGTH, 2.0 * dx, nz as f64 * dx);
    let thinc = Reconstruction::Thinc;
    let mut f = super::slice_under_air(
        [n, 2, nz],
        size,
        G,
        Boundary::FreeSlip,
        Boundary::FreeSlip,
        thinc,
    );
    let k = wavenumber();
    f.set_water_fraction(|lo, hi| {
        let m = 16;
        let s: f64 = (0..m)
            .map(|q| {
                let x = lo[0] + (q as f64 + 0.5) / m as f64 * (hi[0] - lo[0]);
                let eta = DEPTH + AMPLITUDE * (k * x).cos();
                ((eta - lo[2]) / (hi[2] - lo[2])).clamp(0.0, 1.0)
            })
            .sum();
        s / m as f64
    })
    .expect("the tank has air");
    f
}

/// The first mode's amplitude a = (2/L) Σ_i η_i cos(k x_i) Δx [m], η_i = Σ_k α Δz − h the
/// elevation of column i (mean over y).
pub fn mode_amplitude(f: &Fluid) -> f64 {
    let g = f.grid();
    let alpha = f.water_fraction();
    let (dx, dz) = (g.spacing.x, g.spacing.z);
    let k = wavenumber();
    let mut a = 0.0;
    for i in 0..g.n[0] {
        let mut w = 0.0;
        for j in 0..g.n[1] {
            w += (0..g.n[2]).map(|kk| alpha[g.cell(i, j, kk)]).sum::<f64>();
        }
        let eta = w * dz / g.n[1] as f64 - DEPTH;
        a += eta * (k * (i as f64 + 0.5) * dx).cos() * dx;
    }
    2.0 * a / LENGTH
}

/// The fastest air and deep water in the tank [m s⁻¹] (cell-centred speeds).
fn speeds(f: &Fluid) -> (f64, f64) {
    let g = f.grid();
    let alpha = f.water_fraction();
    let u = f.velocity();
    let (mut air, mut water) = (0.0f64, 0.0f64);
    for kk in 0..g.n[2] {
        let deep = (kk as f64 + 0.5) * g.spacing.z < DEPTH - 0.1;
        for j in 0..g.n[1] {
            for i in 0..g.n[0] {
                let c = g.cell(i, j, kk);
                let [sx, sy, sz] = g.strides();
                let v = [
                    0.5 * (u[0][c] + u[0][c + sx]),
                    0.5 * (u[1][c] + u[1][c + sy]),
                    0.5 * (u[2][c] + u[2][c + sz]),
                ];
                let s = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
                if alpha[c] < 0.01 {
                    air = air.max(s);
                } else if alpha[c] > 0.99 && deep {
                    water = water.max(s);
                }
            }
        }
    }
    (air, water)
}

/// Runs the tank at L/Δ = `n` for [`PERIODS`] linear periods.
pub fn run(n: usize) -> Run {
    let start = std::time::Instant::now();
    let mut f = tank(n);
    let v0 = f.water_volume();
    let t_end = PERIODS * linear_period();
    let mut mode = vec![(0.0, mode_amplitude(&f))];
    let (mut max_air, mut max_water) = (0.0f64, 0.0f64);
    while f.time() < t_end {
        f.step_adaptive(t_end);
        mode.push((f.time(), mode_amplitude(&f)));
        let (air, water) = speeds(&f);
        (max_air, max_water) = (max_air.max(air), max_water.max(water));
    }
    let c = f.clipped();
    Run {
        cells_per_length: n,
        mode,
        max_air_speed: max_air,
        max_water_speed: max_water,
        volume_change: (f.water_volume() - v0) / v0,
        clipped: c.above + c.below,
        steps: f.steps(),
        seconds: start.elapsed().as_secs_f64(),
    }
}

/// The criteria of `README.md` at L/Δ = `n`: the period's tolerance (0.5 % at L/Δ ≥ 100, the
/// quick level's 1.5 % below), the amplitude kept, the volume.
pub fn tolerance(n: usize) -> f64 {
    if n >= 100 {
        0.005
    } else {
        0.015
    }
}

/// Whether `run` meets the criteria of `README.md`.
pub fn passes(run: &Run) -> bool {
    let Some(period) = run.period() else {
        return false;
    };
    (period / linear_period() - 1.0).abs() <= tolerance(run.cells_per_length)
        && (0.9..=1.05).contains(&run.amplitude_kept())
        && run.volume_change.abs() <= 1e-12
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_linear_period_is_the_dispersion_relation() {
        // ω² = g k tanh(k h) with k = π, h = 0.5: ω = 5.3166 s⁻¹, T = 1.18182 s.
        assert!((linear_period() - 1.18182).abs() < 1e-5);
    }

    #[test]
    fn the_mode_of_the_initial_surface_is_its_amplitude() {
        // The cosine sampled at cell centres: its discrete projection on cos(kx) is exact to
        // the midpoint rule's error, O((kΔ)²) ≈ 1e-4 relative at L/Δ = 50 (cell fractions are
        // means over the cell, which changes the second digit of that).
        let f = tank(50);
        let a = mode_amplitude(&f);
        assert!((a / AMPLITUDE - 1.0).abs() < 1e-3, "a = {a}");
    }
}
