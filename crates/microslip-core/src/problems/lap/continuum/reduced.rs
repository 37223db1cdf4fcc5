//! The interface problem on the lap joint's m pair slips at given strengths (the Newton driver's
//! model, `numeric::newton`), the fixed point on its contact forces, and the state it reports.

use std::cell::RefCell;

use super::condensed::Condensed;
use super::mesh::Grid;
use super::*;
use crate::numeric::banded::{BandCholesky, NotPositiveDefinite, SymmetricBand};
use crate::numeric::interface::{InterfacePoint, Response};
use crate::numeric::newton::{self, Discretized};

/// The interface problem on the m pair slips at given strengths: the Newton driver's model.
pub(super) struct Reduced<'a> {
    pub(super) c: &'a Condensed,
    friction: f64,
    pressure: f64,
    /// The slips of the loads with every pair elastic and no plastic slip: base + load x unit.
    base: Vec<f64>,
    unit: Vec<f64>,
    /// Contact forces and Delta the same way.
    contact_base: Vec<f64>,
    contact_unit: Vec<f64>,
    delta_base: f64,
    delta_unit: f64,
    /// Jenkins strengths, mu times the contact forces of the fixed point's last iterate.
    strengths: Vec<f64>,
    points: Vec<InterfacePoint>,
    pub(super) slip: Vec<f64>,
    pub(super) load: f64,
    /// Residual scale (N/mm): the clamping force per width plus the transferred force per width.
    scale: f64,
    /// Joint width b (mm).
    width: f64,
    /// Delta's reading at the end of the clamping step (mm).
    clamping_delta: f64,
    /// The factored tangent and the sliding set it belongs to: the tangent S + diag(k_t - k)
    /// depends on nothing else, and the fixed point's solves mostly repeat the set.
    factor: RefCell<Option<(Vec<bool>, BandCholesky)>>,
}

/// A committed state of [`Reduced`], to restart an increment from.
#[derive(Debug, Clone)]
pub(super) struct State {
    points: Vec<InterfacePoint>,
    pub(super) slip: Vec<f64>,
    load: f64,
}

impl<'a> Reduced<'a> {
    pub(super) fn new(c: &'a Condensed, p: &LapParams, force: f64) -> Reduced<'a> {
        let m = c.pairs;
        let scale = p.pressure * p.length + force / (2.0 * p.width);
        Reduced {
            c,
            friction: p.friction,
            pressure: p.pressure,
            base: vec![0.0; m],
            unit: c.slip_p.iter().map(|s| s * p.pressure).collect(),
            contact_base: vec![0.0; m],
            contact_unit: c.contact_p.iter().map(|s| s * p.pressure).collect(),
            delta_base: 0.0,
            delta_unit: c.delta_p * p.pressure,
            strengths: vec![0.0; m],
            points: vec![InterfacePoint::default(); m],
            slip: vec![0.0; m],
            load: 0.0,
            scale,
            width: p.width,
            clamping_delta: 0.0,
            factor: RefCell::new(None),
        }
    }

    /// After the clamping step: P held, the load parameter becomes F (N) from 0.
    pub(super) fn start_force_step(&mut self) {
        self.clamping_delta = self.delta();
        let p = self.pressure;
        self.base = self.c.slip_p.iter().map(|s| s * p).collect();
        self.unit = self.c.slip_f.clone();
        self.contact_base = self.c.contact_p.iter().map(|s| s * p).collect();
        self.contact_unit = self.c.contact_f.clone();
        self.delta_base = self.c.delta_p * p;
        self.delta_unit = self.c.delta_f;
        self.load = 0.0;
    }

    pub(super) fn state(&self) -> State {
        State {
            points: self.points.clone(),
            slip: self.slip.clone(),
            load: self.load,
        }
    }

    pub(super) fn restore(&mut self, state: &State) {
        self.points.clone_from(&state.points);
        self.slip.clone_from(&state.slip);
        self.load = state.load;
    }

    /// The plastic slips q_i (mm) of the committed state.
    pub(super) fn plastic(&self) -> impl Iterator<Item = f64> + '_ {
        self.points.iter().map(|p| p.plastic_slip)
    }

    /// The contact forces of the committed state (N per mm of width): linear in the load and the
    /// pairs' Jenkins forces t_j = k_j (s_j - q_j). With t = S (s_f - s) the body's answer to the
    /// pair forces, the contact is the elastic contact minus R K0^-1 B^T times (t - k s) = -k q.
    pub(super) fn contact_forces(&self) -> Vec<f64> {
        let m = self.c.pairs;
        let kq: Vec<f64> = self
            .plastic()
            .zip(&self.c.stiffness)
            .map(|(q, k)| k * q)
            .collect();
        (0..m)
            .map(|i| {
                let row = &self.c.contact_per_pair[i * m..(i + 1) * m];
                self.contact_base[i]
                    + self.load * self.contact_unit[i]
                    + row.iter().zip(&kq).map(|(a, b)| a * b).sum::<f64>()
            })
            .collect()
    }

    pub(super) fn delta(&self) -> f64 {
        self.delta_base
            + self.load * self.delta_unit
            + self
                .plastic()
                .zip(&self.c.stiffness)
                .zip(&self.c.delta_per_pair)
                .map(|((q, k), d)| d * k * q)
                .sum::<f64>()
    }

    /// One increment to `load`; when its fixed point fails (nothing is committed then), two
    /// half increments, down to `cuts_left` halvings: a closer start is what the fixed point
    /// needs where the covers lift off (mu = 4 near 0.5 F_gross on the bundled joint, issue 36).
    pub(super) fn step_with_cuts(
        &mut self,
        load: f64,
        cuts_left: u32,
    ) -> Result<usize, NumericError> {
        let start = self.state();
        match self.step(load) {
            Err(NumericError::NoConvergence { .. }) if cuts_left > 0 => {
                self.restore(&start);
                let middle = 0.5 * (self.load + load);
                let first = self.step_with_cuts(middle, cuts_left - 1)?;
                Ok(first + self.step_with_cuts(load, cuts_left - 1)?)
            }
            Err(NumericError::NoConvergence { .. }) => {
                self.restore(&start);
                Err(NumericError::NoConvergence {
                    load,
                    cuts: MAX_CUTS,
                })
            }
            other => other,
        }
    }

    /// One increment to `load`: the fixed point on the contact forces, each iterate solved by
    /// Newton from the state committed at the previous increment. Returns the iterations.
    pub(super) fn step(&mut self, load: f64) -> Result<usize, NumericError> {
        let start = self.state();
        // First guess: the contact forces at the start of the increment, moved elastically.
        let mut contact: Vec<f64> = self
            .contact_forces()
            .iter()
            .zip(&self.contact_unit)
            .map(|(c, u)| c + (load - self.load) * u)
            .collect();
        let mut guess: Option<Vec<f64>> = None;
        // Aitken's relaxation of the contact forces (Irons and Tuck): each update moves by
        // omega times the change, omega from the last two changes r: omega_n = -omega_(n-1)
        // r_(n-1).(r_n - r_(n-1)) / |r_n - r_(n-1)|^2, the secant estimate of the best step along
        // them. The plain iteration (omega = 1) contracts slowly where mu is large (0.85 per
        // iteration at mu = 2) and falls into a two-state cycle with wide lift-off (mu = 5 on
        // the bundled joint), issue 36.
        let mut relaxation: f64 = 1.0;
        let mut previous: Option<Vec<f64>> = None;
        for iteration in 1..=MAX_CONTACT_ITERATIONS {
            self.restore(&start);
            // Newton starts from the last iterate's slips (the history is the increment's start).
            if let Some(slip) = guess.take() {
                self.slip = slip;
            }
            self.strengths = contact.iter().map(|c| self.friction * c.max(0.0)).collect();
            newton::load_to(self, load, 1)?;
            let next = self.contact_forces();
            let scale = next.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
            let change = next
                .iter()
                .zip(&contact)
                .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
            let residual: Vec<f64> = next.iter().zip(&contact).map(|(n, c)| n - c).collect();
            if let Some(last) = &previous {
                let (mut along, mut norm) = (0.0, 0.0);
                for (r, l) in residual.iter().zip(last) {
                    along += l * (r - l);
                    norm += (r - l) * (r - l);
                }
                if norm > 0.0 {
                    relaxation = (-relaxation * along / norm).clamp(MIN_RELAXATION, MAX_RELAXATION);
                }
            }
            for (c, r) in contact.iter_mut().zip(&residual) {
                *c += relaxation * r;
            }
            previous = Some(residual);
            guess = Some(self.slip.clone());
            if change <= CONTACT_TOLERANCE * scale {
                // The strengths of the converged contact forces (a last Newton solve would move
                // nothing beyond the tolerance).
                return Ok(iteration);
            }
        }
        Err(NumericError::NoConvergence { load, cuts: 0 })
    }

    /// The largest force F (N) up to which, from the clamped state, every pair sticks: the
    /// plastic slips stay those of the clamping step, and the answer is linear in F. With them
    /// fixed, the condensed equilibrium S (s - s_P - F s_F) = k q has the solution
    /// s = s_clamped + F s_F, so each pair's Jenkins force is t_c + F k s_F and its contact force
    /// c_c + F c_F: the pair sticks while |t_c + F k s_F| <= mu (c_c + F c_F), two inequalities
    /// linear in F. A pair already at its strength and loaded further gives 0.
    pub(super) fn stick_limit(&self) -> f64 {
        let contact = self.contact_forces();
        let mut limit = f64::INFINITY;
        for (i, c) in contact.iter().enumerate() {
            let k = self.c.stiffness[i];
            let shear = k * (self.slip[i] - self.points[i].plastic_slip);
            let rate = k * self.unit[i];
            let (strength, strength_rate) =
                (self.friction * c, self.friction * self.contact_unit[i]);
            // g(F) = g0 + F g1 <= 0 for tau - strength and -tau - strength.
            for (g0, g1) in [
                (shear - strength, rate - strength_rate),
                (-shear - strength, -rate - strength_rate),
            ] {
                if g1 > 0.0 {
                    limit = limit.min((-g0).max(0.0) / g1);
                }
            }
        }
        limit
    }

    /// Commits the stick state at `force` (N, at most [`Reduced::stick_limit`]) after the
    /// clamping state `clamped`; returns the slips from the clamped state, F s_F, computed as
    /// such rather than as a difference of two nearly equal totals.
    pub(super) fn stick_at(&mut self, clamped: &State, force: f64) -> Vec<f64> {
        let increment: Vec<f64> = self.unit.iter().map(|u| force * u).collect();
        self.restore(clamped);
        self.slip = clamped
            .slip
            .iter()
            .zip(&increment)
            .map(|(s, ds)| s + ds)
            .collect();
        self.load = force;
        increment
    }

    /// The state's answer; `slip_from_clamp` is s - s_clamped at each pair (mm).
    pub(super) fn result(
        &self,
        grid: &Grid,
        clamped: &State,
        slip_from_clamp: &[f64],
        increments: usize,
        iterations: usize,
    ) -> ContinuumLap {
        let c = self.c;
        let contact = self.contact_forces();
        let weights = &grid.pair_weights;
        let xs = &grid.pair_x;
        let slip: Vec<(f64, f64)> = xs
            .iter()
            .zip(slip_from_clamp)
            .map(|(&x, ds)| (x, *ds))
            .collect();
        let forces: Vec<f64> = self
            .slip
            .iter()
            .zip(self.plastic())
            .zip(&c.stiffness)
            .map(|((s, q), k)| k * (s - q))
            .collect();
        let shear: Vec<(f64, f64)> = xs
            .iter()
            .zip(forces.iter().zip(weights))
            .map(|(&x, (t, w))| (x, t / w))
            .collect();
        let contact_pressure: Vec<(f64, f64)> = xs
            .iter()
            .zip(contact.iter().zip(weights))
            .map(|(&x, (n, w))| (x, n / w))
            .collect();
        let length = *xs.last().unwrap_or(&0.0);
        // Nominal: K_T |s| >= mu P, P the nominal pressure, slip from the clamped state.
        let saturation = self.friction * self.pressure;
        let nominal = |order: &mut dyn Iterator<Item = usize>| -> f64 {
            let mut previous: Option<(f64, f64)> = None;
            for i in order {
                let (x, s) = slip[i];
                let level = c.stiffness[i] / weights[i] * s.abs();
                if level < saturation {
                    return match previous {
                        None => x,
                        Some((x0, l0)) => x0 + (x - x0) * (saturation - l0) / (level - l0),
                    };
                }
                previous = Some((x, level));
            }
            previous.map_or(0.0, |(x, _)| x)
        };
        let from_start = nominal(&mut (0..slip.len()));
        let from_end = length - nominal(&mut (0..slip.len()).rev());
        let nominal_zones = SlidingZones {
            from_inner_end: from_start,
            from_cover_ends: from_end,
        };
        // Local: |tau| >= (1 - 1e-3) mu p, at node resolution.
        let sliding = |i: usize| {
            let p = contact_pressure[i].1;
            p > 0.0 && shear[i].1.abs() >= (1.0 - LOCAL_SLIDING) * self.friction * p
        };
        let last_of_run = |order: &mut dyn Iterator<Item = usize>| -> Option<usize> {
            let mut last = None;
            for i in order {
                if !sliding(i) {
                    break;
                }
                last = Some(i);
            }
            last
        };
        let local_zones = SlidingZones {
            from_inner_end: last_of_run(&mut (0..xs.len())).map_or(0.0, |i| xs[i]),
            from_cover_ends: last_of_run(&mut (0..xs.len()).rev()).map_or(0.0, |i| length - xs[i]),
        };
        // Delta from the clamped state as F s_F's reading plus the plastic slips' change, not as
        // a difference of totals: P alone gives about 1.7e-3 mm on the bundled joint, whose
        // round-off (4e-19 mm) swallowed Delta at F = 1e-14 N (issue 36).
        let delta = self.load * self.delta_unit
            + self
                .plastic()
                .zip(clamped.points.iter())
                .zip(&c.stiffness)
                .zip(&c.delta_per_pair)
                .map(|(((q, q0), k), d)| d * k * (q - q0.plastic_slip))
                .sum::<f64>();
        ContinuumLap {
            force: self.load,
            delta,
            clamping_delta: self.clamping_delta,
            separated: contact
                .iter()
                .zip(xs)
                .filter(|(n, _)| **n < 0.0)
                .map(|(_, &x)| x)
                .collect(),
            transferred_force: self.width * forces.iter().sum::<f64>(),
            slip,
            shear,
            contact_pressure,
            nominal_zones,
            local_zones,
            increments,
            iterations,
            pairs: c.pairs,
        }
    }
}

impl Discretized for Reduced<'_> {
    const RESIDUAL_TOLERANCE: f64 = 1e-11;

    fn load(&self) -> f64 {
        self.load
    }

    fn displacement(&self) -> &[f64] {
        &self.slip
    }

    fn load_scale(&self, _load: f64) -> f64 {
        self.scale
    }

    fn linearize(&self, slip: &[f64], load: f64) -> (Vec<f64>, SymmetricBand, Vec<Response>) {
        let m = self.c.pairs;
        let responses: Vec<Response> = (0..m)
            .map(|i| self.points[i].respond(slip[i], self.c.stiffness[i], self.strengths[i]))
            .collect();
        // S (s - s_f) + (t - k s): the body's reaction to the slips plus the Jenkins forces
        // beyond the elastic springs already inside S.
        let offset: Vec<f64> = (0..m)
            .map(|i| slip[i] - self.base[i] - load * self.unit[i])
            .collect();
        let mut residual: Vec<f64> = self
            .c
            .condensed_rows
            .chunks_exact(m.max(1))
            .map(|row| row.iter().zip(&offset).map(|(a, b)| a * b).sum())
            .collect();
        let mut tangent = self.c.condensed.clone();
        for (i, r) in responses.iter().enumerate() {
            let k = self.c.stiffness[i];
            residual[i] += r.stress - k * slip[i];
            tangent.add(i, i, r.tangent - k);
        }
        (residual, tangent, responses)
    }

    fn commit(&mut self, slip: Vec<f64>, responses: Vec<Response>, load: f64) {
        for (point, response) in self.points.iter_mut().zip(&responses) {
            point.plastic_slip = response.plastic_slip;
        }
        self.slip = slip;
        self.load = load;
    }

    fn solve_step(
        &self,
        tangent: SymmetricBand,
        rhs: &[f64],
        responses: &[Response],
    ) -> Result<Vec<f64>, NotPositiveDefinite> {
        let sliding: Vec<bool> = responses.iter().map(|r| r.sliding).collect();
        let mut cache = self.factor.borrow_mut();
        if let Some((set, factor)) = cache.as_ref()
            && *set == sliding
        {
            return Ok(factor.solve(rhs));
        }
        let factor = tangent.factor()?;
        let step = factor.solve(rhs);
        *cache = Some((sliding, factor));
        Ok(step)
    }
}
