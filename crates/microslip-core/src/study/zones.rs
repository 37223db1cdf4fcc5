//! The interface's zones at one state, both laws: the stretches that stick, slip elastically,
//! slide or carry no load, and the named boundaries between them (the TUI's zone strip and the
//! regime pane read them).

use crate::kernel::regime::Regime;
use crate::problems::inputs::Model;
use crate::problems::lap::closed_form::{JointForce, LapJoint};
use crate::problems::lap::load_driven::lap_point;
use crate::problems::twin_beams::load_driven::beam_point;
use crate::study::curves::plate_point;

/// What one stretch of the interface does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Zone {
    /// No relative displacement (Coulomb law below the stress mu P).
    Stick,
    /// Elastic slip below mu P (regularized law).
    Microslip,
    /// Sliding at tau = mu P.
    Macroslip,
    /// No load at all (the beams at F = 0).
    Unloaded,
}

/// One stretch [from, to] (mm) of the interface and its zone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZoneSpan {
    /// Start (mm from x = 0).
    pub from: f64,
    /// End (mm from x = 0).
    pub to: f64,
    /// What the stretch does.
    pub zone: Zone,
}

/// A named zone boundary inside the interface (X, X_s, X_r), in mm from x = 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZoneBoundary {
    /// `X`, `X_s` or `X_r`, as in the theory and the regime pane.
    pub name: &'static str,
    /// Position (mm).
    pub at: f64,
}

/// The interface from x = 0 (clamp, plate centre) to L under both laws: the zone strip of the TUI.
#[derive(Debug, Clone, PartialEq)]
pub struct InterfaceZones {
    /// L (mm): beam length or plate half-length.
    pub length: f64,
    /// Coulomb's stretches, from x = 0 outward, covering [0, L].
    pub coulomb: Vec<ZoneSpan>,
    /// The regularized law's stretches.
    pub regularized: Vec<ZoneSpan>,
    /// Boundaries strictly inside (0, L), Coulomb's first.
    pub boundaries: Vec<ZoneBoundary>,
}

/// Two stretches split at `at`: `inner` on [0, at], `outer` on [at, L], leaving out an empty one.
fn split_at(length: f64, at: f64, inner: Zone, outer: Zone) -> Vec<ZoneSpan> {
    let at = at.clamp(0.0, length);
    [(0.0, at, inner), (at, length, outer)]
        .into_iter()
        .filter(|(from, to, _)| to > from)
        .map(|(from, to, zone)| ZoneSpan { from, to, zone })
        .collect()
}

/// The zones of both laws at the model's state: Coulomb sticks up to its stick end and slides
/// beyond; the regularized law slips elastically up to X (X_r) and slides beyond. From the same
/// `beam_point` / `plate_point` as the regime pane, so strip and text cannot disagree.
pub fn interface_zones(model: &Model) -> InterfaceZones {
    let (length, stick_end, micro_end, coulomb, regularized, names) = match model {
        Model::Beam { beams, force } => {
            let row = beam_point(beams, *force);
            let p = (row.stick_end, row.micro_end);
            let r = (row.regime_coulomb, row.regime_regularized);
            (beams.params().length, p.0, p.1, r.0, r.1, ("X_s", "X"))
        }
        Model::Plate(plate) => {
            let row = plate_point(plate);
            let p = (row.stick_end, row.micro_end);
            let r = (row.regime_coulomb, row.regime_regularized);
            (
                plate.params().half_length,
                p.0,
                p.1,
                r.0,
                r.1,
                ("X_s", "X_r"),
            )
        }
        Model::Lap { joint, force } => return lap_zones(joint, *force),
    };
    let zones = |regime: Regime, end: f64, inner: Zone| {
        if regime == Regime::UNLOADED {
            split_at(length, length, Zone::Unloaded, Zone::Unloaded)
        } else {
            split_at(length, end, inner, Zone::Macroslip)
        }
    };
    let inside = |at: f64| at > 0.0 && at < length;
    let boundaries = [
        (names.0, stick_end, coulomb),
        (names.1, micro_end, regularized),
    ]
    .into_iter()
    .filter(|&(_, at, regime)| regime != Regime::UNLOADED && inside(at))
    .map(|(name, at, _)| ZoneBoundary { name, at })
    .collect();
    InterfaceZones {
        length,
        coulomb: zones(coulomb, stick_end, Zone::Stick),
        regularized: zones(regularized, micro_end, Zone::Microslip),
        boundaries,
    }
}

/// The lap joint's zones: sliding from both ends, [0, a] and [L - d, L], sticking (Coulomb) or
/// elastic (regularized) between; boundaries named `a`, `L-d` (regularized) and `a_C`, `L-d_C`
/// (Coulomb).
fn lap_zones(joint: &LapJoint, force: JointForce) -> InterfaceZones {
    let length = joint.params().length;
    let row = lap_point(joint, force);
    let spans = |regime: Regime, (a, d): (f64, f64), middle: Zone| {
        if regime == Regime::UNLOADED {
            return split_at(length, length, Zone::Unloaded, Zone::Unloaded);
        }
        [
            (0.0, a, Zone::Macroslip),
            (a, length - d, middle),
            (length - d, length, Zone::Macroslip),
        ]
        .into_iter()
        .filter(|(from, to, _)| to > from)
        .map(|(from, to, zone)| ZoneSpan { from, to, zone })
        .collect()
    };
    let inside = |at: f64| at > 0.0 && at < length;
    let (ac, dc) = row.zones_coulomb;
    let (ar, dr) = row.zones_regularized;
    let boundaries = [
        ("a_C", ac, row.regime_coulomb),
        ("L-d_C", length - dc, row.regime_coulomb),
        ("a", ar, row.regime_regularized),
        ("L-d", length - dr, row.regime_regularized),
    ]
    .into_iter()
    .filter(|&(_, at, regime)| regime != Regime::UNLOADED && inside(at))
    .map(|(name, at, _)| ZoneBoundary { name, at })
    .collect();
    InterfaceZones {
        length,
        coulomb: spans(row.regime_coulomb, row.zones_coulomb, Zone::Stick),
        regularized: spans(
            row.regime_regularized,
            row.zones_regularized,
            Zone::Microslip,
        ),
        boundaries,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{PlateParams, SqueezedPlate, TipForce, TwinBeams, TwinBeamsParams};

    fn beam_zones(force: f64) -> InterfaceZones {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let force = TipForce::new(force).unwrap();
        interface_zones(&Model::Beam { beams, force })
    }

    fn plate_zones(kt: f64) -> InterfaceZones {
        let plate = SqueezedPlate::new(PlateParams {
            tangential_stiffness: kt,
            ..PlateParams::PAPER
        })
        .unwrap();
        interface_zones(&Model::Plate(plate))
    }

    /// Contiguous stretches from 0 to L, whatever the state.
    fn assert_covers(zones: &InterfaceZones) {
        for spans in [&zones.coulomb, &zones.regularized] {
            assert_eq!(spans.first().unwrap().from, 0.0, "{zones:?}");
            assert_eq!(spans.last().unwrap().to, zones.length, "{zones:?}");
            assert!(spans.windows(2).all(|w| w[0].to == w[1].from), "{zones:?}");
            assert!(spans.iter().all(|s| s.to > s.from), "{zones:?}");
        }
    }

    #[test]
    fn the_beams_zones_change_at_f_thre_and_f_1() {
        // F_thre = 4 mu b h P / 3 = 4 (0.3)(20)(10)(1) / 3 = 80 N by hand; F_1 is just above it.
        let zones: Vec<_> = [0.0, 40.0, 79.9, 80.1, 100.0, 150.0, 300.0]
            .map(beam_zones)
            .into();
        zones.iter().for_each(assert_covers);
        let only = |spans: &[ZoneSpan]| (spans.len() == 1).then(|| spans[0].zone);
        assert_eq!(only(&zones[0].coulomb), Some(Zone::Unloaded));
        assert_eq!(only(&zones[0].regularized), Some(Zone::Unloaded));
        assert_eq!(only(&zones[1].coulomb), Some(Zone::Stick));
        assert_eq!(only(&zones[1].regularized), Some(Zone::Microslip));
        assert_eq!(only(&zones[2].coulomb), Some(Zone::Stick));
        assert_eq!(only(&zones[3].coulomb), Some(Zone::Macroslip));
        assert_eq!(only(&zones[3].regularized), Some(Zone::Microslip));
        assert!(zones[..4].iter().all(|z| z.boundaries.is_empty()));
        // Above F_1, microslip then macroslip, with X moving toward the clamp as F grows.
        let x: Vec<f64> = zones[4..]
            .iter()
            .map(|z| {
                let kinds: Vec<Zone> = z.regularized.iter().map(|s| s.zone).collect();
                assert_eq!(kinds, [Zone::Microslip, Zone::Macroslip]);
                assert_eq!(z.boundaries.len(), 1);
                assert_eq!(z.boundaries[0].name, "X");
                assert_eq!(z.boundaries[0].at, z.regularized[0].to);
                z.boundaries[0].at
            })
            .collect();
        assert!(x.windows(2).all(|w| w[1] < w[0]), "{x:?}");
    }

    #[test]
    fn the_plates_microslip_end_tends_to_the_coulomb_stick_end_as_kt_grows() {
        let stick_end = |z: &InterfaceZones| z.coulomb[0].to;
        let micro_end = |z: &InterfaceZones| z.regularized[0].to;
        let soft = plate_zones(1e4);
        assert_covers(&soft);
        // Soft: no macroslip (its onset is K_T = 1.88e5 MPa/mm), so only X_s is inside.
        assert_eq!(soft.regularized.len(), 1);
        let names: Vec<&str> = soft.boundaries.iter().map(|b| b.name).collect();
        assert_eq!(names, ["X_s"]);
        let gaps: Vec<f64> = [1e6, 1e8, 1e10]
            .map(plate_zones)
            .iter()
            .map(|z| {
                assert_covers(z);
                assert_eq!(z.coulomb[0].zone, Zone::Stick);
                assert_eq!(z.regularized[1].zone, Zone::Macroslip);
                micro_end(z) - stick_end(z)
            })
            .collect();
        // The regularized law slips elastically a little further than Coulomb sticks, and the
        // difference vanishes as K_T grows (plain Coulomb in the limit).
        assert!(gaps.iter().all(|&g| g > 0.0), "{gaps:?}");
        assert!(gaps.windows(2).all(|w| w[1] < w[0]), "{gaps:?}");
        assert!(gaps[2] < 1e-3 * soft.length, "{gaps:?}");
    }
}
