//! The twin beams as a load-driven problem ([`LoadDriven`]): the tip force F on each beam, w(L)
//! its response, F_thre = 4 b h mu P / 3 its regime scale, and the Masing cycle of [`BeamsCycle`].

use crate::kernel::params::ParamError;
use crate::kernel::regime::Law;
use crate::problems::load_driven::LoadDriven;
use crate::problems::twin_beams::closed_form::{TipForce, TwinBeams};
use crate::problems::twin_beams::cycle::BeamsCycle;
use crate::problems::twin_beams::point::{BeamPoint, beam_point};
use crate::problems::twin_beams::problem::{BeamsModel, TwinBeamsProblem};
use crate::problems::{BeamParam, Param};

impl LoadDriven for TwinBeamsProblem {
    type Structure = TwinBeams;
    type Force = TipForce;
    type Cycle = BeamsCycle;
    type Point = BeamPoint;

    const FORCE: Param = Param::Beam(BeamParam::Force);
    const STIFFNESS: Param = Param::Beam(BeamParam::Stiffness);

    fn structure(model: &BeamsModel) -> TwinBeams {
        model.beams
    }

    fn applied_force(model: &BeamsModel) -> Self::Force {
        model.force
    }

    fn at_force(beams: &TwinBeams, force: TipForce) -> BeamsModel {
        BeamsModel {
            beams: *beams,
            force,
        }
    }

    /// Any force of the tip force's domain: the beams carry every one (macroslip past F_thre).
    fn force(_beams: &TwinBeams, newtons: f64) -> Result<TipForce, ParamError> {
        TipForce::new(newtons)
    }

    fn clamped_force(_beams: &TwinBeams, newtons: f64) -> TipForce {
        TipForce::clamped(newtons)
    }

    fn load_value(force: TipForce) -> f64 {
        force.newtons()
    }

    /// F_thre, where Coulomb's interface starts to slide.
    fn force_scale(beams: &TwinBeams) -> f64 {
        beams.threshold_force()
    }

    /// F_thre, where Coulomb's interface starts to slide: the deviation from Coulomb is flat
    /// below it and falls above it (T2).
    fn regime_changes(beams: &TwinBeams) -> Vec<f64> {
        vec![beams.threshold_force()]
    }

    fn response(beams: &TwinBeams, law: Law, force: TipForce) -> f64 {
        match law {
            Law::Coulomb => beams.coulomb(force).tip_deflection(),
            Law::Regularized => beams.regularized(force).tip_deflection(),
        }
    }

    fn point(beams: &TwinBeams, force: TipForce) -> BeamPoint {
        beam_point(beams, force)
    }

    /// From the clamp to the end of the stick zone (Coulomb) or of the microslip zone X
    /// (regularized).
    fn holding_zone(beams: &TwinBeams, law: Law, force: TipForce) -> [f64; 2] {
        match law {
            Law::Coulomb => [0.0, beams.coulomb(force).stick_end()],
            Law::Regularized => [0.0, beams.regularized(force).micro_zone_end()],
        }
    }

    fn cycle(beams: &TwinBeams, law: Law, amplitude: TipForce) -> BeamsCycle {
        BeamsCycle::new(beams, law, amplitude)
    }

    fn tangential_stiffness(beams: &TwinBeams) -> f64 {
        beams.params().tangential_stiffness
    }

    fn with_tangential_stiffness(beams: &TwinBeams, kt: f64) -> Result<TwinBeams, ParamError> {
        beams.with_tangential_stiffness(kt)
    }

    fn interface_strength(beams: &TwinBeams) -> f64 {
        let p = beams.params();
        p.friction * p.pressure
    }

    fn modulus(beams: &TwinBeams) -> f64 {
        beams.params().youngs_modulus
    }
}
