use super::*;
use clap::CommandFactory;

#[test]
fn clap_definition_is_consistent() {
    Cli::command().debug_assert();
}

#[test]
fn fit_progress_shows_after_a_second_at_most_ten_times_a_second_and_is_erased() {
    let grid = |done| fit::Progress::Bracket {
        done,
        total: 784,
        points: 1024,
    };
    let mut line = ProgressLine::new(Vec::new(), true);
    let t0 = line.started;
    let show = |p: fit::Progress| move || text::fit_progress(&p);
    line.update(t0 + Duration::from_millis(999), show(grid(1)));
    assert!(line.out.is_empty(), "nothing within the first second");
    line.update(t0 + Duration::from_millis(1000), show(grid(400)));
    line.update(t0 + Duration::from_millis(1050), show(grid(401)));
    line.update(
        t0 + Duration::from_millis(1100),
        show(fit::Progress::Refine {
            iteration: 2,
            points: 1_000_000,
            pass: fit::Pass::Derivatives,
            done: 250_000,
        }),
    );
    line.finish();
    let text = String::from_utf8(line.out).unwrap();
    assert_eq!(
        text,
        "\r\x1b[2Kmicroslip: fitting: grid search for a start on 1024 measurements, 51%\
         \r\x1b[2Kmicroslip: fitting: refining on 1000000 measurements, iteration 2: derivatives 25%\
         \r\x1b[2K"
    );
    // Not a terminal: never anything, not even the erasing.
    let mut quiet = ProgressLine::new(Vec::new(), false);
    let t0 = quiet.started;
    quiet.update(t0 + Duration::from_secs(5), || {
        text::reading_progress(50, 100)
    });
    quiet.finish();
    assert!(quiet.out.is_empty());
    // A quick fit that showed nothing erases nothing.
    let mut quick = ProgressLine::new(Vec::new(), true);
    quick.finish();
    assert!(quick.out.is_empty());
}

#[test]
fn every_problem_of_the_registry_is_a_subcommand_that_names_it() {
    use clap::Parser;
    for kind in ModelKind::ALL {
        let cli = Cli::try_parse_from(["microslip", kind.name()]).unwrap();
        match cli.command {
            Some(Command::Problem(point)) => assert_eq!(point.kind, kind),
            other => panic!("{kind}: {other:?}"),
        }
        let sweep = Cli::try_parse_from([
            "microslip",
            "sweep",
            kind.name(),
            "--from",
            "1",
            "--to",
            "2",
            "--points",
            "2",
        ])
        .unwrap();
        match sweep.command {
            Some(Command::Sweep(WithProblems {
                command: Some(SweepCommand::Problem(problem)),
                ..
            })) => assert_eq!(problem.kind, kind),
            other => panic!("sweep {kind}: {other:?}"),
        }
    }
}

#[test]
fn a_slip_of_a_problem_s_key_is_told_the_key() {
    for kind in ModelKind::ALL {
        let key = kind.name();
        assert_eq!(closest_problem(key), Some(kind));
        // One letter dropped, one doubled, the last two swapped (`cylindre`).
        let dropped = &key[..key.len() - 1];
        assert_eq!(closest_problem(dropped), Some(kind), "{dropped}");
        let n = key.len();
        let swapped = format!("{}{}{}", &key[..n - 2], &key[n - 1..], &key[n - 2..n - 1]);
        assert_eq!(closest_problem(&swapped), Some(kind), "{swapped}");
        assert_eq!(
            closest_problem(&format!("{key}{}", &key[key.len() - 1..])),
            Some(kind)
        );
    }
    assert_eq!(closest_problem("measurements.csv"), None);
    assert_eq!(edit_distance("kitten", "sitting"), 3);
    assert_eq!(edit_distance("", "lap"), 3);
}
