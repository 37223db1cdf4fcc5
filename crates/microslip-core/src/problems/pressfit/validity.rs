//! Where the press fit's 1-D theory stands (docs/theory.md section 18, (S9) and (S10)): the sizes
//! of what it leaves out, computable from the inputs, and the bound they give on the 1-D
//! Delta's difference from the axisymmetric continuum (`continuum.rs`), measured on a grid of
//! fits and checked on fits held out of it.
//!
//! The theory assumes Lamé's pressure p uniform over L and untouched by the push, and each
//! member's axial strain uniform over its section. The continuum (with the issue's geometry:
//! shaft and hub both spanning L, assembled without friction) keeps Lamé's plane-stress p
//! exactly after assembly (theory.md (S10)), so what departs is:
//!
//! - the walls' shear compliance, in series with the interface's: r_w, the change of the closed
//!   form's Delta when K_T is replaced by K_eff, 1/K_eff = 1/K_T + c_s + c_h
//!   ([`wall_shear_compliances`]);
//! - the load's way into and out of the members at the faces (the shaft's face carries F, the
//!   hub's face none; an eccentric path that bends thin walls over sqrt(r (ro - ri))): e =
//!   sqrt(r (ro - ri)) / L times the bonded fit's share of Delta, F L / (Es As + Eh Ah) / Delta;
//! - the push's Poisson swelling of the shaft, which raises p near the loaded face and stiffens
//!   the fit: pc = max(nus F / (Es As), nuh F / (Eh Ah)) r / delta.
//!
//! The bound is 1.25 (0.35 e + 0.7 r_w + 1.25 pc + 0.005) inside the calibrated ranges
//! ([`CALIBRATED`]); outside them the verdict is [`Validity::NotCalibrated`] and the first range
//! left is named.

use super::closed_form::{CarriedLoad, FitAxis, PressFit};
use crate::kernel::validity::Validity;
use crate::numeric::q8::GAUSS3;

/// The sizes of what the 1-D theory leaves out, for one fit at one push-out force, and the
/// bound they give.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct PressFitValidity {
    /// (ro - r) / L: the hub's wall over the fit length.
    pub end_zone_over_length: f64,
    /// (1/lambda) / (thicker wall): the length over which the shear is handed on, over the
    /// depth it must diffuse through for the section's strain to be uniform; small values are
    /// where the shear-lag assumption is doubtful.
    pub decay_over_wall: f64,
    /// pc, the largest Poisson change of the interference the load makes, over delta:
    /// max(nus F / (Es As), nuh F / (Eh Ah)) r / delta. The shaft's compression swells it and
    /// raises p at the loaded face; the theory keeps p.
    pub poisson_coupling: f64,
    /// delta / r: the strain of the shrink fit, which linear elasticity needs small.
    pub interference_strain: f64,
    /// r_w = |Delta(K_eff) / Delta(K_T) - 1|: the walls' shear compliance
    /// ([`PressFit::effective_stiffness`]).
    pub wall_shear: f64,
    /// e = sqrt(r (ro - ri)) / L x F L / ((Es As + Eh Ah) Delta): the faces' load paths.
    pub end_effect: f64,
    /// The bound on |Delta 1-D / Delta continuum - 1|, a fraction; `None` outside the
    /// calibrated ranges ([`PressFitValidity::outside_calibration`] says which).
    pub expected_error: Option<f64>,
    /// The level of that bound.
    pub validity: Validity,
    /// The first calibrated range the fit leaves, with what was measured beyond it.
    pub outside_calibration: Option<&'static str>,
}

/// The bound's coefficients on (e, r_w, pc, 1), fitted to the calibration grid (every state
/// under it, the mean bound least; theory.md (S10)) and rounded up.
const COEFFICIENTS: [f64; 4] = [0.35, 0.7, 1.25, 0.005];
/// The margin over the fitted bound, as the lap joint's.
const MARGIN: f64 = 1.25;
/// Relative slack on each range's ends, so that a fit on a grid node is inside.
const SLACK: f64 = 1e-9;

/// The calibrated ranges (the grid's), each with what a fit outside it is told.
pub const CALIBRATED: [(&str, f64, f64, &str); 5] = [
    (
        "L/r",
        2.0,
        8.0,
        "L/r outside [2, 8]: fits shorter than their diameter were measured off by up to 68 % \
         (thick walls, stiff interface) against the continuum",
    ),
    ("(r - ri)/r", 0.1, 1.0, "(r - ri)/r outside [0.1, 1]"),
    ("(ro - r)/r", 0.1, 2.0, "(ro - r)/r outside [0.1, 2]"),
    ("K_T r/Es", 0.01, 1.0, "K_T r / Es outside [0.01, 1]"),
    (
        "F/F_gross",
        0.0,
        0.8,
        "F/F_gross beyond 0.8, the grid's highest load",
    ),
];

impl PressFit {
    /// The sizes of what the theory leaves out at push-out `force`, and the bound (S10).
    pub fn validity(&self, force: CarriedLoad) -> PressFitValidity {
        let p = self.params();
        let axis: &FitAxis = self.axial();
        let thicker = (p.fit_radius - p.bore_radius).max(p.outer_radius - p.fit_radius);
        let shaft = p.shaft_poisson * force.value() / (p.shaft_modulus * p.shaft_area());
        let hub = p.hub_poisson * force.value() / (p.hub_modulus * p.hub_area());
        let poisson_coupling = shaft.max(hub) * p.fit_radius / p.interference;
        let wall_shear = self.wall_shear(force);
        let end_effect = self.end_effect(force);
        let r = p.fit_radius;
        let groups = [
            p.length / r,
            (r - p.bore_radius) / r,
            (p.outer_radius - r) / r,
            p.tangential_stiffness * r / p.shaft_modulus,
            force.value() / self.gross_slip_force(),
        ];
        let outside_calibration = CALIBRATED
            .iter()
            .zip(groups)
            .find(|((_, lo, hi, _), x)| !(*x >= lo * (1.0 - SLACK) && *x <= hi * (1.0 + SLACK)))
            .map(|((_, _, _, why), _)| *why);
        let [a, b, c, d] = COEFFICIENTS;
        let bound = MARGIN * (a * end_effect + b * wall_shear + c * poisson_coupling + d);
        let expected_error = outside_calibration.is_none().then_some(bound);
        PressFitValidity {
            end_zone_over_length: (p.outer_radius - p.fit_radius) / p.length,
            decay_over_wall: 1.0 / (axis.decay_rate() * thicker),
            poisson_coupling,
            interference_strain: p.interference / p.fit_radius,
            wall_shear,
            end_effect,
            expected_error,
            validity: expected_error.map_or(Validity::NotCalibrated, Validity::of_error),
            outside_calibration,
        }
    }

    /// e at `force` (S10): sqrt(r (ro - ri)) / L times the bonded fit's share of the
    /// regularized Delta, F L / (Es As + Eh Ah) / Delta; at F = 0 its limit (both linear in F
    /// below first slip: the share at half F_1).
    pub fn end_effect(&self, force: CarriedLoad) -> f64 {
        let p = self.params();
        let at = if force.value() > 0.0 {
            force.value()
        } else {
            0.5 * self.first_slip_force()
        };
        let delta = self.regularized(self.axial().clamped(at)).response();
        let bonded =
            at * p.length / (p.shaft_modulus * p.shaft_area() + p.hub_modulus * p.hub_area());
        let scale = (p.fit_radius * (p.outer_radius - p.bore_radius)).sqrt() / p.length;
        if delta > 0.0 {
            scale * bonded / delta
        } else {
            0.0
        }
    }
}

/// The shear compliances (mm/MPa) of the shaft's and the hub's walls between the interface and
/// their section's mean axial displacement, (S10): a shear flow handed on uniformly over each
/// section (the bars' assumption) has tau(rho) = tau_r (r/rho) A(rho)/A, A(rho) the part of the
/// section between rho and the free surface, and u(r) - u_mean = integral of tau/G A(rho)/A over
/// the wall, so
///
/// ```text
/// c_s = r / (Gs (r^2 - ri^2)^2) x integral_ri^r  (rho^2 - ri^2)^2 / rho d rho,
/// c_h = r / (Gh (ro^2 - r^2)^2) x integral_r^ro  (ro^2 - rho^2)^2 / rho d rho,
/// ```
///
/// (a solid shaft r / (4 Gs); a thin wall t / (3 G), the lap joint's plate). Integrated by
/// Gauss-Legendre on smooth integrands (the closed forms of the integrals cancel to nothing on a
/// thin wall).
pub fn wall_shear_compliances(p: &crate::problems::pressfit::params::PressFitParams) -> (f64, f64) {
    let (ri, r, ro) = (p.bore_radius, p.fit_radius, p.outer_radius);
    let shaft = integral(ri, r, |rho| (rho - ri).powi(2) * (rho + ri).powi(2) / rho)
        / ((r - ri) * (r + ri)).powi(2);
    let hub = integral(r, ro, |rho| (ro - rho).powi(2) * (ro + rho).powi(2) / rho)
        / ((ro - r) * (ro + r)).powi(2);
    (
        r * shaft / p.shaft_shear_modulus(),
        r * hub / p.hub_shear_modulus(),
    )
}

/// The integral of a smooth `f` over [a, b]: 32 panels of the 3-point Gauss rule (the Q8's).
fn integral(a: f64, b: f64, f: impl Fn(f64) -> f64) -> f64 {
    const PANELS: usize = 32;
    let h = (b - a) / PANELS as f64;
    (0..3 * PANELS)
        .map(|n| {
            let (node, weight) = GAUSS3[n % 3];
            let centre = a + ((n / 3) as f64 + 0.5) * h;
            0.5 * h * weight * f(centre + 0.5 * h * node)
        })
        .sum()
}

impl PressFit {
    /// K_eff (MPa/mm): the interface's stiffness in series with both walls' shear
    /// compliances, 1/K_eff = 1/K_T + c_s + c_h ([`wall_shear_compliances`]).
    pub fn effective_stiffness(&self) -> f64 {
        let (shaft, hub) = wall_shear_compliances(&self.params());
        1.0 / (1.0 / self.params().tangential_stiffness + shaft + hub)
    }

    /// r_w at `force`: |Delta(K_eff) / Delta(K_T) - 1| of the regularized law; below first slip
    /// (where both are linear in F, and at F = 0) the same ratio at half the smaller F_1.
    pub fn wall_shear(&self, force: CarriedLoad) -> f64 {
        let Ok(softer) = self.with_tangential_stiffness(self.effective_stiffness()) else {
            return 0.0;
        };
        let at = if force.value() > 0.0 {
            force.value()
        } else {
            0.5 * self.first_slip_force().min(softer.first_slip_force())
        };
        let stiff = self.regularized(self.axial().clamped(at)).response();
        let soft = softer.regularized(softer.axial().clamped(at)).response();
        if stiff > 0.0 {
            (soft / stiff - 1.0).abs()
        } else {
            0.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::pressfit::params::PressFitParams;

    #[test]
    fn the_wall_compliances_reach_their_limits_and_their_closed_forms() {
        let base = PressFitParams::CCX98;
        let g = base.shaft_shear_modulus();
        // Solid shaft: r / (4 G).
        let solid = PressFitParams {
            bore_radius: 0.0,
            ..base
        };
        let (c, _) = wall_shear_compliances(&solid);
        assert!((c * 4.0 * g / 20.0 - 1.0).abs() < 1e-10, "{c}");
        // Thin walls: t / (3 G) to first order in t / r.
        let thin = PressFitParams {
            bore_radius: 19.99,
            outer_radius: 20.01,
            ..base
        };
        let (s, h) = wall_shear_compliances(&thin);
        for c in [s, h] {
            assert!((c * 3.0 * g / 0.01 - 1.0).abs() < 1e-3, "{c}");
        }
        // The bundled fit, by the integrals' closed forms (theory.md (S10)).
        let (s, h) = wall_shear_compliances(&base);
        let (ri, r, ro) = (10.0_f64, 20.0_f64, 30.0_f64);
        let shaft = r / (g * (r * r - ri * ri).powi(2))
            * ((r.powi(4) - ri.powi(4)) / 4.0 - ri * ri * (r * r - ri * ri)
                + ri.powi(4) * (r / ri).ln());
        let hub = r / (g * (ro * ro - r * r).powi(2))
            * (ro.powi(4) * (ro / r).ln() - ro * ro * (ro * ro - r * r)
                + (ro.powi(4) - r.powi(4)) / 4.0);
        assert!((s / shaft - 1.0).abs() < 1e-10, "{s} {shaft}");
        assert!((h / hub - 1.0).abs() < 1e-10, "{h} {hub}");
    }

    #[test]
    fn each_calibrated_range_is_enforced_and_named() {
        // A grid fit (theory.md (S10)): L/r = 4, walls 0.5 r, K_T r/Es = 0.1.
        let inside = PressFitParams {
            bore_radius: 10.0,
            outer_radius: 30.0,
            length: 80.0,
            interference: 2e-3,
            tangential_stiffness: 1050.0,
            ..PressFitParams::CCX98
        };
        let at = |params: PressFitParams, fraction: f64| {
            let fit = PressFit::new(params).unwrap();
            fit.validity(fit.force(fraction * fit.gross_slip_force()).unwrap())
        };
        let v = at(inside, 0.5);
        let bound = v.expected_error.unwrap();
        assert!(v.outside_calibration.is_none());
        // The bound is the calibrated form of its terms.
        let by_hand =
            1.25 * (0.35 * v.end_effect + 0.7 * v.wall_shear + 1.25 * v.poisson_coupling + 0.005);
        assert!((bound / by_hand - 1.0).abs() < 1e-12);
        assert_eq!(v.validity, Validity::of_error(bound));
        for (params, fraction, named) in [
            (
                PressFitParams {
                    length: 30.0,
                    ..inside
                },
                0.5,
                "L/r",
            ),
            (
                PressFitParams {
                    length: 200.0,
                    ..inside
                },
                0.5,
                "L/r",
            ),
            (
                PressFitParams {
                    bore_radius: 19.0,
                    ..inside
                },
                0.5,
                "(r - ri)/r",
            ),
            (
                PressFitParams {
                    outer_radius: 70.0,
                    ..inside
                },
                0.5,
                "(ro - r)/r",
            ),
            (
                PressFitParams {
                    tangential_stiffness: 2e4,
                    ..inside
                },
                0.5,
                "K_T r / Es",
            ),
            (inside, 0.9, "F/F_gross"),
        ] {
            let v = at(params, fraction);
            assert_eq!(v.validity, Validity::NotCalibrated, "{named}");
            assert!(v.expected_error.is_none());
            assert!(v.outside_calibration.unwrap().starts_with(named), "{named}");
        }
        // The indicators vanish with their causes: no load, no Poisson swelling; a soft
        // interface against stiff walls, no wall shear.
        assert_eq!(at(inside, 0.0).poisson_coupling, 0.0);
        let soft = PressFitParams {
            tangential_stiffness: 1e-3,
            ..inside
        };
        assert!(at(soft, 0.5).wall_shear < 1e-6);
    }
}
