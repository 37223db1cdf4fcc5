//! Twin cantilever beams pressed together and bent by equal tip forces (paper section 2.1).
//!
//! Two identical cantilevers (length L, width b, height 2h), clamped at x = 0, are pressed together by
//! a uniform interface pressure P; each carries a transverse tip force F. Euler-Bernoulli kinematics
//! with axial stretching, no shear strain. The derivations, and where the paper's print differs, are in
//! `docs/theory.md` ("Twin beams"); every formula below names its equation there as (B1), (B2), ...
//!
//! Conventions (lower beam): x from the clamp, deflection w in the direction of F, interface slip s(x)
//! of the upper beam relative to the lower one, interface shear tau(x) >= 0 acting on the lower beam.

pub use super::params::{BeamTheory, BeamTheoryError, TwinBeamsParams};
use crate::kernel::hyperbolic::{
    cosh_rem0, cosh_rem2, cosh_sinh_ratio, inv_sinh, one_minus_sech, sinh_ratio, sinh_rem1,
    sinh_rem3, sinhc,
};
use crate::kernel::params::ParamError;
use crate::kernel::regime::Regime;
use crate::kernel::solve::{find_root_in_bracket, find_root_newton};
use crate::problems::{BeamParam, Solution};

/// Timoshenko's shear coefficient of a rectangular section, kappa = 5/6 (B13).
const SHEAR_COEFFICIENT: f64 = 5.0 / 6.0;

/// A validated twin-beam system with its load-independent derived constants.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwinBeams {
    params: TwinBeamsParams,
    /// k = 2 sqrt(K_T / (E h)) (1/mm): inverse length of the microslip boundary layer (B5).
    k: f64,
}

/// A validated tip force F >= 0 (N), applied to each beam.
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd)]
pub struct TipForce(f64);

impl TipForce {
    /// Accepts F in the force domain, 0 to 1e12 N.
    ///
    /// # Errors
    /// [`ParamError`] for a negative, NaN, infinite or too large force.
    pub fn new(newtons: f64) -> Result<Self, ParamError> {
        BeamParam::Force.check(newtons).map(TipForce)
    }

    /// The accepted force nearest to `newtons` (N): itself when accepted, 0 for negative values and
    /// NaN, the largest accepted force above it.
    pub fn clamped(newtons: f64) -> Self {
        TipForce(BeamParam::Force.spec().domain.clamp(newtons))
    }

    /// The force in N.
    pub fn newtons(self) -> f64 {
        self.0
    }
}

impl TwinBeams {
    /// Validates every input against its domain ([`BeamParam::spec`]): finite, positive, bounded.
    ///
    /// # Errors
    /// The first input out of its domain (see [`BeamParam::spec`]), in display order.
    ///
    /// # Examples
    /// ```
    /// use microslip_core::{TipForce, TwinBeams, TwinBeamsParams};
    /// let beams = TwinBeams::new(TwinBeamsParams::PAPER)?;
    /// assert_eq!(beams.threshold_force(), 80.0); // mu P b L, N
    /// let state = beams.regularized(TipForce::new(100.0)?);
    /// assert!((state.micro_zone_end() - 17.3095).abs() < 1e-4); // X, mm
    /// let bad = TwinBeamsParams { friction: -0.3, ..TwinBeamsParams::PAPER };
    /// assert_eq!(
    ///     TwinBeams::new(bad).unwrap_err().to_string(),
    ///     "invalid mu = -0.3: must be > 0 and finite (dimensionless)"
    /// );
    /// # Ok::<(), microslip_core::ParamError>(())
    /// ```
    pub fn new(params: TwinBeamsParams) -> Result<Self, ParamError> {
        let mut fields = params;
        for param in BeamParam::ALL {
            if let Some(&mut value) = fields.value_mut(param) {
                param.check(value)?;
            }
        }
        let k = 2.0
            * (params.tangential_stiffness / (params.youngs_modulus * params.half_height)).sqrt();
        Ok(TwinBeams { params, k })
    }

    /// The inputs this system was built from.
    pub fn params(&self) -> TwinBeamsParams {
        self.params
    }

    /// The same system with another K_T (MPa/mm); validated like [`TwinBeams::new`].
    ///
    /// # Errors
    /// [`ParamError`] when `kt` is outside the K_T domain.
    pub fn with_tangential_stiffness(&self, kt: f64) -> Result<Self, ParamError> {
        TwinBeams::new(TwinBeamsParams {
            tangential_stiffness: kt,
            ..self.params
        })
    }

    /// Inverse boundary-layer length k = 2 sqrt(K_T / (E h)) (1/mm), eq. (B5).
    pub fn decay_rate(&self) -> f64 {
        self.k
    }

    /// Coulomb stress mu P (MPa): the interface shear at which sliding starts.
    pub fn coulomb_stress(&self) -> f64 {
        self.params.friction * self.params.pressure
    }

    /// Saturation slip mu P / K_T (mm): the elastic slip at which the regularized law saturates.
    pub fn saturation_slip(&self) -> f64 {
        self.coulomb_stress() / self.params.tangential_stiffness
    }

    /// Interface shear of the bonded pair, 3F / (4bh) (MPa), eq. (B2): what a rigid (stuck) interface
    /// carries, uniform along x.
    fn bonded_shear(&self, force: f64) -> f64 {
        3.0 * force / (4.0 * self.params.width * self.params.half_height)
    }

    /// tau_b - mu P = 3 (F - F_thre) / (4 b h) (MPa): the shear the interface cannot carry, positive
    /// exactly when F > F_thre.
    fn excess_shear(&self, force: f64) -> f64 {
        self.bonded_shear(force - self.threshold_force())
    }

    /// Coulomb threshold F_thre = 4 mu b h P / 3 (N), eq. (B3): below it the pair sticks.
    pub fn threshold_force(&self) -> f64 {
        let p = &self.params;
        4.0 * p.friction * p.width * p.half_height * p.pressure / 3.0
    }

    /// Regularized law: the force F_1 = F_thre / (1 - sech kL) (N) at which macroslip first appears,
    /// eq. (B7). It appears at the free end, x = L ([`TwinBeams::first_macroslip_position`]).
    pub fn first_macroslip_force(&self) -> f64 {
        self.threshold_force() / one_minus_sech(self.k * self.params.length)
    }

    /// Where macroslip first appears as F grows past F_1: the free end x = L (mm), because the
    /// all-microslip shear stress (B6) increases monotonically from the clamp to the tip.
    pub fn first_macroslip_position(&self) -> f64 {
        self.params.length
    }

    /// Tip deflection (mm) that transverse shear strain adds to each beam, F L / (kappa G b 2h) with
    /// kappa = 5/6 and G = E / (2 (1 + nu)), eq. (B13), whatever [`BeamTheory`] is chosen (the
    /// Timoshenko deflections include it, the Euler-Bernoulli ones do not). The same under every
    /// friction law: the interface shear acts along the beams' axis, so it adds axial force and
    /// moment but no transverse shear force, which is F in each beam.
    pub fn shear_deflection(&self, force: TipForce) -> f64 {
        force.0 * self.params.length * self.shear_compliance()
    }

    /// 1 / (kappa G b 2h) (1/N): shear deflection per unit force and unit length.
    fn shear_compliance(&self) -> f64 {
        let p = &self.params;
        let shear_modulus = p.youngs_modulus / (2.0 * (1.0 + p.poisson));
        1.0 / (SHEAR_COEFFICIENT * shear_modulus * p.width * 2.0 * p.half_height)
    }

    /// The shear deflection F x / (kappa G b 2h) at x under the chosen theory (0 for
    /// Euler-Bernoulli).
    fn theory_shear(&self, force: f64, x: f64) -> f64 {
        match self.params.theory {
            BeamTheory::EulerBernoulli => 0.0,
            BeamTheory::Timoshenko => force * x * self.shear_compliance(),
        }
    }

    /// The same beams under another theory.
    pub fn with_theory(&self, theory: BeamTheory) -> TwinBeams {
        TwinBeams {
            params: TwinBeamsParams {
                theory,
                ..self.params
            },
            k: self.k,
        }
    }

    /// Solution under the plain Coulomb law at tip force `force`.
    pub fn coulomb(&self, force: TipForce) -> CoulombBeams {
        CoulombBeams {
            beams: *self,
            force: force.0,
            slides: force.0 > self.threshold_force(),
        }
    }

    /// Solution under the regularized Coulomb law at tip force `force`.
    pub fn regularized(&self, force: TipForce) -> RegularizedBeams {
        let f = force.0;
        let p = &self.params;
        let bonded = self.bonded_shear(f);
        let lambda = self.k * p.length;
        let has_macroslip = f > self.first_macroslip_force();
        let (micro_end, macro_length, end_shear) = if has_macroslip {
            let (x, a) = self.microslip_boundary(f);
            (x, a, self.coulomb_stress())
        } else {
            // (B6): tau(L) = tau_b (1 - sech kL), the shear at the free end with no macroslip.
            (p.length, 0.0, bonded * one_minus_sech(lambda))
        };
        let kx = self.k * micro_end;
        // C k = tau'(0), the shear gradient at the clamp, (B9); stable for any kX > 0.
        let slope_at_clamp = if micro_end > 0.0 {
            self.k * (end_shear * inv_sinh(kx) + bonded * (0.5 * kx).tanh())
        } else {
            0.0
        };
        let mut state = RegularizedBeams {
            beams: *self,
            force: f,
            has_macroslip,
            micro_end,
            macro_length,
            end_shear,
            bonded_shear: bonded,
            slope_at_clamp,
            total_shear: 0.0,
            moments_at_end: [0.0; 3],
        };
        state.moments_at_end = state.micro_moments(micro_end);
        state.total_shear = state.moments_at_end[0] + self.coulomb_stress() * macro_length;
        state
    }

    /// Solves (B8) for the end X of the microslip zone when F > F_1, and the macroslip length L - X
    /// (mm, mm).
    ///
    /// With z = kX, lambda = kL and q = F_thre / (F - F_thre), the condition that the slip gradient is
    /// continuous at X reads g(z) = q / sinh z - tanh(z/2) - (lambda - z) = 0. g is positive below its
    /// unique root and negative above it up to z = lambda when F > F_1 (docs/theory.md). The smaller
    /// of X and L - X is the unknown: z when the root lies in the lower half [.., lambda / 2], else
    /// y = lambda - z in [0, lambda / 2]; so each is known to 1e-12 relative, and neither is a
    /// difference of nearly equal lengths.
    fn microslip_boundary(&self, force: f64) -> (f64, f64) {
        let length = self.params.length;
        let lambda = self.k * length;
        let q = self.threshold_force() / (force - self.threshold_force());
        // q / sinh z - tanh(z / 2), with m = expm1(-z) (so e^-z = 1 + m): 1/sinh z =
        // -2 (1 + m) / (m (2 + m)) and tanh(z/2) = -m / (2 + m). One expm1 per evaluation, exact for
        // small and large z alike.
        let shear_terms = |z: f64| {
            let m = (-z).exp_m1();
            (-2.0 * q * (1.0 + m) / m + m) / (2.0 + m)
        };
        let g = |z: f64| shear_terms(z) - (lambda - z);
        // g'(z) = cosh z (cosh z - r) / sinh^2 z, r = 1 + q; with e = e^-z:
        // (1 + e^2)((1 - e)^2 - 2 q e) / (1 - e^2)^2.
        let dg = |z: f64| {
            let m = (-z).exp_m1();
            let e = 1.0 + m;
            (1.0 + e * e) * (m * m - 2.0 * q * e) / (m * m * (2.0 + m) * (2.0 + m))
        };
        // For z <= 1, sinh z <= sinh(1) z < 1.1753 z, so g(z) >= q / (1.1753 z) - 1/2 - lambda, which is
        // positive at this lower end: a guaranteed bracket without any search.
        let lower = 0.5 * 1f64.min(lambda).min(q / (1.1753 * (lambda + 0.5)));
        if lower <= f64::MIN_POSITIVE {
            // F is so far above F_thre that X underflows: the whole interface is in macroslip.
            return (0.0, length);
        }
        let half = 0.5 * lambda;
        if lower < half && g(half) < 0.0 {
            // Start from the small-z approximation q/z + z/2 = lambda (exact as z -> 0), which is
            // also close where it is not exact: Newton then needs a handful of steps.
            let discriminant = (lambda * lambda - 2.0 * q).max(0.0);
            let start = 2.0 * q / (lambda + discriminant.sqrt());
            let z = find_root_newton(g, dg, start, lower, half);
            (z / self.k, length - z / self.k)
        } else {
            // g(lambda - y) with the last term written as y itself.
            let from_tip = |y: f64| shear_terms(lambda - y) - y;
            let y = find_root_in_bracket(from_tip, 0.0, lambda - lower.max(half));
            (length - y / self.k, y / self.k)
        }
    }
}

/// Twin beams under the plain Coulomb law at one tip force.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoulombBeams {
    beams: TwinBeams,
    force: f64,
    slides: bool,
}

impl CoulombBeams {
    /// End of the stick zone (mm): the whole interface L while it sticks, 0 once it slides (under
    /// the plain law the twin-beam interface slides all at once).
    pub fn stick_end(&self) -> f64 {
        if self.slides {
            0.0
        } else {
            self.beams.params.length
        }
    }

    /// Stick below or at F_thre, macroslip (the whole interface at once) above; unloaded at F = 0.
    pub fn regime(&self) -> Regime {
        if self.force == 0.0 {
            Regime::UNLOADED
        } else if self.slides {
            Regime::MACROSLIP
        } else {
            Regime::STICK
        }
    }

    /// Interface shear stress tau(x) (MPa): uniform 3F/(4bh) in stick, mu P in slip.
    pub fn shear_stress(&self, _x: f64) -> f64 {
        if self.slides {
            self.beams.coulomb_stress()
        } else {
            self.beams.bonded_shear(self.force)
        }
    }

    /// Interface slip s(x) (mm), eq. (B4): zero in stick, 2 (tau_b - mu P)(L^2 - (L - x)^2) / (E h)
    /// in slip.
    pub fn slip(&self, x: f64) -> f64 {
        if !self.slides {
            return 0.0;
        }
        let p = &self.beams.params;
        // tau_b - mu P = 3 (F - F_thre) / (4 b h): positive whenever F > F_thre, which the
        // difference of the two rounded stresses need not be.
        let excess = self.beams.excess_shear(self.force);
        // L^2 - (L - x)^2 = x (2L - x): no difference of squares.
        let x = x.clamp(0.0, p.length);
        2.0 * excess * x * (2.0 * p.length - x) / (p.youngs_modulus * p.half_height)
    }

    /// Deflection w(x) (mm), eq. (B3)/(B4): the bonded 4h-high beam under 2F in stick; each 2h-high
    /// beam under the reduced tip force F - mu P b h in slip.
    pub fn deflection(&self, x: f64) -> f64 {
        let p = &self.beams.params;
        let shape = 3.0 * p.length * x * x - x * x * x;
        let bh3 = p.width * p.half_height.powi(3);
        let bending = if self.slides {
            (self.force - self.beams.coulomb_stress() * p.width * p.half_height) * shape
                / (4.0 * p.youngs_modulus * bh3)
        } else {
            self.force * shape / (16.0 * p.youngs_modulus * bh3)
        };
        bending + self.beams.theory_shear(self.force, x)
    }

    /// Tip deflection w(L) (mm).
    pub fn tip_deflection(&self) -> f64 {
        self.deflection(self.beams.params.length)
    }
}

/// Twin beams under the regularized Coulomb law at one tip force.
///
/// Holds the few numbers that fix the whole solution: the microslip zone [0, X], the shear at X, the
/// shear gradient at the clamp and the total interface shear force per unit width.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RegularizedBeams {
    beams: TwinBeams,
    force: f64,
    has_macroslip: bool,
    /// X (mm): end of the microslip zone; L when there is no macroslip.
    micro_end: f64,
    /// L - X (mm), solved for directly when it is the smaller of the two; 0 without macroslip.
    macro_length: f64,
    /// tau(X) (MPa): mu P with macroslip, tau_b (1 - sech kL) without.
    end_shear: f64,
    /// tau_b = 3F/(4bh) (MPa), the particular solution of (B5).
    bonded_shear: f64,
    /// tau'(0) (MPa/mm).
    slope_at_clamp: f64,
    /// T(0) = integral of tau over [0, L] (N/mm^2 * mm).
    total_shear: f64,
    /// micro_moments(X), kept because w(L) and every w(x) beyond X need them again.
    moments_at_end: [f64; 3],
}

impl RegularizedBeams {
    /// Microslip alone up to F_1; microslip near the clamp plus macroslip near the tip beyond;
    /// unloaded at F = 0 (no shear, no slip: not "microslip").
    pub fn regime(&self) -> Regime {
        if self.force == 0.0 {
            Regime::UNLOADED
        } else if self.has_macroslip {
            Regime::MICROSLIP_MACROSLIP
        } else {
            Regime::MICROSLIP
        }
    }

    /// End X of the microslip zone, measured from the clamp (mm); L when nothing slides.
    pub fn micro_zone_end(&self) -> f64 {
        self.micro_end
    }

    /// Length L - X of the macroslip zone at the free end (mm); 0 without macroslip. Solved for
    /// directly, so it keeps its relative precision when X is within round-off of L.
    pub fn macroslip_length(&self) -> f64 {
        self.macro_length
    }

    /// The tip force this solution is for (N).
    pub fn force(&self) -> f64 {
        self.force
    }

    /// Interface shear stress tau(x) (MPa), eqs. (B6) and (B9); mu P in the macroslip zone.
    pub fn shear_stress(&self, x: f64) -> f64 {
        if x >= self.micro_end {
            return self.end_shear;
        }
        let k = self.beams.k;
        let kx = k * x.max(0.0);
        if kx < 1.0 {
            // Natural basis tau = -tau_b (cosh kx - 1) + C sinh kx: every term is small when k is.
            -self.bonded_shear * kx * kx * cosh_rem0(kx) + self.slope_at_clamp * x * sinhc(kx)
        } else {
            // Boundary-layer basis: ratios of sinh that cannot overflow.
            let kend = k * self.micro_end;
            self.bonded_shear * (1.0 - sinh_ratio(kend - kx, kend))
                + (self.end_shear - self.bonded_shear) * sinh_ratio(kx, kend)
        }
    }

    /// Shear gradient tau'(x) (MPa/mm) inside the microslip zone.
    fn shear_gradient(&self, x: f64) -> f64 {
        let k = self.beams.k;
        let kx = k * x;
        if kx < 1.0 {
            -self.bonded_shear * k * kx.sinh() + self.slope_at_clamp * kx.cosh()
        } else {
            let kend = k * self.micro_end;
            k * (self.bonded_shear * cosh_sinh_ratio(kend - kx, kend)
                + (self.end_shear - self.bonded_shear) * cosh_sinh_ratio(kx, kend))
        }
    }

    /// Interface slip s(x) (mm): tau / K_T in microslip; (B10) in macroslip.
    pub fn slip(&self, x: f64) -> f64 {
        let p = &self.beams.params;
        if x <= self.micro_end {
            return self.shear_stress(x) / p.tangential_stiffness;
        }
        // (L - X)^2 - (L - x)^2 = (a - b)(a + b) with a = L - X, b = L - x.
        let excess = self.beams.excess_shear(self.force);
        let (a, b) = (
            self.macro_length,
            (p.length - x).clamp(0.0, self.macro_length),
        );
        self.beams.saturation_slip()
            + 2.0 * excess * (a - b) * (a + b) / (p.youngs_modulus * p.half_height)
    }

    /// Moments m_n = integral over [0, y] of (y - xi)^n tau(xi) d xi, n = 0, 1, 2, for 0 <= y <= X
    /// (MPa mm^(n+1)), eq. (B12). Two evaluations, each free of cancellation in its range.
    fn micro_moments(&self, y: f64) -> [f64; 3] {
        if y <= 0.0 {
            return [0.0; 3];
        }
        let k = self.beams.k;
        let z = k * y;
        let tb = self.bonded_shear;
        let ck = self.slope_at_clamp;
        if z < 1.0 {
            // Termwise integrals of -tau_b (cosh kxi - 1) + C sinh kxi, as Taylor-remainder functions.
            let k2 = k * k;
            [
                -tb * k2 * y.powi(3) * sinh_rem1(z) + ck * y * y * cosh_rem0(z),
                -tb * k2 * y.powi(4) * cosh_rem2(z) + ck * y.powi(3) * sinh_rem1(z),
                -2.0 * tb * k2 * y.powi(5) * sinh_rem3(z) + 2.0 * ck * y.powi(4) * cosh_rem2(z),
            ]
        } else {
            // Integration by parts with tau = tau_b + tau'' / k^2 leaves only boundary values.
            let k2 = k * k;
            let m0 = tb * y + (self.shear_gradient(y) - ck) / k2;
            let m1 = tb * y * y / 2.0 + (self.shear_stress(y) - y * ck) / k2;
            let m2 = tb * y.powi(3) / 3.0 + (2.0 * m0 - y * y * ck) / k2;
            [m0, m1, m2]
        }
    }

    /// Deflection w(x) (mm) for 0 <= x <= L, eq. (B11):
    /// w = 3/(2Ebh^3) [F (L x^2/2 - x^3/6) - b h (T(0) x^2/2 - Q(x))], Q(x) = 1/2 int_0^x (x-xi)^2 tau.
    pub fn deflection(&self, x: f64) -> f64 {
        let p = &self.beams.params;
        let x = x.clamp(0.0, p.length);
        let y = x.min(self.micro_end);
        // The part of [0, x] in macroslip; at the tip, the macroslip length itself.
        let a = if x >= p.length {
            self.macro_length
        } else {
            x - y
        };
        let [m0, m1, m2] = if y == self.micro_end {
            self.moments_at_end
        } else {
            self.micro_moments(y)
        };
        let mut q = 0.5 * (a * a * m0 + 2.0 * a * m1 + m2);
        if a > 0.0 {
            q += self.beams.coulomb_stress() * a.powi(3) / 6.0;
        }
        let bh = p.width * p.half_height;
        let bending = self.force * (p.length * x * x / 2.0 - x.powi(3) / 6.0);
        let interface = bh * (self.total_shear * x * x / 2.0 - q);
        3.0 * (bending - interface) / (2.0 * p.youngs_modulus * bh * p.half_height * p.half_height)
            + self.beams.theory_shear(self.force, x)
    }

    /// Tip deflection w(L) (mm).
    pub fn tip_deflection(&self) -> f64 {
        self.deflection(self.beams.params.length)
    }
}

impl Solution for CoulombBeams {
    fn response(&self) -> f64 {
        self.tip_deflection()
    }

    fn regime(&self) -> Regime {
        CoulombBeams::regime(self)
    }

    fn zone_end(&self) -> f64 {
        self.stick_end()
    }
}

impl Solution for RegularizedBeams {
    fn response(&self) -> f64 {
        self.tip_deflection()
    }

    fn regime(&self) -> Regime {
        RegularizedBeams::regime(self)
    }

    fn zone_end(&self) -> f64 {
        self.micro_zone_end()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn paper() -> TwinBeams {
        TwinBeams::new(TwinBeamsParams::PAPER).unwrap()
    }

    fn force(f: f64) -> TipForce {
        TipForce::new(f).unwrap()
    }

    #[test]
    fn paper_thresholds_match_hand_computation() {
        let beams = paper();
        // F_thre = 4 * 0.3 * 20 * 10 * 1 / 3 = 80 N.
        assert!((beams.threshold_force() - 80.0).abs() < 1e-12);
        // k L = 2 sqrt(600 / 2.1e6) * 200 = 6.7612340...; F_1 = 80 / (1 - sech(kL)).
        let kl = 2.0 * (600.0_f64 / 2.1e6).sqrt() * 200.0;
        assert!((beams.first_macroslip_force() - 80.0 / (1.0 - 1.0 / kl.cosh())).abs() < 1e-10);
    }

    #[test]
    fn coulomb_tip_deflection_matches_strength_of_materials() {
        let beams = paper();
        // Bonded pair: 2F on I = b (4h)^3 / 12, w(L) = 2F L^3 / (3 E I).
        let i_bonded = 20.0 * 40.0_f64.powi(3) / 12.0;
        let w = 2.0 * 50.0 * 200.0_f64.powi(3) / (3.0 * 210_000.0 * i_bonded);
        assert!((beams.coulomb(force(50.0)).tip_deflection() - w).abs() < 1e-15);
        // Sliding: one beam (I = b (2h)^3/12) under F minus the friction couple mu P b h per unit length
        // of lever, i.e. the tip force F - mu P b h.
        let i_single = 20.0 * 20.0_f64.powi(3) / 12.0;
        let w = (150.0 - 0.3 * 20.0 * 10.0) * 200.0_f64.powi(3) / (3.0 * 210_000.0 * i_single);
        assert!((beams.coulomb(force(150.0)).tip_deflection() - w).abs() < 1e-14);
    }

    #[test]
    fn coulomb_is_continuous_at_the_threshold() {
        let beams = paper();
        let f = beams.threshold_force();
        let below = beams.coulomb(force(f)).tip_deflection();
        let above = beams.coulomb(force(f * (1.0 + 1e-12))).tip_deflection();
        assert_eq!(beams.coulomb(force(f)).regime(), Regime::STICK);
        assert_eq!(
            beams.coulomb(force(f * (1.0 + 1e-12))).regime(),
            Regime::MACROSLIP
        );
        assert!(((above - below) / below).abs() < 1e-10);
    }

    #[test]
    fn zero_force_gives_a_zero_solution() {
        // Zero load is its own state, not "microslip" (issue 16): nothing is stressed.
        let state = paper().regularized(force(0.0));
        assert_eq!(state.regime(), Regime::UNLOADED);
        assert_eq!(paper().coulomb(force(0.0)).regime(), Regime::UNLOADED);
        assert_eq!(paper().regularized(force(1e-9)).regime(), Regime::MICROSLIP);
        assert_eq!(state.tip_deflection(), 0.0);
        assert_eq!(state.shear_stress(100.0), 0.0);
    }

    #[test]
    fn shear_vanishes_at_the_clamp_and_saturates_at_x() {
        let beams = paper();
        for f in [40.0, 80.0, 100.0, 300.0, 5000.0] {
            let state = beams.regularized(force(f));
            assert!(state.shear_stress(0.0).abs() < 1e-12);
            let x = state.micro_zone_end();
            if state.regime() == Regime::MICROSLIP_MACROSLIP {
                let at_x = state.shear_stress(x * (1.0 - 1e-12));
                assert!((at_x - 0.3).abs() < 1e-9, "F={f}: tau(X-) = {at_x}");
            }
        }
    }

    #[test]
    fn the_microslip_end_and_the_macroslip_length_add_up_to_l() {
        let beams = paper();
        let f_1 = beams.first_macroslip_force();
        // Just above F_1 (X near L, found as L - X), then deep in macroslip (X small, found as X).
        for f in [f_1 * (1.0 + 1e-9), 81.0, 100.0, 1e4, 1e9] {
            let state = beams.regularized(force(f));
            assert_eq!(state.regime(), Regime::MICROSLIP_MACROSLIP);
            let (x, a) = (state.micro_zone_end(), state.macroslip_length());
            assert!(a > 0.0 && x > 0.0, "F={f}");
            assert!(
                (x + a - 200.0).abs() <= 4.0 * f64::EPSILON * 200.0,
                "F={f}: {x} + {a}"
            );
        }
        assert_eq!(beams.regularized(force(50.0)).macroslip_length(), 0.0);
    }

    #[test]
    fn coulomb_slip_is_not_negative_one_ulp_above_the_threshold() {
        // tau_b - mu P from F - F_thre: positive whenever the interface slides.
        let thin = TwinBeams::new(TwinBeamsParams {
            friction: 7.105_017_298_846_543e-6,
            pressure: 1e-6,
            width: 1.192_292_328_757_343e-6,
            half_height: 3_753.103_293_958_533_4,
            ..TwinBeamsParams::PAPER
        })
        .unwrap();
        let f = thin.threshold_force().next_up();
        let c = thin.coulomb(force(f));
        assert_eq!(c.regime(), Regime::MACROSLIP);
        for x in [0.0, 100.0, 200.0] {
            assert!(c.slip(x) >= 0.0, "x={x}: {}", c.slip(x));
        }
    }

    #[test]
    fn clamped_forces_are_the_nearest_accepted_ones() {
        assert_eq!(TipForce::clamped(12.5).newtons(), 12.5);
        assert_eq!(TipForce::clamped(-3.0).newtons(), 0.0);
        assert_eq!(TipForce::clamped(f64::NAN).newtons(), 0.0);
        assert_eq!(TipForce::clamped(1e307).newtons(), 1e12);
    }

    #[test]
    fn bad_inputs_name_their_field() {
        let bad = TwinBeamsParams {
            half_height: -1.0,
            ..TwinBeamsParams::PAPER
        };
        assert_eq!(TwinBeams::new(bad).unwrap_err().field, "h");
        let bad = TwinBeamsParams {
            tangential_stiffness: f64::NAN,
            ..TwinBeamsParams::PAPER
        };
        assert_eq!(TwinBeams::new(bad).unwrap_err().field, "KT");
        assert_eq!(TipForce::new(-1.0).unwrap_err().field, "F");
        assert!(TipForce::new(f64::INFINITY).is_err());
    }
}
