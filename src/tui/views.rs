//! Which view each problem shows in the TUI, kept per problem while another is active: the
//! navigation state of `c`/`C` and `m`. The charts and tables that exist are `chart::view`'s;
//! turning through them is the TUI's.

use crate::chart::view::AnyChart;
use crate::problems::{ByProblem, ModelKind};

/// A table shown in place of a chart.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Table {
    /// The K_T that FE codes assume, and what each does to the answer.
    StiffnessComparison,
}

impl Table {
    /// Every table, in cycling order (after the charts).
    pub const ALL: &'static [Table] = &[Table::StiffnessComparison];

    /// The short title of the table.
    pub fn title(self) -> &'static str {
        match self {
            Table::StiffnessComparison => "K_T: codes vs physics",
        }
    }
}

/// One view of a problem: one of its charts, or a table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum View {
    /// A chart (of the problem the view is for).
    Chart(AnyChart),
    /// A table.
    Table(Table),
}

impl View {
    /// Every view of `kind`: its charts in [`AnyChart::ALL`]'s order, then the tables.
    pub fn all(kind: ModelKind) -> impl Iterator<Item = View> + Clone {
        AnyChart::all()
            .filter(move |c| c.kind() == kind)
            .map(View::Chart)
            .chain(Table::ALL.iter().map(|&t| View::Table(t)))
    }

    /// The view `kind` opens on: its first chart.
    pub fn first(kind: ModelKind) -> View {
        Self::all(kind).next().unwrap_or(View::Table(Table::ALL[0]))
    }

    /// The short title.
    pub fn title(self) -> &'static str {
        match self {
            View::Chart(chart) => chart.title(),
            View::Table(table) => table.title(),
        }
    }

    /// The name in file names (`w-vs-f`, `kt-table`).
    pub fn key(self) -> &'static str {
        match self {
            View::Chart(chart) => chart.key(),
            View::Table(Table::StiffnessComparison) => "kt-table",
        }
    }

    /// The chart shown, if this view is a chart.
    pub fn chart(self) -> Option<AnyChart> {
        match self {
            View::Chart(chart) => Some(chart),
            View::Table(_) => None,
        }
    }

    /// 1-based position among `kind`'s views, and their count.
    pub fn position(self, kind: ModelKind) -> (usize, usize) {
        let index = Self::all(kind).position(|v| v == self).unwrap_or(0);
        (index + 1, Self::all(kind).count())
    }

    /// The next (`forward`) or previous view of `kind`, cycling.
    pub fn turn(self, kind: ModelKind, forward: bool) -> View {
        let all: Vec<View> = Self::all(kind).collect();
        let at = all.iter().position(|&v| v == self).unwrap_or(0);
        let n = all.len();
        if forward {
            all[(at + 1) % n]
        } else {
            all[(at + n - 1) % n]
        }
    }
}

/// The view shown for each problem; each keeps its own while another problem is active.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Views(ByProblem<View>);

impl Default for Views {
    fn default() -> Self {
        Views(ByProblem::from_fn(View::first))
    }
}

impl Views {
    /// The view of `kind`.
    pub fn of(self, kind: ModelKind) -> View {
        self.0[kind]
    }

    /// The views with `kind`'s moved one forward or back.
    pub fn turn(mut self, kind: ModelKind, forward: bool) -> Views {
        self.0[kind] = self.0[kind].turn(kind, forward);
        self
    }

    /// These views with `view` shown for `kind`.
    pub fn with(mut self, kind: ModelKind, view: View) -> Views {
        self.0[kind] = view;
        self
    }

    /// Title, 1-based position and count of `kind`'s view, for the pane title.
    pub fn describe(self, kind: ModelKind) -> (&'static str, usize, usize) {
        let view = self.of(kind);
        let (position, count) = view.position(kind);
        (view.title(), position, count)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn views_cycle_both_ways_through_every_chart_and_table() {
        for kind in ModelKind::ALL {
            let all: Vec<View> = View::all(kind).collect();
            let charts = AnyChart::all().filter(|c| c.kind() == kind).count();
            assert!(charts > 0, "{kind} has no chart");
            assert_eq!(all.len(), charts + Table::ALL.len());
            for (i, &view) in all.iter().enumerate() {
                assert_eq!(view.position(kind), (i + 1, all.len()));
                assert_eq!(view.turn(kind, true).turn(kind, false), view);
                assert!(!view.title().is_empty());
            }
            assert_eq!(all[all.len() - 1].turn(kind, true), View::first(kind));
            assert_eq!(View::first(kind).turn(kind, false), all[all.len() - 1]);
        }
    }
}
