//! A thin plate squeezed on a rigid plane (paper section 2.2).
//!
//! A wide plate (plane strain) of thickness t_p and half-length L lies on a rigid plane and is pressed
//! by a uniform pressure P on its upper face. Poisson's effect makes it spread sideways; friction on the
//! lower face resists. By symmetry only 0 <= x <= L is modelled, with u(0) = 0 and a free end at x = L.
//! Derivations and the paper's misprints: `docs/theory.md`, "Squeezed plate", equations (P1)...

pub use super::params::PlateParams;
use crate::kernel::hyperbolic::{sinh_cosh_ratio, sinh_ratio};
use crate::kernel::params::ParamError;
use crate::kernel::regime::Regime;
use crate::kernel::solve::find_root_in_bracket;
use crate::problems::{PlateParam, Solution};

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
    /// Validates every input against its domain ([`PlateParam::spec`]): lengths, E, P, mu, K_T
    /// positive and bounded; 0 <= nu < 0.5.
    ///
    /// # Errors
    /// The first input out of its domain (see [`PlateParam::spec`]), in display order.
    ///
    /// # Examples
    /// ```
    /// use microslip_core::{PlateParams, SqueezedPlate};
    /// let plate = SqueezedPlate::new(PlateParams::PAPER)?;
    /// let state = plate.regularized();
    /// assert!(state.end_displacement() > plate.coulomb().end_displacement()); // mm
    /// let bad = PlateParams { poisson: 0.5, ..PlateParams::PAPER };
    /// assert_eq!(
    ///     SqueezedPlate::new(bad).unwrap_err().to_string(),
    ///     "invalid nu = 0.5: must be in [0, 0.5) (dimensionless)"
    /// );
    /// # Ok::<(), microslip_core::ParamError>(())
    /// ```
    pub fn new(params: PlateParams) -> Result<Self, ParamError> {
        params.check()?;
        Ok(Self::derive(params))
    }

    /// The same plate with `param` set to the accepted value nearest to `value` (see
    /// [`crate::kernel::params::Domain::clamp`]): infallible, for sweeps whose range was checked.
    pub fn with_clamped(&self, param: PlateParam, value: f64) -> SqueezedPlate {
        let mut params = self.params;
        *params.value_mut(param) = param.spec().domain.clamp(value);
        Self::derive(params)
    }

    /// The derived constants of validated inputs.
    fn derive(params: PlateParams) -> SqueezedPlate {
        let PlateParams {
            thickness: t,
            youngs_modulus: e,
            poisson: nu,
            friction: mu,
            ..
        } = params;
        let compliance = 1.0 - nu * nu;
        SqueezedPlate {
            params,
            alpha: (compliance * params.tangential_stiffness / (e * t)).sqrt(),
            slide_length: nu * t / (mu * (1.0 - nu)),
            strain_gradient: compliance * mu * params.pressure / (e * t),
        }
    }

    /// The inputs this plate was built from.
    pub fn params(&self) -> PlateParams {
        self.params
    }

    /// The same plate with another K_T (MPa/mm); validated like [`SqueezedPlate::new`].
    ///
    /// # Errors
    /// [`ParamError`] when `kt` is outside the K_T domain.
    pub fn with_tangential_stiffness(&self, kt: f64) -> Result<Self, ParamError> {
        SqueezedPlate::new(PlateParams {
            tangential_stiffness: kt,
            ..self.params
        })
    }

    /// The K_T (MPa/mm) at which the regularized u(L) equals `end_displacement` (mm), all else
    /// as in this plate: what an FE result of u(L) says about the stiffness its code really used.
    /// `None` when no K_T in the accepted domain gives it: u(L) falls from the free expansion
    /// nu (1 + nu) P L / E (K_T -> 0) to the Coulomb value (K_T -> infinity), strictly (docs/theory.md,
    /// (P10)), so outside that interval there is no answer, and inside it exactly one.
    pub fn stiffness_for_end_displacement(&self, end_displacement: f64) -> Option<f64> {
        let domain = crate::kernel::params::Domain::STIFFNESS;
        let at = |log_kt: f64| {
            self.with_clamped(PlateParam::Stiffness, log_kt.exp())
                .regularized()
                .end_displacement()
        };
        let (lo, hi) = (domain.min().ln(), domain.max().ln());
        let (u_soft, u_stiff) = (at(lo), at(hi));
        if !(u_stiff..=u_soft).contains(&end_displacement) {
            return None;
        }
        // Relative misfit, so that the root finder sees numbers near 1 whatever the scale of u.
        let log_kt = find_root_in_bracket(|k| at(k) / end_displacement - 1.0, lo, hi);
        Some(log_kt.exp())
    }

    /// alpha = sqrt((1 - nu^2) K_T / (E t_p)) (1/mm), eq. (P4).
    pub fn decay_rate(&self) -> f64 {
        self.alpha
    }

    /// Saturation slip mu P / K_T (mm).
    pub fn saturation_slip(&self) -> f64 {
        self.params.friction * self.params.pressure / self.params.tangential_stiffness
    }

    /// The K_T (MPa/mm) at which macroslip first appears at the free end, all else as in this plate
    /// (docs/theory.md, (P11)): the regularized plate is all microslip while alpha l tanh(alpha L)
    /// <= 1, and alpha grows with K_T, so the onset is the one root of z tanh z = L / l (z = alpha L,
    /// l the Coulomb slip length (P3)), K_T = z^2 E t_p / ((1 - nu^2) L^2). Below it the plate is
    /// all microslip, above it microslip then macroslip. `None` when nu = 0 (the plate does not
    /// expand, so nothing ever slides). The value may lie outside the accepted K_T domain; callers
    /// say so.
    pub fn macroslip_onset_stiffness(&self) -> Option<f64> {
        let p = &self.params;
        if self.slide_length <= 0.0 {
            return None;
        }
        let c = p.half_length / self.slide_length;
        if !c.is_finite() {
            return None;
        }
        // z tanh z <= min(z, z^2) bounds the root below; tanh z >= tanh(1) min(z, 1) bounds it above.
        let t1 = 1f64.tanh();
        let lo = c.max(c.sqrt());
        let hi = (c / t1).max((c / t1).sqrt());
        let z = find_root_in_bracket(|z: f64| z * z.tanh() / c - 1.0, lo, hi);
        let kt = (z / p.half_length).powi(2) * p.youngs_modulus * p.thickness
            / (1.0 - p.poisson * p.poisson);
        kt.is_finite().then_some(kt)
    }

    /// Displacement in a zone sliding at mu P, (P2), written with distances from the free end so
    /// that nothing is a difference of lengths near L: the zone is the last `zone` mm of the
    /// half-plate, u = `start_u` where it starts, and the point is `from_end` = L - x from the end
    /// (0 <= from_end <= zone). With a = zone, b = from_end, (P2) becomes
    /// u = u_0 + kappa (a - b) (l - (a + b) / 2); a <= l in both laws, so every factor is >= 0.
    fn sliding_displacement(&self, zone: f64, start_u: f64, from_end: f64) -> f64 {
        let b = from_end.clamp(0.0, zone);
        start_u + self.strain_gradient * (zone - b) * (self.slide_length - 0.5 * (zone + b))
    }

    /// nu (1 + nu) P / E = kappa l (-): the free plane-strain expansion strain, computed directly
    /// rather than as the product of kappa and l (one huge, the other tiny near nu = 0.5).
    fn free_strain(&self) -> f64 {
        let p = &self.params;
        p.poisson * (1.0 + p.poisson) * p.pressure / p.youngs_modulus
    }

    /// Solution under the plain Coulomb law.
    pub fn coulomb(&self) -> CoulombPlate {
        CoulombPlate {
            plate: *self,
            slide_zone: self.slide_length.min(self.params.half_length),
        }
    }

    /// Solution under the regularized Coulomb law.
    pub fn regularized(&self) -> RegularizedPlate {
        let l = self.params.half_length;
        let big_lambda = self.alpha * l;
        let m = self.alpha * self.slide_length;
        // No macroslip iff the all-microslip end shear K_T u(L) stays <= mu P, i.e. m tanh(alpha L) <= 1.
        let has_macroslip = m * big_lambda.tanh() > 1.0;
        let (micro_end, macro_length) = if has_macroslip {
            self.microslip_boundary(big_lambda, m)
        } else {
            (l, 0.0)
        };
        RegularizedPlate {
            plate: *self,
            micro_end,
            macro_length,
            has_macroslip,
        }
    }

    /// Solves (P6) for X_r and the macroslip length L - X_r (mm), each computed without subtracting
    /// lengths near L: h(z) = alpha (L - l) - z + coth z with z = alpha X_r is strictly decreasing,
    /// h(1/m) >= 0 since coth z > 1/z, and h(Lambda) = coth Lambda - m < 0 (m = alpha l, Lambda =
    /// alpha L). When the root lies in the lower half of the bracket (z <= Lambda / 2) it is found
    /// as z; otherwise as d = Lambda - z, the root of H(d) = d + coth(Lambda - d) - m, in
    /// [0, Lambda / 2]. Either way the smaller of X_r and L - X_r is the unknown, known to 1e-12
    /// relative, and the other is a difference without cancellation.
    fn microslip_boundary(&self, big_lambda: f64, m: f64) -> (f64, f64) {
        let (alpha, l) = (self.alpha, self.params.half_length);
        // alpha (L - l): one rounding, where alpha L - alpha l would lose the digits L and l share.
        let offset = alpha * (l - self.slide_length);
        let h = |z: f64| offset - z + 1.0 / z.tanh();
        let lower = 1.0 / m;
        let half = 0.5 * big_lambda;
        if lower < half && alpha * (0.5 * l - self.slide_length) + 1.0 / half.tanh() < 0.0 {
            let z = find_root_in_bracket(h, lower, half);
            (z / alpha, l - z / alpha)
        } else {
            let big_h = |d: f64| d + 1.0 / (big_lambda - d).tanh() - m;
            let d = find_root_in_bracket(big_h, 0.0, big_lambda - lower.max(half));
            (l - d / alpha, d / alpha)
        }
    }

    /// Contact pressure under the plate, paper section 2.2.1 (rederived, eq. (P8)).
    pub fn contact_pressure(&self) -> ContactPressure {
        ContactPressure::new(&self.params)
    }

    /// The flat-plate model's mean contact pressure over the last t_p before the free end, over P
    /// (the whole half-length when L < t_p), where that model was measured right: a slip zone
    /// L - X_r of at least [`FLAT_END_LAYER_SLIP`] t_p (within -30 % to +41 % of the plane-strain
    /// continuum's excess over P, docs/theory.md (P12)); `None` elsewhere, where it is not the
    /// plate's.
    pub fn end_layer_pressure(&self) -> Option<f64> {
        let p = &self.params;
        let slip = self.regularized().macroslip_length();
        (p.poisson > 0.0 && slip >= FLAT_END_LAYER_SLIP * p.thickness).then(|| {
            self.contact_pressure()
                .mean_ratio_over(p.half_length - p.thickness, p.half_length)
        })
    }
}

/// The squeezed plate under the plain Coulomb law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoulombPlate {
    plate: SqueezedPlate,
    /// Length of the sliding zone at the free end, min(l, L) (mm): kept rather than X_s because
    /// L - X_s loses every digit when l is far below L.
    slide_zone: f64,
}

impl CoulombPlate {
    /// End X_s of the stick zone (mm), eq. (P3): L - nu t_p / (mu (1 - nu)), or 0 when all slides.
    pub fn stick_end(&self) -> f64 {
        self.plate.params.half_length - self.slide_zone
    }

    /// Length L - X_s of the sliding zone at the free end (mm): min(l, L).
    pub fn slide_zone(&self) -> f64 {
        self.slide_zone
    }

    /// Unloaded when nu = 0 (nothing pushes the plate outward, so the interface carries no shear);
    /// macroslip alone when the slip length reaches L; stick then macroslip otherwise.
    pub fn regime(&self) -> Regime {
        if self.plate.params.poisson == 0.0 {
            // Nothing squeezes the plate sideways: no shear anywhere, as the unloaded beams.
            Regime::UNLOADED
        } else if self.slide_zone <= 0.0 {
            Regime::STICK
        } else if self.slide_zone >= self.plate.params.half_length {
            Regime::MACROSLIP
        } else {
            Regime::STICK_MACROSLIP
        }
    }

    /// True when x lies in the sliding zone, decided by the distance from the free end.
    fn slides_at(&self, x: f64) -> bool {
        self.plate.params.half_length - x < self.slide_zone
    }

    /// Displacement u(x) (mm), eq. (P2): zero in the stick zone.
    pub fn displacement(&self, x: f64) -> f64 {
        if self.slides_at(x) {
            self.plate
                .sliding_displacement(self.slide_zone, 0.0, self.plate.params.half_length - x)
        } else {
            0.0
        }
    }

    /// End displacement u(L) (mm), eq. (P3): kappa l^2 / 2 = (1 + nu) nu^2 t_p P / (2 (1 - nu) mu E)
    /// when a stick zone exists, whatever L.
    pub fn end_displacement(&self) -> f64 {
        self.displacement(self.plate.params.half_length)
    }

    /// Interface shear stress (MPa): 0 in the stick zone (the strain is zero, so is its gradient),
    /// mu P in the slip zone.
    pub fn shear_stress(&self, x: f64) -> f64 {
        if self.slides_at(x) {
            self.plate.params.friction * self.plate.params.pressure
        } else {
            0.0
        }
    }
}

/// The squeezed plate under the regularized Coulomb law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RegularizedPlate {
    plate: SqueezedPlate,
    micro_end: f64,
    /// L - X_r (mm), solved for directly when it is the smaller of the two (see
    /// `SqueezedPlate::microslip_boundary`); 0 without macroslip.
    macro_length: f64,
    has_macroslip: bool,
}

impl RegularizedPlate {
    /// End X_r of the microslip zone (mm); L when nothing slides.
    pub fn micro_zone_end(&self) -> f64 {
        self.micro_end
    }

    /// Length L - X_r of the macroslip zone at the free end (mm); 0 without macroslip.
    pub fn macroslip_length(&self) -> f64 {
        self.macro_length
    }

    /// Microslip alone, or microslip near the centre then macroslip near the free end.
    pub fn regime(&self) -> Regime {
        if self.plate.params.poisson == 0.0 {
            Regime::UNLOADED
        } else if self.has_macroslip {
            Regime::MICROSLIP_MACROSLIP
        } else {
            Regime::MICROSLIP
        }
    }

    /// True when x lies in the macroslip zone, decided by the distance from the free end.
    fn slides_at(&self, x: f64) -> bool {
        self.has_macroslip && self.plate.params.half_length - x < self.macro_length
    }

    /// Displacement u(x) (mm): (P5) in microslip, (P2) beyond X_r.
    pub fn displacement(&self, x: f64) -> f64 {
        let p = &self.plate;
        let l = p.params.half_length;
        let ax = p.alpha * x.clamp(0.0, l);
        if !self.has_macroslip {
            // (P5) with sigma_x(L) = 0: u = (kappa l / alpha) sinh(alpha x) / cosh(alpha L).
            return p.free_strain() / p.alpha * sinh_cosh_ratio(ax, p.alpha * l);
        }
        if self.slides_at(x) {
            p.sliding_displacement(self.macro_length, p.saturation_slip(), l - x)
        } else {
            p.saturation_slip()
                * sinh_ratio(ax.min(p.alpha * self.micro_end), p.alpha * self.micro_end)
        }
    }

    /// End displacement u(L) (mm).
    pub fn end_displacement(&self) -> f64 {
        self.displacement(self.plate.params.half_length)
    }

    /// Interface shear stress (MPa): K_T u in microslip, mu P in macroslip.
    pub fn shear_stress(&self, x: f64) -> f64 {
        let p = &self.plate.params;
        if self.slides_at(x) {
            p.friction * p.pressure
        } else {
            (p.tangential_stiffness * self.displacement(x)).min(p.friction * p.pressure)
        }
    }
}

/// Mean relative deviation of P_r from P above which the constant-pressure assumption is flagged.
///
/// 3 % reproduces the paper's statement that the assumption fails below L/h = 20 for mu = 0.3:
/// the mean deviation is ~ mu t_p / L = 2 mu h / L (see docs/theory.md, (P9)).
pub const PRESSURE_DEVIATION_LIMIT: f64 = 0.03;

/// Largest peak |P_r / P - 1| (at the centre or the free end) with which the constant-pressure
/// assumption is still said to hold: 0.5, i.e. the friction strength mu P_r at the edge within half
/// of mu P. The peak does not shrink with L (about mu sqrt(5 (1 - nu)) / 2, (P9)): the mean alone
/// said "holds" for mu = 1, nu = 0.1, L = 100 mm with P_r = 2.76 P at the edge.
pub const PRESSURE_PEAK_LIMIT: f64 = 0.5;

/// The slip zone, in thicknesses, from which the flat-plate model's mean pressure over the last t_p
/// was measured right against the plane-strain continuum (docs/theory.md, (P12)).
pub const FLAT_END_LAYER_SLIP: f64 = 1.0;

/// Contact pressure P_r(x) under a plate kept flat on the plane with saturated friction (eq. (P8)).
///
/// Q(x) = mu h P psi(x / L), h = t_p / 2, where psi solves psi'' - c L psi' - beta^2 L^2 psi =
/// beta^2 L^2 on [0, 1] with psi(0) = psi(1) = 0 (c = beta^2 mu h). Two evaluations, each free of
/// overflow and cancellation in its range (docs/theory.md, (P8)):
/// - (r_p - r_m) L > 1: psi = -1 + ((1 - e_m) e^{r_p (x - L)} + (1 - e_p) e^{r_m x}) / (1 - e_p e_m),
///   r_p > 0 > r_m the roots of r^2 - c r - beta^2 = 0, e_p = e^{-r_p L}, e_m = e^{r_m L}: only
///   decaying exponentials, so no overflow for long plates.
/// - shorter plates: the power series of psi in x / L, whose terms all have one sign, where the
///   exponential form would subtract numbers that agree to all but (r_p - r_m) L of their size.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactPressure {
    half_length: f64,
    /// mu h (mm).
    lever: f64,
    shape: PressureShape,
}

/// Terms of the power series of psi (short plates).
const PRESSURE_SERIES_TERMS: usize = 24;

#[derive(Debug, Clone, Copy, PartialEq)]
enum PressureShape {
    Exponential {
        rate_edge: f64,
        rate_centre: f64,
        weight_edge: f64,
        weight_centre: f64,
    },
    /// psi = psi_p + a psi_h as power series in xi = x / L (see `ContactPressure::series`).
    Series {
        /// c L (-).
        drift: f64,
        /// beta^2 L^2 (-).
        stiffness: f64,
        /// a = -psi_p(1) / psi_h(1).
        weight: f64,
    },
}

impl ContactPressure {
    fn new(p: &PlateParams) -> Self {
        let half_thickness = 0.5 * p.thickness;
        // Timoshenko plate in plane strain: D = E t^3 / (12 (1 - nu^2)), shear stiffness (5/6) G t,
        // so beta^2 = (5/6) G t / D = 5 (1 - nu) / t^2.
        let beta2 = 5.0 * (1.0 - p.poisson) / (p.thickness * p.thickness);
        // The friction stress mu P acts at the lever t/2 only where the plate slides; at nu = 0
        // nothing squeezes it sideways, no shear acts (see `CoulombPlate::regime`), and the
        // pressure stays P everywhere.
        let lever = if p.poisson == 0.0 {
            0.0
        } else {
            p.friction * half_thickness
        };
        let a1 = 0.5 * beta2 * lever;
        let a2 = (a1 * a1 + beta2).sqrt();
        let l = p.half_length;
        // r_m = a1 - a2 = -beta^2 / (a1 + a2): the product of the roots, without the cancellation of
        // a1 - a2 when a1 >> beta.
        let (rate_edge, rate_centre) = (a1 + a2, -beta2 / (a1 + a2));
        let shape = if (rate_edge - rate_centre) * l > 1.0 {
            // 1 - e_p e_m, 1 - e_m and 1 - e_p through expm1: exact when r L is small.
            let det = -((rate_centre - rate_edge) * l).exp_m1();
            PressureShape::Exponential {
                rate_edge,
                rate_centre,
                weight_edge: -(rate_centre * l).exp_m1() / det,
                weight_centre: -(-rate_edge * l).exp_m1() / det,
            }
        } else {
            let (drift, stiffness) = (beta2 * lever * l, beta2 * l * l);
            let particular = Self::series(drift, stiffness, 1.0, false)[0];
            let homogeneous = Self::series(drift, stiffness, 1.0, true)[0];
            PressureShape::Series {
                drift,
                stiffness,
                weight: -particular / homogeneous,
            }
        };
        ContactPressure {
            half_length: l,
            lever,
            shape,
        }
    }

    /// A solution of psi'' - c psi' - b psi = b (= 0 when `homogeneous`) with psi(0) = 0 and
    /// psi'(0) = 0 (particular) or 1 (homogeneous), and its first two derivatives, at `xi` in
    /// [0, 1], as power series (c = c L, b = beta^2 L^2 <= 1/4 here). The coefficients follow
    /// (n + 2)(n + 1) b_{n+2} = c (n + 1) b_{n+1} + b b_n (+ b for n = 0 unless homogeneous): all
    /// of one sign, so the sums are exact to rounding; they fall like 1/n!, so 24 terms exceed f64
    /// precision. The full psi = psi_p + a psi_h with a = -psi_p(1) / psi_h(1).
    fn series(c: f64, b: f64, xi: f64, homogeneous: bool) -> [f64; 3] {
        // b_n, b_{n+1} and xi^n, walking n upwards.
        let (mut current, mut next) = if homogeneous { (0.0, 1.0) } else { (0.0, 0.0) };
        let mut power = 1.0;
        let (mut value, mut slope, mut curvature) = (0.0, 0.0, 0.0);
        let mut previous_power = 0.0; // xi^(n-1)
        let mut before_previous = 0.0; // xi^(n-2)
        for n in 0..PRESSURE_SERIES_TERMS {
            let k = n as f64;
            value += current * power;
            slope += k * current * previous_power;
            curvature += k * (k - 1.0) * current * before_previous;
            let source = if n == 0 && !homogeneous { b } else { 0.0 };
            let after = (c * (k + 1.0) * next + b * current + source) / ((k + 2.0) * (k + 1.0));
            (current, next) = (next, after);
            before_previous = previous_power;
            previous_power = power;
            power *= xi;
        }
        [value, slope, curvature]
    }

    /// psi (-) and its first two derivatives with respect to x (1/mm, 1/mm^2) at `x`.
    fn psi(&self, x: f64) -> [f64; 3] {
        let l = self.half_length;
        match self.shape {
            PressureShape::Exponential {
                rate_edge,
                rate_centre,
                weight_edge,
                weight_centre,
            } => {
                let edge = weight_edge * (rate_edge * (x - l)).exp();
                let centre = weight_centre * (rate_centre * x).exp();
                [
                    edge + centre - 1.0,
                    rate_edge * edge + rate_centre * centre,
                    rate_edge * rate_edge * edge + rate_centre * rate_centre * centre,
                ]
            }
            PressureShape::Series {
                drift,
                stiffness,
                weight,
            } => {
                let xi = x / l;
                let p = Self::series(drift, stiffness, xi, false);
                let h = Self::series(drift, stiffness, xi, true);
                [
                    p[0] + weight * h[0],
                    (p[1] + weight * h[1]) / l,
                    (p[2] + weight * h[2]) / (l * l),
                ]
            }
        }
    }

    /// P_r(x) / P (-), 0 <= x <= L: below 1 near the centre, above 1 near the free end.
    pub fn ratio(&self, x: f64) -> f64 {
        let x = x.clamp(0.0, self.half_length);
        1.0 + self.lever * self.psi(x)[1]
    }

    /// Mean of P_r / P over [from, to] (-), 0 <= from < to <= L: 1 + (Q(to) - Q(from)) / (P (to - from)),
    /// exactly, since P_r - P = Q'. Over the last t_p before the free end it is the one number of this
    /// model that the plane-strain continuum confirms, where friction is saturated there
    /// (docs/theory.md, (P12)).
    pub fn mean_ratio_over(&self, from: f64, to: f64) -> f64 {
        let (from, to) = (
            from.clamp(0.0, self.half_length),
            to.clamp(0.0, self.half_length),
        );
        if to <= from {
            return self.ratio(from);
        }
        1.0 + self.lever * (self.psi(to)[0] - self.psi(from)[0]) / (to - from)
    }

    /// Mean of |P_r / P - 1| over [0, L] (-). Q is convex with Q(0) = Q(L) = 0, so P_r - P = Q'
    /// changes sign once, at the minimum x0 of Q, and the mean is 2 |Q(x0)| / (P L).
    pub fn mean_deviation(&self) -> f64 {
        let l = self.half_length;
        let x0 = match self.shape {
            PressureShape::Exponential {
                rate_edge,
                rate_centre,
                weight_edge,
                weight_centre,
            } => {
                let ratio = -rate_centre * weight_centre / (rate_edge * weight_edge);
                (ratio.ln() + rate_edge * l) / (rate_edge - rate_centre)
            }
            PressureShape::Series { .. } => {
                // psi is nearly the parabola -b x (L - x) / 2: Newton on psi' from the middle.
                let mut x = 0.5 * l;
                for _ in 0..8 {
                    let [_, slope, curvature] = self.psi(x);
                    if curvature.is_nan() || curvature <= 0.0 {
                        break;
                    }
                    x = (x - slope / curvature).clamp(0.0, l);
                }
                x
            }
        };
        2.0 * self.lever * self.psi(x0.clamp(0.0, l))[0].abs() / l
    }

    /// Largest |P_r / P - 1| over [0, L] (-). P_r - P = Q' is increasing (Q is convex), so the
    /// largest departure sits at an end: the centre (below P) or the free edge (above P).
    pub fn peak_deviation(&self) -> f64 {
        (self.ratio(0.0) - 1.0)
            .abs()
            .max((self.ratio(self.half_length) - 1.0).abs())
    }

    /// False when P_r departs from P by more than [`PRESSURE_DEVIATION_LIMIT`] on average or by
    /// more than [`PRESSURE_PEAK_LIMIT`] at its peak: the constant-pressure assumption of the
    /// friction solution no longer holds.
    pub fn constant_pressure_holds(&self) -> bool {
        self.mean_deviation() <= PRESSURE_DEVIATION_LIMIT
            && self.peak_deviation() <= PRESSURE_PEAK_LIMIT
    }
}

impl Solution for CoulombPlate {
    fn response(&self) -> f64 {
        self.end_displacement()
    }

    fn regime(&self) -> Regime {
        CoulombPlate::regime(self)
    }

    fn zone_end(&self) -> f64 {
        self.stick_end()
    }
}

impl Solution for RegularizedPlate {
    fn response(&self) -> f64 {
        self.end_displacement()
    }

    fn regime(&self) -> Regime {
        RegularizedPlate::regime(self)
    }

    fn zone_end(&self) -> f64 {
        self.micro_zone_end()
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
        assert_eq!(c.regime(), Regime::STICK_MACROSLIP);
    }

    #[test]
    fn coulomb_regimes_at_the_extremes_of_nu_and_mu() {
        let no_poisson = PlateParams {
            poisson: 0.0,
            ..PlateParams::PAPER
        };
        // nu = 0: the pressure does not squeeze the plate sideways; no shear under either law,
        // u = 0 exactly, and the continuum agrees exactly (it was 2e-21 mm, "+inf %").
        let plate = SqueezedPlate::new(no_poisson).unwrap();
        let c = plate.coulomb();
        assert_eq!(c.regime(), Regime::UNLOADED);
        assert_eq!(c.end_displacement(), 0.0);
        let r = plate.regularized();
        assert_eq!(r.regime(), Regime::UNLOADED);
        assert_eq!(r.end_displacement(), 0.0);
        let continuum = crate::problems::plate::continuum::solve_plate_continuum(
            no_poisson,
            Default::default(),
        )
        .unwrap();
        assert_eq!(continuum.end_displacement_mean, 0.0);
        assert_eq!(continuum.micro_zone_end, no_poisson.half_length);
        assert_eq!(plate.validity().expected_error(), Some(0.0));
        // No shear, no moment from friction: the contact pressure is P everywhere (it read 0.72 P
        // at the centre and 1.40 P at the edge, as if friction were saturated).
        let pressure = plate.contact_pressure();
        for x in [0.0, 2.5, 5.0, 9.9, 10.0] {
            assert!(
                (pressure.ratio(x) - 1.0).abs() < 1e-12,
                "x = {x}: {}",
                pressure.ratio(x)
            );
        }
        let slippery = PlateParams {
            friction: 1e-3,
            ..PlateParams::PAPER
        };
        let c = SqueezedPlate::new(slippery).unwrap().coulomb();
        assert_eq!(c.regime(), Regime::MACROSLIP);
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
        assert_eq!(r.regime(), Regime::MICROSLIP);
        let alpha = (0.91_f64 / 14_000.0).sqrt();
        let u = 0.3 * 1.3 * 10.0 * (alpha * 10.0).tanh() / (70_000.0 * alpha);
        assert!(((r.end_displacement() - u) / u).abs() < 1e-13);
    }

    #[test]
    fn displacement_and_shear_are_continuous_at_the_microslip_end() {
        let r = plate(1e6).regularized();
        assert_eq!(r.regime(), Regime::MICROSLIP_MACROSLIP);
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
