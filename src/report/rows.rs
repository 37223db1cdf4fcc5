//! One serde row type per table: the single definition of a table's columns, their order and their
//! names (units in the names: `w_coulomb_mm`, `KT_MPa_per_mm`). `report::csv` writes them as CSV
//! (the field names are the header), serde_json as JSON objects. The column names are a contract
//! with users' scripts: do not rename them.
//!
//! The rows here are the tables every problem shares (a cycle's, a chart's data); a problem's own
//! sweep and loop rows are in its folder (`src/problems/<name>/report.rs`), beside the
//! [`crate::report::face::ReportFace`] that names them.

use serde::Serialize;

use crate::chart::{Plot, SeriesKind};
use crate::report::point::cycle::CycleKeys;
use crate::study::curves::{CyclePoint, LoopPoint};

/// One row of `microslip sweep cycle`, headed in the problem's units ([`CycleKeys`]:
/// `Fa_N,D_coulomb_Nmm,...` for a force, `Qa_N_per_mm,D_coulomb_Nmm_per_mm,...` for the
/// cylinder's line load).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CycleRow {
    /// Amplitude (the load's unit).
    pub amplitude: f64,
    /// Coulomb dissipation per cycle, the whole interface (N mm, or N mm per mm of a line load).
    pub d_coulomb: f64,
    /// Regularized dissipation per cycle.
    pub d_regularized: f64,
    /// Coulomb equivalent damping ratio (-).
    pub zeta_coulomb: f64,
    /// Regularized equivalent damping ratio (-).
    pub zeta_regularized: f64,
    /// The keys of the problem's units.
    keys: CycleKeys,
}

impl CycleRow {
    /// A row of zeros headed with `keys`: what a table's header is written from.
    pub fn header(keys: CycleKeys) -> Self {
        let zero = CyclePoint {
            amplitude: 0.0,
            d_coulomb: 0.0,
            d_regularized: 0.0,
            zeta_coulomb: 0.0,
            zeta_regularized: 0.0,
        };
        CycleRow::new(&zero, keys)
    }
}

impl CycleRow {
    /// The row of `p`, headed with `keys`.
    pub fn new(p: &CyclePoint, keys: CycleKeys) -> Self {
        CycleRow {
            amplitude: p.amplitude,
            d_coulomb: p.d_coulomb,
            d_regularized: p.d_regularized,
            zeta_coulomb: p.zeta_coulomb,
            zeta_regularized: p.zeta_regularized,
            keys,
        }
    }
}

impl Serialize for CycleRow {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut out = serializer.serialize_struct("CycleRow", 5)?;
        out.serialize_field(self.keys.amplitude, &self.amplitude)?;
        out.serialize_field(self.keys.dissipations[0], &self.d_coulomb)?;
        out.serialize_field(self.keys.dissipations[1], &self.d_regularized)?;
        out.serialize_field("zeta_coulomb", &self.zeta_coulomb)?;
        out.serialize_field("zeta_regularized", &self.zeta_regularized)?;
        out.end()
    }
}

/// One point of `microslip cycle --format csv` (the hysteresis loop, both laws).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct LoopRow {
    /// `unloading` or `reloading`.
    pub branch: &'static str,
    /// Tip force (N).
    #[serde(rename = "F_N")]
    pub force: f64,
    /// Coulomb tip deflection (mm).
    pub w_coulomb_mm: f64,
    /// Regularized tip deflection (mm).
    pub w_regularized_mm: f64,
}

impl From<&LoopPoint> for LoopRow {
    fn from(p: &LoopPoint) -> Self {
        LoopRow {
            branch: p.branch.label(),
            force: p.force,
            w_coulomb_mm: p.w_coulomb,
            w_regularized_mm: p.w_regularized,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::report::csv::test_support::header;

    /// The headers users' scripts read: a change here breaks them, so it must be deliberate.
    #[test]
    fn headers_are_the_published_contract() {
        let cycle_header = |keys| {
            let mut out = Vec::new();
            super::super::csv::write_header(&mut out, &CycleRow::header(keys)).unwrap();
            String::from_utf8(out).unwrap().trim_end().to_string()
        };
        assert_eq!(
            cycle_header(CycleKeys::FORCE),
            "Fa_N,D_coulomb_Nmm,D_regularized_Nmm,zeta_coulomb,zeta_regularized"
        );
        assert_eq!(
            header::<LoopRow>(),
            "branch,F_N,w_coulomb_mm,w_regularized_mm"
        );
    }
}

/// One point of a chart's data (`x` in the TUI and `microslip plot -o FILE.csv`): the series, and
/// x and y in the units their axis titles name (on a log axis the value, not its logarithm).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct ChartPointRow<'a> {
    /// The series' legend label (`Coulomb`, `K_T/5`, `FE`).
    pub series: &'a str,
    /// The x axis title, with its unit.
    pub x_axis: &'a str,
    /// The x value.
    pub x: f64,
    /// The y axis title, with its unit.
    pub y_axis: &'a str,
    /// The y value.
    pub y: f64,
}

/// Every point of the plot's curves and point sets (the cursor is not data), series by series.
pub fn chart_rows(plot: &Plot) -> impl Iterator<Item = ChartPointRow<'_>> {
    plot.series
        .iter()
        .filter(|s| s.kind() != SeriesKind::Cursor)
        .flat_map(move |s| {
            s.points.iter().map(move |&(x, y)| ChartPointRow {
                series: &s.name,
                x_axis: &plot.x.title,
                x: plot.x.value(x),
                y_axis: &plot.y.title,
                y: plot.y.value(y),
            })
        })
}
