//! The press fit pushed out by F or twisted by T (docs/theory.md section 18, (S1)-(S8)).
//!
//! A shaft (bore ri, fit radius r) shrunk into a hub (outer radius ro) over a length L, pressed
//! together by Lamé's p ([`super::lame`]). x runs from the shaft's loaded end face (x = 0) to the
//! hub's held face (x = L). Pushed out, the shaft carries F at x = 0 and nothing at x = L, the hub
//! nothing at x = 0 and F at its support at x = L; each member is a bar with uniform axial strain
//! over its section, so the slip s = u_shaft - u_hub obeys s'' = w tau (1/(Es As) + 1/(Eh Ah))
//! with w = 2 pi r (S1). Read from x = L backward (xi = L - x), that is the shear lag of
//! [`crate::kernel::shear_lag`]: the shaft is the bar loaded at xi = L, the hub the bar held at
//! xi = 0. This file maps the fit onto it and back into its own coordinate and words. Twisted,
//! the same holds for the circumferential slip with N = T / r and the rigidities G J / r^2 (S6):
//! [`FitAxis`] is one of the two, [`FitLoad`] says which.

use super::lame::{PlaneState, contact_pressure};
use super::params::{FitLoad, PressFitParams};
use crate::kernel::params::{Domain, ParamError};
use crate::kernel::regime::{Law, Regime};
use crate::kernel::shear_lag::{
    ShearLag, ShearLagCycle, ShearLagState, SlipStart, TwoBars, zones_regime,
};
use crate::kernel::solve::find_root_in_bracket;
use crate::problems::Solution;

/// A validated press fit: Lamé's pressure and the shear lag of each load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressFit {
    params: PressFitParams,
    /// Lamé's plane-stress contact pressure p (MPa).
    pressure: f64,
    axial: FitAxis,
    torsion: FitAxis,
}

/// The face where sliding starts as the load grows (S4): the one where the more compliant
/// member carries the load.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SlipFace {
    /// x = 0, the shaft's loaded face: the shaft is the more compliant member.
    Loaded,
    /// x = L, the hub's held face: the hub is the more compliant.
    Held,
    /// Both faces at once: equal rigidities.
    Both,
}

impl SlipFace {
    /// Where, in words, for reports.
    pub fn label(self) -> &'static str {
        match self {
            SlipFace::Loaded => "x = 0 (the shaft's loaded face)",
            SlipFace::Held => "x = L (the hub's held face)",
            SlipFace::Both => "both faces at once (equal rigidities)",
        }
    }

    /// The key in JSON and CSV.
    pub fn key(self) -> &'static str {
        match self {
            SlipFace::Loaded => "x=0",
            SlipFace::Held => "x=L",
            SlipFace::Both => "both",
        }
    }
}

impl PressFit {
    /// Validates every input ([`PressFitParams::check`]) and solves Lamé's pressure.
    ///
    /// # Errors
    /// The first input out of its domain, in display order, then ri < r < ro.
    ///
    /// # Examples
    /// ```
    /// use microslip_core::problems::pressfit::closed_form::PressFit;
    /// use microslip_core::problems::pressfit::params::PressFitParams;
    /// let fit = PressFit::new(PressFitParams::CCX98)?;
    /// assert!((fit.contact_pressure() - 6.152_343_75).abs() < 1e-9); // MPa
    /// assert!((fit.gross_slip_force() - 1371.0).abs() < 0.01); // mu p 2 pi r L, N
    /// let state = fit.regularized(fit.force(0.5 * fit.gross_slip_force())?);
    /// assert!(state.response() > 0.0);
    /// # Ok::<(), microslip_core::ParamError>(())
    /// ```
    pub fn new(params: PressFitParams) -> Result<PressFit, ParamError> {
        params.check()?;
        let pressure = contact_pressure(&params, PlaneState::Stress);
        Ok(PressFit {
            params,
            pressure,
            axial: FitAxis::new(&params, pressure, FitLoad::Axial),
            torsion: FitAxis::new(&params, pressure, FitLoad::Torque),
        })
    }

    /// The inputs this fit was built from.
    pub fn params(&self) -> PressFitParams {
        self.params
    }

    /// The same fit with another K_T (MPa/mm); validated like [`PressFit::new`].
    ///
    /// # Errors
    /// [`ParamError`] when `kt` is outside the K_T domain.
    pub fn with_tangential_stiffness(&self, kt: f64) -> Result<PressFit, ParamError> {
        PressFit::new(PressFitParams {
            tangential_stiffness: kt,
            ..self.params
        })
    }

    /// Lamé's contact pressure p in plane stress (MPa), (S2): what every closed form uses.
    pub fn contact_pressure(&self) -> f64 {
        self.pressure
    }

    /// Lamé's contact pressure in plane strain (MPa), (S2): beside the plane-stress one, for
    /// long members.
    pub fn plane_strain_pressure(&self) -> f64 {
        contact_pressure(&self.params, PlaneState::Strain)
    }

    /// The push-out (F, Delta).
    pub fn axial(&self) -> &FitAxis {
        &self.axial
    }

    /// The torsion (T, theta).
    pub fn torsion(&self) -> &FitAxis {
        &self.torsion
    }

    /// The axis of `load`.
    pub fn axis(&self, load: FitLoad) -> &FitAxis {
        match load {
            FitLoad::Axial => &self.axial,
            FitLoad::Torque => &self.torsion,
        }
    }

    /// F_gross = mu p 2 pi r L (N), (S5).
    pub fn gross_slip_force(&self) -> f64 {
        self.axial.gross_load()
    }

    /// F_1 (N), (S4): where sliding first appears, at [`PressFit::first_slip_face`].
    pub fn first_slip_force(&self) -> f64 {
        self.axial.first_slip_load()
    }

    /// F_2 (N), (S4): where the second face starts sliding too.
    pub fn second_slip_force(&self) -> f64 {
        self.axial.second_slip_load()
    }

    /// The face where the push-out starts sliding (S4).
    pub fn first_slip_face(&self) -> SlipFace {
        self.axial.first_slip_face()
    }

    /// Accepts a push-out force (N): in F's domain and at most F_gross.
    ///
    /// # Errors
    /// [`ParamError`] naming F, its value and the range [0, F_gross].
    pub fn force(&self, newtons: f64) -> Result<CarriedLoad, ParamError> {
        self.axial.load(newtons)
    }

    /// The push-out under plain Coulomb (S7).
    pub fn coulomb(&self, force: CarriedLoad) -> FitState {
        self.axial.coulomb(force)
    }

    /// The push-out under the regularized law (S3)-(S5).
    pub fn regularized(&self, force: CarriedLoad) -> FitState {
        self.axial.regularized(force)
    }
}

/// A load the fit carries, checked against its axis: 0 <= F <= F_gross (N) or 0 <= T <= T_gross
/// (N mm).
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd)]
pub struct CarriedLoad(f64);

impl CarriedLoad {
    /// The load in its unit (N or N mm).
    pub fn value(self) -> f64 {
        self.0
    }
}

/// One way of loading the fit: the shear lag of its two members under the push-out or the torque,
/// with the lever `arm` from the interface's equivalent axial force N to the load (1, or r for
/// T = N r) and from the equivalent end displacement to the response (Delta = Delta_eq, or
/// theta = Delta_eq / r).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitAxis {
    load: FitLoad,
    arm: f64,
    length: f64,
    lag: ShearLag,
}

impl FitAxis {
    fn new(params: &PressFitParams, pressure: f64, load: FitLoad) -> FitAxis {
        let width = params.interface_width();
        let [shaft, hub] = params.rigidities(load);
        FitAxis {
            load,
            arm: load.arm(params),
            length: params.length,
            lag: ShearLag::new(TwoBars {
                loaded: shaft / width,
                held: hub / width,
                width,
                length: params.length,
                friction: params.friction,
                pressure,
                stiffness: params.tangential_stiffness,
            }),
        }
    }

    /// Which load this is.
    pub fn load_kind(&self) -> FitLoad {
        self.load
    }

    /// The gross-slip load (N or N mm), (S5): F_gross = mu p 2 pi r L, T_gross = F_gross r.
    pub fn gross_load(&self) -> f64 {
        self.lag.bars().gross_slip_force() * self.arm
    }

    /// The load at which sliding first appears (S4): F_1 or T_1.
    pub fn first_slip_load(&self) -> f64 {
        self.lag.first_slip_force() * self.arm
    }

    /// The load at which the second face starts sliding (S4): F_2 or T_2.
    pub fn second_slip_load(&self) -> f64 {
        self.lag.second_slip_force() * self.arm
    }

    /// Where sliding starts (S4): the kernel's x = L end is the loaded face.
    pub fn first_slip_face(&self) -> SlipFace {
        match self.lag.slip_start() {
            SlipStart::End => SlipFace::Loaded,
            SlipStart::Start => SlipFace::Held,
            SlipStart::Both => SlipFace::Both,
        }
    }

    /// lambda = sqrt(w K_T (1/A_shaft + 1/A_hub)) (1/mm): 1/lambda is the decay length of the
    /// elastic slip from a loaded face.
    pub fn decay_rate(&self) -> f64 {
        self.lag.decay_rate()
    }

    /// The interface stiffness K_T (MPa/mm).
    pub fn tangential_stiffness(&self) -> f64 {
        self.lag.bars().stiffness
    }

    /// The bonded response per unit load (mm/N or rad/(N mm)), (S5): L / (A_shaft + A_hub) over
    /// arm^2.
    pub fn bonded_compliance(&self) -> f64 {
        self.lag.bonded_compliance() / (self.arm * self.arm)
    }

    /// Accepts `value` as a load of this axis: its parameter's domain, then at most the gross
    /// load.
    ///
    /// # Errors
    /// [`ParamError`] naming F or T, the value and the range [0, gross].
    pub fn load(&self, value: f64) -> Result<CarriedLoad, ParamError> {
        let param = self.load.param();
        let value = param.check(value)?;
        let gross = self.gross_load();
        if value > gross {
            let reason = match self.load {
                FitLoad::Axial => "F_gross = mu p 2 pi r L: the shaft slides out beyond it",
                FitLoad::Torque => {
                    "T_gross = mu p 2 pi r^2 L: the shaft turns in the hub beyond it"
                }
            };
            return Err(param.spec().above(value, gross, reason));
        }
        Ok(CarriedLoad(value))
    }

    /// The accepted load nearest to `value`: 0 for negative values and NaN, the gross load above.
    pub fn clamped(&self, value: f64) -> CarriedLoad {
        let value = if value.is_nan() { 0.0 } else { value };
        CarriedLoad(value.clamp(0.0, self.gross_load()))
    }

    /// Plain Coulomb at `load` (S7).
    pub fn coulomb(&self, load: CarriedLoad) -> FitState {
        self.solve(Law::Coulomb, load)
    }

    /// The regularized law at `load` (S3)-(S5).
    pub fn regularized(&self, load: CarriedLoad) -> FitState {
        self.solve(Law::Regularized, load)
    }

    /// `law` at `load`.
    pub fn solve(&self, law: Law, load: CarriedLoad) -> FitState {
        FitState {
            state: self.lag.solve(law, load.0 / self.arm),
            arm: self.arm,
            length: self.length,
        }
    }

    /// The cycle between +`amplitude` and -`amplitude` under `law` (S7).
    pub fn cycle(&self, law: Law, amplitude: CarriedLoad) -> ShearLagCycle {
        ShearLagCycle::new(&self.lag, law, self.arm, amplitude.0)
    }

    /// The K_T (MPa/mm) at which the regularized response at `load` is `response` (mm or rad):
    /// what an FE result says about the stiffness its code used; `None` when no K_T of the
    /// domain gives it (S8).
    pub fn stiffness_for_response(&self, load: CarriedLoad, response: f64) -> Option<f64> {
        self.lag
            .stiffness_for_end_displacement(load.0 / self.arm, response * self.arm)
    }

    /// The smallest K_T (MPa/mm) for which the regularized response at `load` is within
    /// `tolerance` (a fraction) of Coulomb's (S8): the response falls with K_T (L11), so the
    /// set is one interval [K_T*, 1e12] and K_T* one bracketed root in ln K_T. `None` at zero
    /// load or when even the stiffest accepted K_T is not within it.
    pub fn stiffness_within(&self, load: CarriedLoad, tolerance: f64) -> Option<f64> {
        let coulomb = self.coulomb(load).response();
        if !(coulomb > 0.0 && tolerance > 0.0) {
            return None;
        }
        let excess = |kt: f64| {
            let response = self.lag.with_stiffness(kt).regularized(load.0 / self.arm);
            response.end_displacement() / self.arm / coulomb - 1.0 - tolerance
        };
        let (min, max) = (Domain::STIFFNESS.min(), Domain::STIFFNESS.max());
        if excess(max) > 0.0 {
            return None;
        }
        if excess(min) <= 0.0 {
            return Some(min);
        }
        let k = find_root_in_bracket(|k| excess(min * k.exp()), 0.0, (max / min).ln());
        Some(min * k.exp())
    }
}

/// One law's solution of one axis at one load, in the fit's coordinate (x from the shaft's loaded
/// face) and words.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitState {
    state: ShearLagState,
    arm: f64,
    length: f64,
}

impl FitState {
    /// The law.
    pub fn law(&self) -> Law {
        self.state.law()
    }

    /// The load (N or N mm).
    pub fn load(&self) -> f64 {
        self.state.force() * self.arm
    }

    /// The response (S5): Delta (mm), the shaft's loaded end relative to the hub's held face,
    /// or theta (rad), the shaft's loaded end's rotation relative to the hub's held face.
    pub fn response(&self) -> f64 {
        self.state.end_displacement() / self.arm
    }

    /// Length of the sliding zone from x = 0, the shaft's loaded face (mm).
    pub fn slide_from_loaded_face(&self) -> f64 {
        self.state.slide_from_end()
    }

    /// Length of the sliding zone from x = L, the hub's held face (mm).
    pub fn slide_from_held_face(&self) -> f64 {
        self.state.slide_from_start()
    }

    /// The stretch that holds (sticks or slips elastically), [from, to] along x (mm).
    pub fn holding_zone(&self) -> [f64; 2] {
        [
            self.slide_from_loaded_face(),
            self.length - self.slide_from_held_face(),
        ]
    }

    /// The slip at `x` (mm, axial for the push-out, circumferential r (phi_shaft - phi_hub) for
    /// the torque), positive in the load's direction.
    pub fn slip_at(&self, x: f64) -> f64 {
        self.state.slip_at(self.length - x)
    }

    /// The interface shear at `x` on the shaft (MPa), positive resisting the load.
    pub fn shear_at(&self, x: f64) -> f64 {
        self.state.shear_at(self.length - x)
    }

    /// The zones from x = 0 (the loaded face) outward.
    pub fn regime(&self) -> Regime {
        match self.state.regime() {
            regime @ (Regime::UNLOADED | Regime::MACROSLIP) => regime,
            _ => zones_regime(
                self.law(),
                self.slide_from_loaded_face(),
                self.slide_from_held_face(),
                self.length,
            ),
        }
    }

    /// Energy dissipated per cycle between +load and -load (N mm), (S7): the kernel's friction
    /// work, the same for the torque (T dtheta = N dDelta_eq).
    pub fn cycle_dissipation(&self) -> f64 {
        self.state.cycle_dissipation()
    }
}

impl Solution for FitState {
    fn response(&self) -> f64 {
        FitState::response(self)
    }

    fn regime(&self) -> Regime {
        FitState::regime(self)
    }

    /// The end of the holding zone from x = 0, L - (the slide from the held face).
    fn zone_end(&self) -> f64 {
        self.holding_zone()[1]
    }
}
