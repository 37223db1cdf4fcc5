//! Finite elements for the press fit, independent of its closed forms: the two-bar interface of
//! [`crate::numeric::two_bar`] in the fit's own coordinate (the shaft, bar 0, pushed at x = 0;
//! the hub, bar 1, held at x = L), with the rigidities of the push-out (Es As, Eh Ah) or of the
//! torque (Gs Js / r^2, Gh Jh / r^2, loaded by T / r), over the circumference 2 pi r at Lamé's
//! pressure. It never reads a shear-lag closed form: the closed forms read the same fit as the
//! mirror image of the lap joint's bars ([`crate::kernel::shear_lag`], x -> L - x), this solver
//! does not mirror anything, so an error in that mapping shows as a disagreement.

use std::ops::Deref;

use super::lame::{PlaneState, contact_pressure};
use super::params::{FitLoad, PressFitParams};
use crate::numeric::NumericError;
use crate::numeric::mesh::MeshDensity;
use crate::numeric::two_bar::{TwoBarFe, TwoBarSpec, TwoBarWords};

/// The press fit discretized, under one load, with its history.
#[derive(Debug, Clone)]
pub struct PressFitFe {
    params: PressFitParams,
    load: FitLoad,
    fe: TwoBarFe,
}

/// The fit as two bars under `load`.
fn two_bars(params: &PressFitParams, load: FitLoad) -> TwoBarSpec {
    TwoBarSpec {
        rigidities: params.rigidities(load),
        width: params.interface_width(),
        length: params.length,
        friction: params.friction,
        pressure: contact_pressure(params, PlaneState::Stress),
        stiffness: params.tangential_stiffness,
        loaded_at_start: true,
    }
}

/// The refusals in the fit's words, for each load (the solver's load is the interface's
/// equivalent axial force, T / r for the torque).
fn words(load: FitLoad) -> TwoBarWords {
    match load {
        FitLoad::Axial => TwoBarWords {
            gross: "F_gross = mu p 2 pi r L",
            at_gross: "the whole interface slides and the shaft's position is undetermined",
            length: "the fit length L",
        },
        FitLoad::Torque => TwoBarWords {
            gross: "T_gross / r = mu p 2 pi r L",
            at_gross: "the whole interface slides and the shaft's rotation is undetermined",
            length: "the fit length L",
        },
    }
}

impl PressFitFe {
    /// The unloaded fit on `density.elements` uniform elements (refined to the decay length,
    /// [`TwoBarFe::new`]).
    pub fn new(params: PressFitParams, load: FitLoad, density: MeshDensity) -> PressFitFe {
        PressFitFe {
            params,
            load,
            fe: TwoBarFe::new(two_bars(&params, load), words(load), density),
        }
    }

    /// Refuses fits this solver cannot answer: inputs outside their domains, and fits the
    /// two-bar solver cannot resolve ([`TwoBarFe::check_resolvable`]).
    ///
    /// # Errors
    /// [`NumericError::OutOfRange`] naming why.
    pub fn check_resolvable(params: &PressFitParams, load: FitLoad) -> Result<(), NumericError> {
        params
            .check()
            .map_err(|e| NumericError::OutOfRange(e.to_string()))?;
        TwoBarFe::check_resolvable(&two_bars(params, load), &words(load))
    }

    /// The lever from the solver's force to the load: 1, or r for the torque.
    fn arm(&self) -> f64 {
        self.load.arm(&self.params)
    }

    /// Moves the load (N, or N mm for the torque; either sign) to `value` in `steps` increments.
    ///
    /// # Errors
    /// As [`PressFitFe::check_resolvable`] and [`TwoBarFe::load_to`].
    pub fn load_to(&mut self, value: f64, steps: usize) -> Result<(), NumericError> {
        Self::check_resolvable(&self.params, self.load)?;
        let arm = self.arm();
        self.fe.load_to(value / arm, steps)
    }

    /// The current load (N or N mm).
    pub fn load(&self) -> f64 {
        self.fe.force() * self.arm()
    }

    /// The response: Delta (mm) or theta (rad), the shaft's loaded end relative to the hub's
    /// held face.
    pub fn response(&self) -> f64 {
        self.fe.end_displacement() / self.arm()
    }
}

impl Deref for PressFitFe {
    type Target = TwoBarFe;

    fn deref(&self) -> &TwoBarFe {
        &self.fe
    }
}
