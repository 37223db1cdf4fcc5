//! Studies over any problem: sampling ([`samples`]), sweeps and profiles ([`curves`]),
//! the load-driven sweeps, cycles and loops written once ([`load`]), the interface's zones
//! ([`zones`]), the K_T candidates compared ([`candidates`]), solving a parameter for a
//! target value of a quantity ([`target`]), and the smallest K_T within a tolerance of Coulomb
//! ([`tolerance`]). Above the problems, below charts and reports.

pub mod candidates;
pub mod curves;
pub mod load;
pub mod samples;
pub mod target;
pub mod tolerance;
pub mod zones;
