//! The regularized cylinder solved along a family (issue 47): the answer depends on kappa = K_T
//! a / E* and Q / mu P only, so a sweep over Q at fixed K_T, a `solve --vary Q` scan and a fit's
//! rows at one trial K_T are each one family, in which the solution moves little from one point
//! to the next. Inside a [`family::scope`] (which those operations open), [`solve`] keeps the
//! last few solved points of the last few kappas and each one's last factorization of (H11')'s
//! matrix, and starts from them:
//! - theta is guessed by extrapolating the neighbours' theta(Q) (a cubic through the four nearest), and
//!   the first secant step is Newton's with the neighbours' slope; along a fine sweep the guess
//!   already meets the stop, so a point costs one linear solve;
//! - the matrix changes with c / a only, so a neighbour's LU factors serve as the preconditioner
//!   of an iterative refinement, O(n^2) a step instead of the O(n^3) factorization (refactored
//!   when c / a moved too far for the refinement to converge in a few steps);
//! - the strips' potential is integrated by product integration (`StripRule`), a few dozen
//!   evaluations a row instead of up to a thousand.
//!
//! Each answer is a root of the same equations to the same stop (|Q(theta) / Q - 1| <= 1e-12), so
//! it is the cold solve's ([`super::regularized::solve_normalized`], the reference) to about
//! 1e-12, whatever came before in the scope: tests hold the two within 1e-9 over kappa in [1e-6,
//! 1e6] and Q / mu P from 1e-300 to 1, in sweeps up and down and in random order. Outside a scope
//! [`solve`] is the cold solve itself, so a plain solve never depends on what ran before it; so
//! is a family's first point inside one.

use std::f64::consts::FRAC_PI_2;

use super::collocation::Collocation;
use super::quadrature::{dot, lu_factor, lu_solve};
use super::regularized::{
    AtZone, NormalizedSolution, cold_start, find_angle, finish, solve_normalized, system_matrix,
    system_rhs, trivial,
};
use super::strips::StripRule;
use crate::kernel::family;

/// Solved points kept, and the nearest of them the guess extrapolates from: more are kept than
/// used so that a cycle's branch (which alternates its amplitude with the loads along it) still
/// finds its neighbours.
const KEPT: usize = 8;
const USED: usize = 4;

/// The refinement converges by about |delta gamma| / gamma a step: beyond this relative change of
/// c / a since the factorization, factor anew (a factorization costs about as much as ten
/// refinement steps; 1e-2 needs eight at most, and the first iterate, extrapolated from the
/// last solves, is usually far closer than the factors).
const REFACTOR_BEYOND: f64 = 1e-2;

/// Families kept in one scope: a fit's derivatives alternate K_T with K_T + h, a comparison its
/// rows' K_T, and each keeps its own neighbours.
const FAMILIES_KEPT: usize = 4;

/// What one scope keeps of a family.
struct Family {
    /// kappa (its bits: a different K_T a / E* is a different family).
    kappa: f64,
    /// The last solved points (Q / mu P, theta), newest last.
    points: Vec<(f64, f64)>,
    /// The LU factors of (H11')'s matrix at c / a = `zone`, with their row order.
    zone: f64,
    factors: Vec<f64>,
    pivots: Vec<usize>,
    /// The last two linear solves' unknowns and their c / a: the refinement's first iterate,
    /// extrapolated linearly in c / a, when near.
    last: Vec<f64>,
    last_zone: f64,
    before: Vec<f64>,
    before_zone: f64,
}

/// The families one [`family::scope`] keeps, the most recently solved last.
#[derive(Default)]
pub(super) struct Families(Vec<Family>);

/// The regularized solution on the default mesh for kappa and Q / mu P = `load_ratio`: inside a
/// [`family::scope`] continued from that scope's previous solves of the same kappa (equal to the
/// cold one to about 1e-12), outside it the cold reference [`solve_normalized`], bit for bit
/// whatever was solved before. A family's first point is the cold solve inside a scope too (so a
/// sweep's first row, and every row of a sweep over K_T, is the plain solve's bits).
pub fn solve(kappa: f64, load_ratio: f64) -> NormalizedSolution {
    family::kept(|families: &mut Families| families.solve(kappa, load_ratio))
        .unwrap_or_else(|| solve_normalized(Collocation::default_mesh(), kappa, load_ratio))
}

impl Families {
    /// [`solve`] continued from these families.
    pub(super) fn solve(&mut self, kappa: f64, load_ratio: f64) -> NormalizedSolution {
        let collocation = Collocation::default_mesh();
        let load_ratio = load_ratio.clamp(0.0, 1.0);
        if let Some(done) = trivial(collocation, kappa, load_ratio) {
            return done;
        }
        let kept = &mut self.0;
        let found = kept
            .iter()
            .position(|f| f.kappa.to_bits() == kappa.to_bits());
        let mut family = match found {
            Some(i) => kept.remove(i),
            None => Family::new(kappa),
        };
        let solution = if family.points.is_empty() {
            // A family's first point: the cold solve itself, so a sweep's first row (and each
            // row of a sweep over K_T, each its own family) is the plain solve's bits.
            let cold = solve_normalized(collocation, kappa, load_ratio);
            family.remember(load_ratio, cold.angle);
            cold
        } else {
            // From the kept points near, else (a jump) from the cold start.
            let (start, slope) = match family.guess(load_ratio) {
                Some((start, slope)) => (start, Some(slope)),
                None => (cold_start(kappa, load_ratio), None),
            };
            let found = find_angle(load_ratio, start, slope, |theta| {
                family.solve_at(collocation, theta)
            });
            if let Some((angle, at)) = &found {
                // Kept for the next guess with the Newton correction the neighbours' slope
                // gives: a root is accepted within STOP, and extrapolating from roots with that
                // much scatter would miss the next one by more than STOP (about 15 times as much
                // for a cubic), costing a second solve.
                let corrected = slope.map_or(*angle, |s| angle - (at.carried - load_ratio) * s);
                family.remember(load_ratio, corrected);
            }
            finish(collocation, kappa, load_ratio, found)
        };
        // The most recent last; the least recent dropped beyond FAMILIES_KEPT.
        kept.push(family);
        if kept.len() > FAMILIES_KEPT {
            kept.remove(0);
        }
        solution
    }
}

impl Family {
    fn new(kappa: f64) -> Family {
        Family {
            kappa,
            points: Vec::with_capacity(KEPT + 1),
            zone: f64::NAN,
            factors: Vec::new(),
            pivots: Vec::new(),
            last: Vec::new(),
            last_zone: f64::NAN,
            before: Vec::new(),
            before_zone: f64::NAN,
        }
    }

    /// theta at `load_ratio` and d theta / d(Q / mu P) there from the [`USED`] kept points
    /// nearest it, by the polynomial through them; `None` with no point near enough to extrapolate from: a load
    /// within half of the newest's (near 0 theta spans decades) or, from 0.05 on, within 0.05.
    fn guess(&self, load_ratio: f64) -> Option<(f64, f64)> {
        let mut points = self.points.clone();
        points.sort_by(|a, b| {
            (a.0 - load_ratio)
                .abs()
                .total_cmp(&(b.0 - load_ratio).abs())
        });
        points.truncate(USED);
        let &(newest, _) = points.first()?;
        let (gap, smaller) = ((load_ratio - newest).abs(), load_ratio.min(newest));
        if gap > 0.5 * smaller && (gap > 0.05 || smaller < 0.05) {
            return None;
        }
        // Lagrange's polynomial and its derivative at the load.
        let (mut value, mut slope) = (0.0, 0.0);
        for (i, &(ri, ti)) in points.iter().enumerate() {
            let mut basis = 1.0;
            let mut derivative = 0.0;
            for (j, &(rj, _)) in points.iter().enumerate() {
                if j == i {
                    continue;
                }
                let factor = (load_ratio - rj) / (ri - rj);
                derivative = derivative * factor + basis / (ri - rj);
                basis *= factor;
            }
            value += ti * basis;
            slope += ti * derivative;
        }
        if points.len() == 1 {
            // One neighbour: theta grows about as Q near it (it does at small loads).
            let (r, t) = points[0];
            value = t * load_ratio / r;
            slope = t / r;
        }
        (value.is_finite() && value > 0.0 && value < FRAC_PI_2).then_some((value, slope))
    }

    /// Keeps (Q / mu P, theta), dropping the oldest point beyond [`KEPT`] and any at the same
    /// load.
    fn remember(&mut self, load_ratio: f64, angle: f64) {
        self.points.retain(|&(r, _)| r != load_ratio);
        self.points.push((load_ratio, angle));
        if self.points.len() > KEPT {
            self.points.remove(0);
        }
    }

    /// (H11') at theta = `angle`, the factors kept from a nearby c / a refined to this one's
    /// answer, or refactored.
    fn solve_at(&mut self, collocation: &Collocation, angle: f64) -> Option<AtZone> {
        let epsilon = FRAC_PI_2 / self.kappa;
        let zone = angle.cos();
        let rule = StripRule::new(angle);
        let rhs = system_rhs(collocation, epsilon, angle, |one_minus_t| {
            rule.potential(one_minus_t)
        });
        let near = (zone - self.zone).abs() <= REFACTOR_BEYOND * zone;
        let x = match near.then(|| self.refine(collocation, epsilon, zone, &rhs)) {
            Some(Some(x)) => x,
            _ => {
                let size = rhs.len();
                self.factors = system_matrix(collocation, epsilon, zone);
                self.pivots = vec![0; size];
                if !lu_factor(&mut self.factors, size, &mut self.pivots) {
                    self.zone = f64::NAN;
                    return None;
                }
                self.zone = zone;
                let mut x = rhs;
                lu_solve(&self.factors, size, &self.pivots, &mut x);
                x
            }
        };
        std::mem::swap(&mut self.before, &mut self.last);
        self.before_zone = self.last_zone;
        self.last.clone_from(&x);
        self.last_zone = zone;
        Some(AtZone::new(collocation, angle, x))
    }

    /// The solution of M(zone) x = `rhs` by iterative refinement on the kept factors of
    /// M(self.zone): x <- x + M0^-1 (rhs - M x) until the shear's and the shift's corrections
    /// are at rounding (or stall there); `None` if they do not get there in a few steps.
    fn refine(
        &self,
        collocation: &Collocation,
        epsilon: f64,
        zone: f64,
        rhs: &[f64],
    ) -> Option<Vec<f64>> {
        let size = rhs.len();
        let n = size - 1;
        if zone == self.zone {
            let mut x = rhs.to_vec();
            lu_solve(&self.factors, size, &self.pivots, &mut x);
            return Some(x);
        }
        // From the last solves' unknowns when their c / a is nearer than the factors'.
        let mut x = if (self.last_zone - zone).abs() < (self.zone - zone).abs() {
            let step = (zone - self.last_zone) / (self.last_zone - self.before_zone);
            if step.is_finite() && step.abs() <= 4.0 && self.before.len() == size {
                let (last, before) = (&self.last, &self.before);
                last.iter()
                    .zip(before)
                    .map(|(l, b)| l + step * (l - b))
                    .collect()
            } else {
                self.last.clone()
            }
        } else {
            let mut x = rhs.to_vec();
            lu_solve(&self.factors, size, &self.pivots, &mut x);
            x
        };
        let mut residual = vec![0.0; size];
        let mut last = f64::INFINITY;
        for _ in 0..12 {
            // rhs - M x, M x = epsilon phi (not at u = 1) - gamma K phi - D.
            for (i, r) in residual.iter_mut().enumerate() {
                let potential = dot(&collocation.kernel[i * n..(i + 1) * n], &x[..n]);
                let own = if i < n { epsilon * x[i] } else { 0.0 };
                *r = rhs[i] - (own - zone * potential - x[n]);
            }
            lu_solve(&self.factors, size, &self.pivots, &mut residual);
            for (xi, d) in x.iter_mut().zip(&residual) {
                *xi += d;
            }
            let size_of = |v: &[f64]| v.iter().fold(0.0_f64, |m, e| m.max(e.abs()));
            let (shear, shift) = (size_of(&x[..n]), x[n].abs());
            let (d_shear, d_shift) = (size_of(&residual[..n]), residual[n].abs());
            let change = (d_shear / shear).max(d_shift / shift.max(f64::MIN_POSITIVE));
            // Done when this correction, or the next one it predicts (the steps shrink by
            // their ratio), is at rounding.
            let ratio = change / last;
            if change <= 1e-15 || (last.is_finite() && ratio < 0.1 && change * ratio <= 1e-16) {
                return Some(x);
            }
            if ratio > 0.5 {
                // Stalled: at rounding if small, else not converging.
                return (change <= 1e-12).then_some(x);
            }
            last = change;
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::cylinder::regularized::{STOP, solve_at, solve_normalized};

    fn close(a: f64, b: f64, tolerance: f64, what: &str) {
        assert!(
            (a - b).abs() <= tolerance,
            "{what}: continued {a:e}, cold {b:e}, apart {:e} > {tolerance:e}",
            (a - b).abs()
        );
    }

    fn largest(values: &[f64]) -> f64 {
        values.iter().fold(0.0_f64, |m, s| m.max(s.abs()))
    }

    /// The continued solution against the reference (cold) one. Each is a root of Q(theta) = Q
    /// to |Q(theta) / Q - 1| <= STOP, so their thetas may differ by up to 2 STOP Q / Q'(theta),
    /// which near gross slip (Q' ~ cos^2 theta) is more than 1e-9 of theta: there the reference
    /// itself is not defined more closely (c / a to 3e-7 at Q = 0.999999 mu P). So: the load
    /// the continued one carries within STOP (the cold one sometimes stops on its step, 1e-12
    /// past it); theta within 1e-9 plus that width (Q' measured at the cold
    /// theta); the slips at the edge and the centre (what `sweep` prints) within 1e-9; and the
    /// linear solve at one same theta by [`linear_solves_agree`].
    fn assert_agrees(families: &mut Families, kappa: f64, load_ratio: f64) {
        let collocation = Collocation::default_mesh();
        let cold = solve_normalized(collocation, kappa, load_ratio);
        let warm = families.solve(kappa, load_ratio);
        let what = |name: &str| format!("kappa {kappa:e}, Q / mu P {load_ratio:e}, {name}");
        let (w, c) = (warm.carried(collocation), cold.carried(collocation));
        close(w, load_ratio, STOP * load_ratio, &what("carried"));
        let width = if load_ratio > 0.0 && load_ratio < 1.0 {
            let h = 1e-7 * cold.angle;
            let shifted = solve_at(collocation, kappa, cold.angle + h).expect("regular");
            2.0 * STOP * load_ratio * h / (shifted.carried - c)
        } else {
            0.0
        };
        close(
            warm.angle,
            cold.angle,
            1e-9 * cold.angle + width,
            &what("theta"),
        );
        for t in [0.0, 1.0] {
            let (w, c) = (warm.slip(collocation, t), cold.slip(collocation, t));
            close(w, c, 1e-9 * c.abs(), &what("slip"));
        }
    }

    /// At one theta, the continued path's linear solve (product-integrated strips, refined on
    /// kept factors) against the reference's (graded strips, a fresh factorization): the shear
    /// at every node against its largest, the shift and the carried load, to 1e-9. The nodes at
    /// kappa = 1e6 to 1e-8: there epsilon = 1.6e-6 leaves a nearly first-kind equation whose
    /// condition carries the two strip quadratures' difference (5e-11 at most,
    /// `strips::tests::the_product_rule_agrees_with_the_graded_pieces`) to 5e-9 of the shear (theta = 1.5), a
    /// width the reference has as much as the continued path; what the solve answers (the load,
    /// the shift, the slips) stays within 1e-9.
    fn linear_solves_agree(family: &mut Family, angle: f64) {
        let collocation = Collocation::default_mesh();
        let warm = family.solve_at(collocation, angle).expect("regular");
        let cold = solve_at(collocation, family.kappa, angle).expect("regular");
        let what = |name: &str| format!("kappa {:e}, theta {angle:e}, {name}", family.kappa);
        let conditioned = if family.kappa > 1e5 { 1e-8 } else { 1e-9 };
        let scale = conditioned * largest(&cold.shear);
        for (w, c) in warm.shear.iter().zip(&cold.shear) {
            close(*w, *c, scale, &what("shear"));
        }
        close(
            warm.shift,
            cold.shift,
            1e-9 * cold.shift.abs(),
            &what("shift"),
        );
        close(
            warm.carried,
            cold.carried,
            1e-9 * cold.carried,
            &what("carried"),
        );
    }

    const KAPPAS: [f64; 7] = [1e-6, 1e-3, 0.64, 1.0, 30.0, 1e3, 1e6];
    const LOADS: [f64; 14] = [
        0.0, 1e-300, 1e-9, 1e-6, 1e-3, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.999999, 1.0,
    ];

    /// Over the grid, each point first as a family's first (no neighbour), then along it
    /// upwards, downwards and in a scrambled order, so each point is reached from neighbours
    /// far and near and the factorization is reused and refactored.
    #[test]
    fn continued_solves_are_the_cold_ones_to_1e_9() {
        for kappa in KAPPAS {
            for load in LOADS {
                assert_agrees(&mut Families::default(), kappa, load);
            }
            let mut families = Families::default();
            for load in LOADS.iter().chain(LOADS.iter().rev()) {
                assert_agrees(&mut families, kappa, *load);
            }
            for i in 0..LOADS.len() {
                assert_agrees(&mut families, kappa, LOADS[(i * 5) % LOADS.len()]);
            }
        }
    }

    /// The linear solves over kappa and theta from 1e-300 to nearly pi / 2, the factors kept
    /// from the theta before (refined when it is near, refactored when not).
    #[test]
    fn continued_linear_solves_are_the_cold_ones_to_1e_9() {
        for kappa in KAPPAS {
            let mut family = Family::new(kappa);
            for angle in [
                1e-300,
                1e-100,
                1e-5,
                0.1,
                0.5,
                0.5001,
                0.50011,
                1.0,
                1.5,
                FRAC_PI_2 - 1e-4,
            ] {
                linear_solves_agree(&mut family, angle);
            }
        }
    }

    /// A fine sweep (the case the continuation is for: one linear solve a point, the factors
    /// refined) at the bundled pad's kappa and near Mindlin, with the reference every few points.
    #[test]
    fn a_fine_sweep_is_the_cold_solves() {
        for kappa in [0.64, 64.0] {
            let mut families = Families::default();
            for i in 1..400 {
                let load = 0.3 + 1e-4 * i as f64;
                if i % 40 == 0 {
                    assert_agrees(&mut families, kappa, load);
                } else {
                    families.solve(kappa, load);
                }
            }
        }
    }

    /// Outside a scope [`solve`] is the cold solve, bit for bit, whatever was solved before;
    /// inside one it continues (and the scope's end forgets what it kept).
    #[test]
    fn outside_a_scope_the_solve_is_cold() {
        let collocation = Collocation::default_mesh();
        let cold = solve_normalized(collocation, 0.64, 0.5);
        let within = family::scope(|| {
            for i in 0..20 {
                solve(0.64, 0.45 + 0.005 * i as f64);
            }
            solve(0.64, 0.5)
        });
        assert_eq!(solve(0.64, 0.5), cold);
        // Continued from its neighbours, the root to its stop (checked to 1e-9 above), and not
        // the cold solve's bits: the scope did continue.
        assert_ne!(within, cold);
    }
}
