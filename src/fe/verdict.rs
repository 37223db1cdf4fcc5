//! Whether FE results agree with the closed forms: the numbers of [`super::compare`] judged against
//! what the project states about them, so that `compare` says "agrees" or "does not" instead of
//! leaving a reader to guess whether -0.4 % is good.
//!
//! Three judgements, each on a stated basis:
//! - w(L) (beams) and u(L) (plate): the relative difference against the validity envelope of the
//!   closed form at that point (docs/theory.md, (V2) for the beams' shear-corrected value, (V1) for
//!   the plate's thickness mean). Outside the calibration of (V1) nothing is stated, so nothing is
//!   judged.
//! - X (beams) / X_r (plate): the difference counted in elements of the FE mesh along the
//!   interface ([`InterfaceMesh`]). The FE X is interpolated between interface nodes, so under one
//!   element it is within what the mesh resolves; beyond, the difference is real.
//! - The implied K_T (beams): the deck's K_T against the fitted one, in standard errors of the fit.
//!   Only where the beam theory holds at every point: elsewhere the fit absorbs the theory's error.

/// How many standard errors the deck's K_T may be from the implied one and still match: the usual
/// two-sided 95 % band of a normal estimate.
pub const STIFFNESS_Z_LIMIT: f64 = 2.0;

/// A difference of X below this many elements is within what the mesh resolves.
pub(crate) const MESH_RESOLUTION_ELEMENTS: f64 = 1.0;

/// A relative difference against a stated bound on it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Envelope {
    /// |difference| <= bound.
    Within {
        /// The bound, a fraction.
        bound: f64,
    },
    /// |difference| > bound.
    Outside {
        /// The bound, a fraction.
        bound: f64,
        /// |difference| - bound, a fraction.
        by: f64,
    },
    /// No calibrated bound reaches this point (the plate's (V1) beyond its calibration).
    NotCalibrated,
    /// The difference is undefined (a closed form of 0).
    Undefined,
}

impl Envelope {
    /// `difference` judged against `bound` (`None`: not calibrated).
    pub(crate) fn judge(difference: Option<f64>, bound: Option<f64>) -> Envelope {
        match (difference, bound) {
            (None, _) => Envelope::Undefined,
            (_, None) => Envelope::NotCalibrated,
            (Some(d), Some(bound)) if d.abs() <= bound => Envelope::Within { bound },
            (Some(d), Some(bound)) => Envelope::Outside {
                bound,
                by: d.abs() - bound,
            },
        }
    }

    /// A key for JSON: `within`, `outside`, `not calibrated`, `undefined`.
    pub fn label(self) -> &'static str {
        match self {
            Envelope::Within { .. } => "within",
            Envelope::Outside { .. } => "outside",
            Envelope::NotCalibrated => "not calibrated",
            Envelope::Undefined => "undefined",
        }
    }

    /// The bound, where there is one.
    pub fn bound(self) -> Option<f64> {
        match self {
            Envelope::Within { bound } | Envelope::Outside { bound, .. } => Some(bound),
            Envelope::NotCalibrated | Envelope::Undefined => None,
        }
    }
}

/// The element boundaries of the FE mesh along the interface (mm, increasing), read from the
/// deck's nodes: the interface's node set holds the corner and mid-side nodes of its quadratic
/// elements, so the boundaries are every other node. The decks are graded (finest at the beams'
/// clamp, at the plate's free end), so one mean size would misstate the local resolution.
#[derive(Debug, Clone, PartialEq)]
pub struct InterfaceMesh {
    breaks: Vec<f64>,
}

impl InterfaceMesh {
    /// The mesh whose interface nodes (corner and mid-side, any order) are at `xs`; `None` unless
    /// they make at least one quadratic element (an odd count of 3 or more).
    pub(crate) fn from_quadratic_nodes(xs: &[f64]) -> Option<InterfaceMesh> {
        let mut sorted = xs.to_vec();
        sorted.sort_by(f64::total_cmp);
        if sorted.len() < 3 || sorted.len().is_multiple_of(2) {
            return None;
        }
        let breaks: Vec<f64> = sorted.into_iter().step_by(2).collect();
        breaks
            .windows(2)
            .all(|w| w[1] > w[0])
            .then_some(InterfaceMesh { breaks })
    }

    /// Where `x` lies in element units: element i's start is i, its end i + 1 (linear within it;
    /// clamped to the mesh).
    fn position(&self, x: f64) -> f64 {
        let b = &self.breaks;
        let x = x.clamp(b[0], b[b.len() - 1]);
        let i = b.partition_point(|&v| v <= x).clamp(1, b.len() - 1) - 1;
        i as f64 + (x - b[i]) / (b[i + 1] - b[i])
    }

    /// How many elements lie between `a` and `b` (fractions counted in each element's own size).
    pub fn elements_between(&self, a: f64, b: f64) -> f64 {
        (self.position(a) - self.position(b)).abs()
    }

    /// The size of the element holding `x` (mm).
    pub fn size_at(&self, x: f64) -> f64 {
        let i = (self.position(x).floor() as usize).min(self.breaks.len() - 2);
        self.breaks[i + 1] - self.breaks[i]
    }
}

/// An X (or X_r) difference counted in elements of the FE mesh.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshDifference {
    /// FE minus closed form (mm).
    pub difference: f64,
    /// The number of elements between the two.
    pub elements: f64,
    /// The size of the element holding the FE value (mm).
    pub local_size: f64,
}

impl MeshDifference {
    /// The difference between the FE position `fe` and the closed form's `closed` on `mesh`.
    pub(crate) fn on(mesh: &InterfaceMesh, fe: f64, closed: f64) -> MeshDifference {
        MeshDifference {
            difference: fe - closed,
            elements: mesh.elements_between(fe, closed),
            local_size: mesh.size_at(fe),
        }
    }

    /// Under one element: the FE position is interpolated between nodes, so the mesh cannot tell
    /// the two apart.
    pub fn within_resolution(&self) -> bool {
        self.elements < MESH_RESOLUTION_ELEMENTS
    }
}

/// The deck's K_T against the one the FE points imply.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StiffnessMatch {
    /// Within [`STIFFNESS_Z_LIMIT`] standard errors.
    Matches {
        /// (deck - implied) / standard error.
        z: f64,
    },
    /// Farther.
    DoesNotMatch {
        /// (deck - implied) / standard error.
        z: f64,
    },
    /// The fit gave no positive standard error (none, or 0: points on a closed form exactly).
    NoStandardError,
    /// The fit went through as many loaded points as parameters: no degree of freedom is left to
    /// estimate the scatter, so no z can be computed and nothing is judged by one.
    UncertaintyUnknown {
        /// Loaded FE points (F > 0).
        points: usize,
        /// Parameters fitted through them.
        parameters: usize,
    },
    /// The closed form's theory does not hold at every point (its envelope exceeds 2 %): the fit
    /// would measure the theory, not the interface.
    ClosedFormDoesNotHold,
    /// The closed form's envelope is not calibrated at some point (beyond the measured range,
    /// e.g. the beams' friction strain in (V2)): nothing says the fit would measure the interface.
    ClosedFormNotCalibrated,
    /// No K_T was implied (too few points).
    NotImplied,
}

impl StiffnessMatch {
    /// `deck` against `implied` with its standard error.
    pub(crate) fn judge(deck: f64, implied: f64, std_error: Option<f64>) -> StiffnessMatch {
        match std_error.filter(|s| *s > 0.0 && s.is_finite()) {
            None => StiffnessMatch::NoStandardError,
            Some(s) => {
                let z = (deck - implied) / s;
                if z.abs() <= STIFFNESS_Z_LIMIT {
                    StiffnessMatch::Matches { z }
                } else {
                    StiffnessMatch::DoesNotMatch { z }
                }
            }
        }
    }

    /// A key for JSON.
    pub fn label(self) -> &'static str {
        match self {
            StiffnessMatch::Matches { .. } => "matches",
            StiffnessMatch::DoesNotMatch { .. } => "does not match",
            StiffnessMatch::NoStandardError => "no standard error",
            StiffnessMatch::UncertaintyUnknown { .. } => "not judged: uncertainty unknown",
            StiffnessMatch::ClosedFormDoesNotHold => {
                "not judged: the closed form's theory does not hold"
            }
            StiffnessMatch::ClosedFormNotCalibrated => {
                "not judged: the closed form's envelope is not calibrated"
            }
            StiffnessMatch::NotImplied => "not implied",
        }
    }

    /// z, where it was computed.
    pub fn z(self) -> Option<f64> {
        match self {
            StiffnessMatch::Matches { z } | StiffnessMatch::DoesNotMatch { z } => Some(z),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_envelope_includes_its_bound() {
        let inside = Envelope::judge(Some(-0.0099), Some(0.01));
        assert_eq!(inside, Envelope::Within { bound: 0.01 });
        assert_eq!(
            Envelope::judge(Some(0.01), Some(0.01)),
            Envelope::Within { bound: 0.01 }
        );
        let Envelope::Outside { bound, by } = Envelope::judge(Some(-0.0101), Some(0.01)) else {
            panic!("just outside")
        };
        assert_eq!(bound, 0.01);
        assert!((by - 1e-4).abs() < 1e-12);
        assert_eq!(Envelope::judge(Some(0.5), None), Envelope::NotCalibrated);
        assert_eq!(Envelope::judge(None, Some(0.01)), Envelope::Undefined);
    }

    /// A graded mesh: elements 1, 2, 4 mm (nodes with their mid-sides, shuffled).
    fn graded() -> InterfaceMesh {
        InterfaceMesh::from_quadratic_nodes(&[3.0, 0.0, 5.0, 0.5, 7.0, 1.0, 2.0]).unwrap()
    }

    #[test]
    fn positions_are_counted_in_each_elements_own_size() {
        let mesh = graded();
        assert_eq!(mesh.breaks, vec![0.0, 1.0, 3.0, 7.0]);
        // From the middle of the 1 mm element to the middle of the 4 mm one: 2 elements, 4.5 mm.
        assert!((mesh.elements_between(0.5, 5.0) - 2.0).abs() < 1e-12);
        assert_eq!(mesh.size_at(5.0), 4.0);
        assert_eq!(mesh.size_at(7.0), 4.0);
        assert_eq!(mesh.size_at(0.0), 1.0);
        // An even node count is not a line of quadratic elements.
        assert_eq!(InterfaceMesh::from_quadratic_nodes(&[0.0, 1.0]), None);
    }

    #[test]
    fn under_one_element_is_within_the_resolution() {
        let mesh = graded();
        // 3.9 mm in the 4 mm element: 0.975 elements; 4.1 mm past 3: 1.025.
        let below = MeshDifference::on(&mesh, 6.9, 3.0);
        assert!(below.within_resolution(), "{below:?}");
        let above = MeshDifference::on(&mesh, 7.0, 2.9);
        assert!((above.elements - 1.05).abs() < 1e-12, "{above:?}");
        assert!(!above.within_resolution());
        assert!((above.difference - 4.1).abs() < 1e-12);
    }

    #[test]
    fn two_standard_errors_match() {
        assert_eq!(
            StiffnessMatch::judge(600.0, 619.9, Some(10.0)).label(),
            "matches"
        );
        let beyond = StiffnessMatch::judge(600.0, 620.1, Some(10.0));
        assert_eq!(beyond.label(), "does not match");
        assert!((beyond.z().unwrap() + 2.01).abs() < 1e-9);
        assert_eq!(
            StiffnessMatch::judge(600.0, 600.0, Some(0.0)),
            StiffnessMatch::NoStandardError
        );
        assert_eq!(
            StiffnessMatch::judge(600.0, 610.0, None),
            StiffnessMatch::NoStandardError
        );
    }
}
