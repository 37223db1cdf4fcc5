//! Which view each problem shows in the TUI, kept per problem while another is active: the
//! navigation state of `c`/`C` and `m`. The charts and tables that exist are `chart::view`'s;
//! turning through them is the TUI's.

use crate::chart::view::{AnyChart, View};
use crate::problems::{ByProblem, ModelKind};

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

    /// The default views with `chart` shown for its problem.
    pub fn showing(chart: AnyChart) -> Views {
        let mut views = Views::default();
        views.0[chart.kind()] = View::Chart(chart);
        views
    }

    /// Title, 1-based position and count of `kind`'s view, for the pane title.
    pub fn describe(self, kind: ModelKind) -> (&'static str, usize, usize) {
        let view = self.of(kind);
        let (position, count) = view.position(kind);
        (view.title(), position, count)
    }
}
