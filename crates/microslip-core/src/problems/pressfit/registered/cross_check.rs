//! The press fit against its own finite elements ([`CrossChecked`]): Delta, and the sliding
//! zones over L, in every regime, on the six fits of the folder's tests.

use super::problem::{FitKind, FitProblem, PressFitModel};
use crate::kernel::format::number;
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::cross_check::{CrossChecked, relative_error};
use crate::problems::pressfit::closed_form::PressFit;
use crate::problems::pressfit::discretized::PressFitFe;
use crate::problems::pressfit::params::PressFitParams;
use crate::problems::problem::Registered;

/// The bundled fit; on the full grid also a solid shaft and a thin ring (the held face first).
fn shapes(full: bool) -> Vec<PressFitParams> {
    let base = PressFitParams::CCX98;
    let mut shapes = vec![base];
    if full {
        shapes.push(PressFitParams {
            bore_radius: 0.0,
            length: 40.0,
            ..base
        });
        shapes.push(PressFitParams {
            fit_radius: 10.0,
            bore_radius: 0.0,
            outer_radius: 11.0,
            length: 20.0,
            hub_modulus: 70_000.0,
            interference: 0.005,
            ..base
        });
    }
    shapes
}

impl<K: FitKind> CrossChecked for FitProblem<K>
where
    FitProblem<K>: Registered,
{
    const COMPARED: &'static [&'static str] = K::COMPARED;

    fn grid(full: bool) -> Vec<PressFitModel> {
        let mut models = Vec::new();
        for shape in shapes(full) {
            for kt in [1e3, 1e4, 1e5] {
                let Ok(fit) = PressFit::new(PressFitParams {
                    tangential_stiffness: kt,
                    ..shape
                }) else {
                    continue;
                };
                let axis = fit.axis(K::LOAD);
                let (f1, f2, gross) = (
                    axis.first_slip_load(),
                    axis.second_slip_load(),
                    axis.gross_load(),
                );
                for f in [0.5 * f1, 0.5 * (f1 + f2), 0.5 * (f2 + gross), 0.95 * gross] {
                    if let Ok(force) = axis.load(f) {
                        models.push(PressFitModel { fit, force });
                    }
                }
            }
        }
        models
    }

    fn compare(model: &PressFitModel, density: MeshDensity) -> Result<Vec<f64>, NumericError> {
        let params = model.fit.params();
        let exact = model.fit.axis(K::LOAD).regularized(model.force);
        let mut fe = PressFitFe::new(params, K::LOAD, density);
        fe.load_to(model.force.value(), 4)?;
        let (a, d) = fe.sliding_zones();
        let off = (a - exact.slide_from_loaded_face())
            .abs()
            .max((d - exact.slide_from_held_face()).abs());
        Ok(vec![
            relative_error(fe.response(), exact.response()),
            off / params.length,
        ])
    }

    fn describe(model: &PressFitModel) -> String {
        let p = model.fit.params();
        format!(
            "K_T={} MPa/mm {}={} {} r={} ri={} ro={} L={} delta={} mm Es={} Eh={} MPa nus={} \
             nuh={} mu={}",
            number(p.tangential_stiffness),
            K::LOAD.param(),
            number(model.force.value()),
            K::LOAD.param().spec().unit,
            number(p.fit_radius),
            number(p.bore_radius),
            number(p.outer_radius),
            number(p.length),
            number(p.interference),
            number(p.shaft_modulus),
            number(p.hub_modulus),
            number(p.shaft_poisson),
            number(p.hub_poisson),
            number(p.friction)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::super::problem::{PushOut, Twist};
    use super::*;

    /// What `verify` asks of every problem: the full grid within its 1e-3 on the default mesh,
    /// pushed out and twisted.
    #[test]
    fn the_full_grid_is_within_the_verify_tolerance() {
        fn within<K: FitKind>()
        where
            FitProblem<K>: Registered,
        {
            let grid = FitProblem::<K>::grid(true);
            assert!(grid.len() >= 30, "{}", grid.len());
            for model in &grid {
                let errors = FitProblem::<K>::compare(model, MeshDensity::default()).unwrap();
                assert!(
                    errors.iter().all(|&e| e < 1e-3),
                    "{}: {errors:?}",
                    FitProblem::<K>::describe(model)
                );
            }
        }
        within::<PushOut>();
        within::<Twist>();
    }
}
