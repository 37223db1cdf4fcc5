//! The parameter list, the regime summary and the status line.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Paragraph};

use crate::curves::{beam_point, plate_point};
use crate::model::inputs::Model;
use crate::model::params::{ModelKind, Unit};
use crate::model::stiffness::{mm_to_um, mpa_per_mm_to_mpa_per_um};
use crate::report::{number, sanitize};
use crate::tui::app::{App, Mode};
use crate::tui::theme::Role;

/// A bordered pane with a title.
pub fn pane<'a>(app: &App, title: &'a str) -> Block<'a> {
    let theme = app.theme();
    Block::default()
        .borders(Borders::ALL)
        .border_set(theme.border_set())
        .title(Span::styled(format!(" {title} "), theme.style(Role::Title)))
}

/// Every input of the active model with its unit; the selected row is marked by `>` as well as by
/// colour, so it shows without colour too. While typing, the row shows the text being typed.
pub fn draw_parameters(frame: &mut Frame, app: &App, area: Rect) {
    let theme = app.theme();
    let title = match app.kind() {
        ModelKind::Beam => "Twin beams",
        ModelKind::Plate => "Squeezed plate",
    };
    let inputs = app.inputs();
    let lines: Vec<Line> = app
        .kind()
        .params()
        .iter()
        .enumerate()
        .map(|(i, &param)| {
            let selected = i == app.selected();
            // `get` cannot miss: the parameters come from the active model.
            let value = inputs.get(param).unwrap_or(f64::NAN);
            let shown = match app.mode() {
                Mode::Editing { input } if selected => format!("{}_", input.as_str()),
                _ => number(value),
            };
            let unit = match param.unit() {
                Unit::Dimensionless => "",
                unit => unit.symbol(),
            };
            let text = format!(
                "{} {:<3} {:>11} {:<7}",
                if selected { ">" } else { " " },
                param.name(),
                shown,
                unit
            );
            let style = if selected {
                theme.style(Role::Selected)
            } else {
                ratatui::style::Style::default()
            };
            Line::from(Span::styled(text, style))
        })
        .collect();
    frame.render_widget(Paragraph::new(lines).block(pane(app, title)), area);
}

/// The regime of each law and the numbers that define it, as plain text (readable without colour).
pub fn draw_summary(frame: &mut Frame, app: &App, area: Rect) {
    let theme = app.theme();
    let regime = |label: &str, value: String| {
        Line::from(vec![
            Span::raw(format!(" {label:<12}")),
            Span::styled(value, theme.style(Role::Regime)),
        ])
    };
    let text = |s: String| Line::from(format!(" {s}"));
    let lines = match app.model() {
        Some(Model::Beam { beams, force }) => {
            let row = beam_point(&beams, force);
            let ratio = if row.w_coulomb > 0.0 {
                number(row.w_regularized / row.w_coulomb)
            } else {
                "-".into()
            };
            vec![
                text(format!("At F = {} N", number(row.force))),
                regime("Coulomb", row.regime_coulomb.to_string()),
                regime("regularized", row.regime_regularized.to_string()),
                text(format!(
                    "F_thre {} N  F_1 {} N",
                    number(beams.threshold_force()),
                    number(beams.first_macroslip_force())
                )),
                text(format!("X = {} mm (microslip end)", number(row.micro_end))),
                text(format!("w(L) Coulomb {} mm", number(row.w_coulomb))),
                text(format!("w(L) regular. {} mm", number(row.w_regularized))),
                text(format!("ratio reg/Coulomb {ratio}")),
                text(format!(
                    "mu P/K_T = {} um",
                    number(mm_to_um(beams.saturation_slip()))
                )),
                text(format!(
                    "K_T = {} MPa/um",
                    number(mpa_per_mm_to_mpa_per_um(
                        beams.params().tangential_stiffness
                    ))
                )),
            ]
        }
        Some(Model::Plate(plate)) => {
            let row = plate_point(&plate);
            let ratio = if row.u_coulomb > 0.0 {
                number(row.u_regularized / row.u_coulomb)
            } else {
                "-".into()
            };
            let pressure = plate.contact_pressure();
            vec![
                regime("Coulomb", row.regime_coulomb.to_string()),
                regime("regularized", row.regime_regularized.to_string()),
                text(format!("X_s = {} mm (stick end)", number(row.stick_end))),
                text(format!("X_r = {} mm (micro end)", number(row.micro_end))),
                text(format!("u(L) Coulomb {} mm", number(row.u_coulomb))),
                text(format!("u(L) regular. {} mm", number(row.u_regularized))),
                text(format!("ratio reg/Coulomb {ratio}")),
                text(format!(
                    "mu P/K_T = {} um",
                    number(mm_to_um(plate.saturation_slip()))
                )),
                text(format!(
                    "P_r/P {} to {}",
                    number(pressure.ratio(0.0)),
                    number(pressure.ratio(plate.params().half_length))
                )),
                text(format!(
                    "constant P: {}",
                    if pressure.constant_pressure_holds() {
                        "holds"
                    } else {
                        "FAILS (>3 %)"
                    }
                )),
            ]
        }
        None => vec![text("invalid parameters".into())],
    };
    frame.render_widget(Paragraph::new(lines).block(pane(app, "Regime")), area);
}

/// Model, preset (with `*` when modified), the last message or the typing prompt, and the two keys
/// everyone needs.
pub fn draw_status(frame: &mut Frame, app: &App, area: Rect) {
    let theme = app.theme();
    let marker = if app.modified() { "*" } else { "" };
    let mut spans = vec![Span::styled(
        format!(" {} | {}{marker} ", app.kind(), sanitize(app.preset_name())),
        theme.style(Role::Title),
    )];
    match (app.mode(), app.message()) {
        (Mode::Editing { .. }, _) => {
            let param = app.selected_param();
            spans.push(Span::raw(format!(
                "| {} ({}): type a value, Enter accept, Esc cancel",
                param.name(),
                param.unit()
            )));
        }
        (_, Some(message)) => {
            let role = if message.is_error {
                Role::Error
            } else {
                Role::Info
            };
            // Messages quote paths, names and values users typed or files hold.
            spans.push(Span::styled(
                format!("| {}", sanitize(&message.text)),
                theme.style(role),
            ));
        }
        _ => spans.push(Span::styled("| ? help  q quit", theme.style(Role::Muted))),
    }
    frame.render_widget(Paragraph::new(Line::from(spans)), area);
}
