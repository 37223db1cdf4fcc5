//! One subcommand per problem of the registry, for every command that has per-problem
//! subcommands (`microslip PROBLEM`, `sweep PROBLEM`, `fit PROBLEM`): [`ForKind`] adds one
//! subcommand per [`ModelKind::ALL`] that takes the command, named by the problem's key and
//! described from its [`Description`](crate::problems::Description), so that `--help` lists
//! every problem, `help KEY` and `KEY --help` describe it, and a new problem gets its
//! subcommands from its registry line. A command declares what its subcommands share (its
//! [`clap::Args`]) and, through [`PerProblem`], which problems take it (a capability, never a
//! name) and the options only some problems have (`--continuum` where the problem has a
//! continuum reference; the settings of [`hide_foreign_choices`]).

use super::*;
use clap::{ArgMatches, Args, FromArgMatches, Subcommand};

/// The arguments of a command run for one problem, and how its subcommand for each problem is
/// described.
pub trait PerProblem: Args {
    /// Whether `kind` takes this command (a capability it has: a load to fit).
    fn offered(kind: ModelKind) -> bool;
    /// The subcommand of `kind` from the shared flags (`command`): its help, from the
    /// problem's description, and the options that only some problems take.
    fn describe(kind: ModelKind, command: clap::Command) -> clap::Command;
}

/// A per-problem subcommand as parsed: the problem, the shared flags and the matches of the
/// subcommand, from which its problem's own options are read ([`ForKind::flag`]).
#[derive(Debug)]
pub struct ForKind<A> {
    /// The problem the subcommand names.
    pub kind: ModelKind,
    /// The flags every problem's subcommand of the command has.
    pub args: A,
    /// The subcommand's matches: the options only some problems declare.
    own: ArgMatches,
}

impl<A> ForKind<A> {
    /// The value of a switch only some problems declare (`--continuum`): false where the
    /// problem has no such option or it was not given.
    pub(in crate::cli) fn flag(&self, id: &str) -> bool {
        self.own.try_get_one::<bool>(id).ok().flatten() == Some(&true)
    }

    /// The value of an option only some problems declare (`--kt-from`): `None` where the
    /// problem has no such option or it was not given.
    pub(in crate::cli) fn value(&self, id: &str) -> Option<f64> {
        self.own.try_get_one::<f64>(id).ok().flatten().copied()
    }
}

/// The problem a subcommand's name is, if it takes the command.
fn offered<A: PerProblem>(name: &str) -> Option<ModelKind> {
    name.parse::<ModelKind>().ok().filter(|k| A::offered(*k))
}

impl<A: PerProblem> FromArgMatches for ForKind<A> {
    fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
        Self::from_arg_matches_mut(&mut matches.clone())
    }

    fn from_arg_matches_mut(matches: &mut ArgMatches) -> Result<Self, clap::Error> {
        use clap::error::ErrorKind;
        let Some((name, mut own)) = matches.remove_subcommand() else {
            return Err(clap::Error::raw(
                ErrorKind::MissingSubcommand,
                "a problem's key is required",
            ));
        };
        let kind = offered::<A>(&name).ok_or_else(|| {
            clap::Error::raw(
                ErrorKind::InvalidSubcommand,
                format!("unrecognized subcommand '{name}'"),
            )
        })?;
        let args = A::from_arg_matches_mut(&mut own)?;
        Ok(ForKind { kind, args, own })
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
        *self = Self::from_arg_matches(matches)?;
        Ok(())
    }
}

impl<A: PerProblem> Subcommand for ForKind<A> {
    fn augment_subcommands(command: clap::Command) -> clap::Command {
        ModelKind::ALL
            .iter()
            .filter(|kind| A::offered(**kind))
            .fold(command, |command, kind| {
                let sub = A::augment_args(clap::Command::new(kind.name()));
                command.subcommand(A::describe(*kind, sub))
            })
    }

    fn augment_subcommands_for_update(command: clap::Command) -> clap::Command {
        Self::augment_subcommands(command)
    }

    fn has_subcommand(name: &str) -> bool {
        offered::<A>(name).is_some()
    }
}

/// [`clap::Command::mut_arg`] without moving the argument to the end: the usage line and the
/// generated flag lists keep the order the flags are declared in.
pub(in crate::cli) trait EditArg {
    /// The command with the argument `id` changed by `edit`.
    fn edit_arg(self, id: &str, edit: impl FnMut(clap::Arg) -> clap::Arg) -> Self;
}

impl EditArg for clap::Command {
    fn edit_arg(self, id: &str, mut edit: impl FnMut(clap::Arg) -> clap::Arg) -> Self {
        self.mut_args(|arg| if arg.get_id() == id { edit(arg) } else { arg })
    }
}

/// `intro` and, in parentheses, what `names` gives for each problem of the registry (`beam: L b
/// h ...; plate: ...`).
pub(in crate::cli) fn per_problem_help<S: AsRef<str>>(
    intro: &str,
    names: impl Fn(ModelKind) -> Vec<S>,
) -> String {
    let lists: Vec<String> = ModelKind::ALL
        .iter()
        .map(|kind| {
            let owned = names(*kind);
            let names: Vec<&str> = owned.iter().map(AsRef::as_ref).collect();
            format!("{kind}: {}", names.join(" "))
        })
        .collect();
    format!("{intro} ({})", lists.join("; "))
}

/// The help of a generic command's `--model`: the default problem from the registry, and what
/// the problem must have (`extra`, after a comma, or empty).
pub(in crate::cli) fn model_flag_help(extra: &str) -> String {
    format!(
        "The problem (default: the preset's; without --preset, {}). Given with --preset, both \
         must name the same problem{extra}",
        crate::cli::DEFAULT_PROBLEM
    )
}

/// The problem's title with its first letter capitalized, as a help line starts.
pub(in crate::cli) fn title(kind: ModelKind) -> String {
    let title = kind.description().title;
    let mut chars = title.chars();
    chars.next().map_or_else(String::new, |first| {
        first.to_uppercase().chain(chars).collect()
    })
}

/// The problem's parameters as a help lists them: one line each, key, unit and meaning.
pub(in crate::cli) fn param_lines(kind: ModelKind) -> String {
    let specs: Vec<_> = kind.params().iter().map(|p| p.spec()).collect();
    let key_width = specs.iter().map(|s| s.name.len()).max().unwrap_or(0);
    let unit_width = specs
        .iter()
        .map(|s| s.unit.symbol().len())
        .max()
        .unwrap_or(0);
    specs
        .iter()
        .map(|spec| {
            format!(
                "  {:key_width$}  {:unit_width$}  {}",
                spec.name,
                spec.unit.symbol(),
                spec.meaning
            )
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// `--model` and the `model` positional: the problems' keys, each with its summary in `--help`
/// (a parser rather than `ValueEnum`, which the core crate's type cannot implement here).
pub(in crate::cli) fn model_kind_parser() -> impl clap::builder::TypedValueParser<Value = ModelKind>
{
    use clap::builder::TypedValueParser;
    clap::builder::PossibleValuesParser::new(ModelKind::ALL.map(|kind| {
        let d = kind.description();
        clap::builder::PossibleValue::new(d.key).help(d.summary)
    }))
    .try_map(|key| key.parse::<ModelKind>())
}
