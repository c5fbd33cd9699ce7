//! Numbers and counts in the words `riprap check` prints: four significant digits instead of
//! every bit of a float (0.103, not 0.10300000000000001), and plurals that agree.

use crate::math::Vec3;

/// `x` to four significant digits, trailing zeros dropped: 0.103, 998.2, 1000, 2.5e-7.
pub fn sig4(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let magnitude = x.abs().log10().floor();
    if !(-3.0..6.0).contains(&magnitude) {
        let s = format!("{x:.3e}");
        let (mantissa, exponent) = s.split_once('e').unwrap_or((&s, "0"));
        return format!("{}e{exponent}", trim(mantissa));
    }
    let decimals = (3.0 - magnitude).max(0.0) as usize;
    trim(&format!("{x:.decimals$}"))
}

fn trim(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

/// A vector as `[x, y, z]` with [`sig4`] components.
pub fn vec4(v: Vec3) -> String {
    format!("[{}, {}, {}]", sig4(v.x), sig4(v.y), sig4(v.z))
}

/// `n word` with an `s` unless n is 1: "1 sphere", "3 spheres", "0 wires".
pub fn count(n: f64, word: &str) -> String {
    if n == 1.0 {
        format!("1 {word}")
    } else {
        format!("{n:.0} {word}s")
    }
}

/// Bytes in words, powers of 1000, three significant digits: "999 B", "1.50 kB", "292 MB",
/// "768 TB".
pub fn bytes(b: f64) -> String {
    let (value, unit) = [
        (1e15, "PB"),
        (1e12, "TB"),
        (1e9, "GB"),
        (1e6, "MB"),
        (1e3, "kB"),
    ]
    .into_iter()
    .find(|&(u, _)| b >= u)
    .map_or((b, "B"), |(u, n)| (b / u, n));
    let decimals = match value {
        v if unit == "B" || v >= 100.0 => 0,
        v if v >= 10.0 => 1,
        _ => 2,
    };
    format!("{value:.decimals$} {unit}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_like_0_10300000000000001_print_as_0_103() {
        assert_eq!(sig4(0.10300000000000001), "0.103");
        assert_eq!(sig4(0.0399125), "0.03991");
        assert_eq!(sig4(998.2), "998.2");
        assert_eq!(sig4(1000.0), "1000");
        assert_eq!(sig4(2.5e-7), "2.5e-7");
        assert_eq!(sig4(-0.85), "-0.85");
        assert_eq!(sig4(0.0), "0");
        assert_eq!(
            vec4(Vec3::new(0.10300000000000001, 0.0, 1.0)),
            "[0.103, 0, 1]"
        );
    }

    #[test]
    fn one_sphere_is_not_1_spheres() {
        assert_eq!(count(1.0, "sphere"), "1 sphere");
        assert_eq!(count(3.0, "sphere"), "3 spheres");
        assert_eq!(count(0.0, "wire"), "0 wires");
        assert_eq!(count(621.29, "sphere"), "621 spheres");
    }

    #[test]
    fn byte_counts_read_plainly() {
        assert_eq!(bytes(0.0), "0 B");
        assert_eq!(bytes(999.0), "999 B");
        assert_eq!(bytes(1500.0), "1.50 kB");
        assert_eq!(bytes(3.4e8), "340 MB");
        assert_eq!(bytes(292_000_000.0), "292 MB");
        assert_eq!(bytes(12_340_000_000.0), "12.3 GB");
        assert_eq!(bytes(7.68e14), "768 TB");
    }
}
