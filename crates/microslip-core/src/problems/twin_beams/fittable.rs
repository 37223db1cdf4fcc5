//! The twin beams as a fittable problem ([`Fittable`]): w(L) against the tip force identifies
//! K_T from the microslip slope and mu from where and how the slope changes past F_1 (the
//! paper's section 2.1.3).

use crate::kernel::params::ParamError;
use crate::problems::fittable::Fittable;
use crate::problems::twin_beams::closed_form::TwinBeams;
use crate::problems::twin_beams::params::{BeamParam, TwinBeamsParams};
use crate::problems::twin_beams::problem::TwinBeamsProblem;

impl Fittable for TwinBeamsProblem {
    const RESPONSE_COLUMN: &'static str = "w_mm";
    const FITTED: &'static str = "twin beams";
    /// Poisson's ratio is left out: the closed form (Euler-Bernoulli) does not use it.
    const HELD: &'static [BeamParam] = &[
        BeamParam::Length,
        BeamParam::Width,
        BeamParam::HalfHeight,
        BeamParam::Modulus,
        BeamParam::Pressure,
    ];

    fn interface_of(beams: &TwinBeams) -> (f64, f64) {
        let p = beams.params();
        (p.friction, p.tangential_stiffness)
    }

    fn with_interface(beams: &TwinBeams, mu: f64, kt: f64) -> Result<TwinBeams, ParamError> {
        TwinBeams::new(TwinBeamsParams {
            friction: mu,
            tangential_stiffness: kt,
            ..beams.params()
        })
    }

    fn first_macroslip_force(beams: &TwinBeams) -> f64 {
        beams.first_macroslip_force()
    }
}
