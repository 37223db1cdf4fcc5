//! What a committed interface state reads as along the interface ([`Profiles`]): the profiles
//! every two-body continuum (twin beams, lap joint, press fit) reports, and where the local law
//! says it slides, read once here.

use super::{Reduced, TwoBodyGrid, last_of_run, nominal_front};

/// The local sliding reading: a pair slides where |tau| >= (1 - this) mu p.
pub(crate) const LOCAL_SLIDING: f64 = 1e-3;

/// The profiles of a committed state at each pair, (x (mm), value).
pub(crate) struct Profiles {
    /// The slip from the first stage's end (mm), in the problem's sign.
    pub(crate) slip: Vec<(f64, f64)>,
    /// The Jenkins force over the pair's share of the face (MPa), in the problem's sign.
    pub(crate) shear: Vec<(f64, f64)>,
    /// The contact force over the same share (MPa); negative where the faces would open.
    pub(crate) pressure: Vec<(f64, f64)>,
    /// The x (mm) of the pairs whose contact force is tensile (the tie holds them; no friction).
    pub(crate) separated: Vec<f64>,
}

impl Profiles {
    /// The profiles of `model`'s committed state on `grid`: `slip_from` is u_lower - u_upper
    /// from the first stage's end at each pair (mm), `sign` the problem's sign of slip and shear
    /// against that generic one, `face` the face's extent across the section (1 mm of width for
    /// a slice, 2 pi r for a ring): forces per pair over `face` times the pair's share of the
    /// length are stresses.
    pub(crate) fn read(
        model: &Reduced<'_>,
        grid: &TwoBodyGrid,
        slip_from: &[f64],
        sign: f64,
        face: f64,
    ) -> Profiles {
        let xs = &grid.pair_x;
        let contact = model.contact_forces();
        Profiles {
            slip: xs
                .iter()
                .zip(slip_from)
                .map(|(&x, s)| (x, sign * s))
                .collect(),
            shear: grid.per_face(&model.pair_forces(), sign / face),
            pressure: grid.per_face(&contact, 1.0 / face),
            separated: contact
                .iter()
                .zip(xs)
                .filter(|(n, _)| **n < 0.0)
                .map(|(_, &x)| x)
                .collect(),
        }
    }

    /// Whether pair `i` slides by the local law: in contact and |tau| >= mu p within
    /// [`LOCAL_SLIDING`].
    pub(crate) fn sliding(&self, i: usize, friction: f64) -> bool {
        let p = self.pressure[i].1;
        p > 0.0 && self.shear[i].1.abs() >= (1.0 - LOCAL_SLIDING) * friction * p
    }

    /// The last pair of the sliding run that starts at the first pair, if it slides.
    pub(crate) fn run_from_start(&self, friction: f64) -> Option<usize> {
        last_of_run(|i| self.sliding(i, friction), &mut (0..self.slip.len()))
    }

    /// The last pair of the sliding run that starts at the last pair, if it slides.
    pub(crate) fn run_from_end(&self, friction: f64) -> Option<usize> {
        last_of_run(
            |i| self.sliding(i, friction),
            &mut (0..self.slip.len()).rev(),
        )
    }

    /// The local sliding zones from each end, at node resolution (mm): from the first pair's x
    /// (0) to the last pair of the run that starts there, and from the last pair's x back to the
    /// last of the run that starts at that end; 0 for an end whose pair does not slide.
    pub(crate) fn local_zones(&self, friction: f64) -> [f64; 2] {
        let x = |i: usize| self.slip[i].0;
        let length = self.slip.last().map_or(0.0, |(x, _)| *x);
        [
            self.run_from_start(friction).map_or(0.0, x),
            self.run_from_end(friction).map_or(0.0, |i| length - x(i)),
        ]
    }

    /// The nominal sliding zones from each end, as the 1-D theories define them (mm): the runs
    /// where `stiffness(i)` |s| (K_T |s| at pair i, MPa) reaches `saturation` (mu times the
    /// nominal pressure), interpolated at the crossing (`nominal_front`).
    pub(crate) fn nominal_zones(
        &self,
        stiffness: impl Fn(usize) -> f64,
        saturation: f64,
    ) -> [f64; 2] {
        let xs: Vec<f64> = self.slip.iter().map(|(x, _)| *x).collect();
        let level = |i: usize| stiffness(i) * self.slip[i].1.abs();
        let length = xs.last().copied().unwrap_or(0.0);
        [
            nominal_front(&xs, level, saturation, &mut (0..xs.len())),
            length - nominal_front(&xs, level, saturation, &mut (0..xs.len()).rev()),
        ]
    }
}
