//! The built-in default scenario: a cloud of spheres fed from a hopper near the surface of a
//! small tank of still water, falling through it (a small version of METHOD.md §5, case 4).

/// TOML text of the default scenario (`examples/hopper_cloud.toml`).
pub const DEFAULT_SCENARIO: &str = include_str!("../../examples/hopper_cloud.toml");
