//! The Hertzian cylinder on a flat: the validated contact (Hertz's half-width and peak pressure,
//! (H1)-(H2)), its tangential load, and Mindlin's closed-form answer under plain Coulomb friction
//! ((H7)-(H9)). The regularized law's semi-analytic solution is in
//! [`super::regularized`]. Equation numbers are docs/theory.md's section "The Hertzian cylinder
//! (Cattaneo-Mindlin, regularized)".
//!
//! Coordinates: x along the contact from its centre, the contact is |x| <= a; the tangential
//! load Q pulls the cylinder towards +x. The shear traction q(x) is the one the cylinder exerts
//! on the flat (positive towards +x, integral Q), the slip s(x) the cylinder's surface
//! displacement minus the flat's (positive towards +x).

use std::f64::consts::PI;

use super::params::CylinderParam;
pub use super::params::CylinderParams;
use crate::kernel::params::{Domain, ParamError};
use crate::kernel::regime::{Regime, Zone};
use crate::problems::Solution;

/// A validated cylinder on its flat, with its load-independent constants (Hertz).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cylinder {
    params: CylinderParams,
    /// E* = E / (2 (1 - nu^2)) (MPa), (H1): the contact modulus of two identical bodies.
    contact_modulus: f64,
    /// Hertz half-width a = sqrt(4 P R / (pi E*)) (mm), (H2).
    half_width: f64,
    /// Hertz peak pressure p0 = 2 P / (pi a) (MPa), (H2).
    peak_pressure: f64,
}

/// A validated tangential line load, 0 <= Q <= mu P (N/mm).
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd)]
pub struct TangentialLoad(f64);

impl TangentialLoad {
    /// The load in N/mm (per mm of the cylinder's length).
    pub fn newtons_per_mm(self) -> f64 {
        self.0
    }
}

impl Cylinder {
    /// Validates every input against its domain ([`CylinderParam::spec`]), then the contact's
    /// half-width a < R.
    ///
    /// # Errors
    /// The first input out of its domain, in display order; then P when a >= R (P >= pi E* R / 4).
    ///
    /// # Examples
    /// ```
    /// use microslip_core::problems::cylinder::closed_form::{Cylinder, CylinderParams};
    /// let cylinder = Cylinder::new(CylinderParams::STEEL_PAD)?;
    /// assert!((cylinder.half_width() - 0.7428).abs() < 1e-4); // mm
    /// assert_eq!(cylinder.gross_slip_load(), 600.0); // mu P, N/mm
    /// let load = cylinder.load(300.0)?;
    /// let mindlin = cylinder.coulomb(load);
    /// assert!((mindlin.stick_half_width() / cylinder.half_width() - 0.5f64.sqrt()).abs() < 1e-15);
    /// assert_eq!(
    ///     cylinder.load(700.0).unwrap_err().to_string(),
    ///     "invalid Q = 700: must be in [0, 600] N/mm (gross slip at Q = mu P: \
    ///      the cylinder slides over the flat beyond it)"
    /// );
    /// # Ok::<(), microslip_core::ParamError>(())
    /// ```
    pub fn new(params: CylinderParams) -> Result<Cylinder, ParamError> {
        params.check()?;
        let nu = params.poisson;
        let contact_modulus = params.modulus / (2.0 * (1.0 - nu * nu));
        let half_width = (4.0 * params.normal_load * params.radius / (PI * contact_modulus)).sqrt();
        // A contact at least as wide as the cylinder is no Hertzian contact of a cylinder on a
        // flat (the half-plane theory wants a << R): refused, naming P, the load that widens it
        // (a = R at P = pi E* R / 4).
        if half_width >= params.radius {
            let widest = PI * contact_modulus * params.radius / 4.0;
            return Err(CylinderParam::NormalLoad.spec().above(
                params.normal_load,
                widest.next_down(),
                "pi E* R / 4, where Hertz's half-width a reaches R: no contact of a cylinder on a \
                 flat beyond it",
            ));
        }
        let peak_pressure = 2.0 * params.normal_load / (PI * half_width);
        Ok(Cylinder {
            params,
            contact_modulus,
            half_width,
            peak_pressure,
        })
    }

    /// The inputs this cylinder was built from.
    pub fn params(&self) -> CylinderParams {
        self.params
    }

    /// The same contact with another K_T (MPa/mm); validated like [`Cylinder::new`].
    ///
    /// # Errors
    /// [`ParamError`] when `kt` is outside the K_T domain.
    pub fn with_tangential_stiffness(&self, kt: f64) -> Result<Cylinder, ParamError> {
        Cylinder::new(CylinderParams {
            tangential_stiffness: kt,
            ..self.params
        })
    }

    /// Accepts `newtons_per_mm` as a tangential line load this contact carries: in Q's domain
    /// and at most the gross-slip load mu P. Q = mu P itself is accepted: the limit state in
    /// which the whole contact slides (c = 0), the end of every load axis.
    ///
    /// # Errors
    /// [`ParamError`] naming Q, its value and the range [0, mu P] (with why).
    pub fn load(&self, newtons_per_mm: f64) -> Result<TangentialLoad, ParamError> {
        let value = CylinderParam::TangentialLoad.check(newtons_per_mm)?;
        let gross = self.gross_slip_load();
        if value > gross {
            let spec = CylinderParam::TangentialLoad.spec();
            return Err(ParamError {
                field: spec.name,
                value,
                domain: Domain::NonNegative { max: gross },
                unit: spec.unit,
                reason: None,
            }
            .because("gross slip at Q = mu P: the cylinder slides over the flat beyond it"));
        }
        Ok(TangentialLoad(value))
    }

    /// The accepted load nearest to `newtons_per_mm`: 0 for negative values and NaN, mu P above
    /// it.
    pub fn clamped_load(&self, newtons_per_mm: f64) -> TangentialLoad {
        let value = if newtons_per_mm.is_nan() {
            0.0
        } else {
            newtons_per_mm
        };
        TangentialLoad(value.clamp(0.0, self.gross_slip_load()))
    }

    /// E* = E / (2 (1 - nu^2)) (MPa), (H1): 1/E* = (1 - nu^2)/E + (1 - nu^2)/E for the
    /// cylinder and the flat of the same material.
    pub fn contact_modulus(&self) -> f64 {
        self.contact_modulus
    }

    /// Hertz half-width a (mm), (H2).
    pub fn half_width(&self) -> f64 {
        self.half_width
    }

    /// Hertz peak pressure p0 (MPa), (H2).
    pub fn peak_pressure(&self) -> f64 {
        self.peak_pressure
    }

    /// Hertz pressure p(x) = p0 sqrt(1 - x^2/a^2) (MPa), 0 outside the contact.
    pub fn pressure_at(&self, x: f64) -> f64 {
        self.peak_pressure * edge_root(x / self.half_width)
    }

    /// Gross-slip load mu P (N/mm): the largest tangential line load the contact carries.
    pub fn gross_slip_load(&self) -> f64 {
        self.params.gross_slip_load()
    }

    /// The interface's stiffness relative to the bodies', kappa = K_T a / E* (-), (H6): with Q
    /// / mu P, the one group the normalized answer depends on.
    pub fn stiffness_group(&self) -> f64 {
        self.params.tangential_stiffness * self.half_width / self.contact_modulus
    }

    /// The slip scale mu p0 a / E* (mm), (H6): Mindlin's edge slip at gross slip.
    pub fn slip_scale(&self) -> f64 {
        self.params.friction * self.peak_pressure * self.half_width / self.contact_modulus
    }

    /// Mindlin's answer under plain Coulomb friction at `load` ((H7)-(H9)).
    pub fn coulomb(&self, load: TangentialLoad) -> MindlinState {
        MindlinState {
            cylinder: *self,
            load: load.0,
            stick: mindlin_stick_ratio(load.0 / self.gross_slip_load()),
        }
    }
}

/// sqrt(1 - t^2) for |t| < 1, 0 beyond: the Hertz pressure's shape.
pub(crate) fn edge_root(t: f64) -> f64 {
    (1.0 - t * t).max(0.0).sqrt()
}

/// Mindlin's stick-zone ratio c/a = sqrt(1 - Q / (mu P)) (H8), for a load ratio in [0, 1].
pub fn mindlin_stick_ratio(load_ratio: f64) -> f64 {
    (1.0 - load_ratio.clamp(0.0, 1.0)).sqrt()
}

/// Mindlin's slip in the slip zone, normalized by mu p0 a / E*, at |x| / a = `t` for a stick
/// zone c / a = `gamma` (H9): t sqrt(t^2 - gamma^2) - gamma^2 arcosh(t / gamma), 0 in the stick
/// zone.
pub fn mindlin_slip_normalized(t: f64, gamma: f64) -> f64 {
    let t = t.abs();
    if t <= gamma {
        return 0.0;
    }
    let root = (t * t - gamma * gamma).sqrt();
    // gamma^2 ln((t + root) / gamma), written so that gamma = 0 gives 0, not 0 * inf.
    let log_term = if gamma > 0.0 {
        gamma * gamma * ((t + root) / gamma).ln()
    } else {
        0.0
    };
    (t * root - log_term).max(0.0)
}

/// Mindlin's slip (H9) at |x| / a = `t` for Q / mu P = `load_ratio`, from the load ratio rather
/// than c / a (H9a): with rho = sqrt(t^2 - gamma^2) / t the slip is t^2 (rho - (1 - rho^2)
/// artanh rho), and t^2 - gamma^2 = Q / mu P - (1 - t^2) keeps its digits at a small load, where
/// gamma^2 = 1 - Q / mu P rounds to 1 and (H9) as written returned 0 (the edge slip 0 below Q ~
/// 1e-16 mu P, and a few digits only below 1e-5: the ratio to the regularized s(a) came out
/// wrong by orders of magnitude there).
pub fn mindlin_slip_at_load(t: f64, load_ratio: f64) -> f64 {
    let t = t.abs().min(1.0);
    let excess = load_ratio.clamp(0.0, 1.0) - (1.0 - t) * (1.0 + t);
    if excess <= 0.0 || t == 0.0 {
        return 0.0;
    }
    t * t * mindlin_slip_shape((excess.sqrt() / t).min(1.0))
}

/// rho - (1 - rho^2) artanh rho = 2 sum_{k >= 1} rho^(2k + 1) / ((2k - 1)(2k + 1)) (H9a): by the
/// series below rho = 1/2, where the closed form cancels its O(rho) terms (30 terms, each at
/// most a quarter of the last); 1 at rho = 1 (gamma = 0).
fn mindlin_slip_shape(rho: f64) -> f64 {
    if rho >= 1.0 {
        return 1.0;
    }
    if rho < 0.5 {
        let square = rho * rho;
        let mut power = rho * square;
        let mut sum = 0.0;
        for k in 1..31 {
            sum += 2.0 * power / ((2 * k - 1) * (2 * k + 1)) as f64;
            power *= square;
        }
        return sum;
    }
    rho - (1.0 - rho * rho) * rho.atanh()
}

/// Mindlin's answer (plain Coulomb, K_T -> infinity) at one tangential load: a stick zone |x| <
/// c = a sqrt(1 - Q / mu P) at the centre, sliding at q = mu p beyond.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MindlinState {
    cylinder: Cylinder,
    /// Q (N/mm).
    load: f64,
    /// c / a.
    stick: f64,
}

impl MindlinState {
    /// The contact it is of.
    pub fn cylinder(&self) -> &Cylinder {
        &self.cylinder
    }

    /// Tangential line load Q (N/mm).
    pub fn load(&self) -> f64 {
        self.load
    }

    /// Stick-zone half-width c (mm), (H8).
    pub fn stick_half_width(&self) -> f64 {
        self.stick * self.cylinder.half_width
    }

    /// c / a (-).
    pub fn stick_ratio(&self) -> f64 {
        self.stick
    }

    /// Shear traction q(x) (MPa), (H7): mu p(x) in the slip zone, mu p0 (sqrt(1 - x^2/a^2) - (c/a)
    /// sqrt(1 - x^2/c^2)) in the stick zone; 0 outside the contact and without load.
    pub fn shear_at(&self, x: f64) -> f64 {
        if self.load == 0.0 {
            return 0.0;
        }
        let (a, mu_p0) = (
            self.cylinder.half_width,
            self.cylinder.params.friction * self.cylinder.peak_pressure,
        );
        let t = x / a;
        let stick_part = if self.stick > 0.0 {
            self.stick * edge_root(t / self.stick)
        } else {
            0.0
        };
        mu_p0 * (edge_root(t) - stick_part)
    }

    /// Relative tangential slip s(x) (mm), (H9): 0 in the stick zone, positive (towards +x)
    /// and growing to the edges in the slip zones; taken at the edge beyond the contact.
    pub fn slip_at(&self, x: f64) -> f64 {
        let t = (x / self.cylinder.half_width).abs().min(1.0);
        self.cylinder.slip_scale() * mindlin_slip_at_load(t, self.load_ratio())
    }

    /// The slip at the contact's edge s(a) (mm): the fretting slip amplitude.
    pub fn edge_slip(&self) -> f64 {
        self.slip_at(self.cylinder.half_width)
    }

    /// The slip at the centre s(0) (mm): 0 (it sticks) below gross slip.
    pub fn centre_slip(&self) -> f64 {
        self.slip_at(0.0)
    }

    /// The largest shear over mu p0 (-): sqrt(1 - c^2/a^2) = sqrt(Q / mu P), at the stick
    /// zone's edge; from Q / mu P, since 1 - c^2/a^2 rounds to 0 at a small load.
    pub fn peak_shear_ratio(&self) -> f64 {
        self.load_ratio().sqrt()
    }

    /// Q / mu P (-).
    fn load_ratio(&self) -> f64 {
        (self.load / self.cylinder.gross_slip_load()).clamp(0.0, 1.0)
    }

    /// Unloaded, stick + slip (stick+macroslip from the centre outward), or the whole contact
    /// sliding at Q = mu P.
    pub fn regime(&self) -> Regime {
        if self.load == 0.0 {
            Regime::UNLOADED
        } else if self.stick == 0.0 {
            Regime::MACROSLIP
        } else {
            Regime::from_zones(&[Zone::Stick, Zone::Macroslip])
        }
    }
}

impl Solution for MindlinState {
    /// The edge slip s(a) (mm).
    fn response(&self) -> f64 {
        self.edge_slip()
    }

    fn regime(&self) -> Regime {
        MindlinState::regime(self)
    }

    /// The stick zone's half-width c (mm).
    fn zone_end(&self) -> f64 {
        self.stick_half_width()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pad() -> Cylinder {
        Cylinder::new(CylinderParams::STEEL_PAD).unwrap()
    }

    /// Hertz by hand for the bundled pad: E* = 210000 / 1.82 = 115384.6 MPa, a = sqrt(4 * 1000 *
    /// 50 / (pi * 115384.6)) = 0.74279 mm, p0 = 2000 / (pi a) = 857.1 MPa; the pressure carries P.
    #[test]
    fn hertz_of_the_bundled_pad_by_hand() {
        let c = pad();
        assert!((c.contact_modulus() - 210_000.0 / 1.82).abs() < 1e-9);
        let a = (200_000.0 / (PI * 210_000.0 / 1.82)).sqrt();
        assert!((c.half_width() - a).abs() < 1e-14);
        assert!(
            (c.half_width() - 0.742_79).abs() < 1e-5,
            "{}",
            c.half_width()
        );
        assert!(
            (c.peak_pressure() - 857.1).abs() < 0.05,
            "{}",
            c.peak_pressure()
        );
        // p0 = a E* / (2 R) as well (the curvature condition (H2)).
        assert!((c.peak_pressure() - a * c.contact_modulus() / 100.0).abs() < 1e-9);
        // Integral of p over the contact (Simpson-free: the half-ellipse area pi a p0 / 2) = P.
        assert!((PI * c.half_width() * c.peak_pressure() / 2.0 - 1000.0).abs() < 1e-9);
    }

    #[test]
    fn mindlin_carries_q_and_is_bounded_by_mu_p() {
        let c = pad();
        for ratio in [0.0, 0.1, 0.5, 0.9, 0.999, 1.0] {
            let state = c.coulomb(c.load(ratio * c.gross_slip_load()).unwrap());
            // Integral of q by the trapezoidal rule in the angle (x = a sin t): smooth integrand.
            let n = 20_000;
            let a = c.half_width();
            let mut total = 0.0;
            for i in 0..n {
                let t = -PI / 2.0 + PI * (i as f64 + 0.5) / n as f64;
                let x = a * t.sin();
                total += state.shear_at(x) * a * t.cos() * PI / n as f64;
                assert!(state.shear_at(x) <= 0.6 * c.pressure_at(x) + 1e-9);
                assert!(state.shear_at(x) >= -1e-12);
            }
            assert!((total - ratio * 600.0).abs() < 1e-3, "{ratio}: {total}");
        }
    }

    #[test]
    fn mindlin_slip_is_zero_in_the_stick_zone_and_grows_to_the_edge() {
        let c = pad();
        let state = c.coulomb(c.load(300.0).unwrap());
        let stick = state.stick_half_width();
        assert_eq!(state.slip_at(0.5 * stick), 0.0);
        assert_eq!(state.centre_slip(), 0.0);
        let mut last = 0.0;
        for i in 1..=100 {
            let x = stick + (c.half_width() - stick) * i as f64 / 100.0;
            let s = state.slip_at(x);
            assert!(s > last);
            assert_eq!(s, state.slip_at(-x));
            last = s;
        }
        // At gross slip: s(a) = mu p0 a / E*, and no NaN from the vanishing stick zone.
        let gross = c.coulomb(c.load(600.0).unwrap());
        assert_eq!(gross.stick_half_width(), 0.0);
        assert!((gross.edge_slip() - c.slip_scale()).abs() < 1e-15 * c.slip_scale());
        assert_eq!(gross.regime(), Regime::MACROSLIP);
        assert_eq!(c.coulomb(c.load(0.0).unwrap()).regime(), Regime::UNLOADED);
        assert_eq!(c.coulomb(c.load(0.0).unwrap()).edge_slip(), 0.0);
    }

    /// (H9) differentiated: ds/dx = (2 / (pi E*)) PV integral q(t) / (x - t) dt in the slip zone;
    /// checked by differences of the closed form against the Hilbert transform of (H7), which is
    /// pi mu p0 / a sqrt(x^2 - c^2) there (pi x from the contact's half-ellipse, minus pi (x -
    /// sqrt(x^2 - c^2)) from the stick zone's).
    #[test]
    fn mindlin_slip_gradient_is_the_kernel_s_of_its_shear() {
        let c = pad();
        let state = c.coulomb(c.load(420.0).unwrap());
        let (a, cc) = (c.half_width(), state.stick_half_width());
        let mu_p0 = 0.6 * c.peak_pressure();
        for x in [cc + 0.1 * (a - cc), cc + 0.5 * (a - cc), 0.95 * a] {
            let h = 1e-6 * a;
            let numeric = (state.slip_at(x + h) - state.slip_at(x - h)) / (2.0 * h);
            let hilbert = PI * mu_p0 / a * (x * x - cc * cc).sqrt();
            let expected = 2.0 / (PI * c.contact_modulus()) * hilbert;
            assert!(
                (numeric - expected).abs() < 1e-6 * expected.abs(),
                "{x}: {numeric} vs {expected}"
            );
        }
    }

    #[test]
    fn loads_beyond_gross_slip_negative_or_nan_are_refused() {
        let c = pad();
        assert!(c.load(600.0).is_ok());
        assert!(c.load(600.0_f64.next_up()).is_err());
        assert_eq!(
            c.load(-1.0).unwrap_err().to_string(),
            "invalid Q = -1: must be >= 0 and finite (N/mm)"
        );
        assert_eq!(c.load(f64::NAN).unwrap_err().field, "Q");
        assert_eq!(c.clamped_load(f64::NAN).newtons_per_mm(), 0.0);
        assert_eq!(c.clamped_load(1e9).newtons_per_mm(), 600.0);
    }

    /// (H9a): the slip from the load ratio is (H9) where (H9) keeps its digits (Q / mu P = 0.3,
    /// 0.9, at the edge and inside the slip zone, across the series' switch at rho = 1/2), and
    /// at a small load it is the series' (2/3) (Q / mu P)^(3/2) at the edge, where (H9) from a
    /// rounded c / a gave 0 (Q = 1e-17 mu P) or lost every digit; the peak shear is sqrt(Q /
    /// mu P) there.
    #[test]
    fn mindlin_s_slip_keeps_its_digits_at_small_loads() {
        for (q, t) in [(0.3, 1.0), (0.3, 0.9), (0.9, 0.5), (0.9, 1.0), (0.2, 0.99)] {
            let gamma = mindlin_stick_ratio(q);
            let (from_load, from_zone) = (
                mindlin_slip_at_load(t, q),
                mindlin_slip_normalized(t, gamma),
            );
            assert!(
                (from_load / from_zone - 1.0).abs() < 1e-12,
                "{q} {t}: {from_load} {from_zone}"
            );
        }
        assert_eq!(mindlin_slip_at_load(1.0, 1.0), 1.0);
        assert_eq!(mindlin_slip_at_load(0.5, 0.3), 0.0);
        for q in [1e-6_f64, 1e-17, 1e-200] {
            let edge = mindlin_slip_at_load(1.0, q);
            let series = 2.0 / 3.0 * q.powf(1.5) * (1.0 + 0.2 * q);
            assert!((edge / series - 1.0).abs() < 1e-12, "{q}: {edge}");
        }
        let pad = Cylinder::new(CylinderParams::STEEL_PAD).unwrap();
        let small = pad.coulomb(pad.load(1e-17 * pad.gross_slip_load()).unwrap());
        assert!((small.peak_shear_ratio() / 1e-17f64.sqrt() - 1.0).abs() < 1e-12);
        assert!(small.edge_slip() > 0.0);
    }
}
