//! The built-in default scenario: gravel and armour stones poured onto a rubble-mound slope.

/// TOML text of the default scenario (`examples/armour_on_slope.toml`).
pub const DEFAULT_SCENARIO: &str = include_str!("../../examples/armour_on_slope.toml");
