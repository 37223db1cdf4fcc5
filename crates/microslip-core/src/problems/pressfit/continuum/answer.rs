//! The press fit's answer read from a solved interface state ([`ContinuumPressFit`]).

use super::mesh::Grid;
use super::{ContinuumPressFit, FitZones};
use crate::numeric::two_body::{Profiles, Reduced, State};

/// The state's answer; `slip_from_fit` is s - s_fitted at each pair (mm), `lame` Lamé's
/// plane-stress pressure (MPa), the nominal zones' strength.
pub(super) fn pressfit_answer(
    model: &Reduced<'_>,
    grid: &Grid,
    fitted: &State,
    slip_from_fit: &[f64],
    (increments, iterations): (usize, usize),
    lame: f64,
) -> ContinuumPressFit {
    let c = model.c;
    let weights = &grid.two.pair_weights;
    // The ring's circumference at the interface: pair forces over it and each pair's share of
    // the length are stresses.
    let ring = grid
        .two
        .lower
        .ys
        .last()
        .map_or(0.0, |r| 2.0 * std::f64::consts::PI * r);
    let profiles = Profiles::read(model, &grid.two, slip_from_fit, 1.0, ring);
    let [loaded, held] = profiles.nominal_zones(
        |i| c.stiffness[i] / (weights[i] * ring),
        model.friction() * lame,
    );
    let nominal_zones = FitZones {
        from_loaded_face: loaded,
        from_held_face: held,
    };
    let [loaded, held] = profiles.local_zones(model.friction());
    let local_zones = FitZones {
        from_loaded_face: loaded,
        from_held_face: held,
    };
    let normal: f64 = model.contact_forces().iter().sum();
    let length = profiles.slip.last().map_or(0.0, |(x, _)| *x);
    ContinuumPressFit {
        force: model.load,
        delta: model.reading_from(fitted),
        transferred_force: model.pair_forces().iter().sum(),
        capacity: model.friction() * normal,
        mean_pressure: normal / (ring * length),
        slip: profiles.slip,
        shear: profiles.shear,
        pressure: profiles.pressure,
        separated: profiles.separated,
        nominal_zones,
        local_zones,
        increments,
        iterations,
        pairs: c.pairs,
    }
}
