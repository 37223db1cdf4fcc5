//! The interface problem on the m pair slips at given strengths ([`Reduced`], the Newton driver's
//! model, `numeric::newton`), the fixed point on its contact forces and the load path.

use std::cell::RefCell;

use super::Condensed;
use crate::numeric::NumericError;
use crate::numeric::banded::{BandCholesky, NotPositiveDefinite, SymmetricBand};
use crate::numeric::interface::{InterfacePoint, Response};
use crate::numeric::newton::{self, Discretized};

/// Fixed-point iterations allowed on the contact forces per increment. The iteration contracts
/// at a rate set by how much the strengths move the contact forces, which grows with mu: on the
/// bundled lap joint a few iterations at mu = 0.3, but about 0.85 per iteration at mu = 2 near
/// F = 10 kN with the covers lifting at x = 0 (about 130 iterations; 60 failed there, issue
/// 36). Each iteration is one Newton solve on the pairs, mostly with a kept factor.
const MAX_CONTACT_ITERATIONS: usize = 400;
/// Times a load increment whose fixed point fails may be halved.
const MAX_CUTS: u32 = 6;
/// The bounds of the contact forces' relaxation (Aitken's factor is clamped to them).
const MIN_RELAXATION: f64 = 1.0 / 64.0;
const MAX_RELAXATION: f64 = 2.0;
/// Change of the contact forces, relative to the largest, that ends the fixed point.
const CONTACT_TOLERANCE: f64 = 1e-10;

/// Refuses a loading path whose forces decrease (friction is path-dependent: unloading is
/// another problem).
///
/// # Errors
/// [`NumericError::OutOfRange`] saying so.
pub(crate) fn check_path(forces: &[f64]) -> Result<(), NumericError> {
    if forces.windows(2).any(|w| w[1] < w[0]) {
        return Err(NumericError::OutOfRange(
            "the forces of one loading path must not decrease (friction is path-dependent: \
             unloading is another problem)"
                .into(),
        ));
    }
    Ok(())
}

/// The interface problem on the m pair slips at given strengths: the Newton driver's model.
pub(crate) struct Reduced<'a> {
    pub(crate) c: &'a Condensed,
    friction: f64,
    /// The first load's magnitude (P, MPa): the load parameter of the first stage is its
    /// fraction.
    pressure: f64,
    /// The slips of the loads with every pair elastic and no plastic slip: base + load x unit.
    base: Vec<f64>,
    unit: Vec<f64>,
    /// Contact forces and the reading the same way.
    contact_base: Vec<f64>,
    contact_unit: Vec<f64>,
    reading_base: f64,
    reading_unit: f64,
    /// Jenkins strengths, mu times the contact forces of the fixed point's last iterate.
    strengths: Vec<f64>,
    points: Vec<InterfacePoint>,
    pub(crate) slip: Vec<f64>,
    pub(crate) load: f64,
    /// Residual scale (N/mm per mm of width): the problem's force per width.
    scale: f64,
    /// The reading at the end of the first stage (mm).
    first_reading: f64,
    /// The factored tangent and the sliding set it belongs to: the tangent S + diag(k_t - k)
    /// depends on nothing else, and the fixed point's solves mostly repeat the set.
    factor: RefCell<Option<(Vec<bool>, BandCholesky)>>,
}

/// A committed state of [`Reduced`], to restart an increment from.
#[derive(Debug, Clone)]
pub(crate) struct State {
    pub(crate) points: Vec<InterfacePoint>,
    pub(crate) slip: Vec<f64>,
    load: f64,
}

impl<'a> Reduced<'a> {
    /// The interface of `c` with friction coefficient `friction` under the first load of
    /// magnitude `pressure`, the residual measured against `scale` (N per mm of width); the load
    /// parameter is the fraction of `pressure` until [`Reduced::start_force_step`].
    pub(crate) fn new(c: &'a Condensed, friction: f64, pressure: f64, scale: f64) -> Reduced<'a> {
        let m = c.pairs;
        Reduced {
            c,
            friction,
            pressure,
            base: vec![0.0; m],
            unit: c.slip_p.iter().map(|s| s * pressure).collect(),
            contact_base: vec![0.0; m],
            contact_unit: c.contact_p.iter().map(|s| s * pressure).collect(),
            reading_base: 0.0,
            reading_unit: c.reading_p * pressure,
            strengths: vec![0.0; m],
            points: vec![InterfacePoint::default(); m],
            slip: vec![0.0; m],
            load: 0.0,
            scale,
            first_reading: 0.0,
            factor: RefCell::new(None),
        }
    }

    /// After the clamping step: P held, the load parameter becomes F (N) from 0.
    pub(crate) fn start_force_step(&mut self) {
        self.first_reading = self.reading();
        let p = self.pressure;
        self.base = self.c.slip_p.iter().map(|s| s * p).collect();
        self.unit = self.c.slip_f.clone();
        self.contact_base = self.c.contact_p.iter().map(|s| s * p).collect();
        self.contact_unit = self.c.contact_f.clone();
        self.reading_base = self.c.reading_p * p;
        self.reading_unit = self.c.reading_f;
        self.load = 0.0;
    }

    pub(crate) fn state(&self) -> State {
        State {
            points: self.points.clone(),
            slip: self.slip.clone(),
            load: self.load,
        }
    }

    pub(crate) fn restore(&mut self, state: &State) {
        self.points.clone_from(&state.points);
        self.slip.clone_from(&state.slip);
        self.load = state.load;
    }

    /// The plastic slips q_i (mm) of the committed state.
    pub(crate) fn plastic(&self) -> impl Iterator<Item = f64> + '_ {
        self.points.iter().map(|p| p.plastic_slip)
    }

    /// The contact forces of the committed state (N per mm of width): linear in the load and the
    /// pairs' Jenkins forces t_j = k_j (s_j - q_j). With t = S (s_f - s) the body's answer to the
    /// pair forces, the contact is the elastic contact minus R K0^-1 B^T times (t - k s) = -k q.
    pub(crate) fn contact_forces(&self) -> Vec<f64> {
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

    /// The problem's reading of the committed state (mm).
    pub(crate) fn reading(&self) -> f64 {
        self.reading_base
            + self.load * self.reading_unit
            + self
                .plastic()
                .zip(&self.c.stiffness)
                .zip(&self.c.reading_per_pair)
                .map(|((q, k), d)| d * k * q)
                .sum::<f64>()
    }

    /// The first stage at its full magnitude with no friction (a shrink fit: the hub slides onto
    /// the shaft freely and grips as it cools, so no shear is left at the interface): the
    /// bodies' equilibrium under the first load with a zero Jenkins force at every pair, which
    /// is then committed as the slider positions q = s. The interface's condensed stiffness
    /// without its springs, S - diag(k), is singular along the rigid sliding of one body against
    /// the other (nothing but the interface holds the shaft axially), which changes neither the
    /// contact forces nor a reading taken from this state; pair 0 is pinned to remove it.
    ///
    /// # Errors
    /// [`NumericError::Singular`] when the bodies leave more than that one mode free.
    pub(crate) fn frictionless_first_stage(&mut self) -> Result<(), NumericError> {
        let m = self.c.pairs;
        let rows = &self.c.condensed_rows;
        let mut free = SymmetricBand::zeros(m - 1, m.saturating_sub(2));
        for i in 1..m {
            for j in 1..=i {
                let k = if i == j { self.c.stiffness[i] } else { 0.0 };
                free.add(i - 1, j - 1, rows[i * m + j] - k);
            }
        }
        let rhs: Vec<f64> = (1..m)
            .map(|i| {
                let row = &rows[i * m..(i + 1) * m];
                row.iter().zip(&self.unit).map(|(a, b)| a * b).sum()
            })
            .collect();
        let slip = free
            .factor()
            .map_err(|e| NumericError::Singular(e.row + 1))?
            .solve(&rhs);
        self.slip = std::iter::once(0.0).chain(slip).collect();
        for (point, s) in self.points.iter_mut().zip(&self.slip) {
            point.plastic_slip = *s;
        }
        self.load = 1.0;
        Ok(())
    }

    /// One increment to `load`; when its fixed point fails (nothing is committed then), two
    /// half increments, down to `cuts_left` halvings: a closer start is what the fixed point
    /// needs where the covers lift off (mu = 4 near 0.5 F_gross on the bundled joint, issue 36).
    pub(crate) fn step_with_cuts(
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
    pub(crate) fn step(&mut self, load: f64) -> Result<usize, NumericError> {
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
    pub(crate) fn stick_limit(&self) -> f64 {
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
    pub(crate) fn stick_at(&mut self, clamped: &State, force: f64) -> Vec<f64> {
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

    /// The friction coefficient mu.
    pub(crate) fn friction(&self) -> f64 {
        self.friction
    }

    /// The first load's magnitude (P, MPa).
    pub(crate) fn pressure(&self) -> f64 {
        self.pressure
    }

    /// The reading at the end of the first stage (mm).
    pub(crate) fn first_reading(&self) -> f64 {
        self.first_reading
    }

    /// The pairs' Jenkins forces t_i = k_i (s_i - q_i) of the committed state (N per mm of
    /// width), positive where the lower body's u exceeds the upper body's.
    pub(crate) fn pair_forces(&self) -> Vec<f64> {
        self.slip
            .iter()
            .zip(self.plastic())
            .zip(&self.c.stiffness)
            .map(|((s, q), k)| k * (s - q))
            .collect()
    }

    /// The change of the reading from the first stage's end `clamped` (mm): F times its
    /// elastic reading plus the plastic slips' change, not a difference of totals (which loses
    /// the digits of a small F against the first stage's reading).
    pub(crate) fn reading_from(&self, clamped: &State) -> f64 {
        let c = self.c;
        self.load * self.reading_unit
            + self
                .plastic()
                .zip(clamped.points.iter())
                .zip(&c.stiffness)
                .zip(&c.reading_per_pair)
                .map(|(((q, q0), k), d)| d * k * (q - q0.plastic_slip))
                .sum::<f64>()
    }

    /// Moves the driving load from its committed value to `force` (N): at or below `stick`
    /// ([`Reduced::stick_limit`] from `clamped`, the first stage's end) exactly, as the clamped
    /// state plus F times the unit-force solution; beyond it in `steps` equal increments, each
    /// halved up to [`MAX_CUTS`] times when it fails. Returns the slips from `clamped` at each
    /// pair (mm), the increments taken and the fixed point's iterations.
    ///
    /// # Errors
    /// The failing increment's [`NumericError`] (the committed state is the last that
    /// converged).
    pub(crate) fn advance(
        &mut self,
        clamped: &State,
        force: f64,
        stick: f64,
        steps: usize,
    ) -> Result<(Vec<f64>, usize, usize), NumericError> {
        if force <= stick {
            // Below first slip the answer is the clamped state plus F times the unit-force
            // solution, exactly: no increment can lose F's digits against the clamping state.
            return Ok((self.stick_at(clamped, force), 1, 0));
        }
        let from = self.load;
        let mut iterations = 0;
        for i in 1..=steps {
            let target = if i == steps {
                force
            } else {
                from + (force - from) * i as f64 / steps as f64
            };
            iterations += self.step_with_cuts(target, MAX_CUTS)?;
        }
        let slip = self
            .slip
            .iter()
            .zip(&clamped.slip)
            .map(|(s, s0)| s - s0)
            .collect();
        Ok((slip, steps, iterations))
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
