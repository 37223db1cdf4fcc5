//! Studies over any problem: sweeps, families and loops ([`curves`]), solving a parameter for a
//! target value of a quantity ([`target`]), and the smallest K_T within a tolerance of Coulomb
//! ([`tolerance`]). Above the problems, below charts and reports.

pub mod curves;
pub mod lap;
pub mod target;
pub mod tolerance;
