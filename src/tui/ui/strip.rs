//! The zone strip under the regime summary: the interface from x = 0 (clamp, plate centre, the lap
//! joint's inner plate end) to L,
//! drawn to scale for both laws, so that where the interface sticks, slips elastically and slides
//! is seen at a glance rather than read off X, X_s and X_r. Zones are told apart by their symbols
//! (`=` stick, `~` microslip, `#` macroslip in ASCII) and, with colour, by colour as well; the
//! numbers come from the view ([`StripView`]), built where the pane's text is.
//!
//! Three sizes, chosen by the pane's spare height: two rows (one per law) on small screens; with a
//! heading, the boundaries marked and named, and a legend on taller ones; and on the tallest, two
//! sparkline rows of the interface shear tau(x) / (mu P) (each problem names its own,
//! [`StripView::shear_name`]), where the regularized law's gradual rise against Coulomb's step
//! shows what "microslip" means.

use ratatui::text::{Line, Span};

use crate::report::number_with;
use crate::tui::theme::{Role, Theme};
use crate::tui::view::{StripView, Zone, ZoneSpan};

/// How much of the strip is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum StripSize {
    /// One row per law.
    Compact,
    /// Heading, the two rows, the named boundaries and the legend.
    Marked,
    /// As `Marked`, plus tau(x) / (mu P) of each law as a sparkline.
    WithShear,
}

impl StripSize {
    /// Every size, largest first (the order in which they are tried).
    pub const LARGEST_FIRST: [StripSize; 3] =
        [StripSize::WithShear, StripSize::Marked, StripSize::Compact];

    /// Rows the size takes.
    pub fn rows(self) -> usize {
        match self {
            StripSize::Compact => 2,
            StripSize::Marked => 5,
            StripSize::WithShear => 8,
        }
    }
}

/// Width of the row label (` C `, ` R `).
const LABEL: usize = 3;

/// The cells of the strip in a pane `width` columns wide: one column is kept free on the right,
/// so the strip does not touch the border.
pub fn cells(width: u16) -> usize {
    usize::from(width).saturating_sub(LABEL + 1).max(4)
}

/// The strip's lines for a pane `width` columns wide.
pub fn lines(strip: &StripView, theme: &Theme, width: u16, size: StripSize) -> Vec<Line<'static>> {
    let zones = &strip.zones;
    let cells = cells(width);
    let (coulomb, coulomb_cuts) = zone_cells(&zones.coulomb, zones.length, cells);
    let (regularized, regularized_cuts) = zone_cells(&zones.regularized, zones.length, cells);
    let mut lines = Vec::with_capacity(size.rows());
    if size >= StripSize::Marked {
        let origin = strip.origin;
        lines.push(Line::from(Span::styled(
            format!(
                " Zones: x = 0 ({origin}) to {} mm",
                number_with(zones.length, 3)
            ),
            theme.style(Role::Muted),
        )));
    }
    lines.push(zone_row("C", &coulomb, theme));
    lines.push(zone_row("R", &regularized, theme));
    if size >= StripSize::Marked {
        // A boundary's caret sits on the first cell of the zone beyond it, where its row changes.
        let mut carets: Vec<(usize, String)> = Vec::new();
        let mut cuts = coulomb_cuts.into_iter().chain(regularized_cuts);
        for boundary in &zones.boundaries {
            let Some(cell) = cuts.next() else { break };
            let text = format!("{} {}", boundary.name, number_with(boundary.at, 3));
            match carets.iter_mut().find(|(c, _)| *c == cell) {
                Some((_, label)) => *label = format!("{label}, {text}"),
                None => carets.push((cell, text)),
            }
        }
        let markers = if carets.is_empty() {
            " no boundary inside (0, L)".to_string()
        } else {
            marker_row(&carets, cells)
        };
        lines.push(Line::from(Span::styled(markers, theme.style(Role::Muted))));
        let unloaded = zones.coulomb.iter().any(|z| z.zone == Zone::Unloaded);
        lines.push(legend(theme, unloaded));
    }
    if size >= StripSize::WithShear {
        lines.push(Line::from(Span::styled(
            format!(" {}, 0 to 1:", strip.shear_name),
            theme.style(Role::Muted),
        )));
        // The view samples the shear for each width the pane can have; at another width the
        // rows stay empty rather than solve while drawing.
        let (c, r) = strip
            .shear_for(cells)
            .map_or((&[][..], &[][..]), |s| (&s.coulomb[..], &s.regularized[..]));
        lines.push(spark_row("C", c, theme));
        lines.push(spark_row("R", r, theme));
    }
    lines
}

/// The zone of each of `cells` cells, and the cell where each stretch after the first begins.
/// A stretch that exists gets at least one cell, however short: a macroslip zone of 0.2 mm at the
/// end of a 10 mm plate is what the strip is for.
fn zone_cells(spans: &[ZoneSpan], length: f64, cells: usize) -> (Vec<Zone>, Vec<usize>) {
    let mut zones = Vec::with_capacity(cells);
    let mut cuts = Vec::new();
    for (i, span) in spans.iter().enumerate() {
        let left = spans.len() - 1 - i;
        let end = if left == 0 {
            cells
        } else {
            let at = (span.to / length * cells as f64).round() as usize;
            at.clamp(
                zones.len() + 1,
                cells.saturating_sub(left).max(zones.len() + 1),
            )
        };
        zones.resize(end.min(cells), span.zone);
        if left > 0 {
            cuts.push(end.min(cells));
        }
    }
    (zones, cuts)
}

fn zone_row(label: &str, zones: &[Zone], theme: &Theme) -> Line<'static> {
    let mut spans = vec![Span::raw(format!(" {label} "))];
    for run in zones.chunk_by(|a, b| a == b) {
        spans.push(Span::styled(
            theme.zone_symbol(run[0]).repeat(run.len()),
            theme.zone_style(run[0]),
        ));
    }
    Line::from(spans)
}

/// Carets under the boundaries, each named to its right, or to its left (after a space) where the
/// right has no room; a name that would cover a caret or an earlier name is left out (the text
/// above gives them all).
fn marker_row(carets: &[(usize, String)], cells: usize) -> String {
    // Names are placed left to right: the lap joint's boundaries come as Coulomb's pair then the
    // regularized pair, interleaved along the strip.
    let mut carets = carets.to_vec();
    carets.sort_by_key(|(cell, _)| *cell);
    let carets = carets.as_slice();
    let mut row = vec![' '; LABEL + cells];
    let columns: Vec<usize> = carets
        .iter()
        .map(|(cell, _)| LABEL + (*cell).min(cells - 1))
        .collect();
    for &column in &columns {
        row[column] = '^';
    }
    let mut taken = LABEL; // columns before this one hold a caret's earlier name
    for (&caret, (_, label)) in columns.iter().zip(carets) {
        let width = label.chars().count();
        let right = caret + 1..caret + 1 + width;
        let left = caret.saturating_sub(width + 1)..caret.saturating_sub(1);
        let free = |r: &std::ops::Range<usize>| {
            r.start >= taken
                && r.end <= row.len()
                && r.len() == width
                && !columns.iter().any(|c| r.contains(c))
        };
        let place = [right, left].into_iter().find(|r| free(r));
        if let Some(range) = place {
            for (slot, ch) in row[range.clone()].iter_mut().zip(label.chars()) {
                *slot = ch;
            }
            taken = range.end.max(caret) + 1;
        } else {
            taken = taken.max(caret + 1);
        }
    }
    row.into_iter().collect::<String>().trim_end().to_string()
}

/// The legend of the strip, for the compact strip, which has no row for it: the regime
/// pane puts it on its lower border, so that `=`, `~` and `#` are explained on every screen.
pub fn legend_of(strip: &StripView, theme: &Theme) -> Line<'static> {
    let unloaded = strip.zones.coulomb.iter().any(|z| z.zone == Zone::Unloaded);
    let mut line = legend(theme, unloaded);
    line.spans.push(Span::raw(" "));
    line
}

/// The symbols' meanings; with no load, what the strip shows instead (one symbol, nothing slips).
fn legend(theme: &Theme, unloaded: bool) -> Line<'static> {
    let mut spans = vec![Span::raw(" ")];
    if unloaded {
        spans.push(Span::styled(
            theme.zone_symbol(Zone::Unloaded),
            theme.zone_style(Zone::Unloaded),
        ));
        spans.push(Span::raw("unloaded: no load, no slip"));
        return Line::from(spans);
    }
    for (zone, name) in [
        (Zone::Stick, "stick "),
        (Zone::Microslip, "microslip "),
        (Zone::Macroslip, "macroslip"),
    ] {
        spans.push(Span::styled(
            theme.zone_symbol(zone),
            theme.zone_style(zone),
        ));
        spans.push(Span::raw(name));
    }
    Line::from(spans)
}

fn spark_row(label: &str, ratios: &[f64], theme: &Theme) -> Line<'static> {
    let levels = theme.spark_levels();
    let top = (levels.len() - 1) as f64;
    let bars: String = ratios
        .iter()
        .map(|r| levels[(r * top).round() as usize])
        .collect();
    Line::from(vec![Span::raw(format!(" {label} ")), Span::raw(bars)])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::inputs::Model;
    use crate::tui::summary::ContinuumState;

    fn span(from: f64, to: f64, zone: Zone) -> ZoneSpan {
        ZoneSpan { from, to, zone }
    }

    #[test]
    fn zones_are_drawn_to_scale_and_a_short_one_keeps_a_cell() {
        let spans = [
            span(0.0, 50.0, Zone::Microslip),
            span(50.0, 200.0, Zone::Macroslip),
        ];
        let (cells, cuts) = zone_cells(&spans, 200.0, 20);
        assert_eq!(cuts, [5]);
        assert_eq!(cells.iter().filter(|&&z| z == Zone::Microslip).count(), 5);
        let tiny = [
            span(0.0, 9.99, Zone::Stick),
            span(9.99, 10.0, Zone::Macroslip),
        ];
        let (cells, cuts) = zone_cells(&tiny, 10.0, 20);
        assert_eq!(cuts, [19]);
        assert_eq!(cells[19], Zone::Macroslip);
        let at_start = [
            span(0.0, 0.01, Zone::Stick),
            span(0.01, 10.0, Zone::Macroslip),
        ];
        assert_eq!(zone_cells(&at_start, 10.0, 20).1, [1]);
    }

    /// The strip's rows as plain text, 24 columns wide.
    fn rows(model: &Model, theme: &Theme, size: StripSize) -> Vec<String> {
        let view = crate::tui::view::regime(model, &ContinuumState::Off, &[cells(24)]);
        lines(&view.strip, theme, 24, size)
            .iter()
            .map(|line| line.spans.iter().map(|s| s.content.as_ref()).collect())
            .collect()
    }

    #[test]
    fn an_unloaded_interface_is_drawn_and_explained_as_such() {
        use crate::tui::theme::Charset;
        let theme = Theme {
            charset: Charset::Ascii,
            color: false,
        };
        let beams = crate::TwinBeams::new(crate::TwinBeamsParams::PAPER).unwrap();
        let model = Model::Beam(crate::problems::twin_beams::problem::BeamsModel {
            beams,
            force: crate::TipForce::new(0.0).unwrap(),
        });
        let marked = rows(&model, &theme, StripSize::Marked);
        assert_eq!(marked.len(), StripSize::Marked.rows());
        assert_eq!(marked[1], format!(" C {}", "-".repeat(20)));
        assert_eq!(marked[2], format!(" R {}", "-".repeat(20)));
        assert_eq!(marked[3], " no boundary inside (0, L)");
        assert_eq!(marked[4], " -unloaded: no load, no slip");
        // Loaded past F_1: microslip then macroslip, X named under its boundary.
        let model = Model::Beam(crate::problems::twin_beams::problem::BeamsModel {
            beams,
            force: crate::TipForce::new(100.0).unwrap(),
        });
        let full = rows(&model, &theme, StripSize::WithShear);
        assert_eq!(full.len(), StripSize::WithShear.rows());
        assert_eq!(full[1], format!(" C {}", "#".repeat(20)));
        // X = 17.3 mm of 200 mm on 20 cells: 1.7 -> 2 cells of microslip.
        assert_eq!(full[2], format!(" R ~~{}", "#".repeat(18)));
        assert_eq!(full[3], "     ^X 17.3");
        assert_eq!(full[4], " =stick ~microslip #macroslip");
    }

    #[test]
    fn boundary_names_go_right_then_left_and_never_overlap() {
        assert_eq!(marker_row(&[(2, "X 17.3".into())], 20), "     ^X 17.3");
        assert_eq!(
            marker_row(&[(19, "X_r 9.84".into())], 20),
            "             X_r 9.84 ^"
        );
        // A second name that would cover the first caret or name is left out; its caret stays.
        assert_eq!(
            marker_row(&[(2, "X_s 1".into()), (4, "X_r 2".into())], 20),
            "     ^ ^X_r 2"
        );
        assert_eq!(
            marker_row(&[(2, "X_s 1".into()), (12, "X_r 2".into())], 20),
            "     ^X_s 1    ^X_r 2"
        );
    }
}
