//! The double-lap joint against its own finite elements ([`CrossChecked`]): Delta, and the
//! sliding zones a and d over L, in every regime (all microslip, one end sliding, both, nearly
//! gross slip).

use crate::kernel::format::number;
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::cross_check::{CrossChecked, relative_error};
use crate::problems::lap::LapFe;
use crate::problems::lap::closed_form::LapJoint;
use crate::problems::lap::params::LapParams;
use crate::problems::lap::problem::{LapJointProblem, LapModel};

/// Lap joints of the grid: the bundled one (x = L slides first), and on the full grid a balanced
/// one (both ends at once) and one whose inner plate is stiffer (x = 0 first).
fn lap_shapes(full: bool) -> Vec<LapParams> {
    let aluminium = LapParams::ALUMINIUM;
    let mut shapes = vec![aluminium];
    if full {
        shapes.push(LapParams {
            inner_thickness: 4.0,
            ..aluminium
        });
        shapes.push(LapParams {
            inner_thickness: 6.0,
            friction: 0.6,
            pressure: 5.0,
            ..aluminium
        });
    }
    shapes
}

/// K_T values (MPa/mm) of the lap grid: 1/lambda from 25 mm to 0.25 mm on the bundled joint.
const LAP_STIFFNESSES: [f64; 4] = [100.0, 1e3, 1e4, 1e5];

impl CrossChecked for LapJointProblem {
    /// The zones' error is over the overlap L (a zone of zero length has no relative error).
    const COMPARED: &'static [&'static str] = &["lap Delta (mm)", "lap a, d (/L)"];

    fn grid(full: bool) -> Vec<LapModel> {
        let mut models = Vec::new();
        for shape in lap_shapes(full) {
            for kt in LAP_STIFFNESSES {
                let params = LapParams {
                    tangential_stiffness: kt,
                    ..shape
                };
                let Ok(joint) = LapJoint::new(params) else {
                    continue;
                };
                let (f1, f2, gross) = (
                    joint.first_slip_force(),
                    joint.second_slip_force(),
                    joint.gross_slip_force(),
                );
                for f in [0.5 * f1, 0.5 * (f1 + f2), 0.5 * (f2 + gross), 0.95 * gross] {
                    if let Ok(force) = joint.force(f) {
                        models.push(LapModel { joint, force });
                    }
                }
            }
        }
        models
    }

    fn compare(model: &LapModel, density: MeshDensity) -> Result<Vec<f64>, NumericError> {
        let params = model.joint.params();
        let exact = model.joint.regularized(model.force);
        let mut fe = LapFe::new(params, density);
        fe.load_to(model.force.newtons(), 4)?;
        let (a, d) = fe.sliding_zones();
        let off = (a - exact.slide_at_inner_end())
            .abs()
            .max((d - exact.slide_at_cover_ends()).abs());
        Ok(vec![
            relative_error(fe.joint_displacement(), exact.joint_displacement()),
            off / params.length,
        ])
    }

    fn describe(model: &LapModel) -> String {
        let p = model.joint.params();
        format!(
            "K_T={} MPa/mm F={} N L={} b={} t1={} t2={} mm E1={} E2={} MPa P={} MPa mu={}",
            number(p.tangential_stiffness),
            number(model.force.newtons()),
            number(p.length),
            number(p.width),
            number(p.inner_thickness),
            number(p.cover_thickness),
            number(p.inner_modulus),
            number(p.cover_modulus),
            number(p.pressure),
            number(p.friction)
        )
    }
}
