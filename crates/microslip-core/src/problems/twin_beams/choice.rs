//! The beams' theory as a setting of the problem ([`AnyChoice`]): how presets (`beam_theory =
//! "timoshenko"`) and the command line (`--beam-theory`) reach [`BeamTheory`] through the
//! registry, so that no layer above names it.

use super::TwinBeamsProblem;
use super::params::{BeamTheory, BeamTheoryError};
use crate::problems::Problem;
use crate::problems::choice::{AnyChoice, ChoiceError};
use crate::problems::inputs::Inputs;

/// The twin beams' [`BeamTheory`], as a setting presets and flags name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TheoryChoice;

impl AnyChoice for TheoryChoice {
    fn key(&self) -> &'static str {
        "beam_theory"
    }

    fn comment(&self) -> &'static str {
        "deflection: euler-bernoulli (the paper's) or timoshenko"
    }

    fn owner(&self) -> &'static str {
        "the twin beams"
    }

    fn values(&self) -> &'static [&'static str] {
        &BeamTheoryError::ALLOWED
    }

    fn help(&self) -> &'static str {
        "Beam theory of the twin beams' deflection (default: the preset's, else the paper's \
         Euler-Bernoulli); timoshenko adds each beam's shear deflection"
    }

    fn get(&self, inputs: &Inputs) -> Option<&'static str> {
        TwinBeamsProblem::from_inputs(inputs).map(|p| p.structure.theory.key())
    }

    fn set(&self, inputs: &mut Inputs, text: &str) -> Option<Result<(), ChoiceError>> {
        let mut params = TwinBeamsProblem::from_inputs(inputs)?;
        Some(
            BeamTheory::parse(text)
                .map(|theory| {
                    params.structure.theory = theory;
                    *inputs = TwinBeamsProblem::to_inputs(params);
                })
                .map_err(|e| ChoiceError {
                    what: "beam theory",
                    text: e.text,
                    allowed: &BeamTheoryError::ALLOWED,
                }),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_theory_is_set_and_read_back_and_refused_as_the_parser_refuses_it() {
        let mut inputs = TwinBeamsProblem::to_inputs(TwinBeamsProblem::paper());
        assert_eq!(TheoryChoice.get(&inputs), Some("euler-bernoulli"));
        assert_eq!(TheoryChoice.set(&mut inputs, "Timoshenko"), Some(Ok(())));
        assert_eq!(TheoryChoice.get(&inputs), Some("timoshenko"));
        let refused = TheoryChoice.set(&mut inputs, "x").unwrap().unwrap_err();
        assert_eq!(
            refused.to_string(),
            BeamTheory::parse("x").unwrap_err().to_string()
        );
        assert_eq!(TheoryChoice.get(&inputs), Some("timoshenko"));
        for value in TheoryChoice.values() {
            assert_eq!(TheoryChoice.set(&mut inputs, value), Some(Ok(())));
            assert_eq!(TheoryChoice.get(&inputs), Some(*value));
        }
    }
}
