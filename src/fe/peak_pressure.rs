//! The largest contact pressure a run's interface output holds, against the problem's nominal
//! pressure: a run whose contact locked somewhere is no judge (issue 45).
//!
//! Why: on the twin beams' finest CalculiX deck the clamp corner (first element 0.0125 to 0.016
//! mm long) can lock, in either kinematics: a node pressed to 50 to 134 times the interface
//! pressure P, slips three times the tip's beside it, and w(L) then 0.3 to 1 % off the converged
//! answer (docs/theory.md (BC4a), "On converged ladders"). Every other run of those ladders peaks
//! at 1.0 to 2.6 P. Such a run reads like any other, and its differences from the closed form
//! would be judged (and extrapolated by a ladder) as if the FE code had answered the benchmark.
//! So the peak is read from the same `CONTACT` blocks as the stick slope, and a problem that
//! knows how far its contact pressure can rise in a sound run states it
//! ([`Deck::LOCKED_PRESSURE`](super::face::Deck::LOCKED_PRESSURE)), in its own words; beyond it the
//! comparison says "does not agree", and the suite's case "not converged", naming the node.

use super::stick_slope::ContactStep;

/// How far a problem's contact pressure rises in a sound run, and what locks it beyond.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LockedPressure {
    /// The largest contact pressure a sound run reaches, in times the interface's nominal
    /// pressure, with a margin.
    pub ratio: f64,
    /// Where the problem's contact locks and what to do about it, in its own words (a clause).
    pub advice: &'static str,
}

/// The largest contact pressure of a run's interface output.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PeakPressure {
    /// The pressure (MPa).
    pub pressure: f64,
    /// The node that carries it (the output's numbering).
    pub node: usize,
    /// The FE code's step it is in.
    pub step: usize,
}

impl PeakPressure {
    /// The largest finite contact pressure over every step of `contact`; `None` where the output
    /// gives no pressure (a CSV profile) or no positive one.
    pub fn of(contact: &[ContactStep]) -> Option<PeakPressure> {
        contact
            .iter()
            .flat_map(|step| {
                step.nodes.iter().filter_map(move |n| {
                    let pressure = n.pressure.filter(|p| p.is_finite() && *p > 0.0)?;
                    Some(PeakPressure {
                        pressure,
                        node: n.node,
                        step: step.step,
                    })
                })
            })
            .max_by(|a, b| a.pressure.total_cmp(&b.pressure))
    }

    /// The peak as a multiple of `nominal` (MPa), where `nominal` is a positive pressure.
    pub fn ratio(&self, nominal: f64) -> Option<f64> {
        (nominal.is_finite() && nominal > 0.0).then(|| self.pressure / nominal)
    }

    /// Whether the peak is beyond `limit` times `nominal`: the contact locked.
    pub fn locked(&self, nominal: f64, limit: f64) -> bool {
        self.ratio(nominal).is_some_and(|r| r > limit)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fe::stick_slope::ContactNode;

    fn node(node: usize, pressure: Option<f64>) -> ContactNode {
        ContactNode {
            node,
            slip: [1e-4, 0.0],
            pressure,
            shear: [0.01, 0.0],
        }
    }

    fn step(step: usize, nodes: Vec<ContactNode>) -> ContactStep {
        ContactStep {
            step,
            time: step as f64,
            nodes,
        }
    }

    #[test]
    fn the_peak_is_the_largest_pressure_of_any_step_and_names_its_node() {
        let contact = [
            step(1, vec![node(3, Some(2.0)), node(4, Some(2.1))]),
            step(2, vec![node(3, Some(267.0)), node(4, Some(-40.0))]),
            step(3, vec![node(3, Some(f64::NAN)), node(5, Some(2.6))]),
        ];
        let peak = PeakPressure::of(&contact).unwrap();
        assert_eq!((peak.pressure, peak.node, peak.step), (267.0, 3, 2));
        assert!(peak.locked(2.0, 5.0));
        assert!((peak.ratio(2.0).unwrap() - 133.5).abs() < 1e-12);
    }

    #[test]
    fn a_sound_run_is_not_locked_and_a_profile_without_pressure_has_no_peak() {
        let sound = [step(2, vec![node(1, Some(2.6)), node(2, Some(1.0))])];
        let peak = PeakPressure::of(&sound).unwrap();
        assert!(!peak.locked(1.0, 5.0), "2.6 P is a sound beams' run");
        assert!(
            peak.locked(0.5, 5.0),
            "5.2 times its nominal pressure is not"
        );
        assert_eq!(peak.ratio(0.0), None);
        assert!(!peak.locked(f64::NAN, 5.0));
        let profile = [step(1, vec![node(1, None)])];
        assert_eq!(PeakPressure::of(&profile), None);
        let open = [step(1, vec![node(1, Some(0.0)), node(2, Some(-3.0))])];
        assert_eq!(PeakPressure::of(&open), None);
    }
}
