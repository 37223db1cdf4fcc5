//! What a view shows: the charts of each model and the tables, as enums. The TUI cycles through
//! them and draws them; figure and table exports name them the same way. A chart is never an index.

use crate::problems::ModelKind;

/// The twin beams' charts, in the order the TUI cycles through them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BeamChart {
    /// Tip deflection w(L) against the tip force F, for K_T/5, K_T, 5 K_T and Coulomb.
    Deflection,
    /// End of the microslip zone X against F.
    SlipBoundary,
    /// Interface shear tau(x) along the beams at F.
    Shear,
    /// The hysteresis loop of a cycle between +F and -F.
    Loop,
    /// Dissipation per cycle D against the amplitude F_a.
    Dissipation,
}

/// The squeezed plate's charts, in the order the TUI cycles through them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PlateChart {
    /// End displacement u(L) against K_T (logarithmic K_T axis).
    Displacement,
    /// End of the microslip zone X_r against mu.
    SlipBoundary,
    /// Contact pressure ratio P_r(x)/P along the half-plate.
    ContactPressure,
}

/// A table shown in place of a chart.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Table {
    /// The K_T that FE codes assume, and what each does to the answer.
    StiffnessComparison,
}

/// The charts of one model.
pub trait ChartSet: Copy + Eq + 'static {
    /// Every chart, in cycling order.
    const ALL: &'static [Self];
    /// The short title of the chart.
    fn title(self) -> &'static str;
    /// The chart's name on the command line and in file names (`w-vs-f`).
    fn key(self) -> &'static str;
}

impl ChartSet for BeamChart {
    const ALL: &'static [Self] = &[
        BeamChart::Deflection,
        BeamChart::SlipBoundary,
        BeamChart::Shear,
        BeamChart::Loop,
        BeamChart::Dissipation,
    ];

    fn title(self) -> &'static str {
        match self {
            BeamChart::Deflection => "w(L) vs F",
            BeamChart::SlipBoundary => "X vs F",
            BeamChart::Shear => "tau(x) at F",
            BeamChart::Loop => "loop +-F",
            BeamChart::Dissipation => "D vs F_a",
        }
    }

    fn key(self) -> &'static str {
        match self {
            BeamChart::Deflection => "w-vs-f",
            BeamChart::SlipBoundary => "x-vs-f",
            BeamChart::Shear => "tau",
            BeamChart::Loop => "loop",
            BeamChart::Dissipation => "d-vs-fa",
        }
    }
}

impl ChartSet for PlateChart {
    const ALL: &'static [Self] = &[
        PlateChart::Displacement,
        PlateChart::SlipBoundary,
        PlateChart::ContactPressure,
    ];

    fn title(self) -> &'static str {
        match self {
            PlateChart::Displacement => "u(L) vs K_T",
            PlateChart::SlipBoundary => "X_r vs mu",
            PlateChart::ContactPressure => "P_r(x)/P",
        }
    }

    fn key(self) -> &'static str {
        match self {
            PlateChart::Displacement => "u-vs-kt",
            PlateChart::SlipBoundary => "xr-vs-mu",
            PlateChart::ContactPressure => "pressure",
        }
    }
}

/// A chart of either model, as `microslip plot CHART` names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AnyChart {
    /// A chart of the twin beams.
    Beam(BeamChart),
    /// A chart of the plate.
    Plate(PlateChart),
}

impl AnyChart {
    /// The parameter the chart runs along its x axis (F, K_T, mu), whose value a caption need not
    /// give; None where the x axis is no parameter (tau(x), the loop, P_r(x)).
    pub fn x_param(self) -> Option<crate::problems::Param> {
        use crate::problems::{BeamParam, Param, PlateParam};
        match self {
            AnyChart::Beam(BeamChart::Deflection | BeamChart::SlipBoundary) => {
                Some(Param::Beam(BeamParam::Force))
            }
            AnyChart::Plate(PlateChart::Displacement) => Some(Param::Plate(PlateParam::Stiffness)),
            AnyChart::Plate(PlateChart::SlipBoundary) => Some(Param::Plate(PlateParam::Friction)),
            _ => None,
        }
    }

    /// Every chart: the beams', then the plate's (each model's in cycling order).
    pub const ALL: &'static [AnyChart] = &[
        AnyChart::Beam(BeamChart::Deflection),
        AnyChart::Beam(BeamChart::SlipBoundary),
        AnyChart::Beam(BeamChart::Shear),
        AnyChart::Beam(BeamChart::Loop),
        AnyChart::Beam(BeamChart::Dissipation),
        AnyChart::Plate(PlateChart::Displacement),
        AnyChart::Plate(PlateChart::SlipBoundary),
        AnyChart::Plate(PlateChart::ContactPressure),
    ];

    /// Every chart, as [`AnyChart::ALL`].
    pub fn all() -> impl Iterator<Item = AnyChart> {
        Self::ALL.iter().copied()
    }

    /// The name on the command line (unique over both models).
    pub fn key(self) -> &'static str {
        match self {
            AnyChart::Beam(c) => c.key(),
            AnyChart::Plate(c) => c.key(),
        }
    }

    /// The short title.
    pub fn title(self) -> &'static str {
        match self {
            AnyChart::Beam(c) => c.title(),
            AnyChart::Plate(c) => c.title(),
        }
    }

    /// The chart named `key`, if any.
    pub fn parse(key: &str) -> Option<AnyChart> {
        Self::all().find(|c| c.key().eq_ignore_ascii_case(key))
    }

    /// The model the chart is of.
    pub fn kind(self) -> ModelKind {
        match self {
            AnyChart::Beam(_) => ModelKind::Beam,
            AnyChart::Plate(_) => ModelKind::Plate,
        }
    }
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

/// One view of a model: a chart of that model, or a table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum View<C> {
    /// A chart.
    Chart(C),
    /// A table.
    Table(Table),
}

impl<C: ChartSet> View<C> {
    /// Every view of the model: its charts, then the tables.
    pub fn all() -> impl Iterator<Item = View<C>> + Clone {
        C::ALL
            .iter()
            .map(|&c| View::Chart(c))
            .chain(Table::ALL.iter().map(|&t| View::Table(t)))
    }

    /// The first view (the model's first chart).
    pub fn first() -> View<C> {
        View::Chart(C::ALL[0])
    }

    /// The short title.
    pub fn title(self) -> &'static str {
        match self {
            View::Chart(chart) => chart.title(),
            View::Table(table) => table.title(),
        }
    }

    /// The name in file names: the chart's key, or the table's.
    pub fn key(self) -> &'static str {
        match self {
            View::Chart(chart) => chart.key(),
            View::Table(Table::StiffnessComparison) => "kt-table",
        }
    }

    /// 1-based position among [`View::all`] and their count, for "2/6" in a pane title.
    pub fn position(self) -> (usize, usize) {
        let index = Self::all().position(|v| v == self).unwrap_or(0);
        (index + 1, Self::all().count())
    }

    /// The next view (`forward`) or the previous one, wrapping around.
    pub fn turn(self, forward: bool) -> View<C> {
        if forward {
            self.next()
        } else {
            self.previous()
        }
    }

    /// The next view, wrapping from the last to the first.
    pub fn next(self) -> View<C> {
        Self::all()
            .cycle()
            .skip_while(|&v| v != self)
            .nth(1)
            .unwrap_or(self)
    }

    /// The previous view, wrapping from the first to the last.
    pub fn previous(self) -> View<C> {
        let all: Vec<View<C>> = Self::all().collect();
        all.iter()
            .rev()
            .cycle()
            .skip_while(|&&v| v != self)
            .nth(1)
            .copied()
            .unwrap_or(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn round_trip<C: ChartSet + std::fmt::Debug>() {
        let all: Vec<View<C>> = View::all().collect();
        assert_eq!(all.len(), C::ALL.len() + Table::ALL.len());
        for (i, &view) in all.iter().enumerate() {
            assert_eq!(view.position(), (i + 1, all.len()));
            assert_eq!(view.next().previous(), view);
            assert!(!view.title().is_empty());
        }
        assert_eq!(all[all.len() - 1].next(), View::first());
        assert_eq!(View::<C>::first().previous(), all[all.len() - 1]);
    }

    #[test]
    fn views_cycle_both_ways_through_every_chart_and_table() {
        round_trip::<BeamChart>();
        round_trip::<PlateChart>();
    }

    #[test]
    fn chart_keys_are_unique_and_parse_back() {
        let keys: Vec<&str> = AnyChart::all().map(AnyChart::key).collect();
        for (i, key) in keys.iter().enumerate() {
            assert!(!keys[..i].contains(key), "{key} twice");
            assert_eq!(AnyChart::parse(key).map(AnyChart::key), Some(*key));
        }
        assert_eq!(AnyChart::parse("nope"), None);
        // ALL holds each model's charts in their own order.
        let beams = AnyChart::all().filter_map(|c| match c {
            AnyChart::Beam(b) => Some(b),
            AnyChart::Plate(_) => None,
        });
        assert!(beams.eq(BeamChart::ALL.iter().copied()));
        let plates = AnyChart::all().filter_map(|c| match c {
            AnyChart::Plate(p) => Some(p),
            AnyChart::Beam(_) => None,
        });
        assert!(plates.eq(PlateChart::ALL.iter().copied()));
    }
}
