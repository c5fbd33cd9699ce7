//! Armour layers under waves (issue 29): the damage of rock and concrete armour on a
//! breakwater slope, and the design formulas a coastal engineer sets beside a simulated damage
//! (required size for a design wave, expected damage S or N_od after N waves).
//!
//! The formulas are empirical fits to model tests; each function cites its source and
//! [`validity`] says where the tests ended. Only the deep-water forms are here (h/H_s ≥ 3):
//! the shallow-foreshore form of Van Gent et al. (2003) is out of scope.
//!
//! * [`formulas`]: Hudson (1959, SPM 1984 form) and Van der Meer (1988) for rock, each in both
//!   directions (wave height → size or damage, and back)
//! * [`concrete`]: Van der Meer (1988) for concrete cubes and tetrapods, both directions
//! * [`coefficients`]: Hudson's K_D table and the damage levels S of Van der Meer / the Rock
//!   Manual, with their sources
//! * [`validity`]: the validity ranges of each formula as data, and the list of the ranges an
//!   input violates
//! * [`design`]: the formulas for one structure and sea state side by side, for a report
//! * [`slope`]: the slope frame, flume (x, z) ↔ along-slope and normal (s, η), periodic in y
//! * [`damage`]: per-unit displacement, direction and layer exit, and N_od (Van der Meer 1988)
//! * [`rocking`]: rocks of a unit from its rotation-angle series (hysteresis), for N_or
//! * [`profile`]: profiler-like surface profiles, eroded area A_e and damage level S

pub mod coefficients;
pub mod concrete;
pub mod damage;
pub mod design;
pub mod formulas;
pub mod profile;
pub mod rocking;
pub mod slope;
pub mod validity;
