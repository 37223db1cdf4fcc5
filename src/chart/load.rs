//! The charts every load-driven problem has, written once over [`LoadDriven`]: the response
//! against F with Coulomb and the K_T/5, K_T*5 family, the hysteresis loop at the current force
//! and D against the amplitude, and the finite-element points round the same cycle. Each problem
//! gives only its words ([`LoadLabels`]).

use crate::chart::{Plot, SeriesRole, cursor, line, linear_axis, max_y};
use crate::kernel::format::{number, number_with};
use crate::kernel::regime::Law;
use crate::numeric::NumericError;
use crate::problems::load_driven::{LoadDriven, MasingCycle};
use crate::study::curves::{LoopPoint, Samples, Series};
use crate::study::load;

/// The load's symbol and unit as the problem's descriptor names them (`F`, `N`; the twisted
/// fit's `T`, `N mm`): every title and axis of these charts says the problem's own load.
pub(crate) fn load_words<P: LoadDriven>() -> (&'static str, &'static str) {
    P::INFO.load_words().unwrap_or(("F", "N"))
}

/// Loop points per branch: one per column of a 100-column chart.
pub(crate) const LOOP_POINTS: u64 = super::SAMPLES / 2 + 1;

/// What a load-driven problem's charts call its quantities.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LoadLabels {
    /// The response's symbol in titles: `w(L)`, `Delta`.
    pub response: &'static str,
    /// The response axis's title, with its unit: `w(L) (mm)`.
    pub response_axis: &'static str,
    /// The loop title's prefix (`1 beam `: the loop is one beam's) and D's name in it (`D(2)`:
    /// both beams').
    pub loop_title: (&'static str, &'static str),
    /// The D axis's title, with its unit.
    pub dissipation_axis: &'static str,
}

/// The curves drawn beside a load chart's current one: the model at K_T/5 and K_T*5, as `at`
/// builds it, where that K_T is accepted (`at` gives None otherwise).
pub(crate) fn companions<T>(
    kt: f64,
    at: impl Fn(f64) -> Option<T>,
) -> Vec<(SeriesRole, &'static str, T)> {
    [
        (SeriesRole::Softer, "K_T/5", kt / 5.0),
        (SeriesRole::Stiffer, "K_T*5", kt * 5.0),
    ]
    .into_iter()
    .filter_map(|(role, label, k)| Some((role, label, at(k)?)))
    .collect()
}

/// The response against F over `forces` (0 to `f_max`): Coulomb, the K_T/5 and K_T*5 companions,
/// the current K_T on top, and the cursor at the current force `f`.
pub(crate) fn response_plot<P: LoadDriven>(
    model: &P::Structure,
    labels: &LoadLabels,
    forces: Samples,
    (f, f_max): (f64, f64),
) -> Option<Plot> {
    let kt = P::tangential_stiffness(model);
    let companions = companions(kt, |k| P::with_tangential_stiffness(model, k).ok());
    let (coulomb, regularized) = load::response_vs_force::<P>(model, forces).ok()?;
    // The current K_T last, so that it is drawn on top.
    let mut series = vec![line(SeriesRole::Coulomb, "Coulomb", coulomb)];
    for (role, label, other) in &companions {
        let (_, response) = load::response_vs_force::<P>(other, forces).ok()?;
        series.push(line(*role, *label, response));
    }
    series.push(line(SeriesRole::Current, "K_T", regularized));
    let top = 1.05 * max_y(series.iter().map(|s| &s.points)).max(f64::MIN_POSITIVE);
    let y = linear_axis(labels.response_axis, 0.0, top);
    series.push(cursor(f, y.bounds));
    let (load, unit) = load_words::<P>();
    Some(Plot {
        caption: None,
        title: format!("{} vs {load}, K_T = {} MPa/mm", labels.response, number(kt)),
        x: linear_axis(format!("{load} ({unit})"), 0.0, f_max),
        y,
        series,
    })
}

/// The hysteresis loop at the current force, both laws; the title gives D of both (at most 41
/// characters, the title row of an 80x24 screen's chart pane; C(oulomb) and R(egularized) as in
/// the zone strip).
pub(crate) fn loop_chart<P: LoadDriven>(
    model: &P::Structure,
    labels: &LoadLabels,
    force: P::Force,
) -> Option<Plot> {
    let f = P::load_value(force);
    let (coulomb, regularized) = (
        P::cycle(model, Law::Coulomb, force),
        P::cycle(model, Law::Regularized, force),
    );
    let loops = load::cycle_loop::<P>(model, force, LOOP_POINTS).ok()?;
    let (prefix, d) = labels.loop_title;
    let (load, unit) = load_words::<P>();
    Some(loop_plot(
        format!(
            "{prefix}+-{} {unit}; {d} {} C, {} R N mm",
            number(f),
            number_with(coulomb.dissipation(), 3),
            number_with(regularized.dissipation(), 3)
        ),
        loops,
        coulomb.peak_response().max(regularized.peak_response()),
        (f, &format!("{load} ({unit})")),
        labels.response_axis,
    ))
}

/// D against the amplitude from 0 to `f_max`, both laws, the cursor at the current force.
pub(crate) fn dissipation_chart<P: LoadDriven>(
    model: &P::Structure,
    labels: &LoadLabels,
    force: P::Force,
    amplitudes: Samples,
    f_max: f64,
) -> Option<Plot> {
    let curves = load::dissipation_vs_amplitude::<P>(model, amplitudes).ok()?;
    Some(dissipation_plot(
        &load::cycle_point::<P>(model, force),
        curves,
        (P::load_value(force), f_max),
        (labels.dissipation_axis, load_words::<P>()),
    ))
}

/// A profile along the interface at the current load `f` (its symbol and unit `load`, as
/// [`load_words`]) and K_T (MPa/mm), both laws, with its limit as a flat line: tau(x) under mu P,
/// s(x) under mu P / K_T. `quantity` is the title's symbol and the y axis's title (`tau(x)`,
/// `tau (MPa)`), `limit` the line's name and value.
pub(crate) fn profile_plot(
    quantity: (&str, &str),
    (f, kt): (f64, f64),
    (load, unit): (&str, &str),
    length: f64,
    (coulomb, regularized): (Series, Series),
    (limit_name, limit): (&str, f64),
) -> Plot {
    let top = 1.1 * max_y([&coulomb, &regularized]).max(limit);
    Plot {
        caption: None,
        title: format!(
            "{} at {load} = {} {unit}, K_T = {} MPa/mm",
            quantity.0,
            number(f),
            number(kt)
        ),
        x: linear_axis("x (mm)", 0.0, length),
        y: linear_axis(quantity.1, 0.0, top),
        series: vec![
            line(SeriesRole::Coulomb, "Coulomb", coulomb),
            line(SeriesRole::Current, "regularized", regularized),
            line(
                SeriesRole::Limit,
                limit_name,
                vec![(0.0, limit), (length, limit)],
            ),
        ],
    }
}

/// The hysteresis loop chart of either law's loop points: the response (`y_title`) against the
/// load (`x_title`, `F (N)` or a problem's own load and unit), between -`f` and `f`, its y range
/// from the larger `peak`. Shared with a problem whose load is no force in N (the cylinder's
/// line load, N/mm) and which writes its own title.
pub(crate) fn loop_plot(
    title: String,
    loops: impl Iterator<Item = LoopPoint>,
    peak: f64,
    (f, x_title): (f64, &str),
    y_title: &str,
) -> Plot {
    let (coulomb, regularized): (Series, Series) = loops
        .map(|p| ((p.force, p.w_coulomb), (p.force, p.w_regularized)))
        .unzip();
    let top = 1.05 * peak.max(f64::MIN_POSITIVE);
    let span = f.max(1e-9);
    Plot {
        caption: None,
        title,
        x: linear_axis(x_title, -span, span),
        y: linear_axis(y_title, -top, top),
        series: vec![
            line(SeriesRole::Coulomb, "Coulomb", coulomb),
            line(SeriesRole::Current, "regularized", regularized),
        ],
    }
}

/// D against the amplitude, both laws, the cursor at the current load `f` of the axis to
/// `f_max`; the title gives zeta at `f` (at most 41 characters, an 80x24 chart pane's title row).
/// `load` is the load's symbol and unit ([`load_words`]).
fn dissipation_plot(
    at: &load::CyclePoint,
    (coulomb, regularized): (Series, Series),
    (f, f_max): (f64, f64),
    (y_title, (load, unit)): (&str, (&str, &str)),
) -> Plot {
    let top = 1.05 * max_y([&coulomb, &regularized]).max(f64::MIN_POSITIVE);
    Plot {
        caption: None,
        title: format!(
            "D vs {load}_a; zeta at {load} {} C, {} R",
            number_with(at.zeta_coulomb, 3),
            number_with(at.zeta_regularized, 3)
        ),
        x: linear_axis(format!("{load}_a ({unit})"), 0.0, f_max),
        y: linear_axis(y_title, 0.0, top),
        series: vec![
            line(SeriesRole::Coulomb, "Coulomb", coulomb),
            line(SeriesRole::Current, "regularized", regularized),
            cursor(f, [0.0, top]),
        ],
    }
}

/// A finite-element model driven round the cycle +`fa` -> -`fa` -> +`fa` in `count` steps per
/// branch: `load_to(F)` loads it to F and gives its response there. Its own slider histories
/// round a real reversal, no Masing rule: what the loop chart's points check.
///
/// # Errors
/// The solver's, at the first load it does not reach.
pub(crate) fn fe_loop(
    fa: f64,
    count: usize,
    mut load_to: impl FnMut(f64) -> Result<f64, NumericError>,
) -> Result<Series, NumericError> {
    let mut found = Vec::with_capacity(2 * count);
    for (from, sign) in [(fa, -1.0), (-fa, 1.0)] {
        for i in 1..=count {
            let f = from + sign * 2.0 * fa * i as f64 / count as f64;
            found.push((f, load_to(f)?));
        }
    }
    Ok(found)
}
