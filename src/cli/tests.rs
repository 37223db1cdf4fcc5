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
