//! Rigid blocks made of spheres (METHOD.md §3): the passively moving solid model with quaternions.
//!
//! Coastal armour units (cubes, tetrapods, quarry rock) are rigid clusters of spheres. Their
//! member spheres are ordinary DEM spheres for contacts; what makes them one body is here.
//!
//! | file | holds | equations |
//! |---|---|---|
//! | `mass_properties` | volume, centroid and second moments of a union of spheres (overlaps once) | |
//! | `member_masses` | member masses that carry the union's mass, centroid and inertia | [34][35] |
//! | `templates` | `BlockTemplate`: members in the principal body frame, scaling by D_n or W | [49] I_g0 |
//! | `library` | three-sphere rod, cube, tetrapod, rock clusters | |
//! | `jacobi` | symmetric eigen-solver (principal axes) | |
//! | `rotation` | quaternion step, rotation matrix, I_g = R I_g0 Rᵀ | [41]-[49] |
//! | `blocks` | `Blocks` SoA, `RigidState`, `Body`, member spheres of a new block | |
//! | `members` | member slices; rigid placement; force and torque sums | [46][48] |
//! | `pms` | **the source's model**: recovery of a block from its free members | [34]-[36], [41]-[49] |
//! | `newton_euler` | **the reference integrator**: Newton-Euler with quaternions, symplectic rotation | |
//! | `links` | tension-only wires between blocks, breakable parallel bonds (bending, twist) | |
//! | `bodies` | `RigidBodies`: blocks and links as the time step sees them (link forces, PMS phase) | [34]-[49] |
//!
//! Two ways to move a block, with the same `Blocks` state and the same member spheres:
//!
//! * PMS (`pms::recover_block_motion`), as in the source: members move as free spheres through
//!   the DEM step; afterwards the block's motion is recovered from their momenta and they are
//!   reset to the rigid shape. First order in the rotation; conserves angular momentum.
//! * Newton-Euler (`newton_euler::{kick, drift}`): member forces and torques are summed on the
//!   block, which is integrated by velocity Verlet with a symplectic splitting for the rotation;
//!   members are only ever placed rigidly. Second order; conserves angular momentum; no energy
//!   drift. riprap's tests use it as the reference for PMS.

pub mod blocks;
pub mod bodies;
pub mod jacobi;
pub mod library;
pub mod links;
pub mod mass_properties;
pub mod member_masses;
pub mod members;
pub mod newton_euler;
pub mod pms;
pub mod rotation;
pub mod templates;
