//! The coupling's validation cases (METHOD.md §5), run by `riprap validate`: each a
//! directory with its README (source, set-up, compared quantity, tolerance, run cost).

pub mod block_settling;
pub mod cylinder_strouhal;
pub mod hopper_cloud;
pub mod sheet_flow;
pub mod sphere_drag;
