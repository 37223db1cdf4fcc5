//! Reading presets: TOML text to [`Preset`], collecting every problem with its line (the TOML
//! parser's spans give the lines), and `--set KEY=VALUE` assignments. Keys are parsed by
//! [`ModelKind::param`], the one place that knows how parameters are spelled.

use std::collections::BTreeMap;

use toml::Spanned;

use super::{Located, Preset, PresetError, PresetSource};
use crate::kernel::params::parse_number;
use crate::problems::inputs::Inputs;
use crate::problems::{ModelKind, Param};

/// Applies `KEY=VALUE` as typed on the command line.
///
/// # Errors
/// [`PresetError::Assignment`] without `=`, [`PresetError::UnknownKey`] for a key the model does not
/// have, [`PresetError::NotANumber`] for a value that is not a finite number. The range is checked
/// later, by [`Inputs::validate`].
pub fn apply_assignment(inputs: &mut Inputs, assignment: &str) -> Result<(), PresetError> {
    let (key, value) = assignment
        .split_once('=')
        .ok_or_else(|| PresetError::Assignment {
            text: assignment.to_string(),
        })?;
    let (key, value) = (key.trim(), value.trim());
    let param = inputs.kind().param(key)?;
    inputs.set(param, parse_value(param, value)?)?;
    Ok(())
}

/// A parameter's value from the text a user typed (`--set`, the TUI's value field and `:` line).
/// The range checks come after; this refuses what is no number, with the range it must be in,
/// and a nonzero number that rounds to 0 (`1e-400`) where 0 is refused, quoting the text typed
/// rather than the 0 it became.
///
/// # Errors
/// [`PresetError::NotANumber`] or [`PresetError::Underflow`], with the allowed range.
pub(crate) fn parse_value(param: Param, text: &str) -> Result<f64, PresetError> {
    let spec = param.spec();
    let allowed = || spec.domain.describe(spec.unit);
    let number = parse_number(text).ok_or_else(|| PresetError::NotANumber {
        key: spec.name.to_string(),
        text: text.to_string(),
        allowed: allowed(),
    })?;
    // The digits before the exponent: any of 1-9 makes a nonzero number.
    let mantissa = text.split(['e', 'E']).next().unwrap_or(text);
    let nonzero = mantissa.chars().any(|c| matches!(c, '1'..='9'));
    if number == 0.0 && nonzero && !spec.domain.contains(0.0) {
        return Err(PresetError::Underflow {
            key: spec.name.to_string(),
            text: text.to_string(),
            allowed: allowed(),
        });
    }
    Ok(number)
}

/// 1-based line of a byte offset.
fn line_at(text: &str, offset: usize) -> usize {
    text.as_bytes()[..offset.min(text.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

/// toml's syntax message ("TOML parse error at line L, column C" then an excerpt) on one line.
fn syntax_summary(error: &toml::de::Error) -> String {
    let message = error.to_string();
    let lines: Vec<&str> = message.lines().filter(|l| !l.trim().is_empty()).collect();
    match (lines.first(), lines.last()) {
        (Some(first), Some(last)) if first != last => format!("{first}: {}", last.trim()),
        (Some(first), _) => first.to_string(),
        _ => "invalid TOML".to_string(),
    }
}

impl Preset {
    /// Parses preset text, collecting every problem (for `microslip check`); the first one is enough
    /// for callers that only need to refuse.
    ///
    /// # Errors
    /// Every problem found, each with its 1-based line when it has one, sorted by line.
    ///
    /// # Examples
    /// ```
    /// use microslip::preset::{Preset, PresetSource};
    /// let text = "model = \"beam\"\nKT = 120\nL = -1\nKt = 5\n";
    /// let problems = Preset::parse(text, "mine", PresetSource::Bundled).unwrap_err();
    /// let shown: Vec<String> = problems.iter().map(ToString::to_string).collect();
    /// assert_eq!(shown[0], "line 3: invalid L = -1: must be > 0 and finite (mm)");
    /// assert!(shown[1].starts_with("line 4: unknown key 'Kt' for the beam model"));
    /// ```
    pub fn parse(text: &str, name: &str, source: PresetSource) -> Result<Preset, Vec<Located>> {
        type Table = BTreeMap<Spanned<String>, Spanned<toml::Value>>;
        let table: Table = toml::from_str(text).map_err(|e| {
            vec![Located {
                line: None,
                error: PresetError::Syntax(syntax_summary(&e)),
            }]
        })?;
        let line_of = |key: &Spanned<String>| Some(line_at(text, key.span().start));
        let model = table.iter().find(|(key, _)| key.get_ref() == "model");
        let kind = match model {
            Some((key, value)) => match value.get_ref().as_str().map(str::parse::<ModelKind>) {
                Some(Ok(kind)) => kind,
                found => {
                    let found = match found {
                        Some(_) => format!("'{}'", value.get_ref().as_str().unwrap_or_default()),
                        None => "a non-string value".to_string(),
                    };
                    return Err(vec![Located {
                        line: line_of(key),
                        error: PresetError::Model(format!(
                            "invalid model = {found}: must be {}",
                            ModelKind::choices()
                        )),
                    }]);
                }
            },
            None => {
                return Err(vec![Located {
                    line: None,
                    error: PresetError::Model(format!(
                        "missing key 'model': must be {}",
                        ModelKind::choices()
                    )),
                }]);
            }
        };
        let mut problems = Vec::new();
        let mut lines = BTreeMap::new();
        let mut inputs = Inputs::paper(kind);
        let mut description = String::new();
        for (key, value) in &table {
            let (name_of_key, value) = (key.get_ref().as_str(), value.get_ref());
            let not_a_number = |allowed: String| PresetError::NotANumber {
                key: name_of_key.to_string(),
                text: value.to_string(),
                allowed,
            };
            let choice = super::choice(name_of_key);
            let result = match (name_of_key, choice) {
                ("model", _) => Ok(()),
                // Not a number: a setting that takes a name (the beams' theory), which the
                // problem it belongs to reads.
                (_, Some(choice)) => match value.as_str() {
                    _ if choice.get(&inputs).is_none() => Err(PresetError::ChoiceNotApplicable {
                        key: choice.key(),
                        owner: choice.owner(),
                        model: kind.problem().refused_as(),
                    }),
                    Some(text) => choice
                        .set(&mut inputs, text)
                        .unwrap_or(Ok(()))
                        .map_err(PresetError::Choice),
                    None => Err(PresetError::NotAString {
                        key: name_of_key.to_string(),
                        text: value.to_string(),
                    }),
                },
                ("description", None) => match value.as_str() {
                    Some(text) => {
                        description = text.to_string();
                        Ok(())
                    }
                    None => Err(PresetError::NotAString {
                        key: name_of_key.to_string(),
                        text: value.to_string(),
                    }),
                },
                (_, None) => kind
                    .param(name_of_key)
                    .map_err(PresetError::from)
                    .and_then(|param| {
                        lines.insert(param.name(), line_of(key));
                        let number = value
                            .as_float()
                            .or_else(|| value.as_integer().map(|i| i as f64))
                            .filter(|n| !n.is_nan())
                            .ok_or_else(|| {
                                let spec = param.spec();
                                not_a_number(spec.domain.describe(spec.unit))
                            })?;
                        inputs.set(param, number).map_err(PresetError::from)
                    }),
            };
            if let Err(error) = result {
                problems.push(Located {
                    line: line_of(key),
                    error,
                });
            }
        }
        for error in inputs.all_param_errors() {
            problems.push(Located {
                line: lines.get(error.field).copied().flatten(),
                error: PresetError::Param(error),
            });
        }
        // Every value in its own domain may still leave no state: the lap joint's F beyond
        // F_gross = 2 b mu P L. Said at the line of the value refused, when the file gives it; a
        // value the file leaves at its default is not the file's fault (`--set F=...` may give
        // it), so the preset is refused only when it is used without one.
        if problems.is_empty()
            && let Err(error) = inputs.validate()
            && let Some(line) = lines.get(error.field).copied().flatten()
        {
            problems.push(Located {
                line: Some(line),
                error: PresetError::Param(error),
            });
        }
        if problems.is_empty() {
            Ok(Preset {
                name: name.to_string(),
                description,
                inputs,
                source,
            })
        } else {
            problems.sort_by_key(|p| p.line.unwrap_or(0));
            Err(problems)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::{Param, PlateParam};

    #[test]
    fn every_problem_is_reported_with_its_line() {
        let text = "model = \"beam\"\nKt = 5\nL = -1\nmu = \"high\"\nE = 0\n";
        let problems = Preset::parse(text, "x", PresetSource::Bundled).unwrap_err();
        let shown: Vec<String> = problems.iter().map(ToString::to_string).collect();
        assert_eq!(shown.len(), 4, "{shown:?}");
        assert!(shown[0].starts_with(
            "line 2: unknown key 'Kt' for the beam model (allowed: L b h E nu P mu KT F)"
        ));
        assert!(
            shown[1].starts_with("line 3: invalid L = -1: must be > 0 and finite (mm)"),
            "{shown:?}"
        );
        assert!(
            shown[2].starts_with("line 4: invalid value '\"high\"' for mu"),
            "{shown:?}"
        );
        assert!(shown[3].starts_with("line 5: invalid E = 0"), "{shown:?}");
    }

    #[test]
    fn lines_come_from_the_parser_not_from_the_look_of_the_text() {
        // Quoted keys, keys after comments and blank lines, and a key whose name starts another's.
        let text = "# comment\n\nmodel = \"plate\"\n\"nu\" = 0.7\n  tp=-2 # thin\nP = 1\n";
        let problems = Preset::parse(text, "x", PresetSource::Bundled).unwrap_err();
        let lines: Vec<Option<usize>> = problems.iter().map(|p| p.line).collect();
        assert_eq!(lines, [Some(4), Some(5)], "{problems:?}");
        let problems =
            Preset::parse("description = 3\nmodel = 4\n", "x", PresetSource::Bundled).unwrap_err();
        assert_eq!(
            problems[0].to_string(),
            format!(
                "line 2: invalid model = a non-string value: must be {}",
                ModelKind::choices()
            )
        );
    }

    #[test]
    fn a_lap_force_beyond_gross_slip_is_refused_at_its_line() {
        let problems = Preset::parse(
            "model = \"lap\"\nmu = 0.1\nF = 3000\n",
            "x",
            PresetSource::Bundled,
        )
        .unwrap_err();
        assert_eq!(
            problems[0].to_string(),
            "line 3: invalid F = 3000: must be in [0, 2000] N (F_gross = 2 b mu P L: the joint \
             slides through beyond it)"
        );
    }

    #[test]
    fn syntax_errors_carry_line_and_column() {
        let problems =
            Preset::parse("model = \"beam\"\nL = = 3\n", "x", PresetSource::Bundled).unwrap_err();
        let message = problems[0].to_string();
        assert!(message.contains("line 2, column"), "{message}");
        assert!(!message.contains('\n'));
    }

    #[test]
    fn a_description_that_is_not_text_is_called_what_it_is() {
        for (value, shown) in [("5", "5"), ("true", "true"), ("[1, 2]", "[1, 2]")] {
            let text = format!("model = \"beam\"\ndescription = {value}\n");
            let problems = Preset::parse(&text, "x", PresetSource::Bundled).unwrap_err();
            assert_eq!(
                problems[0].to_string(),
                format!(
                    "line 2: invalid value '{shown}' for description: must be a string, in double quotes"
                )
            );
        }
    }

    #[test]
    fn model_must_be_named() {
        let problems = Preset::parse("L = 3\n", "x", PresetSource::Bundled).unwrap_err();
        assert!(problems[0].to_string().contains("missing key 'model'"));
        let problems =
            Preset::parse("model = \"shell\"\n", "x", PresetSource::Bundled).unwrap_err();
        assert_eq!(
            problems[0].to_string(),
            format!(
                "line 1: invalid model = 'shell': must be {}",
                ModelKind::choices()
            )
        );
    }

    #[test]
    fn assignments_check_key_and_number() {
        let mut inputs = Inputs::paper(ModelKind::Plate);
        apply_assignment(&mut inputs, "nu=0.25").unwrap();
        assert_eq!(inputs.get(Param::Plate(PlateParam::Poisson)), Some(0.25));
        apply_assignment(&mut inputs, " KT = 1e3 ").unwrap();
        assert_eq!(inputs.get(Param::Plate(PlateParam::Stiffness)), Some(1e3));
        let err = apply_assignment(&mut inputs, "F=3")
            .unwrap_err()
            .to_string();
        assert_eq!(
            err,
            "unknown key 'F' for the plate model (allowed: L tp E nu mu P KT)"
        );
        let err = apply_assignment(&mut inputs, "E=abc")
            .unwrap_err()
            .to_string();
        assert_eq!(
            err,
            "invalid value 'abc' for E: not a finite number; must be in [1e-4, 1e7] MPa"
        );
        assert!(apply_assignment(&mut inputs, "E=NaN").is_err());
        assert!(apply_assignment(&mut inputs, "E=inf").is_err());
        assert!(apply_assignment(&mut inputs, "E").is_err());
    }

    #[test]
    fn missing_keys_fall_back_to_the_paper_values() {
        let preset =
            Preset::parse("model = \"plate\"\nKT = 10\n", "x", PresetSource::Bundled).unwrap();
        assert_eq!(
            preset.inputs.get(Param::Plate(PlateParam::Thickness)),
            Some(0.2)
        );
        assert_eq!(
            preset.inputs.get(Param::Plate(PlateParam::Stiffness)),
            Some(10.0)
        );
    }

    #[test]
    fn a_beam_theory_is_read_for_the_beams_and_refused_for_the_others_with_why() {
        let text = "model = \"beam\"\nbeam_theory = \"timoshenko\"\n";
        let preset = Preset::parse(text, "x", PresetSource::Bundled).unwrap();
        assert!(preset.inputs != Inputs::paper(ModelKind::Beam));
        let refused = |text: &str| {
            Preset::parse(text, "x", PresetSource::Bundled).unwrap_err()[0].to_string()
        };
        assert_eq!(
            refused("model = \"beam\"\nbeam_theory = \"x\"\n"),
            "line 2: invalid beam theory 'x': must be \"euler-bernoulli\" or \"timoshenko\""
        );
        assert_eq!(
            refused("model = \"beam\"\nbeam_theory = 3\n"),
            "line 2: invalid value '3' for beam_theory: must be a string, in double quotes"
        );
        assert_eq!(
            refused("model = \"plate\"\nbeam_theory = \"timoshenko\"\n"),
            "line 2: beam_theory applies to the twin beams, not the plate"
        );
        assert_eq!(
            refused("model = \"lap\"\nbeam_theory = 3\n"),
            "line 2: beam_theory applies to the twin beams, not the lap joint (its plates are \
             bars: no bending)"
        );
    }
}
