//! The twin beams against their own finite elements ([`CrossChecked`]): w(L) and X over three
//! geometries, five decades of K_T and forces in every regime.

use crate::kernel::format::number;
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::cross_check::{CrossChecked, relative_error};
use crate::problems::twin_beams::TwinBeamsFe;
use crate::problems::twin_beams::closed_form::{TipForce, TwinBeams};
use crate::problems::twin_beams::params::TwinBeamsParams;
use crate::problems::twin_beams::problem::{BeamsModel, TwinBeamsProblem};

/// Beam geometries of the grid: the paper's, a slender one and a stubby one, each with its own mu, P.
fn beam_shapes(full: bool) -> Vec<TwinBeamsParams> {
    let paper = TwinBeamsParams::PAPER;
    let mut shapes = vec![paper];
    if full {
        shapes.push(TwinBeamsParams {
            length: 500.0,
            width: 10.0,
            half_height: 2.0,
            friction: 0.15,
            pressure: 2.0,
            ..paper
        });
        shapes.push(TwinBeamsParams {
            length: 50.0,
            width: 30.0,
            half_height: 5.0,
            youngs_modulus: 70_000.0,
            friction: 0.8,
            pressure: 0.5,
            ..paper
        });
    }
    shapes
}

/// K_T values (MPa/mm) of the grid: five decades around each data set.
const BEAM_STIFFNESSES: [f64; 5] = [12.0, 120.0, 600.0, 6e3, 6e4];

impl CrossChecked for TwinBeamsProblem {
    const COMPARED: &'static [&'static str] = &["beam w(L) (mm)", "beam X (mm)"];

    /// Stick-like, just below and just above F_1, and two depths of macroslip, at each shape and
    /// K_T.
    fn grid(full: bool) -> Vec<BeamsModel> {
        let mut models = Vec::new();
        for shape in beam_shapes(full) {
            for kt in BEAM_STIFFNESSES {
                let params = TwinBeamsParams {
                    tangential_stiffness: kt,
                    ..shape
                };
                let Ok(beams) = TwinBeams::new(params) else {
                    continue;
                };
                let (f_thre, f_1) = (beams.threshold_force(), beams.first_macroslip_force());
                for f in [
                    0.5 * f_thre,
                    0.98 * f_1,
                    1.02 * f_1,
                    1.5 * f_thre,
                    3.0 * f_thre,
                ] {
                    if let Ok(force) = TipForce::new(f) {
                        models.push(BeamsModel { beams, force });
                    }
                }
            }
        }
        models
    }

    fn compare(model: &BeamsModel, density: MeshDensity) -> Result<Vec<f64>, NumericError> {
        let exact = model.beams.regularized(model.force);
        let mut fe = TwinBeamsFe::new(model.beams.params(), density);
        fe.load_to(model.force.newtons(), 4)?;
        Ok(vec![
            relative_error(fe.tip_deflection(), exact.tip_deflection()),
            relative_error(fe.micro_zone_end(), exact.micro_zone_end()),
        ])
    }

    fn describe(model: &BeamsModel) -> String {
        let p = model.beams.params();
        format!(
            "K_T={} MPa/mm F={} N L={} b={} h={} mm E={} MPa P={} MPa mu={}",
            number(p.tangential_stiffness),
            number(model.force.newtons()),
            number(p.length),
            number(p.width),
            number(p.half_height),
            number(p.youngs_modulus),
            number(p.pressure),
            number(p.friction)
        )
    }
}
