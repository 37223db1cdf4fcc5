//! How far the plate's strip theory holds (V1): its expected difference from a plane-strain
//! continuum, as numbers. The strip theory is exact for a strip whose displacement is uniform through
//! its thickness under a uniform contact pressure; the envelope was measured against the project's
//! plane-strain solver ([`super::continuum`], within 0.2 % of CalculiX on the thickness-mean u(L))
//! and CalculiX itself (docs/theory.md, "Validity of the closed forms").

use super::closed_form::SqueezedPlate;
use crate::kernel::validity::Validity;

/// The strip theory's envelope for one plate (V1). The strip theory states one u(L) for the whole
/// thickness; the envelope bounds how far a plane-strain continuum's u(L) is from it as the
/// thickness mean (what the strip's u stands for, and what [`PlateValidity::validity`] judges), at
/// the contact face and at mid-thickness. It does not bound X_r: the strip theory's slip zone
/// L - X_r was measured up to 2.4 times the continuum's where the mean holds
/// (docs/theory.md, (V1)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlateValidity {
    /// alpha t_p = t_p / l_s, the plate's thickness over the boundary-layer length
    /// l_s = 1/alpha = sqrt(E t_p / ((1 - nu^2) K_T)): how many "layers" the thickness spans.
    pub thickness_over_layer: f64,
    /// The strip theory's slip zone over the thickness, (L - X_r) / t_p.
    pub slip_over_thickness: f64,
    /// Bounds on |u(L) continuum / u(L) strip - 1| for the thickness mean, the contact face and
    /// mid-thickness, in that order; `None` where no calibration reaches (`NotCalibrated` or
    /// `MeasuredWrong`).
    pub expected: Option<[f64; 3]>,
    /// Where no bound from above reaches but the plate lies in a region (V1c) where every
    /// calibration plate was measured off: the least |u(L) continuum / u(L) strip - 1| of the
    /// thickness mean stated for that region (`MeasuredWrong`).
    pub measured_at_least: Option<f64>,
    /// The level of the thickness-mean bound.
    pub validity: Validity,
}

/// What each of [`PlateValidity::expected`] bounds, for reports.
pub const PLATE_QUANTITIES: [&str; 3] = ["thickness mean", "contact face", "mid-thickness"];

/// (V1a), alpha t_p <= 0.5: bound = c (alpha t_p)^2 / (1 - nu)^1.2 with c for the mean, the
/// contact face and mid-thickness. The continuum solver over 540 plates gave at most 0.380, 0.906
/// and 0.456 (examples/v1_calibration.rs); a plate outside that grid needed 0.375 on the mean.
const THICK_COEFFICIENTS: [f64; 3] = [0.40, 0.95, 0.50];
/// Largest alpha t_p over which (V1a) was calibrated.
pub const CALIBRATED_RATIO: f64 = 0.5;
/// The exponent of (1 - nu) in (V1a).
const PLATE_ERROR_POISSON_EXPONENT: f64 = 1.2;
/// (V1b), a slip zone at least 3 thicknesses long and alpha t_p <= 3.5: bound = c t_p / (L - X_r)
/// (mean, face, mid). Measured at most 0.152, 0.469 and 0.198 over the 130 such plates of the grid.
const SLIP_COEFFICIENTS: [f64; 3] = [0.17, 0.52, 0.22];
/// Shortest slip zone, in thicknesses, for which (V1b) was calibrated.
pub const CALIBRATED_SLIP: f64 = 3.0;
/// Largest alpha t_p in the calibration grid of (V1b).
pub const CALIBRATED_RATIO_SLIP: f64 = 3.5;

/// (V1c), where the strip theory is measured wrong: (smallest alpha t_p, the strip theory's slip
/// zone (L - X_r) / t_p below, the least |difference| of the thickness mean stated there). Drawn
/// from the continuum solver over 1354 plates outside (V1a) and (V1b) (`examples/v1_calibration.rs`
/// with and without `--measured-wrong`: alpha t_p 0.55 to 20, nu 0.05 to 0.49, mu 0.02 to 10, t_p/L
/// 0.005 to 0.3), where the least difference measured was 17 % and 46 %; tested on 197 hold-out
/// plates (`--hold-out`, tests/plate_continuum.rs), least 27 % and 57 % (docs/theory.md, (V1c)).
pub const MEASURED_WRONG: [(f64, f64, f64); 2] = [(0.7, 0.5, 0.15), (1.5, 1.0, 0.40)];
/// Largest alpha t_p of the (V1c) grid: the continuum solver stops at 20.
const MEASURED_WRONG_UP_TO_RATIO: f64 = 20.0;

impl SqueezedPlate {
    /// Where the strip theory stands for this plate (V1): the smaller of the bounds that apply.
    pub fn validity(&self) -> PlateValidity {
        let p = self.params();
        let ratio = self.decay_rate() * p.thickness;
        let slip = (p.half_length - self.regularized().micro_zone_end()) / p.thickness;
        if p.poisson == 0.0 {
            // u = 0 exactly in the strip theory and in the continuum (nothing squeezes the plate
            // sideways): the theory is exact for every quantity, whatever alpha t_p.
            return PlateValidity {
                thickness_over_layer: ratio,
                slip_over_thickness: slip,
                expected: Some([0.0; 3]),
                measured_at_least: None,
                validity: Validity::Holds,
            };
        }
        let slip = (p.half_length - self.regularized().micro_zone_end()) / p.thickness;
        let thick = (ratio <= CALIBRATED_RATIO).then(|| {
            THICK_COEFFICIENTS
                .map(|c| c * ratio * ratio / (1.0 - p.poisson).powf(PLATE_ERROR_POISSON_EXPONENT))
        });
        let sliding = (slip >= CALIBRATED_SLIP && ratio <= CALIBRATED_RATIO_SLIP)
            .then(|| SLIP_COEFFICIENTS.map(|c| c / slip));
        let expected = match (thick, sliding) {
            (Some(a), Some(b)) => Some([0, 1, 2].map(|i| a[i].min(b[i]))),
            (a, b) => a.or(b),
        };
        let measured_at_least = if expected.is_none() && ratio <= MEASURED_WRONG_UP_TO_RATIO {
            MEASURED_WRONG
                .iter()
                .filter(|&&(from, below, _)| ratio >= from && slip < below)
                .map(|&(_, _, least)| least)
                .reduce(f64::max)
        } else {
            None
        };
        let validity = match (expected, measured_at_least) {
            (Some(e), _) => Validity::of_error(e[0]),
            (None, Some(_)) => Validity::MeasuredWrong,
            (None, None) => Validity::NotCalibrated,
        };
        PlateValidity {
            thickness_over_layer: ratio,
            slip_over_thickness: slip,
            expected,
            measured_at_least,
            validity,
        }
    }
}

impl PlateValidity {
    /// The bound on the thickness mean, when calibrated.
    pub fn expected_error(&self) -> Option<f64> {
        self.expected.map(|e| e[0])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::PlateParams;

    fn plate(kt: f64) -> SqueezedPlate {
        let paper = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        paper.with_tangential_stiffness(kt).unwrap()
    }

    #[test]
    fn the_papers_plate_holds_only_for_a_soft_interface() {
        assert_eq!(plate(1e4).validity().validity, Validity::Holds);
        assert_eq!(plate(1e5).validity().validity, Validity::NotCalibrated);
        // alpha t_p = 1.61, slip zone 0.8 t_p: (V1c), at least 40 % (the continuum and CalculiX
        // measured 48 %).
        let v = plate(1e6).validity();
        assert_eq!(v.validity, Validity::MeasuredWrong);
        assert_eq!(v.measured_at_least, Some(0.40));
        assert_eq!(v.expected, None);
        // alpha t_p at 1e4: sqrt(0.91 * 1e4 / (70000 * 0.2)) * 0.2 = 0.1612.
        assert!((plate(1e4).validity().thickness_over_layer - 0.16125).abs() < 1e-4);
    }

    #[test]
    fn each_quantity_has_its_bound_and_the_smaller_route_wins() {
        // The paper's plate at K_T = 1e4: alpha t_p = 0.16125, nu = 0.3, no macroslip (X_r = L):
        // only (V1a), c (alpha t_p)^2 / 0.7^1.2 with 0.7^1.2 = 0.65193.
        let v = plate(1e4).validity();
        assert_eq!(v.slip_over_thickness, 0.0);
        let scale = 0.16125f64.powi(2) / 0.7f64.powf(1.2);
        let e = v.expected.unwrap();
        for (got, c) in e.iter().zip([0.40, 0.95, 0.50]) {
            assert!(
                (got / (c * scale) - 1.0).abs() < 2e-3,
                "{got} vs {}",
                c * scale
            );
        }
        assert!(e[1] > e[2] && e[2] > e[0], "face, then mid, then mean");
        // mu = 0.01: the slip zone is many thicknesses long, so (V1b) decides even at
        // alpha t_p = 1.61 (K_T = 1e6), with c / ((L - X_r) / t_p).
        let paper = SqueezedPlate::new(PlateParams {
            friction: 0.01,
            ..PlateParams::PAPER
        })
        .unwrap();
        let v = paper.validity();
        assert!(v.thickness_over_layer > 1.6 && v.slip_over_thickness > 3.0);
        let e = v.expected.unwrap();
        assert!((e[0] * v.slip_over_thickness - 0.17).abs() < 1e-12);
        assert_ne!(v.validity, Validity::NotCalibrated);
        assert_eq!(v.measured_at_least, None, "a bound from above wins");
    }

    #[test]
    fn the_measured_wrong_region_has_its_edges() {
        // alpha t_p set through K_T; the paper's plate (L = 10, t_p = 0.2, nu = 0.3, mu = 0.3).
        let at = |ratio: f64, mu: f64| {
            let kt = ratio * ratio * 70_000.0 / (0.91 * 0.2);
            SqueezedPlate::new(PlateParams {
                friction: mu,
                tangential_stiffness: kt,
                ..PlateParams::PAPER
            })
            .unwrap()
            .validity()
        };
        // mu = 10: no macroslip at these K_T, slip zone 0.
        assert_eq!(at(0.69, 10.0).validity, Validity::NotCalibrated);
        assert_eq!(at(0.71, 10.0).measured_at_least, Some(0.15));
        assert_eq!(at(1.49, 10.0).measured_at_least, Some(0.15));
        assert_eq!(at(1.51, 10.0).measured_at_least, Some(0.40));
        assert_eq!(at(19.9, 10.0).measured_at_least, Some(0.40));
        // Beyond the grid: the continuum solver stops at alpha t_p = 20.
        assert_eq!(at(20.5, 10.0).validity, Validity::NotCalibrated);
        // A long slip zone (mu = 0.01): (V1b) decides, or nothing.
        assert_ne!(at(2.0, 0.01).validity, Validity::MeasuredWrong);
    }
}
