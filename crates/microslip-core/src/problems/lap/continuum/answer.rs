//! The lap joint's answer read from a solved interface state ([`ContinuumLap`]).

use super::mesh::Grid;
use super::{ContinuumLap, SlidingZones};
use crate::numeric::two_body::{Profiles, Reduced, State};

/// The state's answer; `slip_from_clamp` is s - s_clamped at each pair (mm), `width` the joint's
/// b (mm).
pub(super) fn lap_answer(
    model: &Reduced<'_>,
    grid: &Grid,
    clamped: &State,
    slip_from_clamp: &[f64],
    (increments, iterations): (usize, usize),
    width: f64,
) -> ContinuumLap {
    let c = model.c;
    let weights = &grid.two.pair_weights;
    let profiles = Profiles::read(model, &grid.two, slip_from_clamp, 1.0, 1.0);
    // Nominal: K_T |s| >= mu P, P the nominal pressure, slip from the clamped state.
    let saturation = model.friction() * model.pressure();
    let [from_inner_end, from_cover_ends] =
        profiles.nominal_zones(|i| c.stiffness[i] / weights[i], saturation);
    let nominal_zones = SlidingZones {
        from_inner_end,
        from_cover_ends,
    };
    // Local: |tau| >= (1 - 1e-3) mu p, at node resolution.
    let [from_inner_end, from_cover_ends] = profiles.local_zones(model.friction());
    let local_zones = SlidingZones {
        from_inner_end,
        from_cover_ends,
    };
    // Delta from the clamped state as F s_F's reading plus the plastic slips' change, not as
    // a difference of totals: P alone gives about 1.7e-3 mm on the bundled joint, whose
    // round-off (4e-19 mm) swallowed Delta at F = 1e-14 N (issue 36).
    let delta = model.reading_from(clamped);
    ContinuumLap {
        force: model.load,
        delta,
        clamping_delta: model.first_reading(),
        transferred_force: width * model.pair_forces().iter().sum::<f64>(),
        separated: profiles.separated,
        slip: profiles.slip,
        shear: profiles.shear,
        contact_pressure: profiles.pressure,
        nominal_zones,
        local_zones,
        increments,
        iterations,
        pairs: c.pairs,
    }
}
