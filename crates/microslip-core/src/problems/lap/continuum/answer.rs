//! The lap joint's answer read from a solved interface state ([`ContinuumLap`]).

use super::mesh::Grid;
use super::{ContinuumLap, LOCAL_SLIDING, SlidingZones};
use crate::numeric::two_body::{Reduced, State, last_of_run, nominal_front};

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
    let contact = model.contact_forces();
    let weights = &grid.two.pair_weights;
    let xs = &grid.two.pair_x;
    let slip: Vec<(f64, f64)> = xs
        .iter()
        .zip(slip_from_clamp)
        .map(|(&x, ds)| (x, *ds))
        .collect();
    let forces = model.pair_forces();
    let shear = grid.two.per_face(&forces, 1.0);
    let contact_pressure = grid.two.per_face(&contact, 1.0);
    let length = *xs.last().unwrap_or(&0.0);
    // Nominal: K_T |s| >= mu P, P the nominal pressure, slip from the clamped state.
    let saturation = model.friction() * model.pressure();
    let level = |i: usize| c.stiffness[i] / weights[i] * slip[i].1.abs();
    let from_start = nominal_front(xs, level, saturation, &mut (0..slip.len()));
    let from_end = length - nominal_front(xs, level, saturation, &mut (0..slip.len()).rev());
    let nominal_zones = SlidingZones {
        from_inner_end: from_start,
        from_cover_ends: from_end,
    };
    // Local: |tau| >= (1 - 1e-3) mu p, at node resolution.
    let sliding = |i: usize| {
        let p = contact_pressure[i].1;
        p > 0.0 && shear[i].1.abs() >= (1.0 - LOCAL_SLIDING) * model.friction() * p
    };
    let local_zones = SlidingZones {
        from_inner_end: last_of_run(sliding, &mut (0..xs.len())).map_or(0.0, |i| xs[i]),
        from_cover_ends: last_of_run(sliding, &mut (0..xs.len()).rev())
            .map_or(0.0, |i| length - xs[i]),
    };
    // Delta from the clamped state as F s_F's reading plus the plastic slips' change, not as
    // a difference of totals: P alone gives about 1.7e-3 mm on the bundled joint, whose
    // round-off (4e-19 mm) swallowed Delta at F = 1e-14 N (issue 36).
    let delta = model.reading_from(clamped);
    ContinuumLap {
        force: model.load,
        delta,
        clamping_delta: model.first_reading(),
        separated: contact
            .iter()
            .zip(xs)
            .filter(|(n, _)| **n < 0.0)
            .map(|(_, &x)| x)
            .collect(),
        transferred_force: width * forces.iter().sum::<f64>(),
        slip,
        shear,
        contact_pressure,
        nominal_zones,
        local_zones,
        increments,
        iterations,
        pairs: c.pairs,
    }
}
