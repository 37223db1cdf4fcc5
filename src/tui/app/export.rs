//! `x`: the chart shown written as a figure (SVG, PNG, PDF) and its points as CSV.

use std::path::PathBuf;

use super::App;
use crate::chart::pins;
use crate::chart::view::AnyChart;
use crate::tui::effects::{Effect, ExportError};

impl App {
    /// Where `x` writes the exported chart (default: the working directory).
    pub fn set_export_dir(&mut self, dir: PathBuf) {
        self.export_dir = dir;
    }

    /// The file name (without extension) of the chart shown: `microslip-w-vs-f`, or after `v`
    /// `microslip-w-vs-mu`.
    pub(super) fn export_stem(&self) -> String {
        let chart = match (self.varied(), self.kind) {
            (Some(param), kind) => {
                let response = kind.description().response_symbol;
                let name = param.to_string().to_ascii_lowercase();
                let name: String = name
                    .chars()
                    .map(|c| if c.is_ascii_alphanumeric() { c } else { '-' })
                    .collect();
                format!("{response}-vs-{name}")
            }
            (None, kind) => self.views.of(kind).key().to_string(),
        };
        format!("microslip-{chart}")
    }

    /// `x`: asks to write the chart shown as an SVG figure and its points as CSV, under the first
    /// free name (`-2`, `-3`, ... appended); never replaces a file ([`Effect::ExportChart`]).
    pub(super) fn export_chart(&mut self) {
        use crate::report::figure;
        use crate::report::table::{TableFormat, write_table};
        // The chart as shown: the keys before this one may have left it to be rebuilt.
        self.settle();
        if self.view.chart.table.is_some() {
            return self.error("x exports charts; this is a table (microslip kt prints it)");
        }
        // A figure is read away from the screen: the parameters in a caption (as `plot` writes
        // them, less the x axis's), each curve named by its own values.
        let current = self.inputs();
        let pinned: Vec<(u8, crate::Inputs)> = self
            .state()
            .pins
            .iter()
            .map(|pin| (pin.number, pin.inputs))
            .collect();
        let mut plot = pins::named_by_values(self.view.chart.plot.clone(), &current, &pinned);
        let x_param = match self.varied() {
            Some(param) => Some(param),
            None => self.views.of(self.kind).chart().and_then(AnyChart::x_param),
        };
        plot.caption = Some(crate::chart::family::parameter_text(&current, &[x_param]));
        let svg = match figure::svg(&plot) {
            Ok(svg) => svg,
            Err(e) => return self.error(e.to_string()),
        };
        let mut csv = Vec::new();
        // The data of the figure: its curves, named as it names them.
        let rows = crate::report::rows::chart_rows(&plot);
        if let Err(e) = write_table(&mut csv, TableFormat::Csv, rows) {
            return self.error(format!("export failed: {e}"));
        }
        self.asked.push(Effect::ExportChart {
            dir: self.export_dir.clone(),
            stem: self.export_stem(),
            svg,
            csv,
        });
    }

    /// What `x` wrote, or why nothing.
    pub(super) fn exported(&mut self, result: Result<PathBuf, ExportError>) {
        match result {
            Ok(svg) => self.info(format!(
                "chart exported: {} (+ .png, .pdf, .csv data)",
                svg.display()
            )),
            Err(ExportError::Failed { path, reason }) => {
                self.error(format!("cannot export to {}: {reason}", path.display()))
            }
            Err(ExportError::AllTaken { stem }) => self.error(format!(
                "export: {stem}-2 to -{} all exist; move some away",
                crate::tui::effects::MAX_EXPORT_NUMBER
            )),
        }
    }
}
