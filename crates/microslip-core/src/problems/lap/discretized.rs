//! Finite elements for the double-lap joint, independent of the closed forms.
//!
//! The covers move alike and nothing bends (docs/theory.md section 9), so the joint is two bars
//! over the overlap [0, L]: the inner plate (axial rigidity E1 t1 b) and both covers lumped into
//! one (2 E2 t2 b), coupled through both faces (width 2 b). That is the discretized two-bar
//! interface of [`crate::numeric::two_bar`], which the press fit shares: the cover bar is held at
//! x = 0, where the covers hand the force to the clamp, and F pulls the inner bar at x = L. This
//! file maps the joint onto it and says its refusals in the joint's words; nothing here reads a
//! closed form.

use std::ops::{Deref, DerefMut};

use super::params::LapParams;
use crate::numeric::NumericError;
use crate::numeric::mesh::MeshDensity;
pub use crate::numeric::two_bar::{ELEMENTS_PER_DECAY, MAX_ELEMENTS};
use crate::numeric::two_bar::{TwoBarFe, TwoBarSpec, TwoBarWords};

/// The joint's refusals in its own words.
const WORDS: TwoBarWords = TwoBarWords {
    gross: "F_gross = 2 b mu P L",
    at_gross: "both interfaces slide over the whole overlap and the inner plate's position is \
               undetermined",
    length: "the overlap L",
};

/// The double-lap joint discretized, with its current force and interface history: the two-bar
/// solver ([`TwoBarFe`], which it dereferences to for the slip, shear and zones) on the joint's
/// members.
#[derive(Debug, Clone)]
pub struct LapFe {
    params: LapParams,
    fe: TwoBarFe,
}

/// The joint as two bars: the inner plate (bar 0, loaded at x = L) and both covers (bar 1, held
/// at x = 0), over both faces.
fn two_bars(params: &LapParams) -> TwoBarSpec {
    TwoBarSpec {
        rigidities: [
            params.inner_modulus * params.inner_thickness * params.width,
            2.0 * params.cover_modulus * params.cover_thickness * params.width,
        ],
        width: 2.0 * params.width,
        length: params.length,
        friction: params.friction,
        pressure: params.pressure,
        stiffness: params.tangential_stiffness,
        loaded_at_start: false,
    }
}

impl LapFe {
    /// The unloaded joint (F = 0) on a uniform mesh of `density.elements` elements, refined to at
    /// least [`ELEMENTS_PER_DECAY`] per 1/lambda and capped at [`MAX_ELEMENTS`]
    /// ([`TwoBarFe::new`]). The default 400 elements ([`MeshDensity::default`]) put 77 elements
    /// in each 1/lambda of the bundled joint (lambda L = 5.2): F_1 within 2e-5, Delta within 6e-6
    /// and the zone ends within 3e-4 mm (measured against the closed forms in
    /// tests/lap_cross_check.rs). A joint the cap cannot resolve is refused by
    /// [`LapFe::load_to`].
    pub fn new(params: LapParams, density: MeshDensity) -> Self {
        LapFe {
            params,
            fe: TwoBarFe::new(two_bars(&params), WORDS, density),
        }
    }

    /// Moves the force from its current value to `force` (N, either sign: a negative force pushes
    /// the inner plate back in) in `steps` equal increments ([`TwoBarFe::load_to`]).
    ///
    /// # Errors
    /// [`NumericError::OutOfRange`] for parameters outside their domains, a joint whose 1/lambda
    /// the largest mesh cannot resolve ([`LapFe::check_resolvable`]), or |F| >= F_gross = 2 b mu
    /// P L (beyond it no static state exists; at it both interfaces slide whole and the inner
    /// plate's position is undetermined); [`NumericError::BadLoad`] for a non-finite force;
    /// [`NumericError::NoConvergence`] when an increment fails even after 12 halvings;
    /// [`NumericError::Singular`] should never happen below F_gross.
    pub fn load_to(&mut self, force: f64, steps: usize) -> Result<(), NumericError> {
        Self::check_resolvable(&self.params)?;
        self.fe.load_to(force, steps)
    }

    /// Refuses joints this solver cannot answer: parameters outside their domains (the bars
    /// would have no stiffness or the interface no strength), and joints the two-bar solver
    /// cannot resolve ([`TwoBarFe::check_resolvable`]: lambda L above 1333, or bars far stiffer
    /// than the whole interface).
    ///
    /// # Errors
    /// [`NumericError::OutOfRange`] with the field out of its domain, or with lambda L and the
    /// largest K_T that is resolved.
    pub fn check_resolvable(params: &LapParams) -> Result<(), NumericError> {
        params
            .check()
            .map_err(|e| NumericError::OutOfRange(e.to_string()))?;
        TwoBarFe::check_resolvable(&two_bars(params), &WORDS)
    }

    /// The joint displacement Delta = u_inner(L) - u_cover(0) (mm): what an extensometer across
    /// the overlap reads (u_cover(0) is held at 0; it is subtracted all the same so that the
    /// definition does not hang on where the model is held).
    pub fn joint_displacement(&self) -> f64 {
        self.fe.end_displacement()
    }
}

impl Deref for LapFe {
    type Target = TwoBarFe;

    fn deref(&self) -> &TwoBarFe {
        &self.fe
    }
}

impl DerefMut for LapFe {
    fn deref_mut(&mut self) -> &mut TwoBarFe {
        &mut self.fe
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn aluminium(elements: usize) -> LapFe {
        LapFe::new(LapParams::ALUMINIUM, MeshDensity::with_elements(elements))
    }

    /// F_1 as this model sees it: below it the model is linear, so the force that brings the
    /// first point to mu P is read off a small load.
    fn own_first_slip_force(elements: usize) -> f64 {
        let mut fe = aluminium(elements);
        fe.load_to(1.0, 1).unwrap();
        let mu_p = 3.0;
        let largest = fe
            .converged
            .iter()
            .map(|r| r.stress.abs())
            .fold(0.0, f64::max);
        mu_p / largest
    }

    fn sliding_points(fe: &LapFe) -> usize {
        fe.converged.iter().filter(|r| r.sliding).count()
    }

    #[test]
    fn the_interface_carries_the_whole_force_at_every_converged_step() {
        let mut fe = aluminium(100);
        let gross = LapParams::ALUMINIUM.gross_slip_force();
        let path = [0.2, 0.5, 0.9, 0.99, 0.3, -0.4, -0.95, 0.0, 0.7];
        for target in path.map(|f| f * gross) {
            // One converged step at a time, so that every step is checked.
            let start = fe.force();
            for i in 1..=4 {
                fe.load_to(start + (target - start) * f64::from(i) / 4.0, 1)
                    .unwrap();
                let error = (fe.transferred_force() - fe.force()).abs();
                assert!(error < 1e-9 * gross, "F = {}: off by {error} N", fe.force());
            }
        }
    }

    #[test]
    fn below_first_slip_nothing_slides_and_the_joint_is_linear() {
        let onset = own_first_slip_force(100);
        // The aluminium joint's onset lies between a third and a half of F_gross = 6000 N.
        assert!(onset > 2000.0 && onset < 3000.0, "{onset}");
        let mut fe = aluminium(100);
        fe.load_to(0.5 * onset, 1).unwrap();
        let half = fe.joint_displacement();
        fe.load_to(0.99 * onset, 3).unwrap();
        assert_eq!(sliding_points(&fe), 0);
        assert_eq!(fe.sliding_zones(), (0.0, 0.0));
        assert!((fe.joint_displacement() / half - 1.98).abs() < 1e-9);
        fe.load_to(1.01 * onset, 1).unwrap();
        assert!(sliding_points(&fe) > 0);
    }

    #[test]
    fn unloading_leaves_residual_slip_only_where_something_slid() {
        let onset = own_first_slip_force(100);
        let mut elastic = aluminium(100);
        elastic.load_to(0.9 * onset, 3).unwrap();
        let loaded = elastic.joint_displacement();
        elastic.load_to(0.0, 3).unwrap();
        assert!(elastic.points.iter().all(|p| p.plastic_slip == 0.0));
        assert!(elastic.joint_displacement().abs() < 1e-12 * loaded);
        assert!(elastic.slip_at(20.0).abs() < 1e-12 * loaded);

        let mut slid = aluminium(100);
        slid.load_to(4800.0, 3).unwrap();
        let loaded = slid.joint_displacement();
        let (a, d) = slid.sliding_zones();
        assert!(a > 0.0 && d > 0.0, "{a} {d}");
        slid.load_to(0.0, 3).unwrap();
        // The slid ends keep a plastic slip, the middle none; the joint stays stretched.
        assert!(slid.plastic_slip_at(0.0) > 0.0 && slid.plastic_slip_at(40.0) > 0.0);
        assert_eq!(slid.plastic_slip_at(20.0), 0.0);
        assert!(slid.joint_displacement() > 1e-3 * loaded);
        assert!(slid.transferred_force().abs() < 1e-9 * 6000.0);
    }

    #[test]
    fn a_full_cycle_closes_and_is_antisymmetric() {
        let mut fe = aluminium(100);
        let amplitude = 0.8 * LapParams::ALUMINIUM.gross_slip_force();
        fe.load_to(amplitude, 4).unwrap();
        let top = fe.joint_displacement();
        fe.load_to(-amplitude, 16).unwrap();
        let bottom = fe.joint_displacement();
        fe.load_to(amplitude, 16).unwrap();
        assert!((bottom + top).abs() < 1e-9 * top, "{bottom} vs {top}");
        assert!(
            (fe.joint_displacement() / top - 1.0).abs() < 1e-9,
            "{} vs {top}",
            fe.joint_displacement()
        );
        // And the loop is open: at zero force on the way down the joint is still stretched.
        let mut half = aluminium(100);
        half.load_to(amplitude, 4).unwrap();
        half.load_to(0.0, 8).unwrap();
        assert!(half.joint_displacement() > 1e-3 * top);
    }

    #[test]
    fn a_rising_load_does_not_depend_on_the_steps() {
        let mut one = aluminium(100);
        one.load_to(5000.0, 1).unwrap();
        let mut many = aluminium(100);
        many.load_to(5000.0, 20).unwrap();
        assert!((one.joint_displacement() / many.joint_displacement() - 1.0).abs() < 1e-12);
        let (a1, d1) = one.sliding_zones();
        let (a2, d2) = many.sliding_zones();
        assert!((a1 - a2).abs() < 1e-9 && (d1 - d2).abs() < 1e-9);
    }

    #[test]
    fn the_mesh_resolves_the_decay_length_and_refuses_what_it_cannot() {
        // lambda L = 5.16 for the bundled joint: 62 elements at least.
        assert_eq!(aluminium(10).elements(), 62);
        assert_eq!(aluminium(100).elements(), 100);
        let stiff = LapParams {
            tangential_stiffness: 1e7,
            ..LapParams::ALUMINIUM
        };
        // lambda L = 516: 12 elements per 1/lambda.
        assert_eq!(
            LapFe::new(stiff, MeshDensity::default()).elements(),
            (12.0 * 516.397_779_494_322_3_f64).ceil() as usize
        );
        let too_stiff = LapParams {
            tangential_stiffness: 1e10,
            ..LapParams::ALUMINIUM
        };
        let Err(NumericError::OutOfRange(message)) = LapFe::check_resolvable(&too_stiff) else {
            panic!("refused")
        };
        assert!(
            message.contains("lower K_T to at most 66600000 MPa/mm"),
            "{message}"
        );
        let named = LapParams {
            tangential_stiffness: 6.66e7,
            ..LapParams::ALUMINIUM
        };
        assert!(LapFe::check_resolvable(&named).is_ok());
        let negative = LapParams {
            width: -1.0,
            ..LapParams::ALUMINIUM
        };
        assert!(LapFe::check_resolvable(&negative).is_err());
    }

    #[test]
    fn forces_without_a_static_state_are_refused() {
        let mut fe = aluminium(100);
        assert!(matches!(
            fe.load_to(f64::NAN, 1),
            Err(NumericError::BadLoad(_))
        ));
        for f in [6000.0, -6000.0, 1e9] {
            let Err(NumericError::OutOfRange(message)) = fe.load_to(f, 1) else {
                panic!("{f} refused")
            };
            assert!(
                message.contains("F_gross = 2 b mu P L = 6000 N"),
                "{message}"
            );
        }
        assert_eq!(fe.force(), 0.0);
        // Just below F_gross the elastic middle has shrunk below 1/lambda (7.7 mm here): to 1.7
        // mm, where its equilibrium for a short middle, l^3 lambda^2 / 12 = L (1 - F / F_gross)
        // (by hand from s'' = lambda^2 s with s = mu P / K_T at both ends), puts it.
        fe.load_to(5999.0, 4).unwrap();
        let (a, d) = fe.sliding_zones();
        assert!((40.0 - a - d - 1.69).abs() < 0.05, "{a} {d}");
    }
}
