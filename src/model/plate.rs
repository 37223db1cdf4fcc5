//! A thin plate squeezed on a rigid plane (paper section 2.2).
//!
//! A wide plate (plane strain) of thickness t_p and half-length L lies on a rigid plane and is pressed
//! by a uniform pressure P on its upper face. Poisson's effect makes it spread sideways; friction on the
//! lower face resists. By symmetry only 0 <= x <= L is modelled, with u(0) = 0 and a free end at x = L.
//! Derivations and the paper's misprints: `docs/theory.md`, "Squeezed plate", equations (P1)...

use super::hyperbolic::{sinh_cosh_ratio, sinh_ratio};
use super::params::{ParamError, PlateParam};
use super::regime::Regime;
use super::solve::find_root_in_bracket;

/// Raw inputs of the squeezed-plate problem (mm, MPa, MPa/mm); validated by [`SqueezedPlate::new`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlateParams {
    /// Half-length L (mm).
    pub half_length: f64,
    /// Thickness t_p (mm).
    pub thickness: f64,
    /// Young's modulus E (MPa).
    pub youngs_modulus: f64,
    /// Poisson ratio nu (-), 0 <= nu < 0.5.
    pub poisson: f64,
    /// Friction coefficient mu (-).
    pub friction: f64,
    /// Applied pressure P (MPa).
    pub pressure: f64,
    /// Tangential contact stiffness K_T (MPa/mm).
    pub tangential_stiffness: f64,
}

impl PlateParams {
    /// The paper's data set (section 2.2.3): L=10, t_p=0.2 mm, E=70000 MPa, nu=0.3, mu=0.3, P=10 MPa.
    /// The paper sweeps K_T; 1e6 MPa/mm (= 1000 MPa/um) is a default that shows both zones.
    pub const PAPER: PlateParams = PlateParams {
        half_length: 10.0,
        thickness: 0.2,
        youngs_modulus: 70_000.0,
        poisson: 0.3,
        friction: 0.3,
        pressure: 10.0,
        tangential_stiffness: 1e6,
    };

    /// The field that holds `param`.
    pub fn value_mut(&mut self, param: PlateParam) -> &mut f64 {
        match param {
            PlateParam::HalfLength => &mut self.half_length,
            PlateParam::Thickness => &mut self.thickness,
            PlateParam::Modulus => &mut self.youngs_modulus,
            PlateParam::Poisson => &mut self.poisson,
            PlateParam::Friction => &mut self.friction,
            PlateParam::Pressure => &mut self.pressure,
            PlateParam::Stiffness => &mut self.tangential_stiffness,
        }
    }
}

/// A validated squeezed plate with its derived constants.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SqueezedPlate {
    params: PlateParams,
    /// alpha = sqrt((1 - nu^2) K_T / (E t_p)) (1/mm), eq. (P4).
    alpha: f64,
    /// l = nu t_p / (mu (1 - nu)) (mm): length of the Coulomb slip zone, eq. (P3).
    slide_length: f64,
    /// kappa = (1 - nu^2) mu P / (E t_p) (1/mm): the slope of the strain in a sliding zone, (P2).
    strain_gradient: f64,
}

impl SqueezedPlate {
    /// Validates every input: lengths, E, P, mu, K_T finite and > 0; 0 <= nu < 0.5.
    ///
    /// # Errors
    /// The first input out of its domain (see [`PlateParam::spec`]), in display order.
    ///
    /// # Examples
    /// ```
    /// use microslip::{PlateParams, SqueezedPlate};
    /// let plate = SqueezedPlate::new(PlateParams::PAPER)?;
    /// let state = plate.regularized();
    /// assert!(state.end_displacement() > plate.coulomb().end_displacement()); // mm
    /// let bad = PlateParams { poisson: 0.5, ..PlateParams::PAPER };
    /// assert_eq!(
    ///     SqueezedPlate::new(bad).unwrap_err().to_string(),
    ///     "invalid nu = 0.5: must be in [0, 0.5) (dimensionless)"
    /// );
    /// # Ok::<(), microslip::ParamError>(())
    /// ```
    pub fn new(params: PlateParams) -> Result<Self, ParamError> {
        let mut fields = params;
        for param in PlateParam::ALL {
            param.check(*fields.value_mut(param))?;
        }
        let PlateParams {
            thickness: t,
            youngs_modulus: e,
            poisson: nu,
            friction: mu,
            ..
        } = params;
        let compliance = 1.0 - nu * nu;
        Ok(SqueezedPlate {
            params,
            alpha: (compliance * params.tangential_stiffness / (e * t)).sqrt(),
            slide_length: nu * t / (mu * (1.0 - nu)),
            strain_gradient: compliance * mu * params.pressure / (e * t),
        })
    }

    /// The inputs this plate was built from.
    pub fn params(&self) -> PlateParams {
        self.params
    }

    /// The same plate with another K_T (MPa/mm); validated like [`SqueezedPlate::new`].
    ///
    /// # Errors
    /// [`ParamError`] when `kt` is not finite and > 0.
    pub fn with_tangential_stiffness(&self, kt: f64) -> Result<Self, ParamError> {
        SqueezedPlate::new(PlateParams {
            tangential_stiffness: kt,
            ..self.params
        })
    }

    /// alpha = sqrt((1 - nu^2) K_T / (E t_p)) (1/mm), eq. (P4).
    pub fn decay_rate(&self) -> f64 {
        self.alpha
    }

    /// Saturation slip mu P / K_T (mm).
    pub fn saturation_slip(&self) -> f64 {
        self.params.friction * self.params.pressure / self.params.tangential_stiffness
    }

    /// Displacement of a zone sliding at mu P from `start` (where it equals `start_u`) to x, (P2).
    fn sliding_displacement(&self, start: f64, start_u: f64, x: f64) -> f64 {
        let l = self.params.half_length;
        start_u
            + self.strain_gradient
                * (self.slide_length * (x - start) - 0.5 * ((l - start).powi(2) - (l - x).powi(2)))
    }

    /// Solution under the plain Coulomb law.
    pub fn coulomb(&self) -> CoulombPlate {
        CoulombPlate {
            plate: *self,
            stick_end: (self.params.half_length - self.slide_length).max(0.0),
        }
    }

    /// Solution under the regularized Coulomb law.
    pub fn regularized(&self) -> RegularizedPlate {
        let l = self.params.half_length;
        let big_lambda = self.alpha * l;
        let m = self.alpha * self.slide_length;
        // No macroslip iff the all-microslip end shear K_T u(L) stays <= mu P, i.e. m tanh(alpha L) <= 1.
        let has_macroslip = m * big_lambda.tanh() > 1.0;
        let micro_end = if has_macroslip {
            // (P6): h(z) = Lambda - z + coth z - m, strictly decreasing; h(1/m) >= 0 since coth z > 1/z,
            // and h(Lambda) = coth Lambda - m < 0.
            let h = |z: f64| big_lambda - z + 1.0 / z.tanh() - m;
            find_root_in_bracket(h, 1.0 / m, big_lambda) / self.alpha
        } else {
            l
        };
        RegularizedPlate {
            plate: *self,
            micro_end,
            has_macroslip,
        }
    }

    /// Contact pressure under the plate, paper section 2.2.1 (rederived, eq. (P8)).
    pub fn contact_pressure(&self) -> ContactPressure {
        ContactPressure::new(&self.params)
    }
}

/// The squeezed plate under the plain Coulomb law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoulombPlate {
    plate: SqueezedPlate,
    stick_end: f64,
}

impl CoulombPlate {
    /// End X_s of the stick zone (mm), eq. (P3): L - nu t_p / (mu (1 - nu)), or 0 when all slides.
    pub fn stick_end(&self) -> f64 {
        self.stick_end
    }

    /// Stick only when nu = 0 (nothing pushes the plate outward); macroslip alone when the slip length
    /// exceeds L; stick then macroslip otherwise.
    pub fn regime(&self) -> Regime {
        let l = self.plate.params.half_length;
        if self.stick_end >= l {
            Regime::Stick
        } else if self.stick_end <= 0.0 {
            Regime::Macroslip
        } else {
            Regime::StickMacroslip
        }
    }

    /// Displacement u(x) (mm), eq. (P2): zero in the stick zone.
    pub fn displacement(&self, x: f64) -> f64 {
        if x <= self.stick_end {
            0.0
        } else {
            self.plate.sliding_displacement(self.stick_end, 0.0, x)
        }
    }

    /// End displacement u(L) (mm), eq. (P3): kappa l^2 / 2 = (1 + nu) nu^2 t_p P / (2 (1 - nu) mu E)
    /// when a stick zone exists.
    pub fn end_displacement(&self) -> f64 {
        self.displacement(self.plate.params.half_length)
    }

    /// Interface shear stress (MPa): 0 in the stick zone (the strain is zero, so is its gradient),
    /// mu P in the slip zone.
    pub fn shear_stress(&self, x: f64) -> f64 {
        if x <= self.stick_end {
            0.0
        } else {
            self.plate.params.friction * self.plate.params.pressure
        }
    }
}

/// The squeezed plate under the regularized Coulomb law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RegularizedPlate {
    plate: SqueezedPlate,
    micro_end: f64,
    has_macroslip: bool,
}

impl RegularizedPlate {
    /// End X_r of the microslip zone (mm); L when nothing slides.
    pub fn micro_zone_end(&self) -> f64 {
        self.micro_end
    }

    /// Microslip alone, or microslip near the centre then macroslip near the free end.
    pub fn regime(&self) -> Regime {
        if self.has_macroslip {
            Regime::MicroslipMacroslip
        } else {
            Regime::Microslip
        }
    }

    /// Displacement u(x) (mm): (P5) in microslip, (P2) beyond X_r.
    pub fn displacement(&self, x: f64) -> f64 {
        let p = &self.plate;
        let ax = p.alpha * x.max(0.0);
        if !self.has_macroslip {
            // (P5) with sigma_x(L) = 0: u = (kappa l / alpha) sinh(alpha x) / cosh(alpha L).
            let amplitude = p.strain_gradient * p.slide_length / p.alpha;
            return amplitude
                * sinh_cosh_ratio(
                    ax.min(p.alpha * p.params.half_length),
                    p.alpha * p.params.half_length,
                );
        }
        if x <= self.micro_end {
            p.saturation_slip() * sinh_ratio(ax, p.alpha * self.micro_end)
        } else {
            p.sliding_displacement(self.micro_end, p.saturation_slip(), x)
        }
    }

    /// End displacement u(L) (mm).
    pub fn end_displacement(&self) -> f64 {
        self.displacement(self.plate.params.half_length)
    }

    /// Interface shear stress (MPa): K_T u in microslip, mu P in macroslip.
    pub fn shear_stress(&self, x: f64) -> f64 {
        let p = &self.plate.params;
        if x > self.micro_end {
            p.friction * p.pressure
        } else {
            p.tangential_stiffness * self.displacement(x)
        }
    }
}

/// Mean relative deviation of P_r from P above which the constant-pressure assumption is flagged.
///
/// 3 % reproduces the paper's statement that the assumption fails below L/h = 20 for mu = 0.3:
/// the mean deviation is ~ mu t_p / L = 2 mu h / L (see docs/theory.md, (P9)).
pub const PRESSURE_DEVIATION_LIMIT: f64 = 0.03;

/// Contact pressure P_r(x) under a plate kept flat on the plane with saturated friction (eq. (P8)).
///
/// Q(x) = mu h P [-1 + ((1 - e_m) e^{r_p (x - L)} + (1 - e_p) e^{r_m x}) / (1 - e_p e_m)], with
/// h = t_p / 2, r_p > 0 > r_m the roots of r^2 - beta^2 mu h r - beta^2 = 0, e_p = e^{-r_p L},
/// e_m = e^{r_m L}: a form with only decaying exponentials, so no overflow for long plates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactPressure {
    half_length: f64,
    /// mu h (mm).
    lever: f64,
    rate_edge: f64,
    rate_centre: f64,
    weight_edge: f64,
    weight_centre: f64,
}

impl ContactPressure {
    fn new(p: &PlateParams) -> Self {
        let half_thickness = 0.5 * p.thickness;
        // Timoshenko plate in plane strain: D = E t^3 / (12 (1 - nu^2)), shear stiffness (5/6) G t,
        // so beta^2 = (5/6) G t / D = 5 (1 - nu) / t^2.
        let beta2 = 5.0 * (1.0 - p.poisson) / (p.thickness * p.thickness);
        let lever = p.friction * half_thickness;
        let a1 = 0.5 * beta2 * lever;
        let a2 = (a1 * a1 + beta2).sqrt();
        let (rate_edge, rate_centre) = (a1 + a2, a1 - a2);
        let e_p = (-rate_edge * p.half_length).exp();
        let e_m = (rate_centre * p.half_length).exp();
        let det = 1.0 - e_p * e_m;
        ContactPressure {
            half_length: p.half_length,
            lever,
            rate_edge,
            rate_centre,
            weight_edge: (1.0 - e_m) / det,
            weight_centre: (1.0 - e_p) / det,
        }
    }

    fn edge_term(&self, x: f64) -> f64 {
        self.weight_edge * (self.rate_edge * (x - self.half_length)).exp()
    }

    fn centre_term(&self, x: f64) -> f64 {
        self.weight_centre * (self.rate_centre * x).exp()
    }

    /// P_r(x) / P (-), 0 <= x <= L: below 1 near the centre, above 1 near the free end.
    pub fn ratio(&self, x: f64) -> f64 {
        let x = x.clamp(0.0, self.half_length);
        1.0 + self.lever
            * (self.rate_edge * self.edge_term(x) + self.rate_centre * self.centre_term(x))
    }

    /// Shear force Q(x) / P (mm) in the paper's sign convention.
    fn shear_over_pressure(&self, x: f64) -> f64 {
        self.lever * (self.edge_term(x) + self.centre_term(x) - 1.0)
    }

    /// Mean of |P_r / P - 1| over [0, L] (-). Q is convex with Q(0) = Q(L) = 0, so P_r - P = Q'
    /// changes sign once, at the minimum x0 of Q, and the mean is 2 |Q(x0)| / (P L).
    pub fn mean_deviation(&self) -> f64 {
        let ratio = -self.rate_centre * self.weight_centre / (self.rate_edge * self.weight_edge);
        let x0 = ((ratio.ln() + self.rate_edge * self.half_length)
            / (self.rate_edge - self.rate_centre))
            .clamp(0.0, self.half_length);
        2.0 * self.shear_over_pressure(x0).abs() / self.half_length
    }

    /// False when P_r departs from P by more than [`PRESSURE_DEVIATION_LIMIT`] on average, i.e. when
    /// the constant-pressure assumption of the friction solution no longer holds.
    pub fn constant_pressure_holds(&self) -> bool {
        self.mean_deviation() <= PRESSURE_DEVIATION_LIMIT
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plate(kt: f64) -> SqueezedPlate {
        SqueezedPlate::new(PlateParams {
            tangential_stiffness: kt,
            ..PlateParams::PAPER
        })
        .unwrap()
    }

    #[test]
    fn coulomb_matches_hand_values() {
        let c = plate(1e5).coulomb();
        // l = 0.3 * 0.2 / (0.3 * 0.7) = 0.2857142857 mm.
        assert!((c.stick_end() - (10.0 - 0.2 / 0.7)).abs() < 1e-13);
        // u(L) = (1 + nu) nu^2 t_p P / (2 (1 - nu) mu E).
        let u = 1.3 * 0.09 * 0.2 * 10.0 / (2.0 * 0.7 * 0.3 * 70_000.0);
        assert!(((c.end_displacement() - u) / u).abs() < 1e-13);
        assert_eq!(c.regime(), Regime::StickMacroslip);
    }

    #[test]
    fn coulomb_regimes_at_the_extremes_of_nu_and_mu() {
        let no_poisson = PlateParams {
            poisson: 0.0,
            ..PlateParams::PAPER
        };
        let c = SqueezedPlate::new(no_poisson).unwrap().coulomb();
        assert_eq!(c.regime(), Regime::Stick);
        assert_eq!(c.end_displacement(), 0.0);
        let slippery = PlateParams {
            friction: 1e-3,
            ..PlateParams::PAPER
        };
        let c = SqueezedPlate::new(slippery).unwrap().coulomb();
        assert_eq!(c.regime(), Regime::Macroslip);
        assert_eq!(c.stick_end(), 0.0);
        // Whole half-plate sliding: u(L) = kappa (l L - L^2 / 2).
        let (kappa, l) = (
            0.91 * 1e-3 * 10.0 / (70_000.0 * 0.2),
            0.3 * 0.2 / (1e-3 * 0.7),
        );
        let u = kappa * (l * 10.0 - 50.0);
        assert!(((c.end_displacement() - u) / u).abs() < 1e-13);
    }

    #[test]
    fn all_microslip_end_displacement_matches_hand_value() {
        // K_T = 1: alpha L = 10 sqrt(0.91 / 14000); u(L) = nu (1 + nu) P tanh(alpha L) / (E alpha).
        let r = plate(1.0).regularized();
        assert_eq!(r.regime(), Regime::Microslip);
        let alpha = (0.91_f64 / 14_000.0).sqrt();
        let u = 0.3 * 1.3 * 10.0 * (alpha * 10.0).tanh() / (70_000.0 * alpha);
        assert!(((r.end_displacement() - u) / u).abs() < 1e-13);
    }

    #[test]
    fn displacement_and_shear_are_continuous_at_the_microslip_end() {
        let r = plate(1e6).regularized();
        assert_eq!(r.regime(), Regime::MicroslipMacroslip);
        let x = r.micro_zone_end();
        let (below, above) = (
            r.displacement(x * (1.0 - 1e-13)),
            r.displacement(x * (1.0 + 1e-13)),
        );
        assert!(((below - above) / below).abs() < 1e-9);
        assert!((r.shear_stress(x) - 3.0).abs() < 1e-9);
    }

    #[test]
    fn contact_pressure_balances_the_applied_load() {
        // The integral of P_r - P over [0, L] is Q(L) - Q(0) = 0; check it by quadrature.
        let cp = plate(1e5).contact_pressure();
        let n = 200_000;
        let dx = 10.0 / n as f64;
        let integral: f64 = (0..n)
            .map(|i| (cp.ratio((i as f64 + 0.5) * dx) - 1.0) * dx)
            .sum();
        assert!(integral.abs() < 1e-6, "{integral}");
        assert!(cp.ratio(0.0) < 1.0 && cp.ratio(10.0) > 1.0);
        assert!(cp.constant_pressure_holds());
    }

    #[test]
    fn short_thick_plates_break_the_constant_pressure_assumption() {
        // L / h = 10: mean deviation ~ 2 mu h / L = 0.06 > 3 %.
        let stubby = PlateParams {
            half_length: 1.0,
            ..PlateParams::PAPER
        };
        let cp = SqueezedPlate::new(stubby).unwrap().contact_pressure();
        assert!(!cp.constant_pressure_holds(), "{}", cp.mean_deviation());
    }

    #[test]
    fn bad_inputs_name_their_field() {
        let bad = PlateParams {
            poisson: 0.5,
            ..PlateParams::PAPER
        };
        assert_eq!(SqueezedPlate::new(bad).unwrap_err().field, "nu");
        let bad = PlateParams {
            thickness: 0.0,
            ..PlateParams::PAPER
        };
        assert_eq!(SqueezedPlate::new(bad).unwrap_err().field, "tp");
    }
}
