//! Named SI constants, so that scenario code reads as an engineer writes it.
//!
//! Every quantity in riprap is SI; these only make literals readable:
//! `2.0 * MILLIMETRE` is `0.002` (metres).

/// One millimetre [m].
pub const MILLIMETRE: f64 = 1.0e-3;
/// One centimetre [m].
pub const CENTIMETRE: f64 = 1.0e-2;
/// One gram [kg].
pub const GRAM: f64 = 1.0e-3;
/// One minute [s].
pub const MINUTE: f64 = 60.0;
/// One hour [s].
pub const HOUR: f64 = 3600.0;
/// One degree [rad].
pub const DEGREE: f64 = std::f64::consts::PI / 180.0;
/// Standard gravity [m s⁻²].
pub const STANDARD_GRAVITY: f64 = 9.81;
