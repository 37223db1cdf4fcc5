//! The Hertzian cylinder under the regularized law (q = K_T s up to mu p): the semi-analytic
//! solution of docs/theory.md (H10)-(H14).
//!
//! In the normalized variables (H6) (x / a, q / (mu p0), s K_T / (mu p0)) the answer depends on
//! kappa = K_T a / E* and Q / (mu P) only. The contact has one elastic ("microslip") zone |x| <
//! c at the centre, where q = K_T s < mu p, and two sliding zones c < |x| < a at q = mu p, for
//! every 0 < Q < mu P. The unknown is the shear phi = q / (mu p0) in the microslip zone (equal
//! to the pressure's shape at its edges, where q meets mu p), with the rigid shift; for a given c
//! the equations are linear (H11') and collocated on the graded mesh of [`super::collocation`];
//! c itself is the root of Q(c) = Q (H13'), found by the secant method in theta = arccos(c / a),
//! safeguarded by a bracket. The shear, not its deficit mu p - q, is the unknown so that a small
//! load is a small unknown: with the deficit, Q / mu P = 1 - (4 c / pi a) integral psi was a
//! difference of numbers near 1 and lost Q below about 1e-8 mu P (issue 46).

use std::f64::consts::{FRAC_PI_2, PI};

use super::closed_form::{Cylinder, TangentialLoad, edge_root, mindlin_stick_ratio};
use super::collocation::{Collocation, CollocationMesh};
use super::quadrature::solve_with_constant;
use super::strips::{StripRule, strip_area, strip_potential};
use crate::kernel::family;
use crate::kernel::params::Domain;
use crate::kernel::regime::{Regime, Zone};
use crate::kernel::solve::find_root_in_bracket;
use crate::problems::Solution;

/// Unknowns of the default mesh ([`CollocationMesh::DEFAULT`]).
pub const DEFAULT_UNKNOWNS: usize =
    (CollocationMesh::DEFAULT.layers + 1) * CollocationMesh::DEFAULT.points;

/// The regularized solution in normalized form (H6): what depends on kappa and Q / mu P only.
#[derive(Debug, Clone, PartialEq)]
pub struct NormalizedSolution {
    /// kappa = K_T a / E*.
    pub kappa: f64,
    /// Q / (mu P).
    pub load_ratio: f64,
    /// c / a, the microslip zone's half-width.
    pub zone: f64,
    /// theta = arccos(c / a): what the solve finds, kept because 1 - c / a (about theta^2 / 2)
    /// falls as Q^2 and is lost in c / a's rounding below Q / mu P ~ 1e-8.
    pub angle: f64,
    /// The constant D of (H11'): (pi / 2) s E* / (mu p0 a) minus the shear's log potential,
    /// the same at every x (it holds the rigid shift).
    pub shift: f64,
    /// phi = q / (mu p0) at the collocation points u_i = x / c.
    pub shear: Vec<f64>,
}

impl NormalizedSolution {
    /// The solution's fields on `collocation`.
    fn fields<'a>(&'a self, collocation: &'a Collocation) -> Fields<'a> {
        Fields {
            collocation,
            kappa: self.kappa,
            zone: self.zone,
            angle: self.angle,
            shift: self.shift,
            shear: &self.shear,
        }
    }

    /// q / (mu p0) at t = x / a (H10), inside or beyond the microslip zone.
    pub fn shear(&self, collocation: &Collocation, t: f64) -> f64 {
        self.fields(collocation).shear(t)
    }

    /// s E* / (mu p0 a) at t = x / a: q / K_T in the microslip zone, by (H13)'s potential beyond
    /// it; at the edge beyond the contact.
    pub fn slip(&self, collocation: &Collocation, t: f64) -> f64 {
        self.fields(collocation).slip(t)
    }

    /// s E* / (mu p0 a) at t = x / a <= 1 by (H13)'s potential wherever t lies: beyond the
    /// microslip zone it is [`NormalizedSolution::slip`]; inside it, it must equal q / K_T,
    /// which the collocation imposes at its points only.
    pub fn potential_slip(&self, collocation: &Collocation, t: f64) -> f64 {
        self.fields(collocation).potential_slip(t)
    }

    /// phi = q / (mu p0) at t = x / a in the microslip zone by its polynomial interpolant on
    /// the mesh (what [`NormalizedSolution::shear`] uses for kappa above [`NYSTROM_BELOW`]).
    pub fn interpolated_shear(&self, collocation: &Collocation, t: f64) -> f64 {
        if self.zone == 0.0 {
            return 0.0;
        }
        collocation.interpolate(&self.shear, t.abs() / self.zone)
    }

    /// The edge slip s(a) E* / (mu p0 a).
    pub fn edge_slip(&self, collocation: &Collocation) -> f64 {
        self.slip(collocation, 1.0)
    }

    /// Q / (mu P) this solution carries (H13'): (4 / pi) times the integral of phi over [0, 1],
    /// the microslip zone's share from the nodal values, the strips' in closed form.
    pub fn carried(&self, collocation: &Collocation) -> f64 {
        carried(collocation, self.zone, self.angle, &self.shear)
    }
}

/// (H13'): (4 / pi) (c / a times the integral over u of phi(c u) + the strips' area): a sum of
/// positive terms, so a small load is carried to full relative precision.
fn carried(collocation: &Collocation, zone: f64, angle: f64, shear: &[f64]) -> f64 {
    let integral: f64 = collocation
        .weights
        .iter()
        .zip(shear)
        .map(|(w, f)| w * f)
        .sum();
    4.0 / PI * (zone * integral + strip_area(angle))
}

/// Below this kappa the shear inside the microslip zone is evaluated as K_T times (H13)'s
/// potential (the Nystrom interpolant: the kernel's integral smooths the nodal values' error,
/// and the law multiplies it by kappa); above it, by the nodal values' polynomial interpolant
/// (whose error does not grow with kappa). Both are about 1e-5 of mu p0 here (docs/theory.md
/// (H14)).
pub const NYSTROM_BELOW: f64 = 30.0;

/// One regularized solution's fields, read from its nodal values.
struct Fields<'a> {
    collocation: &'a Collocation,
    kappa: f64,
    zone: f64,
    angle: f64,
    shift: f64,
    shear: &'a [f64],
}

impl Fields<'_> {
    /// q / (mu p0) at t = x / a (H10): phi inside the microslip zone (never below 0 nor above
    /// the pressure's shape), sqrt(1 - t^2) in the sliding zones, 0 beyond the contact.
    fn shear(&self, t: f64) -> f64 {
        let t = t.abs();
        if t >= 1.0 {
            return 0.0;
        }
        if t >= self.zone || self.zone == 0.0 {
            return edge_root(t);
        }
        let inside = if self.kappa < NYSTROM_BELOW {
            self.kappa * self.potential_slip(t)
        } else {
            self.collocation.interpolate(self.shear, t / self.zone)
        };
        inside.clamp(0.0, edge_root(t))
    }

    /// s E* / (mu p0 a) at t = x / a (taken at the edge beyond the contact): q / (kappa mu p0)
    /// inside the microslip zone (the law itself), (H13) beyond it.
    fn slip(&self, t: f64) -> f64 {
        let t = t.abs().min(1.0);
        if t < self.zone {
            return self.shear(t) / self.kappa;
        }
        self.potential_slip(t)
    }

    /// (H13') in a sliding strip at t = cos `alpha` (alpha <= theta): 1 - t = 2 sin^2(alpha / 2)
    /// keeps its digits where t itself rounds to 1 (the strips are O(Q^2) wide).
    fn strip_slip(&self, alpha: f64) -> f64 {
        let t = alpha.cos();
        if self.zone == 0.0 {
            return (2.0 / PI) * (self.shift + FRAC_PI_2 * t * t);
        }
        let mut row = vec![0.0; self.collocation.size()];
        self.collocation.kernel_row(t / self.zone, &mut row);
        let potential: f64 = row.iter().zip(self.shear).map(|(k, f)| k * f).sum();
        let strips = StripRule::new(self.angle).potential(2.0 * (0.5 * alpha).sin().powi(2));
        ((2.0 / PI) * (self.shift + self.zone * potential + strips)).max(0.0)
    }

    /// (H13'): s E* / (mu p0 a) = (2 / pi) (D + the microslip zone's potential at t / zone +
    /// the strips' E(t)), at any t = |x| / a <= 1; never below 0 (the slip of a positive shear
    /// under q = K_T s is positive: a negative value could only be rounding).
    fn potential_slip(&self, t: f64) -> f64 {
        let t = t.abs().min(1.0);
        if self.zone == 0.0 {
            // The whole contact slides: the shift alone (s(0) = mu p0 / K_T) and Hertz's
            // quadratic potential.
            return (2.0 / PI) * (self.shift + FRAC_PI_2 * t * t);
        }
        let mut row = vec![0.0; self.collocation.size()];
        self.collocation.kernel_row(t / self.zone, &mut row);
        let potential: f64 = row.iter().zip(self.shear).map(|(k, f)| k * f).sum();
        let strips = StripRule::new(self.angle).potential(1.0 - t);
        ((2.0 / PI) * (self.shift + self.zone * potential + strips)).max(0.0)
    }
}

/// One linear solve of (H11') at theta = arccos(c / a): the shear and the shift, and (H13')'s
/// Q / mu P.
pub(super) struct AtZone {
    pub(super) shear: Vec<f64>,
    pub(super) shift: f64,
    pub(super) carried: f64,
}

impl AtZone {
    /// The unknowns `solution` (the shear, then the shift) at theta = `angle`.
    pub(super) fn new(collocation: &Collocation, angle: f64, mut solution: Vec<f64>) -> AtZone {
        let shift = solution.pop().unwrap_or(0.0);
        AtZone {
            carried: carried(collocation, angle.cos(), angle, &solution),
            shear: solution,
            shift,
        }
    }
}

/// (H11')'s matrix at c / a = `zone` for epsilon = pi / (2 kappa): epsilon phi(u) - gamma
/// integral_0^1 phi(gamma v) K(u, v) dv - D at the collocation points, and without the epsilon
/// phi term (substituted into the right-hand side) at u = 1.
pub(super) fn system_matrix(collocation: &Collocation, epsilon: f64, zone: f64) -> Vec<f64> {
    let n = collocation.size();
    let size = n + 1;
    let mut matrix = vec![0.0; size * size];
    for i in 0..size {
        let row = &collocation.kernel[i * n..(i + 1) * n];
        for (j, k) in row.iter().enumerate() {
            matrix[i * size + j] = -zone * k;
        }
        matrix[i * size + n] = -1.0;
        if i < n {
            matrix[i * size + i] += epsilon;
        }
    }
    matrix
}

/// (H11')'s right-hand side at theta = `angle`: the strips' potential E(gamma u) at the
/// collocation points and, less epsilon phi(1) = epsilon sqrt(1 - gamma^2), at u = 1;
/// `strips(1 - t)` is E(t).
pub(super) fn system_rhs(
    collocation: &Collocation,
    epsilon: f64,
    angle: f64,
    strips: impl Fn(f64) -> f64,
) -> Vec<f64> {
    let n = collocation.size();
    // 1 - gamma, exact for a small angle.
    let width = 2.0 * (0.5 * angle).sin().powi(2);
    let mut rhs = vec![0.0; n + 1];
    for (i, r) in rhs.iter_mut().enumerate() {
        let u = collocation.nodes.get(i).copied().unwrap_or(1.0);
        // 1 - gamma u = (1 - u) + u (1 - gamma), both exact.
        *r = strips((1.0 - u) + u * width);
        if i == n {
            *r -= epsilon * angle.sin();
        }
    }
    rhs
}

/// Solves (H11') at c / a = cos `angle` for kappa = `kappa`: epsilon phi(u) - gamma integral_0^1
/// phi(gamma v) K(u, v) dv - D = E(gamma u) at the collocation points and, with phi(1) = sqrt(1 -
/// gamma^2) substituted, at u = 1 (the edge condition); `None` when the matrix is singular. The
/// reference: a fresh factorization and the graded strips at every call.
pub(super) fn solve_at(collocation: &Collocation, kappa: f64, angle: f64) -> Option<AtZone> {
    let size = collocation.size() + 1;
    let epsilon = FRAC_PI_2 / kappa;
    let mut matrix = system_matrix(collocation, epsilon, angle.cos());
    let mut rhs = system_rhs(collocation, epsilon, angle, |one_minus_t| {
        strip_potential(angle, one_minus_t)
    });
    let shift = solve_with_constant(&mut matrix, size, &mut rhs)?;
    rhs.push(shift);
    Some(AtZone::new(collocation, angle, rhs))
}

/// The small-kappa limit of c / a (H15): the root of (2 / pi) (gamma sqrt(1 - gamma^2) +
/// arccos gamma) = Q / mu P, both bodies rigid beside the interface.
pub fn compliant_limit_zone(load_ratio: f64) -> f64 {
    compliant_limit_angle(load_ratio).cos()
}

/// [`compliant_limit_zone`]'s theta = arccos gamma.
fn compliant_limit_angle(load_ratio: f64) -> f64 {
    let target = load_ratio.clamp(0.0, 1.0);
    // In theta = arccos gamma the function (2 / pi) (sin theta cos theta + theta) rises from 0
    // to 1 with slope (4 / pi) cos^2 theta: Newton from the side where it is concave, safeguarded.
    let (mut lo, mut hi) = (0.0, FRAC_PI_2);
    let mut theta = FRAC_PI_2 * target;
    for _ in 0..100 {
        let f = (2.0 / PI) * (theta.sin() * theta.cos() + theta) - target;
        if f > 0.0 {
            hi = theta;
        } else {
            lo = theta;
        }
        let slope = (4.0 / PI) * theta.cos().powi(2);
        let mut next = theta - f / slope;
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        if (next - theta).abs() <= 1e-16 {
            theta = next;
            break;
        }
        theta = next;
    }
    theta
}

/// Where the root search on c stops: |Q(c) / Q - 1| below it (relative: (H13') carries a small
/// load to full precision, so the stop is as tight at Q = 1e-300 mu P as at mu P / 2).
pub(super) const STOP: f64 = 1e-12;

/// The regularized solution on `mesh` for kappa = `kappa` > 0 and Q / mu P = `load_ratio` in
/// [0, 1] (H14): theta = arccos(c / a) from Q(theta) = Q by the secant method kept inside a
/// bracket; Q(theta) rises from 0 (theta = 0) to mu P (theta = pi / 2), linearly near 0 (the
/// elastic asymptote (H17)), so the first secant, through the origin, is already close at any
/// small load.
pub fn solve_normalized(
    collocation: &Collocation,
    kappa: f64,
    load_ratio: f64,
) -> NormalizedSolution {
    let load_ratio = load_ratio.clamp(0.0, 1.0);
    if let Some(done) = trivial(collocation, kappa, load_ratio) {
        return done;
    }
    let found = find_angle(load_ratio, cold_start(kappa, load_ratio), None, |theta| {
        solve_at(collocation, kappa, theta)
    });
    finish(collocation, kappa, load_ratio, found)
}

/// The answers at Q = 0 (no shear, no slip) and Q = mu P (gross slip: no microslip zone, s(0) =
/// mu p0 / K_T), which need no solve.
pub(super) fn trivial(
    collocation: &Collocation,
    kappa: f64,
    load_ratio: f64,
) -> Option<NormalizedSolution> {
    let n = collocation.size();
    if load_ratio == 0.0 {
        Some(normalized(kappa, load_ratio, 0.0, 0.0, vec![0.0; n]))
    } else if load_ratio == 1.0 {
        Some(normalized(
            kappa,
            load_ratio,
            FRAC_PI_2,
            FRAC_PI_2 / kappa,
            vec![0.0; n],
        ))
    } else {
        None
    }
}

fn normalized(
    kappa: f64,
    load_ratio: f64,
    angle: f64,
    shift: f64,
    shear: Vec<f64>,
) -> NormalizedSolution {
    NormalizedSolution {
        kappa,
        load_ratio,
        zone: if angle >= FRAC_PI_2 { 0.0 } else { angle.cos() },
        angle,
        shift,
        shear,
    }
}

/// The solution from [`find_angle`]'s answer.
pub(super) fn finish(
    collocation: &Collocation,
    kappa: f64,
    load_ratio: f64,
    found: Option<(f64, AtZone)>,
) -> NormalizedSolution {
    match found {
        Some((angle, at)) => normalized(kappa, load_ratio, angle, at.shift, at.shear),
        // Never met: every matrix singular. Mindlin's zone with no shear is finite at least.
        None => normalized(
            kappa,
            load_ratio,
            mindlin_stick_ratio(load_ratio).acos(),
            FRAC_PI_2 / kappa,
            vec![0.0; collocation.size()],
        ),
    }
}

/// The first theta of a solve with nothing known: between the compliant limit (H15) and
/// Mindlin's, weighted by kappa.
pub(super) fn cold_start(kappa: f64, load_ratio: f64) -> f64 {
    let soft = compliant_limit_angle(load_ratio);
    let stiff = mindlin_stick_ratio(load_ratio).acos();
    (soft + kappa * stiff) / (1.0 + kappa)
}

/// theta with Q(theta) = Q from `start`, 0 < Q / mu P = `load_ratio` < 1, `at` solving (H11')
/// at a theta: the secant method kept inside the bracket [0, pi / 2]. Its first step is
/// Newton's with `slope` = d theta / d(Q / mu P) when one is known (a neighbour's along a
/// sweep), else the secant through Q(0) = 0. The best point met, with its solve.
pub(super) fn find_angle(
    load_ratio: f64,
    start: f64,
    slope: Option<f64>,
    mut at: impl FnMut(f64) -> Option<AtZone>,
) -> Option<(f64, AtZone)> {
    let (mut lo, mut hi) = (0.0, FRAC_PI_2);
    let mut theta = start.clamp(1e-300, FRAC_PI_2 * (1.0 - 1e-6));
    // The previous point of the secant: Q(0) = 0.
    let mut previous = (0.0, -load_ratio);
    let mut slope = slope.filter(|s| s.is_finite() && *s > 0.0);
    let mut best: Option<(f64, f64, AtZone)> = None;
    for _ in 0..100 {
        let Some(solved) = at(theta) else {
            // A singular matrix (never met): move inside the bracket and go on.
            theta = 0.5 * (lo + hi);
            continue;
        };
        let f = solved.carried - load_ratio;
        if f > 0.0 {
            hi = theta;
        } else {
            lo = theta;
        }
        let closer = best.as_ref().is_none_or(|(_, g, _)| f.abs() < g.abs());
        let step_from = previous;
        previous = (theta, f);
        if closer {
            best = Some((theta, f, solved));
        }
        if f.abs() <= STOP * load_ratio {
            break;
        }
        // The ratio first: f and theta are both O(Q), and their product underflows below Q ~
        // 1e-160 mu P.
        let mut next = match slope.take() {
            Some(s) => theta - f * s,
            None => theta - (theta - step_from.0) * (f / (f - step_from.1)),
        };
        if !(next > lo && next < hi && next.is_finite()) {
            // Bisect, geometrically while the bracket spans decades.
            next = if lo > 0.0 && hi > 4.0 * lo {
                (lo * hi).sqrt()
            } else if lo == 0.0 {
                0.25 * hi
            } else {
                0.5 * (lo + hi)
            };
        }
        if (next - theta).abs() <= 1e-15 * theta {
            break;
        }
        theta = next;
    }
    best.map(|(angle, _, solved)| (angle, solved))
}

/// Answers [`Cylinder::regularized`] keeps (about 1 KiB each), the most recently asked for
/// last: the faces of one model (its point, zone strip, profiles and quantities) ask for the same
/// solve several times per frame, and a cycle's branches ask for its amplitude at every point.
#[derive(Default)]
struct KeptAnswers(Vec<RegularizedState>);

impl KeptAnswers {
    const SIZE: usize = 8;

    fn find(&mut self, cylinder: &Cylinder, newtons: f64) -> Option<RegularizedState> {
        let i = self
            .0
            .iter()
            .position(|s| s.cylinder == *cylinder && s.load == newtons)?;
        let state = self.0.remove(i);
        self.0.push(state);
        Some(state)
    }

    fn keep(&mut self, state: RegularizedState) {
        if self.0.len() >= Self::SIZE {
            self.0.remove(0);
        }
        self.0.push(state);
    }
}

/// The regularized answer at one tangential load, on the default mesh ([`CollocationMesh::DEFAULT`]): a
/// microslip zone |x| < c at the centre where q = K_T s < mu p, sliding at q = mu p beyond.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RegularizedState {
    cylinder: Cylinder,
    /// Q (N/mm).
    load: f64,
    /// c / a.
    zone: f64,
    /// theta = arccos(c / a).
    angle: f64,
    /// The shift of (H11').
    shift: f64,
    /// phi = q / (mu p0) at the default mesh's collocation points.
    shear: [f64; DEFAULT_UNKNOWNS],
}

impl Cylinder {
    /// The regularized law's answer at `load` ((H10)-(H14), the default mesh). A solve is a
    /// function call: outside a [`family::scope`] it is the cold reference
    /// ([`solve_normalized`]), the same bits whatever was solved before; inside one (a sweep, a
    /// target scan, a fit, a cycle) it continues from that scope's earlier solves of the same
    /// K_T a / E* ([`super::continued`]: a sweep's point costs one linear solve), the cold answer
    /// to about 1e-12. The last answers are kept (`KeptAnswers`), per thread outside a scope
    /// (cold, so a kept answer is a new solve's bits) and in the scope's memory inside one.
    pub fn regularized(&self, load: TangentialLoad) -> RegularizedState {
        thread_local! {
            static COLD: std::cell::RefCell<KeptAnswers> =
                const { std::cell::RefCell::new(KeptAnswers(Vec::new())) };
        }
        let newtons = load.newtons_per_mm();
        let scoped = family::kept(|kept: &mut KeptAnswers| {
            kept.find(self, newtons).unwrap_or_else(|| {
                let state = self.solve_regularized(load);
                kept.keep(state);
                state
            })
        });
        if let Some(state) = scoped {
            return state;
        }
        if let Some(state) = COLD.with(|kept| kept.borrow_mut().find(self, newtons)) {
            return state;
        }
        let state = self.solve_regularized(load);
        COLD.with(|kept| kept.borrow_mut().keep(state));
        state
    }

    /// [`Cylinder::regularized`] without the kept answer.
    fn solve_regularized(&self, load: TangentialLoad) -> RegularizedState {
        let solution = super::continued::solve(
            self.stiffness_group(),
            load.newtons_per_mm() / self.gross_slip_load(),
        );
        let mut shear = [0.0; DEFAULT_UNKNOWNS];
        for (d, s) in shear.iter_mut().zip(&solution.shear) {
            *d = *s;
        }
        RegularizedState {
            cylinder: *self,
            load: load.newtons_per_mm(),
            zone: solution.zone,
            angle: solution.angle,
            shift: solution.shift,
            shear,
        }
    }
}

impl Cylinder {
    /// The K_T (MPa/mm) at which this contact's regularized edge slip s(a) at `load` equals
    /// `edge_slip` (mm), all else as in this contact: what an FE result of s(a) says about the
    /// stiffness its code really used. s(a) falls with K_T at every load (H16), from large values
    /// at the softest accepted K_T towards Mindlin's, so there is at most one answer; `None` when
    /// no K_T in the accepted domain gives it (at Q = 0, or an s(a) at or below Mindlin's).
    pub fn stiffness_for_edge_slip(&self, load: TangentialLoad, edge_slip: f64) -> Option<f64> {
        // K_T = min e^k, k in [0, ln(max / min)]: the root finder's bracket starts at 0.
        let min = Domain::STIFFNESS.min();
        let at = |k: f64| {
            self.with_tangential_stiffness(min * k.exp())
                .map(|c| c.regularized(load).edge_slip())
        };
        let span = (Domain::STIFFNESS.max() / min).ln();
        let (soft, stiff) = (at(0.0).ok()?, at(span).ok()?);
        if !(edge_slip > 0.0 && (stiff..=soft).contains(&edge_slip)) {
            return None;
        }
        // Relative misfit, so that the root finder sees numbers near 1 whatever the scale.
        let k = find_root_in_bracket(
            |k| at(k).map_or(f64::NAN, |s| s / edge_slip - 1.0),
            0.0,
            span,
        );
        Some(min * k.exp())
    }
}

impl RegularizedState {
    /// The normalized form (a copy of the nodal values).
    pub fn normalized(&self) -> NormalizedSolution {
        NormalizedSolution {
            kappa: self.cylinder.stiffness_group(),
            load_ratio: self.load / self.cylinder.gross_slip_load(),
            zone: self.zone,
            angle: self.angle,
            shift: self.shift,
            shear: self.shear.to_vec(),
        }
    }

    /// The contact it is of.
    pub fn cylinder(&self) -> &Cylinder {
        &self.cylinder
    }

    /// Tangential line load Q (N/mm).
    pub fn load(&self) -> f64 {
        self.load
    }

    /// Half-width c of the microslip zone (mm), where q = K_T s < mu p.
    pub fn micro_half_width(&self) -> f64 {
        self.zone * self.cylinder.half_width()
    }

    /// c / a (-).
    pub fn zone_ratio(&self) -> f64 {
        self.zone
    }

    /// Width a - c of each sliding zone at the contact's edges (mm).
    /// From 1 - c / a = 2 sin^2(theta / 2), which keeps its digits when the strips are far
    /// narrower than c / a's rounding (a - c falls as Q^2).
    pub fn edge_slide_width(&self) -> f64 {
        self.cylinder.half_width() * 2.0 * (0.5 * self.angle).sin().powi(2)
    }

    /// theta = arccos(c / a) (rad): 1 - c / a = 2 sin^2(theta / 2) to full precision.
    pub fn zone_angle(&self) -> f64 {
        self.angle
    }

    /// The solution's fields on the default mesh.
    fn fields(&self) -> Fields<'_> {
        Fields {
            collocation: Collocation::default_mesh(),
            kappa: self.cylinder.stiffness_group(),
            zone: self.zone,
            angle: self.angle,
            shift: self.shift,
            shear: &self.shear,
        }
    }

    /// mu p0 (MPa).
    fn strength(&self) -> f64 {
        self.cylinder.params().friction * self.cylinder.peak_pressure()
    }

    /// Shear traction q(x) (MPa): K_T s(x) in the microslip zone, mu p(x) in the sliding zones,
    /// 0 outside the contact.
    pub fn shear_at(&self, x: f64) -> f64 {
        if self.load == 0.0 {
            return 0.0;
        }
        self.strength() * self.fields().shear(x / self.cylinder.half_width())
    }

    /// Relative tangential slip s(x) (mm), positive towards +x; taken at the edge beyond the
    /// contact.
    pub fn slip_at(&self, x: f64) -> f64 {
        if self.load == 0.0 {
            return 0.0;
        }
        self.cylinder.slip_scale() * self.fields().slip(x / self.cylinder.half_width())
    }

    /// The slip at the contact's edge s(a) (mm): the fretting slip amplitude.
    pub fn edge_slip(&self) -> f64 {
        self.slip_at(self.cylinder.half_width())
    }

    /// The plastic slip s - mu p / K_T (mm, never below 0) at x = a cos `alpha` in a sliding
    /// strip (0 <= alpha <= theta, [`RegularizedState::zone_angle`]): what the friction works
    /// through on first loading. In the angle, because the strips are O(Q^2) wide and x = a cos
    /// alpha would round to a below Q ~ 1e-8 mu P.
    pub fn strip_plastic_slip(&self, alpha: f64) -> f64 {
        if self.load == 0.0 {
            return 0.0;
        }
        let fields = self.fields();
        let elastic = alpha.sin() / fields.kappa;
        self.cylinder.slip_scale() * (fields.strip_slip(alpha) - elastic).max(0.0)
    }

    /// The slip at the centre s(0) (mm).
    pub fn centre_slip(&self) -> f64 {
        self.slip_at(0.0)
    }

    /// The largest q / (mu p0) (-): at the microslip zone's edge, where q = mu p(c) = mu p0 sin
    /// theta, or at a collocation point inside it if larger there (it never is: q grows
    /// towards c).
    pub fn peak_shear_ratio(&self) -> f64 {
        if self.load == 0.0 {
            return 0.0;
        }
        let at_edge = if self.zone == 0.0 {
            1.0
        } else {
            self.angle.sin()
        };
        self.shear.iter().copied().fold(at_edge, f64::max)
    }

    /// Unloaded; microslip at the centre and macroslip at the edges (for every 0 < Q < mu P:
    /// p vanishes at the edges, K_T s does not); the whole contact sliding at Q = mu P.
    pub fn regime(&self) -> Regime {
        if self.load == 0.0 {
            Regime::UNLOADED
        } else if self.zone == 0.0 {
            Regime::MACROSLIP
        } else {
            Regime::from_zones(&[Zone::Microslip, Zone::Macroslip])
        }
    }
}

impl Solution for RegularizedState {
    /// The edge slip s(a) (mm).
    fn response(&self) -> f64 {
        self.edge_slip()
    }

    fn regime(&self) -> Regime {
        RegularizedState::regime(self)
    }

    /// The microslip zone's half-width c (mm).
    fn zone_end(&self) -> f64 {
        self.micro_half_width()
    }
}
