//! The incident and the reflected wave in a flume, from the surface records of three gauges
//! (Mansard & Funke 1980): how a laboratory measures a wave's height in front of a structure
//! or an absorber that sends part of it back, and how much it sends back.
//!
//! At angular frequency ω [s⁻¹] a record η(t) [m] at gauge p, x_p [m] along the flume, has a
//! complex amplitude B_p [m] with η ≈ m + Re(B_p e^{iωt}) ([`harmonic`]). A wave Z_I [m]
//! travelling towards +x and one Z_R [m] travelling back give, with k [m⁻¹] the wavenumber,
//!
//! ```text
//! B_p = Z_I e^{−i k x_p} + Z_R e^{+i k x_p} + ε_p
//! ```
//!
//! and the least-squares Z_I, Z_R over three gauges ([`separate`]) leave ε, the part of the
//! records no such pair explains (noise, a wrong k), as small as it can be. The equations are
//! singular when the gauges are half a wavelength apart; [`spacing_problem`] gives Mansard &
//! Funke's rules for the spacing.

use std::f64::consts::PI;

use rustfft::num_complex::Complex64;

use crate::math::{Mat3, Vec3};

/// The complex amplitude B [m] of the record's harmonic at ω [s⁻¹] over [t0, t1] [s]:
/// η ≈ m + Re(B e^{iωt}) by least squares with a mean m. Over whole periods of evenly spaced
/// samples the mean and the other harmonics are orthogonal to it, so it is exact for them.
pub fn harmonic(record: &[(f64, f64)], omega: f64, t0: f64, t1: f64) -> Complex64 {
    // Normal equations (Σ f fᵀ) x = Σ f η of η ≈ m + c cos ωt + s sin ωt, f = (1, cos, sin);
    // then B = c − i s.
    let (mut a, mut b) = (Mat3::ZERO, Vec3::ZERO);
    for &(t, eta) in record.iter().filter(|p| (t0..=t1).contains(&p.0)) {
        let f = Vec3::new(1.0, (omega * t).cos(), (omega * t).sin());
        a += Mat3::from_cols(f * f.x, f * f.y, f * f.z);
        b += f * eta;
    }
    let x = a.inverse() * b;
    Complex64::new(x.y, -x.z)
}

/// The incident and the reflected wave at one frequency.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Separation {
    /// Z_I [m]: the incident wave is Re(Z_I e^{i(ωt − kx)}); |Z_I| its amplitude.
    pub incident: Complex64,
    /// Z_R [m]: the reflected wave is Re(Z_R e^{i(ωt + kx)}).
    pub reflected: Complex64,
}

impl Separation {
    /// The incident wave's height 2|Z_I| [m].
    pub fn incident_height(&self) -> f64 {
        2.0 * self.incident.norm()
    }

    /// The reflection coefficient K_r = |Z_R| / |Z_I| [-].
    pub fn reflection_coefficient(&self) -> f64 {
        self.reflected.norm() / self.incident.norm()
    }

    /// The incident wave's phase at x [m]: arg of Z_I e^{−ikx}, in (−π, π] [rad].
    pub fn incident_phase(&self, k: f64, x: f64) -> f64 {
        (self.incident * Complex64::from_polar(1.0, -k * x)).arg()
    }
}

/// Z_I and Z_R from the complex amplitudes `b` [m] at gauges `x` [m] (three or more) for the
/// wavenumber `k` [m⁻¹], by least squares (Mansard & Funke 1980). With e_p = e^{−ikx_p},
/// n gauges and S = Σ e_p², the normal equations are
///
/// ```text
/// [ n   S̄ ] [Z_I]   [ Σ ē_p B_p ]
/// [ S   n ] [Z_R] = [ Σ e_p B_p ]
/// ```
///
/// singular (n² = |S|²) when every k x_p is the same modulo π. `None` then.
pub fn separate(b: &[Complex64], x: &[f64], k: f64) -> Option<Separation> {
    assert_eq!(b.len(), x.len(), "one amplitude per gauge");
    let n = b.len() as f64;
    let (mut s, mut rhs_i, mut rhs_r) = (Complex64::ZERO, Complex64::ZERO, Complex64::ZERO);
    for (&bp, &xp) in b.iter().zip(x) {
        let e = Complex64::from_polar(1.0, -k * xp);
        s += e * e;
        rhs_i += e.conj() * bp;
        rhs_r += e * bp;
    }
    let det = n * n - s.norm_sqr();
    if det <= 1e-9 * n * n {
        return None;
    }
    Some(Separation {
        incident: (rhs_i * n - s.conj() * rhs_r) / det,
        reflected: (rhs_r * n - s * rhs_i) / det,
    })
}

/// What is wrong with gauges at x₁, x₁ + `x12`, x₁ + `x13` [m] for a wave `wavelength` [m]
/// long, by Mansard & Funke's (1980) rules: x₁₂ near L/10, L/6 < x₁₃ < L/3, and x₁₃ not at
/// L/5 or 3L/10 (here: not within L/50 of them). `None` when they hold.
pub fn spacing_problem(x12: f64, x13: f64, wavelength: f64) -> Option<String> {
    let (r12, r13) = (x12 / wavelength, x13 / wavelength);
    let near = |a: f64, b: f64| (a - b).abs() < 0.02;
    if !(0.05..=0.15).contains(&r12) {
        Some(format!(
            "the first two gauges are {r12:.3} L apart; Mansard & Funke ask for about L/10"
        ))
    } else if !(1.0 / 6.0 < r13 && r13 < 1.0 / 3.0) {
        Some(format!(
            "the first and third gauges are {r13:.3} L apart; Mansard & Funke ask for between \
             L/6 and L/3"
        ))
    } else if near(r13, 0.2) || near(r13, 0.3) {
        Some(format!(
            "the first and third gauges are {r13:.3} L apart, too near L/5 or 3L/10"
        ))
    } else {
        None
    }
}

/// The array a flume's validation uses at a station x₁: x₁, x₁ + L/10, x₁ + L/4 [m] (the
/// middle of Mansard & Funke's allowed range for x₁₃).
pub fn gauge_array(x1: f64, wavelength: f64) -> [f64; 3] {
    [x1, x1 + 0.1 * wavelength, x1 + 0.25 * wavelength]
}

/// The phase difference k Δx [rad] from phases φ₁, φ₂ [rad] measured Δx apart, unwrapped
/// with the expected wavenumber `k` [m⁻¹]: φ₂ − φ₁ plus the whole turns that bring it nearest
/// to k Δx.
pub fn unwrapped_phase(phi1: f64, phi2: f64, k: f64, dx: f64) -> f64 {
    let raw = phi2 - phi1;
    raw + 2.0 * PI * ((k * dx - raw) / (2.0 * PI)).round()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Records of an incident wave (a_I, φ_I), a reflected one (a_R, φ_R) and a second
    /// harmonic at gauges `x`, sampled every 0.01 s over three periods of T = 1 s (300
    /// samples, the last at 2.99 s).
    fn records(x: &[f64], k: f64, waves: [(f64, f64); 2]) -> Vec<Vec<(f64, f64)>> {
        let w = 2.0 * PI;
        let [(ai, pi), (ar, pr)] = waves;
        x.iter()
            .map(|&x| {
                (0..300)
                    .map(|q| {
                        let t = q as f64 * 0.01;
                        let eta = 0.01
                            + ai * (w * t - k * x + pi).cos()
                            + ar * (w * t + k * x + pr).cos()
                            + 0.002 * (2.0 * (w * t - k * x)).cos();
                        (t, eta)
                    })
                    .collect()
            })
            .collect()
    }

    #[test]
    fn the_harmonic_fit_reads_amplitude_and_phase() {
        // Three whole periods sampled evenly: the mean and the second harmonic are orthogonal
        // to the first, so the fit is exact to round-off.
        let rec = &records(&[0.0], 0.0, [(0.02, -0.7), (0.0, 0.0)])[0];
        let b = harmonic(rec, 2.0 * PI, 0.0, 3.0);
        assert!((b.norm() - 0.02).abs() < 1e-14, "{b}");
        assert!((b.arg() + 0.7).abs() < 1e-12, "{}", b.arg());
    }

    #[test]
    fn three_gauges_separate_an_incident_and_a_reflected_wave() {
        // K_r = 0.15 with arbitrary phases, gauges at the array of the validation cases: the
        // model is exact and the fit too, so Z_I and Z_R come back to round-off.
        let l = 1.464;
        let k = 2.0 * PI / l;
        let x = gauge_array(3.0, l);
        let rec = records(&x, k, [(0.02, 0.3), (0.003, 1.1)]);
        let b: Vec<Complex64> = rec
            .iter()
            .map(|r| harmonic(r, 2.0 * PI, 0.0, 3.0))
            .collect();
        let s = separate(&b, &x, k).expect("a good array");
        assert!((s.incident_height() - 0.04).abs() < 1e-13, "{s:?}");
        assert!((s.reflection_coefficient() - 0.15).abs() < 1e-10, "{s:?}");
        assert!((s.incident.arg() - 0.3).abs() < 1e-10, "{s:?}");
        assert!((s.reflected.arg() - 1.1).abs() < 1e-9, "{s:?}");
        // One gauge alone reads the sum: between 0.034 and 0.046 m.
        assert!((2.0 * b[0].norm() - 0.04).abs() > 1e-3);
    }

    #[test]
    fn a_pure_progressive_wave_has_no_reflection() {
        let l = 2.0;
        let k = 2.0 * PI / l;
        let x = gauge_array(1.0, l);
        let rec = records(&x, k, [(0.01, 0.0), (0.0, 0.0)]);
        let b: Vec<Complex64> = rec
            .iter()
            .map(|r| harmonic(r, 2.0 * PI, 0.0, 3.0))
            .collect();
        let s = separate(&b, &x, k).unwrap();
        assert!(s.reflection_coefficient() < 1e-12, "{s:?}");
    }

    #[test]
    fn gauges_half_a_wavelength_apart_cannot_separate() {
        let k = 2.0 * PI;
        let b = [Complex64::ONE; 3];
        assert!(separate(&b, &[0.0, 0.5, 1.0], k).is_none());
        assert!(spacing_problem(0.5, 1.0, 1.0).is_some());
        assert!(spacing_problem(0.1, 0.2, 1.0).is_some(), "L/5");
        assert!(spacing_problem(0.1, 0.25, 1.0).is_none());
    }

    #[test]
    fn phases_unwrap_to_the_expected_turn() {
        let k = 2.0 * PI;
        // Four and a quarter wavelengths: the raw difference is −0.75 turns off by five.
        let phi2 = (0.25 * 2.0 * PI + 0.1) - 2.0 * PI;
        let d = unwrapped_phase(0.1, phi2, k, 4.25);
        assert!((d - 4.25 * 2.0 * PI).abs() < 1e-12, "{d}");
    }
}
