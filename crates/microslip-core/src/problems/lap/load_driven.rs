//! The double-lap joint as a load-driven problem ([`LoadDriven`]): the force F through the joint,
//! in [0, F_gross]; Delta its response; F_gross = 2 b mu P L its regime scale; the Masing cycle
//! of [`LapCycle`].

use crate::kernel::params::ParamError;
use crate::kernel::regime::Law;
use crate::problems::lap::closed_form::{JointForce, LapJoint};
use crate::problems::lap::cycle::LapCycle;
use crate::problems::lap::point::{LapPoint, lap_point};
use crate::problems::lap::problem::{LapJointProblem, LapModel};
use crate::problems::load_driven::LoadDriven;
use crate::problems::{LapParam, Param};

impl LoadDriven for LapJointProblem {
    type Structure = LapJoint;
    type Force = JointForce;
    type Cycle = LapCycle;
    type Point = LapPoint;

    const FORCE: Param = Param::Lap(LapParam::Force);
    const STIFFNESS: Param = Param::Lap(LapParam::Stiffness);

    fn structure(model: &LapModel) -> LapJoint {
        model.joint
    }

    fn applied_force(model: &LapModel) -> Self::Force {
        model.force
    }

    fn at_force(joint: &LapJoint, force: JointForce) -> LapModel {
        LapModel {
            joint: *joint,
            force,
        }
    }

    /// A force in the force domain and at most F_gross (no static state beyond, (L6)).
    fn force(joint: &LapJoint, newtons: f64) -> Result<JointForce, ParamError> {
        joint.force(newtons)
    }

    fn clamped_force(joint: &LapJoint, newtons: f64) -> JointForce {
        joint.clamped_force(newtons)
    }

    fn load_value(force: JointForce) -> f64 {
        force.newtons()
    }

    /// F_gross = 2 b mu P L, where the whole overlap slides.
    fn force_scale(joint: &LapJoint) -> f64 {
        joint.gross_slip_force()
    }

    /// F_1 and F_2, where sliding starts at the first and at the second end (L2), (L3).
    fn regime_changes(joint: &LapJoint) -> Vec<f64> {
        vec![joint.first_slip_force(), joint.second_slip_force()]
    }

    fn response(joint: &LapJoint, law: Law, force: JointForce) -> f64 {
        match law {
            Law::Coulomb => joint.coulomb(force).joint_displacement(),
            Law::Regularized => joint.regularized(force).joint_displacement(),
        }
    }

    fn point(joint: &LapJoint, force: JointForce) -> LapPoint {
        lap_point(joint, force)
    }

    /// Between the sliding zones: from x = a to x = L - d.
    fn holding_zone(joint: &LapJoint, law: Law, force: JointForce) -> [f64; 2] {
        let state = match law {
            Law::Coulomb => joint.coulomb(force),
            Law::Regularized => joint.regularized(force),
        };
        [
            state.slide_at_inner_end(),
            joint.params().length - state.slide_at_cover_ends(),
        ]
    }

    fn cycle(joint: &LapJoint, law: Law, amplitude: JointForce) -> LapCycle {
        LapCycle::new(joint, law, amplitude)
    }

    fn tangential_stiffness(joint: &LapJoint) -> f64 {
        joint.params().tangential_stiffness
    }

    fn with_tangential_stiffness(joint: &LapJoint, kt: f64) -> Result<LapJoint, ParamError> {
        joint.with_tangential_stiffness(kt)
    }

    fn interface_strength(joint: &LapJoint) -> f64 {
        let p = joint.params();
        p.friction * p.pressure
    }

    /// The inner plate's E1.
    fn modulus(joint: &LapJoint) -> f64 {
        joint.params().inner_modulus
    }

    /// At a range from zero, a force of 1e-9 of its end stands for the limit F -> 0: there the
    /// regularized joint is elastic and Coulomb's is bonded (its slip grows as F^2), so their
    /// ratio tends to the elastic compliance over the bonded one, the largest deviation of the
    /// range (the F^2 term is then 1e-9 of the bonded one).
    fn deviation_probes(_joint: &LapJoint, [from, to]: [f64; 2]) -> Vec<f64> {
        if from == 0.0 {
            vec![1e-9 * to]
        } else {
            Vec::new()
        }
    }
}
