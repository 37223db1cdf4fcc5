//! From a preset and `--set` to a validated model: loading, overrides and the errors that name the command.

use super::*;

/// The members of `plot --family KEY=V1,V2,...`: each value set on top of `model`'s inputs and
/// checked as `--set` checks it (the same messages, after the flag).
pub(super) fn family_models(
    model: &Model,
    spec: &str,
) -> Result<(crate::Param, Vec<(f64, Model)>), CliError> {
    use crate::chart::family::MAX_MEMBERS;
    let refuse = |why: String| CliError::Invalid(format!("--family {spec}: {why}"));
    let (key, values) = spec
        .split_once('=')
        .ok_or_else(|| refuse("expected KEY=V1,V2,... (e.g. P=0.5,1,2)".to_string()))?;
    let key = key.trim();
    let param = model.kind().param(key).map_err(|e| refuse(e.to_string()))?;
    let values: Vec<&str> = values.split(',').map(str::trim).collect();
    if values.len() > MAX_MEMBERS {
        return Err(refuse(format!(
            "{} values given, at most {MAX_MEMBERS} (more curves cannot be told apart)",
            values.len()
        )));
    }
    let mut members: Vec<(f64, Model)> = Vec::with_capacity(values.len());
    for value in values {
        let mut inputs = model.inputs();
        preset::apply_assignment(&mut inputs, &format!("{key}={value}"))
            .map_err(|e| refuse(e.to_string()))?;
        let member = inputs.validate().map_err(|e| refuse(e.to_string()))?;
        let number = member.inputs().get(param).unwrap_or(f64::NAN);
        if members.iter().any(|(v, _)| *v == number) {
            return Err(refuse(format!("{key} = {value} is given twice")));
        }
        members.push((number, member));
    }
    Ok((param, members))
}

/// The models of `plot --pin`: each pin's assignments on top of `model`'s inputs.
pub(super) fn pinned_models(model: &Model, pins: &[String]) -> Result<Vec<Model>, CliError> {
    use crate::chart::pins::MAX_PINS;
    if pins.len() > MAX_PINS {
        return Err(CliError::Invalid(format!(
            "--pin: {} pins given, at most {MAX_PINS} (more curves cannot be told apart)",
            pins.len()
        )));
    }
    pins.iter()
        .map(|pin| {
            let mut inputs = model.inputs();
            let mut keys: Vec<&str> = Vec::new();
            for assignment in pin.split(',').map(str::trim) {
                let key = assignment.split('=').next().unwrap_or("").trim();
                if keys.contains(&key) {
                    return Err(CliError::Invalid(format!(
                        "--pin {pin}: {key} is given twice; a pin sets each parameter once"
                    )));
                }
                keys.push(key);
                preset::apply_assignment(&mut inputs, assignment)
                    .map_err(|e| CliError::Invalid(format!("--pin {pin}: {e}")))?;
            }
            inputs
                .validate()
                .map_err(|e| CliError::Invalid(format!("--pin {pin}: {e}")))
        })
        .collect()
}

pub(super) fn load(
    args: &InputArgs,
    wanted: ModelKind,
    command: &str,
) -> Result<(String, Model), CliError> {
    load_for(args, wanted, command, Load::Used)
}

/// Whether a command reads the model's load (F): one that does not (a cycle's amplitude, a fit's
/// or a comparison's own forces) must not be refused over it (issue 36).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Load {
    /// The command uses F: validated against everything (the lap joint's F <= F_gross).
    Used,
    /// The command does not: F checked against its own domain only, the model unloaded.
    Unused,
}

pub(super) fn load_for(
    args: &InputArgs,
    wanted: ModelKind,
    command: &str,
    load: Load,
) -> Result<(String, Model), CliError> {
    let (name, preset) = resolve_preset(args, wanted)?;
    if preset.inputs.kind() != wanted {
        return Err(wrong_model(args, preset.inputs.kind(), wanted, command));
    }
    apply_and_validate(args, name, preset, load)
}

/// The typed model of problem `P` from `args` (a preset of another problem is refused by name),
/// validated with or without its load ([`Load`]): what a command written for one problem's
/// types (its report, its deck, its comparison) starts from.
pub(super) fn load_problem<P: Problem + Registered>(
    args: &InputArgs,
    command: &str,
    load: Load,
) -> Result<(String, P::Model), CliError> {
    let (name, model) = load_for(args, P::KIND, command, load)?;
    let typed =
        P::from_model(&model).ok_or_else(|| wrong_model(args, model.kind(), P::KIND, command))?;
    Ok((name, typed))
}

/// The problem whose key `word` is a slip of (`cylindre`, `lapp`): within two edits of it,
/// and closer than to any other key; `None` when no key is that close.
pub(super) fn closest_problem(word: &str) -> Option<ModelKind> {
    let word = word.to_lowercase();
    ModelKind::ALL
        .iter()
        .map(|kind| (edit_distance(&word, kind.name()), *kind))
        .filter(|(distance, _)| *distance <= 2)
        .min_by_key(|(distance, _)| *distance)
        .map(|(_, kind)| kind)
}

/// The Levenshtein distance between `a` and `b`, by characters.
pub(super) fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let above = row[j + 1];
            row[j + 1] = (above + 1)
                .min(row[j] + 1)
                .min(diagonal + usize::from(ca != *cb));
            diagonal = above;
        }
    }
    row[b.len()]
}

/// `cycle` or `sweep cycle` given a problem without a load (the plate): which problems have
/// one, from the registry.
pub(super) fn no_load_to_cycle(args: &InputArgs, kind: ModelKind, command: &str) -> CliError {
    let loaded: Vec<&str> = ModelKind::ALL
        .into_iter()
        .filter(|k| k.description().load.is_some())
        .map(|k| k.name())
        .collect();
    CliError::Invalid(format!(
        "preset '{}' is a {kind} preset; `microslip {command}` needs a preset of a problem with \
         a load ({}): the {} has no load to cycle",
        args.preset.as_deref().unwrap_or_default(),
        loaded.join(", "),
        kind.description().title
    ))
}

/// A preset of the problem `found` given to a command for `wanted`.
pub(super) fn wrong_model(
    args: &InputArgs,
    found: ModelKind,
    wanted: ModelKind,
    command: &str,
) -> CliError {
    CliError::WrongModel {
        preset: args.preset.clone().unwrap_or_default(),
        found,
        wanted,
        command: command.to_string(),
    }
}

/// A deck whose header describes another problem than the results reader was asked for.
pub(super) fn deck_of_other_model(found: ModelKind) -> CliError {
    CliError::Invalid(format!(
        "the deck's header describes the {found} problem, not the one compared"
    ))
}

/// Like [`load`], for commands that accept any problem (`default` picks the default preset).
pub(super) fn load_any(args: &InputArgs, default: ModelKind) -> Result<(String, Model), CliError> {
    let (name, preset) = resolve_preset(args, default)?;
    apply_and_validate(args, name, preset, Load::Used)
}

/// As [`load_any`] for a command that does not use the load ([`Load::Unused`]).
pub(super) fn load_any_structure(
    args: &InputArgs,
    default: ModelKind,
) -> Result<(String, Model), CliError> {
    let (name, preset) = resolve_preset(args, default)?;
    apply_and_validate(args, name, preset, Load::Unused)
}

pub(super) fn resolve_preset(
    args: &InputArgs,
    default: ModelKind,
) -> Result<(String, Preset), CliError> {
    let preset = preset::resolve(
        args.preset
            .as_deref()
            .unwrap_or(preset::default_name(default)),
    )?;
    Ok((preset.name.clone(), preset))
}

/// The preset of a generic command (`sweep`, `fit`), whose problem comes from `--model` or the
/// preset: `--model`'s default preset without `--preset`; both given, they must agree.
pub(super) fn resolve_generic(
    args: &InputArgs,
    model: Option<ModelKind>,
) -> Result<(String, Preset), CliError> {
    let (name, preset) = resolve_preset(args, model.unwrap_or(DEFAULT_PROBLEM))?;
    let kind = preset.inputs.kind();
    if let Some(model) = model
        && model != kind
    {
        return Err(CliError::Invalid(format!(
            "--model {model} and --preset {} disagree: the preset is a {kind} preset; drop \
             --model, or give a {model} preset",
            args.preset.as_deref().unwrap_or_default()
        )));
    }
    Ok((name, preset))
}

pub(super) fn apply_and_validate(
    args: &InputArgs,
    name: String,
    preset: Preset,
    load: Load,
) -> Result<(String, Model), CliError> {
    let preset_name = name.clone();
    let mut inputs: Inputs = preset.inputs;
    for assignment in &args.assignments {
        preset::apply_assignment(&mut inputs, assignment)?;
    }
    // "modified" only where a value differs from the preset's: `--set F=3000` on a preset whose F
    // is 3000 leaves the preset as it is, and saying otherwise sends users looking for a change.
    let set_changed = inputs != preset.inputs;
    let before_choices = inputs;
    for (key, text) in &args.choices {
        apply_choice(&mut inputs, key, text)?;
    }
    let choice_flags: Vec<String> = args
        .choices
        .iter()
        .map(|(key, _)| format!("--{}", key.replace('_', "-")))
        .collect();
    let mut changed_by: Vec<String> = Vec::new();
    if set_changed {
        changed_by.push("--set".to_string());
    }
    if inputs != before_choices {
        changed_by.extend(choice_flags);
    }
    let name = if changed_by.is_empty() {
        name
    } else {
        format!("{name} (modified by {})", changed_by.join(" and "))
    };
    let validated = match load {
        Load::Used => inputs.validate(),
        Load::Unused => inputs.validate_without_load(),
    };
    let model = validated.map_err(|e| blame_the_values_set(args, &preset_name, e))?;
    Ok((name, model))
}

/// A value refused because values given with `--set` moved its range (`--set P=1e-6` on the
/// cylinder's preset leaves its Q = 300 N/mm beyond mu P): the refusal says that the value is
/// the preset's, not one typed, and how to set it too; any other refusal as it is.
fn blame_the_values_set(args: &InputArgs, preset: &str, e: ParamError) -> CliError {
    let typed = |key: &str| {
        args.assignments
            .iter()
            .any(|a| a.split_once('=').is_some_and(|(k, _)| k.trim() == key))
    };
    if args.assignments.is_empty() || typed(e.field) {
        return CliError::Param(e);
    }
    let set: Vec<&str> = args
        .assignments
        .iter()
        .filter_map(|a| a.split_once('=').map(|(k, _)| k.trim()))
        .collect();
    CliError::Invalid(format!(
        "{e}; {} = {} is the value of {preset}, not one given with --set: the values set ({}) \
         moved its range, so set it too (--set {}=...)",
        e.field,
        Compact(e.value),
        set.join(", "),
        e.field
    ))
}

/// Sets the problem's setting `key` (a name, not a number: `beam_theory`) from its flag
/// (`--beam-theory`, the key with `-` for `_`), through the registry; refused, naming whose
/// setting it is, for the inputs of a problem without it.
fn apply_choice(inputs: &mut Inputs, key: &str, text: &str) -> Result<(), CliError> {
    let Some(choice) = preset::choice(key) else {
        return Ok(());
    };
    match choice.set(inputs, text) {
        Some(set) => set.map_err(|e| CliError::Theory(e.to_string())),
        None => {
            // The one-line refusal leaves out the preset's parenthesis (why it has none).
            let refused = inputs.kind().problem().refused_as();
            let model = refused.split(" (").next().unwrap_or(refused);
            Err(CliError::Theory(format!(
                "--{} applies to {}, not {model}",
                key.replace('_', "-"),
                choice.owner()
            )))
        }
    }
}

/// Checks a flag that is not a model parameter against `domain`.
/// [`Domain::check`] (which also turns -0 into 0) with the flag's name in the refusal.
pub(super) fn check_flag(
    flag: &'static str,
    value: f64,
    domain: Domain,
    unit: Unit,
) -> Result<f64, CliError> {
    domain.check(flag, value, unit).map_err(|_| CliError::Flag {
        flag,
        value,
        allowed: domain.refusal(value, unit),
    })
}
