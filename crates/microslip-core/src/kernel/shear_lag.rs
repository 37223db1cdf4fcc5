//! The shear lag of two bars coupled through one frictional interface (docs/theory.md section 9,
//! (L1)-(L10), written for any two bars in section 18, (S1)): the closed forms the double-lap
//! joint and the press fit share.
//!
//! Two bars lie side by side over [0, L], joined along an interface of width w (the lap joint's
//! two faces, 2 b; the press fit's circumference, 2 pi r) under a uniform normal pressure p. The
//! *loaded* bar (axial rigidity A1 = a1 w) carries the whole force F at x = L and is free at
//! x = 0; the *held* bar (A2 = a2 w) is free at x = L and hands F to its support at x = 0. With
//! tau the interface shear on the loaded bar (positive resisting F) and s = u_loaded - u_held:
//!
//! ```text
//! N1' = w tau,   N1 + N2 = F,   s'' = C tau,   C = 1/a1 + 1/a2,
//! s'(0) = -F/A2,   s'(L) = F/A1,
//! ```
//!
//! and the law: tau = K_T s up to mu p (regularized) or stick/slide at mu p (Coulomb). The
//! rigidities enter per unit interface width (a = A / w, N/mm), so the lap joint maps onto it
//! with factors of two only (a1 = E1 t1 / 2, a2 = E2 t2, w = 2 b), which are exact in binary:
//! its numbers do not move by a bit. Every regime of both laws is one shape: a sliding zone of
//! length `a` from x = 0 and one of length `d` from x = L (either may be empty), where tau = mu p
//! and the slip is a parabola, and between them a zone that sticks (Coulomb) or deforms
//! elastically (regularized law) with slopes `p` at its start and `q` at its end
//! (s'(a) = -p, s'(L - d) = q).
//!
//! Nothing here knows a problem: the caller validates its own inputs and maps its bars, its
//! width and its coordinate onto these.

use crate::kernel::hyperbolic::{cosh_sinh_ratio, one_minus_tanhc, sech, tanhc};
use crate::kernel::params::Domain;
use crate::kernel::regime::{Law, Regime, Zone};
use crate::kernel::solve::{find_root_in_bracket, find_root_newton};

/// The two bars and their interface, as numbers the caller has validated (all > 0, finite).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoBars {
    /// a1 = A1 / w (N/mm): the axial rigidity of the bar loaded at x = L, per unit interface
    /// width.
    pub loaded: f64,
    /// a2 = A2 / w (N/mm): the bar held at x = 0, per unit interface width.
    pub held: f64,
    /// Interface width w (mm): the length of the interface's cross-section line.
    pub width: f64,
    /// Interface length L (mm).
    pub length: f64,
    /// Friction coefficient mu (-).
    pub friction: f64,
    /// Normal pressure p on the interface (MPa).
    pub pressure: f64,
    /// Tangential stiffness K_T (MPa/mm).
    pub stiffness: f64,
}

impl TwoBars {
    /// F_gross = w mu p L (N): the whole interface sliding; no larger force can be carried.
    pub fn gross_slip_force(&self) -> f64 {
        self.width * self.friction * self.pressure * self.length
    }
}

/// Where sliding starts as the force grows (L2): the end where the more compliant bar carries
/// the load.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SlipStart {
    /// x = 0, where the held bar carries F: it is the more compliant (a1 > a2).
    Start,
    /// x = L, where the loaded bar carries F: it is the more compliant (a1 < a2).
    End,
    /// Both ends at once (a1 = a2).
    Both,
}

/// The shear lag of [`TwoBars`] with its load-independent constants (L2)-(L4').
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShearLag {
    bars: TwoBars,
    /// C = 1/a1 + 1/a2 (mm/N).
    c: f64,
    /// lambda = sqrt(C K_T) (1/mm), (L2).
    lambda: f64,
    /// F_1 and F_2 (N), (L3) and (L4'): load-independent, solved once.
    slip_forces: (f64, f64),
    /// The elastic length at F_2 (mm): with L at F_1, where (L4)'s root starts from.
    second_elastic: f64,
}

impl ShearLag {
    /// The shear lag of `bars` (validated by the caller).
    pub fn new(bars: TwoBars) -> ShearLag {
        let c = 1.0 / bars.loaded + 1.0 / bars.held;
        let lambda = (c * bars.stiffness).sqrt();
        let mut lag = ShearLag {
            bars,
            c,
            lambda,
            slip_forces: (0.0, 0.0),
            second_elastic: 0.0,
        };
        let (second, elastic) = lag.solve_second_slip_force();
        lag.slip_forces = (lag.solve_first_slip_force(), second);
        lag.second_elastic = elastic;
        lag
    }

    /// The bars this was built from.
    pub fn bars(&self) -> TwoBars {
        self.bars
    }

    /// The same bars with K_T = `kt` (MPa/mm).
    pub fn with_stiffness(&self, kt: f64) -> ShearLag {
        ShearLag::new(TwoBars {
            stiffness: kt,
            ..self.bars
        })
    }

    /// lambda = sqrt(C K_T) (1/mm), (L2): 1/lambda is the decay length of the elastic slip.
    pub fn decay_rate(&self) -> f64 {
        self.lambda
    }

    /// The Coulomb stress mu p (MPa).
    pub fn coulomb_stress(&self) -> f64 {
        self.bars.friction * self.bars.pressure
    }

    /// The saturation slip mu p / K_T (mm).
    pub fn saturation_slip(&self) -> f64 {
        self.coulomb_stress() / self.bars.stiffness
    }

    /// The bonded compliance L / (w (a1 + a2)) = L / (A1 + A2) (mm/N), (L6): both bars strained
    /// alike, what remains of Delta / F when nothing slips.
    pub fn bonded_compliance(&self) -> f64 {
        self.bars.length / (self.bars.width * (self.bars.loaded + self.bars.held))
    }

    /// Which end slides first (L2).
    pub fn slip_start(&self) -> SlipStart {
        let (loaded, held) = (self.bars.loaded, self.bars.held);
        if loaded < held {
            SlipStart::End
        } else if loaded > held {
            SlipStart::Start
        } else {
            SlipStart::Both
        }
    }

    /// (L3): the force F_1 at which sliding first appears:
    /// C mu p w L tanhc(lambda L) / (1/a_s + sech(lambda L)/a_o), a_s the rigidity of the bar
    /// that carries the load at the sliding end (the more compliant one).
    pub fn first_slip_force(&self) -> f64 {
        self.slip_forces.0
    }

    fn solve_first_slip_force(&self) -> f64 {
        let (soft, stiff) = self.soft_stiff();
        let z = self.lambda * self.bars.length;
        self.c * self.coulomb_stress() * self.bars.width * self.bars.length * tanhc(z)
            / (1.0 / soft + sech(z) / stiff)
    }

    fn soft_stiff(&self) -> (f64, f64) {
        let (loaded, held) = (self.bars.loaded, self.bars.held);
        (loaded.min(held), loaded.max(held))
    }

    /// (L4'): the force F_2 at which the other end starts sliding too (F_1 when a1 = a2): with
    /// the elastic zone l solving l + (l/2) tanhc(lambda l/2) (a_o - a_s)/a_s = L,
    /// F_2 = w a_o (C/2) mu p l tanhc(lambda l/2).
    pub fn second_slip_force(&self) -> f64 {
        self.slip_forces.1
    }

    /// F_2 (N) and the elastic length there (mm).
    fn solve_second_slip_force(&self) -> (f64, f64) {
        let (soft, stiff) = self.soft_stiff();
        let lambda = self.lambda;
        let length = self.bars.length;
        let excess = (stiff - soft) / soft;
        let elastic = find_root_in_bracket(
            |l| l + 0.5 * l * tanhc(0.5 * lambda * l) * excess - length,
            0.0,
            length,
        );
        let force = self.bars.width
            * stiff
            * self.c
            * 0.5
            * self.coulomb_stress()
            * elastic
            * tanhc(0.5 * lambda * elastic);
        // F_2 <= F_gross exactly (F_2 tends to it as one bar's rigidity or lambda L tends to 0),
        // but the product above rounds: a bar a hundred million times the other's rigidity gave
        // F_2 = 6000.000000000001 N over F_gross = 6000 N. An interface whose second end slides
        // after the whole interface does is none: clamp.
        (force.min(self.bars.gross_slip_force()), elastic)
    }

    /// The slopes of the slip at the two ends that the force sets (L1), in units of C mu p, so
    /// lengths: G0 = g0 / (C mu p) at x = 0 and GL = gL / (C mu p) at x = L, with
    /// G0 + GL = L F / F_gross.
    fn end_slope_lengths(&self, force: f64) -> (f64, f64) {
        let per_width = force / (self.bars.width * self.c * self.coulomb_stress());
        (per_width / self.bars.held, per_width / self.bars.loaded)
    }

    /// Solution under plain Coulomb at `force` (N, 0 <= F <= F_gross, checked by the caller),
    /// (L7): sliding zones a = G0 and d = GL, the rest sticks and carries no shear.
    pub fn coulomb(&self, force: f64) -> ShearLagState {
        let (g0, gl) = self.end_slope_lengths(force);
        self.state(Law::Coulomb, force, g0, gl)
    }

    /// Solution under the regularized law at `force` (N, 0 <= F <= F_gross): all microslip up to
    /// F_1 (L2), one end sliding up to F_2 (L4), both beyond (L5), all sliding at F_gross (L6).
    pub fn regularized(&self, force: f64) -> ShearLagState {
        let f = force;
        let (g0, gl) = self.end_slope_lengths(f);
        let length = self.bars.length;
        let lambda = self.lambda;
        let (a, d) = if f <= self.first_slip_force() {
            (0.0, 0.0)
        } else if f < self.second_slip_force() {
            // (L4): the elastic length e from the end that still sticks; the sliding end's slope
            // length and the other's.
            let (sliding, other) = match self.slip_start() {
                SlipStart::Start => (g0, gl),
                SlipStart::End | SlipStart::Both => (gl, g0),
            };
            // d/de [e (1 - tanhc(lambda e))] = tanh^2(lambda e); Newton from e interpolated
            // between L at F_1 and the elastic length at F_2, certified and bracketed (it falls
            // back to Brent's method on [0, L]).
            let (f1, f2) = self.slip_forces;
            let start = length + (self.second_elastic - length) * (f - f1) / (f2 - f1);
            let elastic = find_root_newton(
                |e| length - e * one_minus_tanhc(lambda * e) - sliding - other * sech(lambda * e),
                |e| {
                    let t = (lambda * e).tanh();
                    -t * t + other * lambda * sech(lambda * e) * t
                },
                start,
                0.0,
                length,
            );
            match self.slip_start() {
                SlipStart::Start => (length - elastic, 0.0),
                SlipStart::End | SlipStart::Both => (0.0, length - elastic),
            }
        } else {
            // (L5): l (1 - tanhc(lambda l/2)) = L (1 - F/F_gross).
            let remaining = (length - g0 - gl).max(0.0);
            // phi(l) = l (1 - tanhc(lambda l/2)) grows with slope tanh^2(lambda l/2): like
            // lambda^2 l^3 / 12 for short zones, like l - 2/lambda for long ones; Newton starts
            // from the larger of the two estimates (phi is convex, so it then never overshoots
            // below the root) and is certified and bracketed.
            let start = (remaining + 2.0 / lambda)
                .max((12.0 * remaining / (lambda * lambda)).cbrt())
                .min(length);
            let elastic = find_root_newton(
                |l| l * one_minus_tanhc(0.5 * lambda * l) - remaining,
                |l| {
                    let t = (0.5 * lambda * l).tanh();
                    t * t
                },
                start,
                0.0,
                length,
            );
            let half_t = 0.5 * elastic * tanhc(0.5 * lambda * elastic);
            ((g0 - half_t).max(0.0), (gl - half_t).max(0.0))
        };
        self.state(Law::Regularized, f, g0, gl).with_zones(a, d)
    }

    /// The solution under `law` at `force`.
    pub fn solve(&self, law: Law, force: f64) -> ShearLagState {
        match law {
            Law::Coulomb => self.coulomb(force),
            Law::Regularized => self.regularized(force),
        }
    }

    /// The state with sliding zones set by `law` before [`ShearLagState::with_zones`] (Coulomb's
    /// are final: a = G0, d = GL).
    fn state(&self, law: Law, force: f64, g0: f64, gl: f64) -> ShearLagState {
        let state = ShearLagState {
            lag: *self,
            law,
            force,
            g0,
            gl,
            a: 0.0,
            d: 0.0,
        };
        match law {
            Law::Coulomb => state.with_zones(g0, gl),
            Law::Regularized => state,
        }
    }

    /// The K_T (MPa/mm) at which the regularized end displacement at `force` equals
    /// `displacement` (mm), all else as here: what an FE result says about the stiffness its code
    /// used. The displacement falls with K_T at every force (L11), so there is at most one
    /// answer; `None` when no K_T in the accepted domain gives it.
    pub fn stiffness_for_end_displacement(&self, force: f64, displacement: f64) -> Option<f64> {
        // K_T = min e^k, k in [0, ln(max / min)]: the root finder's bracket starts at 0.
        let min = Domain::STIFFNESS.min();
        let at = |k: f64| {
            let kt = min * k.exp();
            Domain::STIFFNESS.contains(kt).then(|| {
                self.with_stiffness(kt)
                    .regularized(force)
                    .end_displacement()
            })
        };
        let span = (Domain::STIFFNESS.max() / min).ln();
        let (soft, stiff) = (at(0.0)?, at(span)?);
        if !(displacement > 0.0 && (stiff..=soft).contains(&displacement)) {
            return None;
        }
        // Relative misfit, so that the root finder sees numbers near 1 whatever the scale.
        let k = find_root_in_bracket(
            |k| at(k).map_or(f64::NAN, |d| d / displacement - 1.0),
            0.0,
            span,
        );
        Some(min * k.exp())
    }
}

/// One law's solution at one force: the two sliding zones and what follows from them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShearLagState {
    lag: ShearLag,
    law: Law,
    force: f64,
    /// End slope lengths G0 = g0/(C mu p), GL = gL/(C mu p) (mm).
    g0: f64,
    gl: f64,
    /// Sliding zone from x = 0 (mm).
    a: f64,
    /// Sliding zone from x = L (mm).
    d: f64,
}

impl ShearLagState {
    fn with_zones(self, a: f64, d: f64) -> ShearLagState {
        let length = self.lag.bars.length;
        let a = a.clamp(0.0, length);
        ShearLagState {
            a,
            d: d.clamp(0.0, length - a),
            ..self
        }
    }

    /// The law this state is solved under.
    pub fn law(&self) -> Law {
        self.law
    }

    /// The force (N).
    pub fn force(&self) -> f64 {
        self.force
    }

    /// Length a of the sliding zone from x = 0 (mm).
    pub fn slide_from_start(&self) -> f64 {
        self.a
    }

    /// Length d of the sliding zone from x = L (mm).
    pub fn slide_from_end(&self) -> f64 {
        self.d
    }

    /// The zone between the sliding ones, [a, L - d]: elastic (regularized) or stuck (Coulomb).
    pub fn middle_zone(&self) -> (f64, f64) {
        (self.a, self.lag.bars.length - self.d)
    }

    /// The slip at the ends of the sliding zones (mm): mu p / K_T under the regularized law, 0
    /// under Coulomb.
    fn zone_edge_slip(&self) -> f64 {
        match self.law {
            Law::Coulomb => 0.0,
            Law::Regularized => self.lag.saturation_slip(),
        }
    }

    /// The slopes p = -s'(a) and q = s'(L - d) of the slip at the middle zone's ends, in units
    /// of C mu p (lengths): G0 - a and GL - d, since s' changes by C mu p per mm of sliding zone
    /// (L5).
    fn middle_slope_lengths(&self) -> (f64, f64) {
        ((self.g0 - self.a).max(0.0), (self.gl - self.d).max(0.0))
    }

    /// The slip s(x) = u_loaded - u_held (mm) at `x` (clamped to [0, L]), (L4)-(L7): in a
    /// sliding zone edge + u (p + C mu p u / 2) with u the distance into it from the middle
    /// zone; in the middle zone the elastic profile [q cosh(lambda (x - a)) + p cosh(lambda
    /// (L - d - x))] / (lambda sinh(lambda l)) (regularized), or 0 (Coulomb: it sticks).
    pub fn slip_at(&self, x: f64) -> f64 {
        let lag = &self.lag;
        let length = lag.bars.length;
        let x = x.clamp(0.0, length);
        let (start, end) = self.middle_zone();
        let c_mu_p = lag.c * lag.coulomb_stress();
        let (p, q) = self.middle_slope_lengths();
        let edge = self.zone_edge_slip();
        let parabola = |u: f64, slope: f64| edge + u * c_mu_p * (slope + 0.5 * u);
        if x < start {
            return parabola(start - x, p);
        }
        if x > end {
            // d - (L - x), not x - (L - d): a zone far shorter than the interface would lose
            // its digits to L in the difference (exact at x = L).
            return parabola((self.d - (length - x)).max(0.0), q);
        }
        match self.law {
            Law::Coulomb => 0.0,
            Law::Regularized => {
                let l = end - start;
                let lambda = lag.lambda;
                if l * lambda == 0.0 {
                    // F_gross, or the whole interface one point: the middle zone has shrunk to
                    // its edge value.
                    return edge;
                }
                c_mu_p
                    * (q * cosh_sinh_ratio(lambda * (x - start), lambda * l)
                        + p * cosh_sinh_ratio(lambda * (end - x), lambda * l))
                    / lambda
            }
        }
    }

    /// The interface shear tau(x) on the loaded bar (MPa), positive resisting F: mu p in the
    /// sliding zones; K_T s in the elastic zone (regularized), 0 in the stick zone (Coulomb).
    pub fn shear_at(&self, x: f64) -> f64 {
        let mu_p = self.lag.coulomb_stress();
        let (start, end) = self.middle_zone();
        if x < start || x > end {
            return mu_p;
        }
        match self.law {
            Law::Coulomb => 0.0,
            Law::Regularized => (self.lag.bars.stiffness * self.slip_at(x)).min(mu_p),
        }
    }

    /// The end displacement Delta = u_loaded(L) - u_held(0) (mm), (L6):
    /// (1 - alpha) s(0) + alpha s(L) + F L / (A1 + A2), alpha = a2 / (a1 + a2).
    pub fn end_displacement(&self) -> f64 {
        let bars = &self.lag.bars;
        let alpha = bars.held / (bars.loaded + bars.held);
        (1.0 - alpha) * self.slip_at(0.0)
            + alpha * self.slip_at(bars.length)
            + self.force * self.lag.bonded_compliance()
    }

    /// The zones from x = 0 outward.
    pub fn regime(&self) -> Regime {
        if self.force == 0.0 {
            return Regime::UNLOADED;
        }
        let (start, end) = self.middle_zone();
        if end - start <= 0.0 {
            return Regime::MACROSLIP;
        }
        zones_regime(self.law, self.a, self.d, self.lag.bars.length)
    }

    /// (L10): energy dissipated per cycle between +F and -F (N mm), from the friction work of
    /// Masing's loop: every point of a sliding zone slides back and forth by twice its plastic
    /// slip s_p at the turning point against mu p over the width w, so
    /// D = 4 w mu p sum over both zones of integral(s_p) = 2 w mu p C mu p sum (p u^2 + u^3/3)
    /// with u the zone's length and p its middle-zone slope length: a sum of positive terms.
    pub fn cycle_dissipation(&self) -> f64 {
        let lag = &self.lag;
        let mu_p = lag.coulomb_stress();
        let (p, q) = self.middle_slope_lengths();
        let zone = |u: f64, slope: f64| u * u * (slope + u / 3.0);
        2.0 * lag.bars.width * mu_p * lag.c * mu_p * (zone(self.a, p) + zone(self.d, q))
    }
}

/// The regime of a loaded interface whose sliding zones from x = 0 and from x = L are `a` and
/// `d` (mm) over a `length`: shared by the closed forms and the readers of FE slip profiles, so
/// that both name the same zones the same way.
pub fn zones_regime(law: Law, a: f64, d: f64, length: f64) -> Regime {
    if a + d >= length {
        return Regime::MACROSLIP;
    }
    let middle = match law {
        Law::Coulomb => Zone::Stick,
        Law::Regularized => Zone::Microslip,
    };
    match (a > 0.0, d > 0.0) {
        (true, true) => Regime::from_zones(&[Zone::Macroslip, middle, Zone::Macroslip]),
        (false, true) => Regime::from_zones(&[middle, Zone::Macroslip]),
        (true, false) => Regime::from_zones(&[Zone::Macroslip, middle]),
        (false, false) => Regime::from_zones(&[middle]),
    }
}

/// One law's cycle between +amplitude and -amplitude of a [`ShearLag`] under Masing's rule
/// (docs/theory.md (L9)), with the lever `arm` from the interface's force to the load (1 for a
/// force, r for the press fit's torque): the virgin curve, the peak, the dissipation (L10) and
/// the secant stiffness that each problem's `MasingCycle` hands on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShearLagCycle {
    lag: ShearLag,
    law: Law,
    arm: f64,
    /// The state at the turning point.
    peak: ShearLagState,
}

impl ShearLagCycle {
    /// The cycle of `lag` under `law` with amplitude `load` (in the load's unit, checked by the
    /// caller: 0 <= load <= arm F_gross).
    pub fn new(lag: &ShearLag, law: Law, arm: f64, load: f64) -> ShearLagCycle {
        ShearLagCycle {
            lag: *lag,
            law,
            arm,
            peak: lag.solve(law, load / arm),
        }
    }

    /// The amplitude (the load's unit).
    pub fn amplitude(&self) -> f64 {
        self.peak.force() * self.arm
    }

    /// Where sliding starts on first loading: F_1 (times the arm) under the regularized law, 0
    /// under plain Coulomb (both ends slide from the first newton, (L7)).
    pub fn onset(&self) -> f64 {
        match self.law {
            Law::Coulomb => 0.0,
            Law::Regularized => self.lag.first_slip_force() * self.arm,
        }
    }

    /// The accepted interface force nearest to `load` over the arm: 0 for NaN, F_gross above.
    fn clamped(&self, load: f64) -> f64 {
        let force = if load.is_nan() { 0.0 } else { load / self.arm };
        force.clamp(0.0, self.lag.bars.gross_slip_force())
    }

    /// The virgin curve (the response's unit), odd in the load; beyond the gross load taken at
    /// it (the branches never ask for more than the amplitude).
    pub fn virgin(&self, load: f64) -> f64 {
        let state = self.lag.solve(self.law, self.clamped(load.abs()));
        (state.end_displacement() / self.arm).copysign(load)
    }

    /// The peak response.
    pub fn peak_response(&self) -> f64 {
        self.peak.end_displacement() / self.arm
    }

    /// (L10): the friction work of the plastic slip at the turning point; 0 while nothing
    /// slides.
    pub fn dissipation(&self) -> f64 {
        self.peak.cycle_dissipation()
    }

    /// Peak elastic energy U = amplitude x peak response / 2, the secant definition.
    pub fn peak_energy(&self) -> f64 {
        0.5 * self.amplitude() * self.peak_response()
    }

    /// Secant stiffness amplitude / peak response; at zero amplitude the initial slope: the
    /// bonded one under Coulomb (its slip grows as the load squared), the elastic one under the
    /// regularized law.
    pub fn secant_stiffness(&self) -> f64 {
        let response = self.peak_response();
        if response > 0.0 {
            return self.amplitude() / response;
        }
        match self.law {
            Law::Coulomb => self.arm * self.arm / self.lag.bonded_compliance(),
            Law::Regularized => {
                let probe = self.clamped(0.5 * self.lag.first_slip_force() * self.arm);
                probe * self.arm / (self.lag.regularized(probe).end_displacement() / self.arm)
            }
        }
    }
}
