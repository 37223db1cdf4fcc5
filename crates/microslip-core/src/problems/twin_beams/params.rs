//! The inputs of the twin-beam problem: keys, units, meanings, domains and steps.

use std::fmt;
use std::str::FromStr;

use crate::kernel::params::{
    Domain, FACTOR, FRICTION, MODULUS, POISSON, ParamError, ParamSpec, STIFFNESS, Scale, Unit, spec,
};
use crate::problems::{ModelKind, ParamKey, UnknownParam};

/// The inputs of the twin-beam problem.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BeamParam {
    /// Beam length L (mm).
    Length,
    /// Beam width b (mm).
    Width,
    /// Half height h of one beam (mm): each beam is 2h high.
    HalfHeight,
    /// Young's modulus E (MPa).
    Modulus,
    /// Interface pressure P (MPa).
    Pressure,
    /// Friction coefficient mu (-).
    Friction,
    /// Tangential contact stiffness K_T (MPa/mm).
    Stiffness,
    /// Poisson ratio nu (-), for the Timoshenko deflection.
    Poisson,
    /// Tip force F on each beam (N).
    Force,
}

impl BeamParam {
    /// Every beam parameter, in display order.
    pub const ALL: [BeamParam; 9] = [
        BeamParam::Length,
        BeamParam::Width,
        BeamParam::HalfHeight,
        BeamParam::Modulus,
        BeamParam::Poisson,
        BeamParam::Pressure,
        BeamParam::Friction,
        BeamParam::Stiffness,
        BeamParam::Force,
    ];

    /// Key, unit, meaning, domain and step.
    pub fn spec(self) -> ParamSpec {
        const LENGTH: Domain = Domain::LENGTH;
        match self {
            BeamParam::Length => {
                spec("L", Unit::Millimetre, "beam length", LENGTH, FACTOR).usual(0.1, 1e4)
            }
            BeamParam::Width => {
                spec("b", Unit::Millimetre, "beam width", LENGTH, FACTOR).usual(0.1, 1e4)
            }
            BeamParam::HalfHeight => spec(
                "h",
                Unit::Millimetre,
                "half height (each beam is 2h high)",
                LENGTH,
                FACTOR,
            )
            .usual(0.1, 1e4)
            // A user who types the whole 20 mm height gets beams twice too thick (w(L) 8x small).
            .noted("half"),
            BeamParam::Modulus => MODULUS,
            BeamParam::Pressure => spec(
                "P",
                Unit::Megapascal,
                "interface pressure",
                Domain::PRESSURE,
                FACTOR,
            )
            .usual(1e-3, 2e3),
            BeamParam::Friction => FRICTION,
            BeamParam::Stiffness => STIFFNESS,
            BeamParam::Poisson => POISSON,
            BeamParam::Force => spec(
                "F",
                Unit::Newton,
                "tip force on each beam",
                Domain::FORCE,
                Scale::FractionOfScale {
                    fine: 0.01,
                    coarse: 0.1,
                },
            )
            .usual(0.0, 1e7),
        }
    }

    /// Checks `value` against this parameter's domain.
    ///
    /// # Errors
    /// [`ParamError`] naming the key, the value and the allowed range.
    pub fn check(self, value: f64) -> Result<f64, ParamError> {
        let spec = self.spec();
        spec.domain.check(spec.name, value, spec.unit)
    }
}

impl fmt::Display for BeamParam {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.spec().name)
    }
}

impl FromStr for BeamParam {
    type Err = UnknownParam;

    fn from_str(key: &str) -> Result<Self, Self::Err> {
        <BeamParam as ParamKey>::parse_key(key, ModelKind::Beam)
    }
}

/// Which beam theory the deflection uses. The friction closed forms (thresholds, X, tau, slip) are
/// the same under both: the interface shear acts along the beams' axis, so transverse shear strain
/// changes only the deflection, by F x / (kappa G b 2h) (B13).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum BeamTheory {
    /// No shear strain: the paper's model.
    #[default]
    EulerBernoulli,
    /// Plus each beam's shear deflection (kappa = 5/6, G = E / (2 (1 + nu))): within 1 % of
    /// continuum FE for the beams measured (docs/theory.md, (V2)).
    Timoshenko,
}

impl BeamTheory {
    /// Both theories, the paper's first.
    pub const ALL: [BeamTheory; 2] = [BeamTheory::EulerBernoulli, BeamTheory::Timoshenko];

    /// The name in presets, flags and JSON.
    pub fn key(self) -> &'static str {
        match self {
            BeamTheory::EulerBernoulli => "euler-bernoulli",
            BeamTheory::Timoshenko => "timoshenko",
        }
    }

    /// The name for people.
    pub fn label(self) -> &'static str {
        match self {
            BeamTheory::EulerBernoulli => "Euler-Bernoulli",
            BeamTheory::Timoshenko => "Timoshenko",
        }
    }

    /// Reads [`BeamTheory::key`] (also `euler`).
    ///
    /// # Errors
    /// [`BeamTheoryError`], naming the accepted names, when `text` is none of them.
    pub fn parse(text: &str) -> Result<BeamTheory, BeamTheoryError> {
        match text.trim().to_ascii_lowercase().as_str() {
            "euler-bernoulli" | "euler" => Ok(BeamTheory::EulerBernoulli),
            "timoshenko" => Ok(BeamTheory::Timoshenko),
            _ => Err(BeamTheoryError {
                text: text.to_string(),
            }),
        }
    }

    /// The other theory.
    pub fn other(self) -> BeamTheory {
        match self {
            BeamTheory::EulerBernoulli => BeamTheory::Timoshenko,
            BeamTheory::Timoshenko => BeamTheory::EulerBernoulli,
        }
    }
}

/// A beam theory [`BeamTheory::parse`] does not know: the text given, and the names it accepts
/// ([`BeamTheoryError::ALLOWED`]).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "invalid beam theory '{text}': must be \"{}\" or \"{}\"",
    Self::ALLOWED[0],
    Self::ALLOWED[1]
)]
pub struct BeamTheoryError {
    /// The text given.
    pub text: String,
}

impl BeamTheoryError {
    /// The names accepted (each [`BeamTheory::key`]; `euler` is read as `euler-bernoulli` too).
    pub const ALLOWED: [&'static str; 2] = ["euler-bernoulli", "timoshenko"];
}

/// Raw inputs of the twin-beam problem (mm, MPa, MPa/mm); validated by
/// [`TwinBeams::new`](crate::problems::twin_beams::closed_form::TwinBeams::new).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwinBeamsParams {
    /// Beam length L (mm).
    pub length: f64,
    /// Beam width b (mm).
    pub width: f64,
    /// Half of the height of one beam, h (mm): each beam is 2h high.
    pub half_height: f64,
    /// Young's modulus E (MPa).
    pub youngs_modulus: f64,
    /// Interface pressure P (MPa).
    pub pressure: f64,
    /// Friction coefficient mu (-).
    pub friction: f64,
    /// Tangential contact stiffness K_T (MPa/mm).
    pub tangential_stiffness: f64,
    /// Poisson ratio nu (-): used by the Timoshenko deflection only.
    pub poisson: f64,
    /// The beam theory of the deflection.
    pub theory: BeamTheory,
}

impl TwinBeamsParams {
    /// The paper's data set (section 2.1.2): L=200, b=20, h=10 mm, E=210000 MPa, P=1 MPa, mu=0.3,
    /// K_T = mu P / 5e-4 mm = 600 MPa/mm.
    pub const PAPER: TwinBeamsParams = TwinBeamsParams {
        length: 200.0,
        width: 20.0,
        half_height: 10.0,
        youngs_modulus: 210_000.0,
        pressure: 1.0,
        friction: 0.3,
        tangential_stiffness: 600.0,
        poisson: 0.3,
        theory: BeamTheory::EulerBernoulli,
    };

    /// The field that holds `param`, or `None` for the tip force, which is not a property of the
    /// structure (see [`TipForce`](crate::problems::twin_beams::closed_form::TipForce)).
    pub(crate) fn value_mut(&mut self, param: BeamParam) -> Option<&mut f64> {
        Some(match param {
            BeamParam::Length => &mut self.length,
            BeamParam::Width => &mut self.width,
            BeamParam::HalfHeight => &mut self.half_height,
            BeamParam::Modulus => &mut self.youngs_modulus,
            BeamParam::Pressure => &mut self.pressure,
            BeamParam::Friction => &mut self.friction,
            BeamParam::Stiffness => &mut self.tangential_stiffness,
            BeamParam::Poisson => &mut self.poisson,
            BeamParam::Force => return None,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_unknown_beam_theory_is_refused_with_the_text_and_the_names_accepted() {
        assert_eq!(BeamTheory::parse(" Euler "), Ok(BeamTheory::EulerBernoulli));
        let error = BeamTheory::parse("kirchhoff").unwrap_err();
        assert_eq!(error.text, "kirchhoff");
        assert_eq!(
            error.to_string(),
            "invalid beam theory 'kirchhoff': must be \"euler-bernoulli\" or \"timoshenko\""
        );
        for name in BeamTheoryError::ALLOWED {
            assert_eq!(BeamTheory::parse(name).map(BeamTheory::key), Ok(name));
        }
    }
}
