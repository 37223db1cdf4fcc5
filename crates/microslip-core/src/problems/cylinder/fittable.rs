//! The cylinder as a fittable problem ([`Fittable`]): the edge slip s(a) (the fretting slip
//! amplitude) measured against the tangential line load Q identifies K_T and mu
//! (docs/theory.md, "Fitting mu and K_T to the cylinder's s(a) against Q").
//!
//! Why both show: at small Q the microslip zone covers nearly the whole contact and s(a) is the
//! elastic interface's, linear in Q with a slope set by K_T alone; Mindlin's part grows as
//! mu^(-1/2) Q^(3/2) and takes over as Q nears mu P, so the curve's bend carries mu. With a
//! finite K_T the edges slide from the first newton per mm (p -> 0 there), so there is no load
//! below which mu is absent from the curve: the first-slip load is 0, and how well the data
//! show mu is left to its standard error.
//!
//! The contact carries no Q beyond mu P (gross slip), so, as for the lap joint, the fit
//! searches only the mu that carry every measured load.

use super::closed_form::{Cylinder, CylinderParams};
use super::params::CylinderParam;
use super::problem::CylinderProblem;
use crate::kernel::params::ParamError;
use crate::problems::fittable::Fittable;

impl Fittable for CylinderProblem {
    const LOAD_COLUMN: &'static str = "Q_N_per_mm";
    /// The regularized s(a), as `sweep cylinder` heads it.
    const RESPONSE_COLUMN: &'static str = "sa_mm";
    const FITTED: &'static str = "Hertzian cylinder";
    /// Every input but mu, K_T and Q: nu enters through E* (H1).
    const HELD: &'static [CylinderParam] = &[
        CylinderParam::Radius,
        CylinderParam::Modulus,
        CylinderParam::Poisson,
        CylinderParam::NormalLoad,
    ];

    fn interface_of(cylinder: &Cylinder) -> (f64, f64) {
        let p = cylinder.params();
        (p.friction, p.tangential_stiffness)
    }

    fn with_interface(cylinder: &Cylinder, mu: f64, kt: f64) -> Result<Cylinder, ParamError> {
        Cylinder::new(CylinderParams {
            friction: mu,
            tangential_stiffness: kt,
            ..cylinder.params()
        })
    }

    /// 0: under the regularized law the edges slide for every Q > 0 (module docs).
    fn first_macroslip_force(_cylinder: &Cylinder) -> f64 {
        0.0
    }

    /// mu P / mu = P (N/mm): the gross-slip load grows in proportion to mu.
    fn force_per_friction(cylinder: &Cylinder) -> Option<f64> {
        Some(cylinder.params().normal_load)
    }
}
