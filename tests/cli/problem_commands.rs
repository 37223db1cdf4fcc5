//! One path from a command to a problem (issue 43, item 3): every problem of the registry is a
//! subcommand of `microslip`, `sweep` and (with a fit) `fit`, described from its registry entry
//! with only the flags it takes. The problems, their parameters, settings and capabilities are
//! read from the registry here, never listed by hand.

use super::*;
use microslip::problems::ModelKind;

/// The flags of every problem's settings (`--beam-theory`) with whether `kind` has each.
fn setting_flags(kind: ModelKind) -> Vec<(String, bool)> {
    let own = kind.problem().faces().choices;
    ModelKind::ALL
        .iter()
        .flat_map(|k| k.problem().faces().choices)
        .map(|c| {
            (
                format!("--{}", c.key().replace('_', "-")),
                own.iter().any(|o| o.key() == c.key()),
            )
        })
        .collect()
}

#[test]
fn help_lists_every_registered_problem() {
    let help = stdout_of(&["--help"]);
    let commands: Vec<&str> = help
        .lines()
        .skip_while(|l| *l != "Commands:")
        .take_while(|l| !l.is_empty())
        .filter_map(|l| l.strip_prefix("  "))
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    for kind in ModelKind::ALL {
        assert!(commands.contains(&kind.name()), "{kind}: {commands:?}");
    }
    let sweep = stdout_of(&["sweep", "--help"]);
    for kind in ModelKind::ALL {
        assert!(
            sweep
                .lines()
                .any(|l| l.starts_with(&format!("  {} ", kind.name()))),
            "sweep {kind}: {sweep}"
        );
    }
}

#[test]
fn help_key_and_key_help_describe_the_problem_with_only_its_flags() {
    for kind in ModelKind::ALL {
        let key = kind.name();
        let help = stdout_of(&[key, "--help"]);
        assert_eq!(help, stdout_of(&["help", key]), "{key}");
        let d = kind.description();
        // The help is wrapped: words compared, not lines.
        let words = |text: &str| text.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(
            words(&help).contains(&words(d.title)),
            "{key}: no title in\n{help}"
        );
        assert!(
            words(&help).contains(&words(d.summary)),
            "{key}: no summary in\n{help}"
        );
        assert!(help.contains(&format!("Usage: microslip {key} ")), "{help}");
        for param in kind.params() {
            let spec = param.spec();
            assert!(
                // The unit may be two words (`N mm`).
                help.lines().any(|l| {
                    l.trim_start()
                        .strip_prefix(spec.name)
                        .filter(|rest| rest.starts_with(' '))
                        .is_some_and(|rest| rest.trim_start().starts_with(spec.unit.symbol()))
                }),
                "{key}: parameter {} ({}) not listed in\n{help}",
                spec.name,
                spec.unit.symbol()
            );
        }
        assert_eq!(
            help.contains("--continuum"),
            kind.problem().faces().continuum.is_some(),
            "{key}: --continuum in\n{help}"
        );
        // Its own subcommands of sweep and fit show the same settings' flags.
        let mut helps = vec![help, stdout_of(&["sweep", key, "--help"])];
        if kind.problem().faces().fittable.is_some() {
            helps.push(stdout_of(&["fit", key, "--help"]));
        }
        if kind.description().load.is_some() {
            helps.push(stdout_of(&["cycle", key, "--help"]));
        }
        for help in &helps {
            for (flag, own) in setting_flags(kind) {
                assert_eq!(help.contains(&flag), own, "{key}: {flag} in\n{help}");
            }
        }
    }
}

#[test]
fn a_problem_refuses_a_setting_it_does_not_have_by_name() {
    for kind in ModelKind::ALL {
        for (flag, own) in setting_flags(kind) {
            if own {
                continue;
            }
            let owner = ModelKind::ALL
                .iter()
                .flat_map(|k| k.problem().faces().choices)
                .find(|c| format!("--{}", c.key().replace('_', "-")) == flag)
                .map(|c| c.owner())
                .unwrap();
            let value = ModelKind::ALL
                .iter()
                .flat_map(|k| k.problem().faces().choices)
                .find(|c| c.owner() == owner)
                .map(|c| c.values()[0])
                .unwrap();
            let stderr = failure(&[kind.name(), &flag, value], 2);
            assert!(
                stderr.contains(&format!("{flag} applies to {owner}")),
                "{kind}: {stderr}"
            );
        }
    }
}

#[test]
fn the_cylinder_help_is_stable() {
    insta::assert_snapshot!("help_cylinder", stdout_of(&["cylinder", "--help"]));
}

#[test]
fn a_slip_of_a_problem_or_command_gets_a_suggestion() {
    for (args, suggested) in [
        (&["cylindre"][..], "'cylinder'"),
        (&["lapp"], "'lap'"),
        (&["sweep", "lapp"], "'lap'"),
        (&["sweep", "cylindre", "--from", "0"], "'cylinder'"),
        (&["swep"], "'sweep'"),
        (&["fit", "lapp"], "'fit lap DATA.csv'"),
        (
            &["fit", "cylindre", "tests/data/reports/inputs/fit-beam.csv"],
            "'fit cylinder DATA.csv'",
        ),
    ] {
        let stderr = failure(args, 2);
        assert!(
            stderr.contains("did you mean") && stderr.contains(suggested),
            "{args:?}: {stderr}"
        );
    }
}

#[test]
fn fit_of_a_problem_without_a_file_names_the_missing_file() {
    for kind in ModelKind::ALL
        .into_iter()
        .filter(|k| k.problem().faces().fittable.is_some())
    {
        let stderr = failure(&["fit", kind.name()], 2);
        assert!(
            stderr.contains("required arguments were not provided: <DATA.csv>"),
            "{kind}: {stderr}"
        );
        assert!(!stderr.contains("cannot read"), "{kind}: {stderr}");
    }
    // A problem without a fit, given where the file goes, is named as such.
    for kind in ModelKind::ALL
        .into_iter()
        .filter(|k| k.problem().faces().fittable.is_none())
    {
        let stderr = failure(&["fit", kind.name()], 2);
        assert!(
            stderr.contains(&format!("the {kind} problem has no load")),
            "{kind}: {stderr}"
        );
    }
}

#[test]
fn figures_help_offers_only_what_it_writes() {
    let help = stdout_of(&["figures", "--help"]);
    assert!(help.contains("- svg:") && help.contains("- pdf:"), "{help}");
    assert!(!help.contains("- csv:"), "{help}");
}

/// Every problem's subcommand of `sweep` writes what the generic sweep writes for it.
#[test]
fn sweep_problem_is_the_generic_sweep_of_that_problem() {
    for kind in ModelKind::ALL {
        let preset = kind.description().paper_preset;
        let stiffness = kind
            .params()
            .iter()
            .find(|p| p.is_stiffness())
            .unwrap()
            .name();
        let common = [
            "--vary", stiffness, "--from", "100", "--to", "1000", "--points", "3",
        ];
        let by_key = stdout_of(&[&["sweep", kind.name()][..], &common].concat());
        let generic = stdout_of(&[&["sweep", "--preset", preset][..], &common].concat());
        assert_eq!(by_key, generic, "{kind}");
    }
}

/// Every problem with a load has its subcommand of `cycle`, which writes what `cycle --model`
/// writes for it; a problem without one is named as such.
#[test]
fn cycle_problem_is_the_generic_cycle_of_that_problem() {
    for kind in ModelKind::ALL {
        let common = ["--amplitude", "1", "--format", "json"];
        if kind.description().load.is_none() {
            let stderr = failure(&[&["cycle", kind.name()][..], &common].concat(), 2);
            assert!(
                stderr.contains(&format!("the {kind} problem does not take this command")),
                "{stderr}"
            );
            continue;
        }
        let by_key = stdout_of(&[&["cycle", kind.name()][..], &common].concat());
        let generic = stdout_of(&[&["cycle", "--model", kind.name()][..], &common].concat());
        assert_eq!(by_key, generic, "{kind}");
    }
}
