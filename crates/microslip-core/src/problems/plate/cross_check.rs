//! The squeezed plate against its own finite elements ([`CrossChecked`]): u(L) and X_r over
//! three plates and K_T from stick to gross slip.

use crate::kernel::format::number;
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::cross_check::{CrossChecked, relative_error};
use crate::problems::plate::PlateFe;
use crate::problems::plate::closed_form::SqueezedPlate;
use crate::problems::plate::params::PlateParams;
use crate::problems::plate::problem::SqueezedPlateProblem;

/// Plate variants of the grid.
fn plate_shapes(full: bool) -> Vec<PlateParams> {
    let paper = PlateParams::PAPER;
    let mut shapes = vec![paper];
    if full {
        shapes.push(PlateParams {
            thickness: 1.0,
            poisson: 0.45,
            friction: 0.8,
            ..paper
        });
        shapes.push(PlateParams {
            half_length: 50.0,
            thickness: 0.1,
            poisson: 0.1,
            friction: 0.1,
            pressure: 1.0,
            ..paper
        });
    }
    shapes
}

/// K_T values (MPa/mm) of the grid.
const PLATE_STIFFNESSES: [f64; 6] = [1.0, 1e3, 1e5, 1e6, 1e7, 1e8];

impl CrossChecked for SqueezedPlateProblem {
    const COMPARED: &'static [&'static str] = &["plate u(L) (mm)", "plate X_r (mm)"];

    fn grid(full: bool) -> Vec<SqueezedPlate> {
        let mut models = Vec::new();
        for shape in plate_shapes(full) {
            for kt in PLATE_STIFFNESSES {
                let params = PlateParams {
                    tangential_stiffness: kt,
                    ..shape
                };
                if let Ok(plate) = SqueezedPlate::new(params) {
                    models.push(plate);
                }
            }
        }
        models
    }

    fn compare(plate: &SqueezedPlate, density: MeshDensity) -> Result<Vec<f64>, NumericError> {
        let params = plate.params();
        let exact = plate.regularized();
        let mut fe = PlateFe::new(params, density);
        fe.load_to(params.pressure, 2)?;
        Ok(vec![
            relative_error(fe.end_displacement(), exact.end_displacement()),
            relative_error(fe.micro_zone_end(), exact.micro_zone_end()),
        ])
    }

    fn describe(plate: &SqueezedPlate) -> String {
        let p = plate.params();
        format!(
            "K_T={} MPa/mm L={} t_p={} mm E={} MPa nu={} mu={} P={} MPa",
            number(p.tangential_stiffness),
            number(p.half_length),
            number(p.thickness),
            number(p.youngs_modulus),
            number(p.poisson),
            number(p.friction),
            number(p.pressure)
        )
    }
}
