//! The interface's zones at one state, both laws: the stretches that stick, slip elastically,
//! slide or carry no load, and the named boundaries between them (the TUI's zone strip and the
//! regime pane read them).

use crate::kernel::regime::Regime;
use crate::problems::inputs::Model;
use crate::problems::zoned::LawLayout;

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

/// The zones of both laws at the model's state, for any problem whose interface holds over one
/// stretch under each law ([`Zoned`](crate::problems::zoned::Zoned)): the stretch sticks
/// (Coulomb) or slips elastically (regularized) and the interface slides on either side of it;
/// an unloaded law's interface is unloaded throughout. The boundaries are the stretch's named
/// edges strictly inside (0, L), Coulomb's first. Empty for a problem without a layout.
pub fn interface_zones(model: &Model) -> InterfaceZones {
    let Some(layout) = model
        .kind()
        .problem()
        .faces()
        .zoned
        .and_then(|layout| layout(model))
    else {
        return InterfaceZones {
            length: 0.0,
            coulomb: Vec::new(),
            regularized: Vec::new(),
            boundaries: Vec::new(),
        };
    };
    let length = layout.length;
    let spans = |law: &LawLayout, middle: Zone| {
        if law.regime == Regime::UNLOADED {
            return split_at(length, length, Zone::Unloaded, Zone::Unloaded);
        }
        let [from, to] = law.holding.map(|at| at.clamp(0.0, length));
        [
            (0.0, from, Zone::Macroslip),
            (from, to, middle),
            (to, length, Zone::Macroslip),
        ]
        .into_iter()
        .filter(|(from, to, _)| to > from)
        .map(|(from, to, zone)| ZoneSpan { from, to, zone })
        .collect()
    };
    let inside = |at: f64| at > 0.0 && at < length;
    let boundaries = [layout.coulomb, layout.regularized]
        .into_iter()
        .filter(|law| law.regime != Regime::UNLOADED)
        .flat_map(|law| law.edges.into_iter().zip(law.holding))
        .filter(|&(_, at)| inside(at))
        .map(|(name, at)| ZoneBoundary { name, at })
        .collect();
    InterfaceZones {
        length,
        coulomb: spans(&layout.coulomb, Zone::Stick),
        regularized: spans(&layout.regularized, Zone::Microslip),
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
        interface_zones(&Model::Beam(
            crate::problems::twin_beams::problem::BeamsModel { beams, force },
        ))
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
