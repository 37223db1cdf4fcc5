//! What a CalculiX run of the cylinder deck gives, read from its `.dat` (the node displacements
//! of the two contact faces, `*NODE PRINT`) and the `.frd` beside it (the contact pressure):
//!
//! - the contact pressure at the end of the normal step: CalculiX's own CPRESS at the flat's
//!   face nodes (the deck's slave face), from the `.frd`'s `CONTACT` block of step 1. Without
//!   the `.frd`, the penalty law's p = K_N x penetration at each node pair (the deck's
//!   `*SURFACE BEHAVIOR` slope K_N; the gap of the cylinder node over the flat node below it,
//!   both on the undeformed x). The pairs agree with CPRESS to 0.5 % of p0 inside the contact
//!   while the faces stay facing, but a cylinder that is not a half-plane (a / R above 0.015)
//!   slides on the flat during the normal step and its pairs part: at a / R = 0.06 they carried
//!   368 of the 500 N/mm pressing (issue 45). So a pressure whose fitted Hertz ellipse does not
//!   carry the deck's line load P to [`EQUILIBRIUM_TOLERANCE`] is not used: the run's a, p0 and c are then not given
//!   (s(a) is still read). The two nodes at the edge scatter in both, so a and p0 are the
//!   least-squares Hertz ellipse p^2 = p0^2 (1 - x^2/a^2) through the nodes above 0.3 p0;
//! - under Q the pressure is that of the normal step: two bodies of one material do not couple
//!   the shear into the pressure (docs/theory.md), and CalculiX's CPRESS moved by less than
//!   0.1 % of p0 under Q in the study (the gap, read under Q, would mix the bodies' tilt into
//!   the tiny penetration);
//! - the slip s(x) = u_x(cylinder) - u_x(flat), measured from the end of the normal step;
//! - the micro-slip zone |x| < c: contiguous from the centre, where K_T |s| < mu p (the law's
//!   elastic branch), each side interpolated where K_T |s| / (mu p) crosses 1; c is the mean of
//!   both sides;
//! - s(a) at Hertz's a (the mean of both sides; the slip is steep there at a stiff K_T, so the
//!   comparison reads both at one place; the FE's own a is reported beside it) and s(0).

use std::collections::HashMap;

use crate::fe::results::{DatRead, NOT_FINISHED, ResultsError, load_step_time, node_coordinate};
use crate::fe::stick_slope::ContactStep;

use super::deck_writer::sets;

/// One FE point of the cylinder: the contact at the end of a load step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderFePoint {
    /// Tangential line load Q (N/mm).
    pub load: f64,
    /// Slip at the contact's edges x = +-a (Hertz's a, mm), the mean of both: the fretting slip
    /// amplitude.
    pub edge_slip: f64,
    /// What a CalculiX run gives beside s(a); None from a CSV curve (`Q_N_per_mm,sa_mm`).
    pub contact: Option<FeContact>,
}

/// The contact of an FE run at one load step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FeContact {
    /// Contact half-width a (mm), from the normal step's pressure.
    pub half_width: f64,
    /// Peak pressure p0 (MPa), from the normal step's pressure.
    pub peak_pressure: f64,
    /// Half-width c of the zone where K_T |s| < mu p (mm).
    pub micro_half_width: f64,
    /// Slip at the centre (mm).
    pub centre_slip: f64,
}

/// How far the load the pressure read carries may be from the deck's line load P (a fraction)
/// and its a, p0 and c be given.
///
/// The load carried is the fitted Hertz ellipse's, pi a p0 / 2 ([`hertz_fit`]): a sum over the
/// nodes would miss up to 1.6 % at the edges on an a/8 mesh (a square root falls to zero there).
/// On the deck's meshes inside the envelope the fitted a and p0 are within 0.8 % and 0.1 % of
/// Hertz's (docs/theory.md section 16), so 3 % is over three times their error, and far inside
/// the 26 % the node pairs lost at a / R = 0.06.
pub const EQUILIBRIUM_TOLERANCE: f64 = 0.03;

/// A face node's coordinate (mm), displacement (mm) and number.
type FaceNode = ([f64; 3], [f64; 3], usize);

/// The contact faces at one time: x (mm), the facing nodes' displacements (mm).
struct Faces {
    xs: Vec<f64>,
    /// The flat's face nodes, in x order (the deck's slave face: CPRESS is given at them).
    ids: Vec<usize>,
    /// (flat, cylinder) displacement pairs, in x order.
    pairs: Vec<([f64; 3], [f64; 3])>,
    /// The cylinder node's height above the flat node, undeformed (mm): its arc.
    heights: Vec<f64>,
}

/// The normal penalty K_N (MPa/mm) a deck gives CalculiX: the line after its
/// `*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR` card.
fn normal_slope(deck: &str) -> Result<f64, ResultsError> {
    let mut lines = deck.lines();
    while let Some(line) = lines.next() {
        if line
            .to_ascii_uppercase()
            .contains("PRESSURE-OVERCLOSURE=LINEAR")
        {
            return lines
                .next()
                .and_then(|l| l.split(',').next())
                .and_then(|v| v.trim().parse::<f64>().ok())
                .filter(|k| *k > 0.0 && k.is_finite())
                .ok_or_else(|| {
                    ResultsError::Missing("the deck's normal penalty K_N is not a number".into())
                });
        }
    }
    Err(ResultsError::Missing(
        "the deck has no linear pressure-overclosure law (is it a cylinder deck?)".into(),
    ))
}

/// The least-squares Hertz ellipse p^2 = p0^2 (1 - x^2 / a^2) through the nodes above 0.3 of
/// the largest pressure: (a, p0), or None when fewer than three nodes press.
pub(crate) fn hertz_fit(xs: &[f64], pressures: &[f64]) -> Option<(f64, f64)> {
    let top = pressures.iter().copied().fold(0.0, f64::max);
    let points: Vec<(f64, f64)> = xs
        .iter()
        .zip(pressures)
        .filter(|(_, p)| **p > 0.3 * top)
        .map(|(x, p)| (x * x, p * p))
        .collect();
    if points.len() < 3 {
        return None;
    }
    let n = points.len() as f64;
    let (mu, mv) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), (u, v)| (a + u / n, b + v / n));
    let suu: f64 = points.iter().map(|(u, _)| (u - mu) * (u - mu)).sum();
    let suv: f64 = points.iter().map(|(u, v)| (u - mu) * (v - mv)).sum();
    let slope = -suv / suu;
    let intercept = mv + slope * mu;
    (slope > 0.0 && intercept > 0.0).then(|| ((intercept / slope).sqrt(), intercept.sqrt()))
}

/// y at `x` on the polyline (xs, ys), xs increasing; None outside it.
fn interpolate(xs: &[f64], ys: &[f64], x: f64) -> Option<f64> {
    xs.windows(2).zip(ys.windows(2)).find_map(|(w, v)| {
        (w[0] <= x && x <= w[1]).then(|| v[0] + (v[1] - v[0]) * (x - w[0]) / (w[1] - w[0]))
    })
}

/// The half-width (mm) of the zone, contiguous from x = 0 toward both ends, where
/// `ratio` < 1, each side interpolated where the ratio crosses 1; the mean of both sides.
pub(crate) fn micro_zone(xs: &[f64], ratio: &[f64]) -> f64 {
    let centre = (0..xs.len())
        .min_by(|&i, &j| xs[i].abs().total_cmp(&xs[j].abs()))
        .unwrap_or(0);
    let reach = |step: isize| -> f64 {
        let mut k = centre as isize;
        let inside = |k: isize| k >= 0 && (k as usize) < xs.len();
        if ratio[centre] >= 1.0 {
            return 0.0;
        }
        while inside(k + step) && ratio[(k + step) as usize] < 1.0 {
            k += step;
        }
        let here = k as usize;
        if !inside(k + step) {
            return xs[here].abs();
        }
        let next = (k + step) as usize;
        let (r0, r1) = (ratio[here], ratio[next]);
        let t = if r1.is_finite() {
            (1.0 - r0) / (r1 - r0)
        } else {
            0.0
        };
        (xs[here] + (xs[next] - xs[here]) * t).abs()
    };
    0.5 * (reach(1) + reach(-1))
}

/// What a cylinder run is read with besides its deck and `.dat`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct CylinderReading<'a> {
    /// The `.frd`'s interface at the end of each step; `None`: no `.frd` (the node pairs' pressure).
    pub contact: Option<&'a [ContactStep]>,
    /// The load steps (N/mm).
    pub loads: &'a [f64],
    /// The deck's line load P (N/mm), which the normal step's pressure must carry.
    pub pressing: f64,
    /// The deck's stick slope K_T (MPa/mm).
    pub kt: f64,
    /// The friction coefficient.
    pub mu: f64,
    /// Where s(a) is read: Hertz's a (mm).
    pub edge: f64,
}

/// The normal step's pressure at the faces' nodes (MPa): CPRESS from the `.frd`'s step 1 where
/// given, else the node pairs' penalty (see the module's docs).
fn normal_pressures(normal: &Faces, contact: Option<&[ContactStep]>, slope: f64) -> Vec<f64> {
    if let Some(step) = contact.and_then(|steps| steps.iter().find(|s| s.step == 1)) {
        let by_node: HashMap<usize, f64> = step
            .nodes
            .iter()
            .map(|n| (n.node, n.pressure.unwrap_or(0.0).max(0.0)))
            .collect();
        return normal
            .ids
            .iter()
            .map(|id| by_node.get(id).copied().unwrap_or(0.0))
            .collect();
    }
    normal
        .pairs
        .iter()
        .zip(&normal.heights)
        .map(|((f, c), h)| slope * (f[1] - c[1] - h).max(0.0))
        .collect()
}

/// The cylinder points of a run: one per load step that CalculiX finished (see
/// [`CylinderReading`]).
///
/// # Errors
/// A malformed `.dat` line, a set missing at the end of the normal step or of a load step, no
/// pressing node (a run that failed in its normal step).
pub(crate) fn cylinder_points(
    deck: &str,
    dat: &str,
    reading: &CylinderReading,
) -> Result<Vec<CylinderFePoint>, ResultsError> {
    let CylinderReading {
        contact,
        loads,
        pressing,
        kt,
        mu,
        edge,
    } = *reading;
    let dat = DatRead::of(deck, dat)?;
    let nodes = &dat.nodes;
    let slope = normal_slope(deck)?;
    let faces_at = |time: f64, what: &str| -> Result<Faces, ResultsError> {
        let missing = |why: String| ResultsError::Missing(format!("{what}: {why} {NOT_FINISHED}"));
        let flat = dat.block(sets::FLAT_FACE, time).map_err(missing)?;
        let cylinder = dat.block(sets::CYLINDER_FACE, time).map_err(missing)?;
        // (coordinate, displacement, node) of a face's rows, in x order.
        let along = |rows: &[(usize, [f64; 3])]| -> Result<Vec<FaceNode>, _> {
            let mut line: Vec<FaceNode> = rows
                .iter()
                .map(|(id, u)| node_coordinate(nodes, *id).map(|c| (c, *u, *id)))
                .collect::<Result<_, ResultsError>>()?;
            line.sort_by(|a, b| a.0[0].total_cmp(&b.0[0]));
            Ok::<_, ResultsError>(line)
        };
        let (flat, cylinder) = (along(&flat.rows)?, along(&cylinder.rows)?);
        if flat.len() != cylinder.len()
            || flat
                .iter()
                .zip(&cylinder)
                .any(|(f, c)| (f.0[0] - c.0[0]).abs() > 1e-9 * f.0[0].abs().max(1.0))
        {
            return Err(ResultsError::Missing(format!(
                "{what}: the contact faces' nodes do not face each other (is this a cylinder deck?)"
            )));
        }
        Ok(Faces {
            xs: flat.iter().map(|f| f.0[0]).collect(),
            ids: flat.iter().map(|f| f.2).collect(),
            heights: flat
                .iter()
                .zip(&cylinder)
                .map(|(f, c)| c.0[1] - f.0[1])
                .collect(),
            pairs: flat
                .iter()
                .zip(&cylinder)
                .map(|(f, c)| (f.1, c.1))
                .collect(),
        })
    };
    let normal = faces_at(1.0, "at the end of the normal step (time 1)")?;
    let pressures = normal_pressures(&normal, contact, slope);
    let (half_width, peak_pressure) = hertz_fit(&normal.xs, &pressures).ok_or_else(|| {
        ResultsError::Missing(
            "no node presses at the end of the normal step: the run did not close the contact"
                .into(),
        )
    })?;
    // A pressure that does not carry P is not the run's: its a, p0 and c are not given.
    let carried = 0.5 * std::f64::consts::PI * half_width * peak_pressure;
    let balanced = (carried / pressing - 1.0).abs() <= EQUILIBRIUM_TOLERANCE;
    let slips_at =
        |faces: &Faces| -> Vec<f64> { faces.pairs.iter().map(|(f, c)| c[0] - f[0]).collect() };
    let zero = slips_at(&normal);
    let mut points = Vec::with_capacity(loads.len());
    for (n, &load) in loads.iter().enumerate() {
        let time = load_step_time(n);
        let faces = faces_at(
            time,
            &format!(
                "load step {} of {} (Q = {load} N/mm, time {time})",
                n + 1,
                loads.len()
            ),
        )?;
        let slips: Vec<f64> = slips_at(&faces)
            .iter()
            .zip(&zero)
            .map(|(s, s0)| s - s0)
            .collect();
        let ratio: Vec<f64> = slips
            .iter()
            .zip(&pressures)
            .map(|(s, p)| {
                if *p > 0.0 {
                    kt * s.abs() / (mu * p)
                } else {
                    f64::INFINITY
                }
            })
            .collect();
        let at = |x: f64| interpolate(&faces.xs, &slips, x).unwrap_or(f64::NAN);
        points.push(CylinderFePoint {
            load,
            edge_slip: 0.5 * (at(edge) + at(-edge)),
            contact: balanced.then(|| FeContact {
                half_width,
                peak_pressure,
                micro_half_width: micro_zone(&faces.xs, &ratio),
                centre_slip: at(0.0),
            }),
        });
    }
    Ok(points)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[ignore = "reads the study's run in $CYL_RUN"]
    fn read_study_run() {
        let dir = std::env::var("CYL_RUN").unwrap();
        let kt: f64 = std::env::var("CYL_KT").map_or(5e4, |v| v.parse().unwrap());
        let deck = std::fs::read_to_string(format!("{dir}/cyl.inp")).unwrap();
        let dat = std::fs::read_to_string(format!("{dir}/cyl.dat")).unwrap();
        let a = std::env::var("CYL_A").map_or(0.525_231_918_323_660_1, |v| v.parse().unwrap());
        let contact =
            crate::fe::load::frd_contact(std::path::Path::new(&format!("{dir}/cyl.dat"))).ok();
        let reading = CylinderReading {
            contact: contact.as_deref(),
            loads: &[90.0, 180.0],
            pressing: 500.0,
            kt,
            mu: 0.6,
            edge: a,
        };
        for p in cylinder_points(&deck, &dat, &reading).unwrap() {
            println!("{p:?}");
        }
    }

    #[test]
    fn a_hertz_ellipse_is_fitted_exactly() {
        let xs: Vec<f64> = (-20..=20).map(|i| f64::from(i) * 0.05).collect();
        let ps: Vec<f64> = xs
            .iter()
            .map(|x| 600.0 * (1.0 - (x / 0.8f64).powi(2)).max(0.0).sqrt())
            .collect();
        let (a, p0) = hertz_fit(&xs, &ps).unwrap();
        assert!(
            (a - 0.8).abs() < 1e-12 && (p0 - 600.0).abs() < 1e-9,
            "{a} {p0}"
        );
    }

    #[test]
    fn the_micro_zone_is_read_from_the_centre_on_both_sides() {
        let xs = [-2.0, -1.0, 0.0, 1.0, 2.0];
        // Crosses 1 halfway between x = 1 and 2 on the right, at x = -1 on the left.
        let c = micro_zone(&xs, &[3.0, 1.0, 0.2, 0.5, 1.5]);
        assert!((c - 0.5 * (1.5 + 1.0)).abs() < 1e-12, "{c}");
        assert_eq!(micro_zone(&xs, &[2.0, 2.0, 1.5, 2.0, 2.0]), 0.0);
        assert_eq!(micro_zone(&xs, &[0.1; 5]), 2.0);
    }
}
