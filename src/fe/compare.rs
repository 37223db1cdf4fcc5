//! FE results against the closed forms, point by point, and the K_T the FE results imply.
//!
//! Beams: the FE w(L) against the paper's Euler-Bernoulli closed form and against it plus each
//! beam's shear deflection (B13), which continuum elements include; the implied K_T (and mu) come
//! from the existing fit ([`crate::fit`]) run on the FE points with the shear deflection taken off,
//! so that it measures the interface, not the beam theory. Plate: u(L) against the strip theory,
//! and per point the K_T whose closed-form u(L) equals the FE value.

use super::continuum_verdict::{ContinuumVerdict, NotSolved};
use super::results::{BeamFePoint, FeInterface, LapFePoint, PlateFePoint};
use super::verdict::{Envelope, InterfaceMesh, MeshDifference, StiffnessMatch};
use crate::fit::{self, FitError, FitResult};
use crate::kernel::regime::Regime;
use crate::kernel::validity::Validity;

/// One FE point of the beams beside the closed forms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BeamCompared {
    /// The FE point.
    pub fe: BeamFePoint,
    /// Euler-Bernoulli w(L) under the regularized law (mm): the paper's closed form.
    pub euler: f64,
    /// The same plus the shear deflection (mm).
    pub shear_corrected: f64,
    /// The closed form's regime.
    pub regime: Regime,
    /// The closed form's start of the macroslip zone X (mm): L when there is none.
    pub macroslip_start: f64,
    /// The envelope (V2) of the shear-corrected (Timoshenko) value: the stated bound on its
    /// difference from continuum FE; `None` where (V2) is not calibrated (friction strain).
    pub shear_corrected_within: Option<f64>,
    /// FE X against the closed form's in elements of the FE mesh, when the results have the slip
    /// and the mesh is known (CalculiX results with their deck).
    pub macroslip_start_mesh: Option<MeshDifference>,
    /// This point's w(L) against the beams' plane-stress continuum at the deck's parameters and
    /// load (`None`: not checked).
    pub continuum: Option<Result<ContinuumVerdict, NotSolved>>,
}

/// (FE - closed form) / closed form, or `None` where the closed form is 0 (no load, or a plate
/// with nu = 0 that nothing squeezes sideways): a relative difference is undefined there, and
/// dividing printed "-inf %" and "NaN %".
pub(crate) fn relative_difference(fe: f64, closed: f64) -> Option<f64> {
    (closed != 0.0).then(|| fe / closed - 1.0)
}

impl BeamCompared {
    /// (FE - closed form) / closed form against the Euler-Bernoulli value; `None` at F = 0.
    pub fn difference_euler(&self) -> Option<f64> {
        relative_difference(self.fe.deflection, self.euler)
    }

    /// (FE - closed form) / closed form against the shear-corrected value; `None` at F = 0.
    pub fn difference_shear_corrected(&self) -> Option<f64> {
        relative_difference(self.fe.deflection, self.shear_corrected)
    }

    /// The shear-corrected difference against its envelope (V2).
    pub fn envelope(&self) -> Envelope {
        Envelope::judge(
            self.difference_shear_corrected(),
            self.shear_corrected_within,
        )
    }

    /// FE X minus the closed form's (mm), when the FE results have the slip.
    pub fn macroslip_start_difference(&self) -> Option<f64> {
        self.fe
            .interface
            .map(|i| i.macroslip_start - self.macroslip_start)
    }
}

/// The beams' comparison.
#[derive(Debug, Clone, PartialEq)]
pub struct BeamComparison {
    /// Point by point.
    pub rows: Vec<BeamCompared>,
    /// The Poisson ratio used for the shear deflection.
    pub poisson: f64,
    /// mu and K_T fitted to the FE points less their shear deflection.
    pub implied: Result<FitResult, FitError>,
    /// The K_T the closed forms used: the deck's stick slope (MPa/mm).
    pub stiffness: f64,
}

impl BeamComparison {
    /// Whether the beam theory holds (V2 within 2 %) at every point, so that a K_T fitted through
    /// it measures the interface; false too where (V2) is not calibrated.
    pub fn closed_form_holds(&self) -> bool {
        self.rows.iter().all(|r| {
            r.shear_corrected_within
                .is_some_and(|bound| Validity::of_error(bound) == Validity::Holds)
        })
    }

    /// Whether (V2) has a bound at every point (the friction strain within its calibration).
    pub fn closed_form_calibrated(&self) -> bool {
        self.rows.iter().all(|r| r.shear_corrected_within.is_some())
    }

    /// The deck's K_T against the implied one.
    pub fn stiffness_match(&self) -> StiffnessMatch {
        match &self.implied {
            Err(_) => StiffnessMatch::NotImplied,
            Ok(_) if !self.closed_form_calibrated() => StiffnessMatch::ClosedFormNotCalibrated,
            Ok(_) if !self.closed_form_holds() => StiffnessMatch::ClosedFormDoesNotHold,
            Ok(fit) => match fit.kt.evidence {
                fit::Evidence::NoDegreesOfFreedom { points, parameters } => {
                    StiffnessMatch::UncertaintyUnknown { points, parameters }
                }
                _ => StiffnessMatch::judge(self.stiffness, fit.kt.value, fit.kt.std_error),
            },
        }
    }
}

/// The FE zone end against the closed form's on `mesh`, when there are both.
pub(crate) fn on_mesh(
    mesh: Option<&InterfaceMesh>,
    fe: Option<FeInterface>,
    closed: f64,
) -> Option<MeshDifference> {
    Some(MeshDifference::on(mesh?, fe?.macroslip_start, closed))
}

/// One FE point of the plate beside the closed forms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlateCompared {
    /// The FE point.
    pub fe: PlateFePoint,
    /// The strip theory's u(L) under the regularized law at the FE run's K_T (mm).
    pub closed: f64,
    /// Under the plain Coulomb law (mm).
    pub coulomb: f64,
    /// The closed form's regime.
    pub regime: Regime,
    /// The closed form's X_r (mm).
    pub micro_zone_end: f64,
    /// The K_T (MPa/mm) whose closed-form u(L) equals the FE value; `None` when no accepted K_T
    /// does (the FE value is outside the range the strip theory can give), or when the strip
    /// theory does not hold at the run's K_T ([`PlateCompared::strip_validity`]): there the
    /// difference is the strip theory's, not the interface's, and inverting it would name a K_T
    /// the run did not have (a run at 1e7 "implied" 5.8e5).
    pub implied_stiffness: Option<f64>,
    /// (V1) for the thickness mean at the run's K_T.
    pub strip_validity: Validity,
    /// (V1)'s bound on the thickness mean's difference, a fraction; `None` where no calibration
    /// reaches.
    pub strip_within: Option<f64>,
    /// FE X_r against the closed form's in elements of the FE mesh (CalculiX results).
    pub micro_zone_end_mesh: Option<MeshDifference>,
    /// u(L) against the plane-strain continuum at the run's parameters, where it was solved
    /// (`compare`, `bench`; the TUI's pane leaves it out): the verdict, or why there is none.
    pub continuum: Option<Result<ContinuumVerdict, NotSolved>>,
}

impl PlateCompared {
    /// (FE - closed form) / closed form for u(L); `None` where the closed form is 0.
    pub fn difference(&self) -> Option<f64> {
        relative_difference(self.fe.end_displacement, self.closed)
    }

    /// The thickness mean's difference against its envelope (V1).
    pub fn envelope(&self) -> Envelope {
        Envelope::judge(self.difference(), self.strip_within)
    }

    /// The same at the contact face and at mid-thickness, when the results have them and the
    /// closed form is not 0.
    pub fn differences_through_thickness(&self) -> Option<[f64; 2]> {
        let [face, mid] = self.fe.through_thickness?;
        Some([
            relative_difference(face, self.closed)?,
            relative_difference(mid, self.closed)?,
        ])
    }

    /// The FE interface state, when the results have the slip.
    pub fn fe_interface(&self) -> Option<FeInterface> {
        self.fe.interface
    }
}

/// One FE point of the double-lap joint beside the closed forms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapCompared {
    /// The FE point.
    pub fe: LapFePoint,
    /// The shear-lag Delta under the regularized law at the deck's K_T (mm).
    pub closed: f64,
    /// Under the plain Coulomb law (mm).
    pub coulomb: f64,
    /// The closed form's regime.
    pub regime: Regime,
    /// The closed form's sliding zones from x = 0 and from x = L (mm).
    pub zones: (f64, f64),
    /// The K_T (MPa/mm) whose closed-form Delta equals the FE value at this force; `None` where
    /// none does, or where the shear-lag theory does not hold (the difference would be the
    /// theory's, not the interface's).
    pub implied_stiffness: Option<f64>,
    /// The shear-lag theory's level at this force ((L14)).
    pub theory_validity: Validity,
    /// Its bound on Delta's difference from a continuum, a fraction; `None` where not calibrated.
    pub theory_within: Option<f64>,
    /// FE a and d against the closed form's in elements of the FE mesh (CalculiX results).
    pub zones_mesh: Option<[MeshDifference; 2]>,
    /// Delta against the plane-stress continuum at the deck's parameters and this force, where
    /// it was solved (`compare`, `bench`): the verdict, or why there is none.
    pub continuum: Option<Result<ContinuumVerdict, NotSolved>>,
}

impl LapCompared {
    /// (FE - closed form) / closed form for Delta; `None` at F = 0.
    pub fn difference(&self) -> Option<f64> {
        relative_difference(self.fe.joint_displacement, self.closed)
    }

    /// Delta's difference against the theory's envelope (L14).
    pub fn envelope(&self) -> Envelope {
        Envelope::judge(self.difference(), self.theory_within)
    }

    /// Of a and d, the one farther from the closed form in elements of the mesh.
    pub fn worse_zone_mesh(&self) -> Option<MeshDifference> {
        self.zones_mesh
            .map(|[a, d]| if a.elements >= d.elements { a } else { d })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::plate::deck::compare_plate;
    use crate::problems::twin_beams::deck::compare_beams;
    use crate::{PlateParams, SqueezedPlate, TipForce, TwinBeams, TwinBeamsParams};

    #[test]
    fn closed_form_points_compare_to_zero_and_imply_their_own_stiffness() {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let truth = TwinBeams::new(TwinBeamsParams {
            tangential_stiffness: 300.0,
            ..TwinBeamsParams::PAPER
        })
        .unwrap();
        // "FE" points made of another K_T's closed form plus the shear deflection.
        let points: Vec<BeamFePoint> = [40.0, 60.0, 80.0, 100.0, 150.0, 200.0]
            .map(|f| {
                let force = TipForce::new(f).unwrap();
                BeamFePoint {
                    force: f,
                    deflection: truth.regularized(force).tip_deflection()
                        + truth.shear_deflection(force),
                    interface: None,
                }
            })
            .to_vec();
        let same = compare_beams(&truth, &points, None);
        for row in &same.rows {
            assert!(row.difference_shear_corrected().unwrap().abs() < 1e-12);
            assert!(
                row.difference_euler().unwrap() > 0.0,
                "shear adds deflection"
            );
        }
        let other = compare_beams(&beams, &points, None);
        let fit = other.implied.unwrap();
        assert!(
            (fit.kt.value / 300.0 - 1.0).abs() < 1e-4,
            "{}",
            fit.kt.value
        );
        assert!((fit.mu.value / 0.3 - 1.0).abs() < 1e-4, "{}", fit.mu.value);
    }

    #[test]
    fn plate_stiffness_is_recovered_from_its_own_end_displacement() {
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        for kt in [1e2, 1e4, 3e5, 1e6, 1e8] {
            let u = plate
                .with_tangential_stiffness(kt)
                .unwrap()
                .regularized()
                .end_displacement();
            let found = plate.stiffness_for_end_displacement(u).unwrap();
            assert!((found / kt - 1.0).abs() < 1e-6, "K_T {kt}: found {found}");
        }
        // Below the Coulomb value, or beyond the free expansion, no K_T gives it.
        let coulomb = plate.coulomb().end_displacement();
        assert_eq!(plate.stiffness_for_end_displacement(0.5 * coulomb), None);
        let p = PlateParams::PAPER;
        let free = p.poisson * (1.0 + p.poisson) * p.pressure * p.half_length / p.youngs_modulus;
        assert_eq!(plate.stiffness_for_end_displacement(1.01 * free), None);
    }

    /// The strip theory's u(L) of the paper's plate at `kt`.
    fn paper_u(kt: f64) -> f64 {
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let at = plate.with_tangential_stiffness(kt).unwrap();
        at.regularized().end_displacement()
    }

    fn mean_only(stiffness: f64, end_displacement: f64) -> PlateFePoint {
        PlateFePoint {
            stiffness,
            end_displacement,
            through_thickness: None,
            interface: None,
        }
    }

    #[test]
    fn no_stiffness_is_implied_where_the_strip_theory_does_not_hold() {
        // The paper's plate at K_T = 1e7 (alpha t_p = 5.1): a u(L) that the strip theory reaches
        // at a softer K_T would "imply" that K_T; it is withheld.
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let u = paper_u(5.8e5);
        assert!(plate.stiffness_for_end_displacement(u).is_some());
        let rows = compare_plate(&plate, &[mean_only(1e7, u)], None);
        assert_eq!(rows[0].implied_stiffness, None);
        assert_ne!(rows[0].strip_validity, Validity::Holds);
    }

    #[test]
    fn plate_comparison_uses_each_points_stiffness() {
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let rows = compare_plate(&plate, &[mean_only(1e4, 1.1 * paper_u(1e4))], None);
        assert!((rows[0].difference().unwrap() - 0.1).abs() < 1e-12);
        assert_eq!(rows[0].regime, Regime::MICROSLIP);
        assert_eq!(rows[0].strip_validity, Validity::Holds);
        assert!(
            rows[0].implied_stiffness.unwrap() < 1e4,
            "more displacement, softer"
        );
    }
}
