//! `plot` and `figures`, pins, families and the K_T tolerance.

use super::*;

#[test]
fn plot_writes_png_and_pdf_by_the_extension_and_refuses_one_it_cannot_write() {
    let dir = tempfile::tempdir().unwrap();
    let file = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    for name in ["w.png", "W.PDF", "w.svg"] {
        stdout_of(&["plot", "w-vs-f", "--fe", "-o", &file(name)]);
    }
    let png = std::fs::read(file("w.png")).unwrap();
    assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"), "not a PNG");
    let image = resvg::tiny_skia::Pixmap::decode_png(&png).unwrap();
    assert_eq!((image.width(), image.height()), (1600, 1000));
    // The title (the top 80 px, text alone: the built-in font, not the system's), the axes and
    // curves (the rest) are drawn in dark ink on white.
    let title = dark_pixels(&image, 0..80);
    let body = dark_pixels(&image, 80..1000);
    assert!(title > 500, "{title} dark pixels in the title band");
    assert!(body > 5000, "{body} dark pixels under the title");
    assert!(
        image.pixels()[0].red() == 255,
        "the background is opaque white"
    );
    let pdf = std::fs::read(file("W.PDF")).unwrap();
    assert!(pdf.starts_with(b"%PDF-"), "not a PDF");
    assert!(
        pdf.windows(b"DejaVu".len()).any(|w| w == b"DejaVu"),
        "the PDF embeds its font"
    );
    assert!(
        std::fs::read_to_string(file("w.svg"))
            .unwrap()
            .starts_with("<svg")
    );
    // `--format` on stdout; an extension that no format has, or one that contradicts --format,
    // is refused before anything is written.
    let output = microslip()
        .args(["plot", "w-vs-f", "--format", "png"])
        .output()
        .unwrap();
    assert!(output.status.success() && output.stdout.starts_with(b"\x89PNG"));
    let error = failure(&["plot", "w-vs-f", "-o", &file("w.jpg")], 2);
    assert!(
        error.contains("-o/--output") && error.contains("w.jpg") && error.contains(".png, .pdf"),
        "{error}"
    );
    let error = failure(
        &["plot", "w-vs-f", "--format", "pdf", "-o", &file("x.svg")],
        2,
    );
    assert!(
        error.contains("--format = pdf") && error.contains(".svg"),
        "{error}"
    );
    assert!(!dir.path().join("w.jpg").exists() && !dir.path().join("x.svg").exists());
}

#[test]
fn figures_writes_png_or_pdf_when_asked_and_refuses_csv() {
    let dir = tempfile::tempdir().unwrap();
    for (format, magic) in [("png", &b"\x89PNG"[..]), ("pdf", &b"%PDF-"[..])] {
        let out = dir.path().join(format);
        let args = [
            "figures",
            "--out",
            out.to_str().unwrap(),
            "--no-fe",
            "--format",
            format,
        ];
        stdout_of(&args);
        let index = std::fs::read_to_string(out.join("index.html")).unwrap();
        let file = out.join(format!("beam-w-vs-f.{format}"));
        assert!(
            index.contains(&format!("beam-w-vs-f.{format}\"")),
            "{index}"
        );
        assert!(std::fs::read(&file).unwrap().starts_with(magic), "{file:?}");
        assert!(!out.join("beam-w-vs-f.svg").exists());
    }
    let error = failure(&["figures", "--out", "x", "--format", "csv"], 2);
    assert!(
        error.contains("--format = csv") && error.contains("svg, png, pdf"),
        "{error}"
    );
}

#[test]
fn figures_writes_every_figure_its_data_and_an_index() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("figs");
    let text = stdout_of(&["figures", "--out", out.to_str().unwrap(), "--no-fe"]);
    assert!(text.contains("index.html"));
    let index = std::fs::read_to_string(out.join("index.html")).unwrap();
    let figures: Vec<&str> = index
        .split("<img src=\"")
        .skip(1)
        .map(|s| s.split('"').next().unwrap())
        .collect();
    assert!(figures.len() >= 9, "{figures:?}");
    for svg in figures {
        let body = std::fs::read_to_string(out.join(svg)).unwrap();
        assert!(body.starts_with("<svg"), "{svg}");
        assert!(out.join(svg.replace(".svg", ".csv")).exists(), "{svg}");
    }
}

#[test]
fn kt_tolerance_answers_with_the_stiffness_and_each_codes_setting() {
    let text = stdout_of(&["kt", "--tolerance", "1%"]);
    assert!(
        text.contains("within 1 % of Coulomb at F = 100 N"),
        "{text}"
    );
    assert!(text.contains("K_T >= 423.1 MPa/mm"), "{text}");
    assert!(text.contains("SLIP TOLERANCE <=") && text.contains("stick slope lambda >= 423"));
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "kt",
        "--tolerance",
        "0.01",
        "--from",
        "0",
        "--to",
        "300",
        "--format",
        "json",
    ]))
    .unwrap();
    let kt = json["KT_min_MPa_per_mm"].as_f64().unwrap();
    let expected = paper_beams_stiffness_within(0.01);
    assert!((kt / expected - 1.0).abs() < 1e-9, "{kt} vs {expected}");
    assert_eq!(json["force_range_N"], serde_json::json!([0.0, 300.0]));
    let plate = stdout_of(&["kt", "--tolerance", "1%", "--preset", "paper-plate"]);
    // Rounded to four significant digits, as the text shows K_T.
    let shown = format!("K_T >= {:.3e} MPa/mm", paper_plate_stiffness_within(0.01));
    assert!(plate.contains("u(L)") && plate.contains(&shown), "{plate}");
    for (args, says) in [
        (&["kt", "--tolerance", "0"][..], "--tolerance"),
        (&["kt", "--tolerance", "1%", "--from", "-3"], "--from"),
        (
            &["kt", "--tolerance", "1%", "--from", "0", "--to", "0"],
            "no positive force",
        ),
        (
            &[
                "kt",
                "--tolerance",
                "1%",
                "--preset",
                "paper-plate",
                "--to",
                "5",
            ],
            "plate",
        ),
    ] {
        let error = failure(args, 2);
        assert!(error.contains(says), "{args:?}: {error}");
    }
}

#[test]
fn plot_pins_draw_the_chart_at_other_values_over_the_same_range() {
    let data = stdout_of(&["plot", "w-vs-f", "--pin", "mu=0.2", "--format", "csv"]);
    let pinned: Vec<&str> = data
        .lines()
        .filter(|l| l.starts_with("pin 1: mu 0.2->0.3,"))
        .collect();
    assert_eq!(pinned.len(), 200, "{data}");
    // Over the current chart's force range (3 F_thre = 240 N at mu = 0.3, not 160 N at mu = 0.2),
    // and at 240 N the same w(L) as `microslip beam` at mu = 0.2.
    let last: Vec<&str> = pinned[199].split(',').collect();
    assert_eq!(last[2], "240.0");
    let point = stdout_of(&[
        "beam", "--set", "mu=0.2", "--set", "F=240", "--format", "json",
    ]);
    let json: serde_json::Value = serde_json::from_str(&point).unwrap();
    let w = json["regularized"]["w_tip_mm"].as_f64().unwrap();
    let pinned_w: f64 = last[4].parse().unwrap();
    assert!((pinned_w - w).abs() <= 1e-12 * w, "{pinned_w} vs {w}");
    // Several values per pin, and the refusals name the pin.
    let two = stdout_of(&[
        "plot",
        "x-vs-f",
        "--pin",
        "mu=0.2,KT=1000",
        "--format",
        "csv",
    ]);
    assert!(two.contains("pin 1: mu 0.2->0.3 KT 1000->600,"), "{two}");
    let error = failure(&["plot", "w-vs-f", "--pin", "mu=-1"], 2);
    assert!(
        error.contains("--pin mu=-1") && error.contains("mu"),
        "{error}"
    );
    let five: Vec<&str> = ["mu=0.1", "mu=0.2", "mu=0.4", "mu=0.5", "mu=0.6"]
        .iter()
        .flat_map(|p| ["--pin", *p])
        .collect();
    let error = failure(&[&["plot", "w-vs-f"], five.as_slice()].concat(), 2);
    assert!(error.contains("at most 4"), "{error}");
}

#[test]
fn kt_says_what_its_tolerance_is_of_and_offers_the_other_reading() {
    let text = stdout_of(&["kt", "--tolerance", "1%"]);
    assert!(
        text.contains("1 % of the Coulomb answer") && text.contains("--of current"),
        "{text}"
    );
    let text = stdout_of(&["kt", "--tolerance", "0.1%", "--of", "current"]);
    assert!(
        text.contains("within 0.1 % of the current K_T's (600 MPa/mm)") && text.contains(" to "),
        "{text}"
    );
    let said = failure(&["kt", "--of", "current"], 2);
    assert!(said.contains("--tolerance"), "{said}");
    // The table says how far each candidate's w(L) is from the current K_T's.
    // Abaqus's default, 30 MPa/mm here, against the paper's 600, from the closed forms:
    let w = |kt: f64| {
        microslip::TwinBeams::new(microslip::TwinBeamsParams {
            tangential_stiffness: kt,
            ..microslip::TwinBeamsParams::PAPER
        })
        .unwrap()
        .regularized(microslip::TipForce::new(100.0).unwrap())
        .tip_deflection()
    };
    let expected = format!("+{:.1} %", 100.0 * (w(30.0) / w(600.0) - 1.0));
    let table = stdout_of(&["kt"]);
    let abaqus = table.lines().find(|l| l.starts_with("Abaqus")).unwrap();
    assert!(
        table.contains("vs current") && abaqus.contains(&expected),
        "{expected}: {table}"
    );
}

#[test]
fn plot_family_draws_one_curve_per_value_over_the_whole_force_axis() {
    let data = stdout_of(&["plot", "w-vs-f", "--family", "P=0.5,1,2", "--format", "csv"]);
    assert!(data.starts_with("series,x_axis,x,y_axis,y\n"), "{data}");
    let series = csv_series(&data);
    let names: Vec<&str> = series.iter().map(|s| s.0.as_str()).collect();
    // Equal rank: no Coulomb, no K_T/5 or K_T*5, no cursor; the unit in every name.
    assert_eq!(names, ["P = 0.5 MPa", "P = 1 MPa", "P = 2 MPa"]);
    // Each member over the whole axis, which shows P = 2 MPa's regime change (F_thre = 160 N).
    for (name, points, last) in &series {
        assert_eq!((*points, *last), (200, 480.0), "{name}");
    }
    let svg = stdout_of(&["plot", "w-vs-f", "--family", "P=0.5,1,2"]);
    for text in [
        "w(L) vs F, P = 0.5, 1, 2 MPa",
        "P = 0.5 MPa",
        "L = 200 mm, b = 20 mm, h = 10 mm, E = 210000 MPa, nu = 0.3, mu = 0.3, KT = 600 MPa/mm",
    ] {
        assert!(svg.contains(text), "{text}");
    }
    assert!(!svg.contains(">\ncurrent\n<") && !svg.contains("K_T/5"));
    // A series the same for every member may be added once; one that differs is refused.
    let names = plotted_names(&[
        "w-vs-f",
        "--family",
        "KT=120,3000",
        "--series",
        "coulomb,current",
    ]);
    assert_eq!(names, ["Coulomb", "KT = 120 MPa/mm", "KT = 3000 MPa/mm"]);
    let error = failure(
        &[
            "plot", "w-vs-f", "--family", "P=0.5,2", "--series", "coulomb",
        ],
        2,
    );
    assert!(error.contains("differs between the members"), "{error}");
}

#[test]
fn plot_family_refusals_name_the_flag() {
    for (args, says) in [
        (
            &["--family", "P=0.5,-1"][..],
            "--family P=0.5,-1: invalid P = -1: must be > 0",
        ),
        (&["--family", "Q=1,2"], "--family Q=1,2: unknown key 'Q'"),
        (
            &["--family", "P=1,x"],
            "--family P=1,x: invalid value 'x' for P",
        ),
        (&["--family", "P"], "--family P: expected KEY=V1,V2"),
        (&["--family", "P=1,1"], "P = 1 is given twice"),
        (
            &["--family", "P=1,2,3,4,5,6,7"],
            "7 values given, at most 6",
        ),
        (&["--family", "P=1,2", "--pin", "mu=0.2"], "--pin"),
        (&["--family", "P=1,2", "--fe"], "--fe"),
    ] {
        let error = failure(&[&["plot", "w-vs-f"], args].concat(), 2);
        assert!(error.contains(says), "{args:?}: {error}");
    }
    // The same messages as --set gives, after the flag.
    let set = failure(&["plot", "w-vs-f", "--set", "P=-1"], 2);
    let family = failure(&["plot", "w-vs-f", "--family", "P=-1"], 2);
    let reason = set.trim_start_matches("microslip: ");
    assert!(family.ends_with(reason), "{family} vs {set}");
}

#[test]
fn plot_series_and_no_cursor_choose_what_is_drawn() {
    let names = plotted_names(&["w-vs-f", "--series", "current,coulomb"]);
    assert_eq!(names, ["Coulomb", "K_T"]);
    let svg = stdout_of(&["plot", "w-vs-f", "--series", "current,coulomb"]);
    assert!(!svg.contains(">\ncurrent\n<") && !svg.contains("K_T*5"));
    let with_cursor = stdout_of(&["plot", "w-vs-f"]);
    assert!(with_cursor.contains(">\ncurrent\n<"));
    let without = stdout_of(&["plot", "w-vs-f", "--no-cursor"]);
    assert!(!without.contains(">\ncurrent\n<") && without.contains(">\nK_T/5\n<"));
    let error = failure(&["plot", "w-vs-f", "--series", "current,nope"], 2);
    assert!(
        error.contains(
            "unknown series 'nope' (allowed: current, coulomb, softer, stiffer, limit, fe, \
             continuum, measured, external, cursor)"
        ),
        "{error}"
    );
    let error = failure(&["plot", "w-vs-f", "--series", "limit"], 2);
    assert!(
        error.contains("chart w-vs-f has no limit series; it has: "),
        "{error}"
    );
    let error = failure(&["plot", "w-vs-f", "--series", "fe"], 2);
    assert!(error.contains("fe needs --fe"), "{error}");
    let error = failure(&["plot", "w-vs-f", "--series", "cursor", "--no-cursor"], 2);
    assert!(error.contains("--no-cursor"), "{error}");
    // The mu P line of tau(x) alone with Coulomb.
    let names = plotted_names(&["tau", "--series", "coulomb,limit"]);
    assert_eq!(names, ["Coulomb", "mu P"]);
}

/// Plotters rounds to whole pixels, which makes gentle slopes stairs; curves are written at
/// fractional pixels.
#[test]
fn plot_curves_are_drawn_at_fractional_pixels() {
    let svg = stdout_of(&["plot", "w-vs-f", "--family", "P=0.5,1,2"]);
    let curves: Vec<&str> = svg
        .lines()
        .filter(|l| l.starts_with("<polyline") && l.matches(',').count() > 100)
        .collect();
    assert_eq!(curves.len(), 3, "{svg}");
    for curve in curves {
        let points = curve.split("points=\"").nth(1).unwrap();
        let coordinates: Vec<f64> = points
            .trim_end_matches("\"/>")
            .split([' ', ','])
            .map(|c| c.parse().unwrap())
            .collect();
        let fractional = coordinates.iter().filter(|c| c.fract() != 0.0).count();
        assert!(fractional > coordinates.len() / 2, "{curve}");
    }
}

#[test]
fn a_family_along_the_chart_s_own_axis_is_refused() {
    for (args, param) in [
        (
            &["plot", "w-vs-f", "--family", "F=0,100"][..],
            "F is the x axis of chart w-vs-f",
        ),
        (
            &[
                "plot",
                "u-vs-kt",
                "--preset",
                "paper-plate",
                "--family",
                "KT=1e3,1e6",
            ][..],
            "KT is the x axis of chart u-vs-kt",
        ),
    ] {
        let said = failure(args, 2);
        assert!(said.contains(param), "{said}");
    }
}

/// Beyond the friction strain (V2) was measured at (mu P = 10 MPa on the paper's beams:
/// mu P L / (2 E h) = 10 x 200 / (2 x 210000 x 10) = 4.76e-4 > 1.2e-4), every output says "not
/// calibrated" instead of a bound, and `compare` does not judge the implied K_T by it.
#[test]
fn beams_beyond_the_calibrated_friction_strain_get_no_bound() {
    let set = ["--set", "mu=1", "--set", "P=10", "--set", "KT=3000"];
    let args = |command: &[&'static str]| -> Vec<&'static str> {
        command.iter().copied().chain(set).collect()
    };
    let json: serde_json::Value =
        serde_json::from_str(&stdout_of(&args(&["beam", "--format", "json"]))).unwrap();
    let theory = &json["beam_theory"];
    assert_eq!(theory["validity"], "not calibrated", "{json}");
    for key in [
        "vs_continuum_within",
        "vs_continuum_nlgeom_within_fraction",
        "vs_continuum_linear_within_fraction",
    ] {
        assert!(theory.get(key).is_none(), "{key}: {json}");
    }
    assert_eq!(
        theory["validity_linear_geometry"], "not calibrated",
        "{json}"
    );
    let strain = theory["friction_strain"].as_f64().unwrap();
    assert!((strain / (10.0 * 200.0 / (2.0 * 210_000.0 * 10.0)) - 1.0).abs() < 1e-12);
    let text = stdout_of(&args(&["beam"]));
    assert!(
        text.contains("not calibrated") && text.contains("4.76e-4"),
        "{text}"
    );
    let csv = stdout_of(&args(&[
        "sweep", "beam", "--from", "0", "--to", "60000", "--points", "2",
    ]));
    assert!(
        csv.lines()
            .nth(2)
            .unwrap()
            .ends_with(",euler-bernoulli,,,,"),
        "{csv}"
    );
    // Any FE points (these are made up): the implied K_T is not judged through (V2).
    let dir = tempfile::tempdir().unwrap();
    let fe = dir.path().join("fe.csv");
    std::fs::write(&fe, "F_N,w_mm\n20000,1.5\n30000,3.0\n40000,4.5\n").unwrap();
    let mut compare = vec!["compare", "beam", fe.to_str().unwrap()];
    compare.extend(set);
    let text = compare_report(&compare);
    assert!(
        text.contains("implied K_T not judged (the beam theory's envelope is not calibrated"),
        "{text}"
    );
}

/// The lap joint from the command line (issue 24): every command that has it, and what it refuses
/// and why.
#[test]
fn the_lap_joint_from_the_command_line() {
    let text = stdout_of(&["lap"]);
    for needed in [
        "Clamped double-lap joint",
        "F_1        = 2015.89 N",
        "at x = L (covers' ends)",
        "macroslip+microslip+macroslip",
        // Issue 33: where the continuum was solved, its measured difference replaces the bound.
        "Delta +1.09 % from the 2-D continuum solved below (holds; measured, in place of the \
         envelope's bound of 3.4 %)",
        "2-D continuum (plane stress, nu = 0.3",
    ] {
        assert!(text.contains(needed), "{needed}\n{text}");
    }
    // F beyond F_gross: refused with the bound and why, exit 2.
    let refused = failure(&["lap", "--set", "F=6001"], 2);
    assert!(
        refused.contains(
            "invalid F = 6001: must be in [0, 6000] N (F_gross = 2 b mu P L: the joint slides \
             through beyond it)"
        ),
        "{refused}"
    );
    // Sweeps over F (up to F_gross) and over any parameter, refusing an end with no state.
    let csv = stdout_of(&[
        "sweep", "lap", "--from", "0", "--to", "6000", "--points", "7",
    ]);
    assert!(
        csv.starts_with("F_N,Delta_coulomb_mm,Delta_regularized_mm,a_mm,d_mm,"),
        "{csv}"
    );
    assert_eq!(csv.lines().count(), 8);
    assert!(
        csv.lines()
            .next()
            .unwrap()
            .ends_with(",shear_lag_within,shear_lag_within_fraction"),
        "{csv}"
    );
    // At F_gross the envelope (calibrated up to 0.9 F_gross) gives no bound: an empty cell.
    assert!(
        csv.lines()
            .last()
            .unwrap()
            .ends_with("macroslip,macroslip,,"),
        "{csv}"
    );
    let beyond = failure(
        &[
            "sweep", "lap", "--from", "0", "--to", "7000", "--points", "3",
        ],
        2,
    );
    assert!(beyond.contains("F_gross"), "{beyond}");
    let varied = stdout_of(&[
        "sweep", "lap", "--vary", "KT", "--from", "100", "--to", "1e5", "--points", "4",
    ]);
    assert!(
        varied.starts_with("KT_MPa_per_mm,F_N,Delta_coulomb_mm"),
        "{varied}"
    );
    let low_mu = failure(
        &[
            "sweep", "lap", "--vary", "mu", "--from", "0.1", "--to", "0.5", "--points", "3",
        ],
        2,
    );
    assert!(low_mu.contains("at mu = 0.1, invalid F = 3000"), "{low_mu}");
    // Cycles of a lap preset; the loop's columns name Delta.
    let cycle = stdout_of(&["cycle", "--preset", "lap-aluminium", "--amplitude", "4000"]);
    assert!(cycle.contains("Double-lap joint, force cycling"), "{cycle}");
    let loop_csv = stdout_of(&[
        "cycle",
        "--preset",
        "lap-aluminium",
        "--amplitude",
        "4000",
        "--format",
        "csv",
        "--points",
        "3",
    ]);
    assert!(loop_csv.starts_with("branch,F_N,Delta_coulomb_mm,Delta_regularized_mm"));
    let too_big = failure(
        &["cycle", "--preset", "lap-aluminium", "--amplitude", "9000"],
        2,
    );
    assert!(
        too_big.contains("--amplitude = 9000") && too_big.contains("F_gross"),
        "{too_big}"
    );
    let sweep_cycle = stdout_of(&[
        "sweep",
        "cycle",
        "--from",
        "0",
        "--to",
        "6000",
        "--points",
        "4",
        "--preset",
        "lap-aluminium",
    ]);
    assert_eq!(sweep_cycle.lines().count(), 5, "{sweep_cycle}");
    // Solve searches only where F <= F_gross; kt --tolerance answers for Delta.
    let solved = stdout_of(&["solve", "lap", "--vary", "mu", "--target", "Delta=0.015"]);
    assert!(solved.contains("searched mu in [0.15, 10]"), "{solved}");
    let tolerance = stdout_of(&["kt", "--preset", "lap-aluminium", "--tolerance", "1%"]);
    assert!(tolerance.contains("(L11)"), "{tolerance}");
    assert!(failure(&["lap", "--beam-theory", "timoshenko"], 2).contains("not the lap joint"));
    // The deck is written, its header naming the command that reads its results.
    let deck = stdout_of(&["deck", "ccx", "lap", "--loads", "1000,3000"]);
    assert!(deck.contains("** microslip-deck: model=lap"), "{deck}");
    assert!(
        deck.contains("** Compare it:  microslip compare lap JOB.dat"),
        "{deck}"
    );
    let beyond = failure(&["deck", "ccx", "lap", "--loads", "1000,7000"], 2);
    assert!(
        beyond.contains("--loads = 7000") && beyond.contains("F_gross"),
        "{beyond}"
    );
    // A beam curve is not a lap curve: its columns are named.
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("r.csv");
    std::fs::write(&data, "F_N,w_mm\n1,0.001\n").unwrap();
    let compare = failure(&["compare", "lap", data.to_str().unwrap()], 2);
    assert!(compare.contains("Delta_mm"), "{compare}");
    let fit = failure(
        &[
            "fit",
            "beam",
            data.to_str().unwrap(),
            "--preset",
            "lap-aluminium",
        ],
        2,
    );
    assert!(fit.contains("needs a beam preset"), "{fit}");
    // fit lap: a sweep of a joint with mu 0.4, K_T 2500 gives both back.
    let measured = dir.path().join("joint.csv");
    std::fs::write(
        &measured,
        stdout_of(&[
            "sweep", "lap", "--from", "100", "--to", "5500", "--points", "30", "--set", "mu=0.4",
            "--set", "KT=2500",
        ]),
    )
    .unwrap();
    let fitted = stdout_of(&["fit", "lap", measured.to_str().unwrap()]);
    assert!(fitted.contains("  mu  = 0.4 +- "), "{fitted}");
    assert!(fitted.contains("F_gross = 8000 N"), "{fitted}");
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "fit",
        "lap",
        measured.to_str().unwrap(),
        "--format",
        "json",
    ]))
    .unwrap();
    assert!((json["KT_MPa_per_mm"]["value"].as_f64().unwrap() / 2500.0 - 1.0).abs() < 1e-9);
    assert!(json.get("F_thre_N").is_none() && json.get("F_gross_N").is_some());
    let too_low = failure(
        &["fit", "lap", measured.to_str().unwrap(), "--fix", "mu=0.05"],
        2,
    );
    assert!(too_low.contains("F_gross"), "{too_low}");
    // The plate has no load to cycle.
    let plate = failure(&["cycle", "--amplitude", "1", "--preset", "paper-plate"], 2);
    assert!(
        plate.contains(&format!(
            "needs a preset of a problem with a load ({})",
            super::loaded_problems(", ")
        )),
        "{plate}"
    );
}
