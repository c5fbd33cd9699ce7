//! LES of turbulent plane channel flow at Re_τ = 178.12 against the DNS of Moser, Kim &
//! Mansour (1999): the mean velocity profile U⁺(y⁺), the bulk velocity U_b⁺ and the skin
//! friction C_f. The case, the reference data and the tolerances are described in
//! `src/validation/channel180/README.md`.
//!
//! Set-up, in units of the half height h [m] and the friction velocity u_τ [m s⁻¹]
//! (ρ = 1 kg m⁻³):
//!
//! ```text
//! walls y = ±h (no slip), periodic in x (streamwise) and z (spanwise)
//! ν = u_τ h / Re_τ                                   Re_τ = 178.12 (MKM)
//! −dP/dx = ρ u_τ² / h                                (a constant driving gradient [51])
//! Smagorinsky C_s = 0.1, van Driest A⁺ = 25          [56]-[58]
//! ```
//!
//! With the wall shear stress τ_w the mean streamwise momentum balance of the whole channel
//! is 2 h (−dP/dx) = 2 τ_w, so the driving gradient prescribes u_τ = sqrt(τ_w/ρ) once the
//! flow is statistically steady, and the LES predicts the bulk velocity U_b: U_b⁺ = U_b / u_τ,
//! C_f = τ_w / (½ ρ U_b²) = 2 / U_b⁺². The measured mean wall stress over the averaging
//! window, which should be ρ u_τ², tells how steady the run was.
//!
//! The flow starts from Reichardt's law of the wall (an analytical turbulent profile, not the
//! reference) with large-scale divergence-free perturbations of random phase drawn from a
//! seeded generator, so the run is deterministic (and identical on any number of threads).
//! After a spin-up time the plane-averaged (x, z) streamwise velocity is sampled at a fixed
//! interval and averaged in time and over the two halves of the channel.

use crate::fluid::{
    Boundaries, Boundary, DrivingPressureGradient, Fluid, FluidParameters, Smagorinsky,
    StaggeredGrid, TimeStepLimits,
};
use crate::math::Vec3;
use std::f64::consts::{PI, TAU};

/// The mean velocity of Moser, Kim & Mansour (1999) at Re_τ = 178.12: y/h, y⁺, U⁺ (columns
/// of `chan180.means`; provenance in the README of this directory).
const MKM_MEANS: &str = include_str!("mkm1999_chan180_means.csv");

/// Re_τ = u_τ h / ν of the reference DNS.
pub const RE_TAU: f64 = 178.12;

/// The reference profile: (y/h, y⁺, U⁺) from the wall to the centreline, 65 points.
pub fn mkm_1999_profile() -> Vec<[f64; 3]> {
    MKM_MEANS
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('y') && !l.trim().is_empty())
        .map(|l| {
            let mut v = l.split(',').map(|s| s.trim().parse::<f64>().unwrap());
            [v.next().unwrap(), v.next().unwrap(), v.next().unwrap()]
        })
        .collect()
}

/// U_b⁺ = ∫₀¹ U⁺ d(y/h) of the reference profile by the trapezoidal rule (15.68).
pub fn mkm_1999_bulk_velocity() -> f64 {
    let p = mkm_1999_profile();
    p.windows(2)
        .map(|w| 0.5 * (w[0][2] + w[1][2]) * (w[1][0] - w[0][0]))
        .sum()
}

/// U⁺ of the reference at `y_plus`, linear between its points.
pub fn mkm_1999_u_plus(y_plus: f64) -> f64 {
    let p = mkm_1999_profile();
    let k = p.partition_point(|r| r[1] < y_plus).clamp(1, p.len() - 1);
    let (a, b) = (p[k - 1], p[k]);
    a[2] + (b[2] - a[2]) * (y_plus - a[1]) / (b[1] - a[1])
}

/// One channel run: grid, box, times and model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChannelCase {
    /// Cells along x (streamwise), y (wall-normal) and z (spanwise); `cells[1]` even.
    pub cells: [usize; 3],
    /// Box lengths L_x, L_z [h]; the height is 2h.
    pub lengths: [f64; 2],
    /// Friction Reynolds number u_τ h / ν.
    pub re_tau: f64,
    /// Time before averaging starts [h/u_τ].
    pub spin_up: f64,
    /// Length of the averaging window [h/u_τ].
    pub average: f64,
    /// Interval between samples of the averages [h/u_τ].
    pub sample_interval: f64,
    /// Seed of the initial perturbations.
    pub seed: u64,
    /// Advective Courant number of the adaptive time step.
    pub cfl: f64,
    /// The subgrid model.
    pub smagorinsky: Smagorinsky,
}

impl ChannelCase {
    /// The validation case: 2πh × 2h × πh on 32 × 64 × 32 cells (Δx⁺ = 35, Δy⁺ = 5.6,
    /// Δz⁺ = 17.5), Smagorinsky C_s = 0.1 with van Driest damping, 30 h/u_τ of spin-up then
    /// 50 h/u_τ of averages sampled every 0.25 h/u_τ, CFL 0.3.
    pub fn validation() -> ChannelCase {
        ChannelCase {
            cells: [32, 64, 32],
            lengths: [TAU, PI],
            re_tau: RE_TAU,
            spin_up: 30.0,
            average: 50.0,
            sample_interval: 0.25,
            seed: 2024,
            cfl: 0.3,
            smagorinsky: Smagorinsky::default(),
        }
    }

    /// Cell sizes in wall units (Δx⁺, Δy⁺, Δz⁺).
    pub fn wall_units(&self) -> [f64; 3] {
        [
            self.lengths[0] / self.cells[0] as f64 * self.re_tau,
            2.0 / self.cells[1] as f64 * self.re_tau,
            self.lengths[1] / self.cells[2] as f64 * self.re_tau,
        ]
    }
}

/// The outcome of a channel run; velocities in units of u_τ.
#[derive(Clone, Debug)]
pub struct ChannelResult {
    /// The case run.
    pub case: ChannelCase,
    /// Steps taken.
    pub steps: u64,
    /// Samples in the averages.
    pub samples: usize,
    /// Mean bulk velocity U_b⁺ over the averaging window.
    pub bulk_velocity: f64,
    /// Skin friction C_f = 2 / U_b⁺².
    pub skin_friction: f64,
    /// Mean wall shear stress (viscous and subgrid) over the window, in units of ρ u_τ²
    /// (1 when the run is statistically steady).
    pub wall_stress: f64,
    /// The time-, plane- and half-averaged profile at the cell centres: (y⁺, U⁺).
    pub profile: Vec<(f64, f64)>,
    /// U_b⁺ against time (t in h/u_τ), one point per sample interval from t = 0.
    pub bulk_history: Vec<(f64, f64)>,
}

impl ChannelResult {
    /// (U_b⁺ − U_b⁺_ref) / U_b⁺_ref against the reference bulk velocity.
    pub fn bulk_velocity_error(&self) -> f64 {
        self.bulk_velocity / mkm_1999_bulk_velocity() - 1.0
    }

    /// The largest |U⁺ − U⁺_ref| / U⁺_ref over the cell centres with y⁺ in `range`.
    pub fn profile_error(&self, range: std::ops::RangeInclusive<f64>) -> f64 {
        self.profile
            .iter()
            .filter(|(y, _)| range.contains(y))
            .map(|&(y, u)| (u / mkm_1999_u_plus(y) - 1.0).abs())
            .fold(0.0, f64::max)
    }
}

/// SplitMix64: a small deterministic generator for the initial perturbations.
struct SplitMix64(u64);

impl SplitMix64 {
    /// A uniform number in [−1, 1).
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

/// Reichardt's law of the wall, U⁺(y⁺) = ln(1 + κ y⁺)/κ + 7.8 [1 − e^(−y⁺/11) − (y⁺/11) e^(−y⁺/3)]
/// with κ = 0.41 (Reichardt 1951): the analytical mean profile the runs start from.
pub fn reichardt(y_plus: f64) -> f64 {
    let kappa = 0.41;
    (1.0 + kappa * y_plus).ln() / kappa
        + 7.8 * (1.0 - (-y_plus / 11.0).exp() - y_plus / 11.0 * (-y_plus / 3.0).exp())
}

/// The fluid of a channel case at t = 0: Reichardt's profile plus large-scale perturbations
/// (Fourier modes up to wavenumber 3 in x and 4 in z, random amplitudes and phases, an
/// envelope (1 − y²) that vanishes on the walls, about 1.5 u_τ r.m.s. per component), made
/// divergence-free.
pub fn channel_fluid(case: &ChannelCase) -> Fluid {
    assert!(
        case.cells[1] % 2 == 0,
        "the channel needs an even number of cells across"
    );
    let [lx, lz] = case.lengths;
    let grid = StaggeredGrid::new(
        case.cells,
        Vec3::new(lx, 2.0, lz),
        Vec3::new(0.0, -1.0, 0.0),
    );
    let bcs = Boundaries::periodic().with(1, Boundary::WALL, Boundary::WALL);
    let mut par = FluidParameters::laminar(1.0, 1.0 / case.re_tau);
    par.smagorinsky = Some(case.smagorinsky);
    par.driving_pressure_gradient = DrivingPressureGradient::Constant {
        force_density: Vec3::X, // ρ u_τ² / h with ρ = u_τ = h = 1
    };
    par.time_step = TimeStepLimits {
        cfl: case.cfl,
        ..TimeStepLimits::default()
    };
    let mut fluid = Fluid::new(grid, bcs, par).expect("valid channel set-up");

    let mut rng = SplitMix64(case.seed);
    // (component, kx, kz, amplitude, phase x, phase z)
    let mut modes = Vec::new();
    for c in 0..3 {
        for kx in 0..=3 {
            for kz in 0..=4 {
                if kx + kz > 0 {
                    let amp = rng.next();
                    modes.push((
                        c,
                        kx as f64,
                        kz as f64,
                        amp,
                        PI * rng.next(),
                        PI * rng.next(),
                    ));
                }
            }
        }
    }
    // Each mode has r.m.s. |amp|/2 · (r.m.s. of the envelope ≈ 0.73); about 19 modes per
    // component with E[amp²] = 1/3: scale to 1.5 u_τ r.m.s.
    let scale = 1.5 / (0.5 * 0.73 * (19.0f64 / 3.0).sqrt());
    let re_tau = case.re_tau;
    fluid.set_velocity(|x| {
        let y_plus = (1.0 - x.y.abs()) * re_tau;
        let envelope = 1.0 - x.y * x.y;
        let mut u = Vec3::new(reichardt(y_plus.max(0.0)), 0.0, 0.0);
        for &(c, kx, kz, amp, px, pz) in &modes {
            let wave = (TAU * kx * x.x / lx + px).cos() * (TAU * kz * x.z / lz + pz).cos();
            u[c] += scale * amp * wave * envelope;
        }
        u
    });
    fluid.project();
    fluid
}

/// Plane averages of u over x and z at each cell row j [u_τ]; their mean is U_b.
fn plane_averages(fluid: &Fluid, out: &mut [f64]) {
    let g = fluid.grid();
    let u = fluid.velocity()[0];
    let per_plane = (g.n[0] * g.n[2]) as f64;
    for (j, o) in out.iter_mut().enumerate() {
        let mut sum = 0.0;
        for k in 0..g.n[2] {
            let c = g.cell(0, j, k);
            sum += u[c..c + g.n[0]].iter().sum::<f64>();
        }
        *o = sum / per_plane;
    }
}

/// The wall shear stress averaged over both walls y = ±h [Pa], as the momentum equation sees
/// it: the viscous stress μ (u₁ − u_ghost)/Δy = 2 μ u₁/Δy plus the subgrid stress
/// μ_e (u₁ − u_ghost)/Δy, μ_e the mean μ_SGS [Pa s] of the four cells around the wall edge of
/// the x-face (two of them ghosts, copies of the wall cells).
///
/// `u` is the streamwise velocity on the x-faces with filled ghosts [m s⁻¹], `mu_t` μ_SGS at
/// the cell centres with filled ghosts (zeros without the model), `mu` the dynamic viscosity
/// [Pa s]; the walls are normal to y. Summed over the cells of both walls, this is exactly
/// the momentum the discrete viscous and subgrid terms take out of the box.
pub fn wall_shear_stress(grid: &StaggeredGrid, mu: f64, u: &[f64], mu_t: &[f64]) -> f64 {
    let dy = grid.spacing.y;
    let sy = grid.strides()[1] as isize;
    let mut sum = 0.0;
    for (j, ghost) in [(0, -sy), (grid.n[1] - 1, sy)] {
        for k in 0..grid.n[2] {
            for i in 0..grid.n[0] {
                let c = grid.cell(i, j, k);
                let cg = c.wrapping_add_signed(ghost);
                let mu_e = 0.25 * (mu_t[c] + mu_t[c - 1] + mu_t[cg] + mu_t[cg - 1]);
                sum += (mu + mu_e) * (u[c] - u[cg]) / dy;
            }
        }
    }
    sum / (2 * grid.n[0] * grid.n[2]) as f64
}

/// Runs a channel case: spin-up, then the averages; `progress(t, U_b⁺)` is called once per
/// unit of time [h/u_τ].
pub fn run_channel(case: &ChannelCase, progress: &mut dyn FnMut(f64, f64)) -> ChannelResult {
    let mut fluid = channel_fluid(case);
    let ny = case.cells[1];
    let mut planes = vec![0.0; ny];
    let mut mean = vec![0.0; ny];
    let (mut samples, mut tau_sum) = (0usize, 0.0);
    let mut bulk_history = Vec::new();
    let t_end = case.spin_up + case.average;
    let n_samples = (t_end / case.sample_interval).round() as usize;
    let mut next_report = 1.0;
    for s in 0..=n_samples {
        let t = s as f64 * case.sample_interval;
        while fluid.time() < t - 1e-9 {
            fluid.step_adaptive(t);
        }
        plane_averages(&fluid, &mut planes);
        let bulk = planes.iter().sum::<f64>() / ny as f64;
        assert!(bulk.is_finite(), "channel run diverged at t = {t}");
        bulk_history.push((t, bulk));
        if t >= next_report - 1e-9 {
            progress(t, bulk);
            next_report += 1.0;
        }
        if t > case.spin_up + 1e-9 {
            for (m, p) in mean.iter_mut().zip(&planes) {
                *m += p;
            }
            let mu = fluid.parameters().dynamic_viscosity();
            let (u, mu_t) = (fluid.velocity()[0], fluid.eddy_viscosity());
            tau_sum += wall_shear_stress(fluid.grid(), mu, u, mu_t);
            samples += 1;
        }
    }
    let samples_f = samples.max(1) as f64;
    let dy_plus = 2.0 / ny as f64 * case.re_tau;
    let profile = (0..ny / 2)
        .map(|j| {
            let u = 0.5 * (mean[j] + mean[ny - 1 - j]) / samples_f;
            ((j as f64 + 0.5) * dy_plus, u)
        })
        .collect();
    let bulk_velocity = mean.iter().sum::<f64>() / (ny as f64 * samples_f);
    ChannelResult {
        case: *case,
        steps: fluid.steps(),
        samples,
        bulk_velocity,
        skin_friction: 2.0 / (bulk_velocity * bulk_velocity),
        wall_stress: tau_sum / samples_f,
        profile,
        bulk_history,
    }
}
