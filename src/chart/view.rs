//! The charts of each problem, as enums, with what the generic layers need to know of each (its
//! key, title, x parameter, load axis, default y scale): `plot`, `figures`, families and the TUI
//! name them the same way. A chart is never an index. Which one the TUI shows, and the table it
//! can show instead, are the TUI's (`tui/views.rs`).

use crate::problems::{BeamParam, LapParam, ModelKind, Param, PlateParam};

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

/// The double-lap joint's charts, in the order the TUI cycles through them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LapChart {
    /// Joint displacement Delta against F, for K_T/5, K_T, 5 K_T and Coulomb.
    Displacement,
    /// The zones against F: the sliding zones [0, a] and [L - d, L] outside the outline of the
    /// middle zone, for both laws.
    Zones,
    /// Interface shear tau(x) along the overlap at F.
    Shear,
    /// Interface slip s(x) = u_inner - u_cover along the overlap at F.
    Slip,
    /// The hysteresis loop of Delta for a force cycling between +F and -F.
    Loop,
    /// Dissipation per cycle D against the amplitude F_a.
    Dissipation,
}

/// The charts of one model.
pub trait ChartSet: Copy + Eq + 'static {
    /// Every chart, in cycling order.
    const ALL: &'static [Self];
    /// The short title of the chart.
    fn title(self) -> &'static str;
    /// The chart's name on the command line and in file names (`w-vs-f`).
    fn key(self) -> &'static str;
    /// The parameter the chart runs along its x axis (F, K_T, mu), whose value a caption need
    /// not give; None where the x axis is no parameter (tau(x), the loop, P_r(x), D vs F_a).
    fn x_param(self) -> Option<Param>;
    /// True where the x axis is the problem's load (F, or the amplitude F_a), which a family of
    /// curves widens to the span its widest member needs.
    fn load_axis(self) -> bool;
    /// True where the chart's quantity spans decades: it opens on a log y axis.
    fn spans_decades(self) -> bool;
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

    fn x_param(self) -> Option<Param> {
        match self {
            BeamChart::Deflection | BeamChart::SlipBoundary => Some(Param::Beam(BeamParam::Force)),
            BeamChart::Shear | BeamChart::Loop | BeamChart::Dissipation => None,
        }
    }

    fn load_axis(self) -> bool {
        match self {
            BeamChart::Deflection | BeamChart::SlipBoundary | BeamChart::Dissipation => true,
            BeamChart::Shear | BeamChart::Loop => false,
        }
    }

    fn spans_decades(self) -> bool {
        match self {
            BeamChart::Dissipation => true,
            BeamChart::Deflection
            | BeamChart::SlipBoundary
            | BeamChart::Shear
            | BeamChart::Loop => false,
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

    fn x_param(self) -> Option<Param> {
        match self {
            PlateChart::Displacement => Some(Param::Plate(PlateParam::Stiffness)),
            PlateChart::SlipBoundary => Some(Param::Plate(PlateParam::Friction)),
            PlateChart::ContactPressure => None,
        }
    }

    fn load_axis(self) -> bool {
        // The plate has no load parameter: its pressure is fixed.
        false
    }

    fn spans_decades(self) -> bool {
        match self {
            PlateChart::Displacement => true,
            PlateChart::SlipBoundary | PlateChart::ContactPressure => false,
        }
    }
}

impl ChartSet for LapChart {
    const ALL: &'static [Self] = &[
        LapChart::Displacement,
        LapChart::Zones,
        LapChart::Shear,
        LapChart::Slip,
        LapChart::Loop,
        LapChart::Dissipation,
    ];

    fn title(self) -> &'static str {
        match self {
            LapChart::Displacement => "Delta vs F",
            LapChart::Slip => "s(x) at F",
            LapChart::Zones => "zones vs F",
            LapChart::Shear => "tau(x) at F",
            LapChart::Loop => "loop +-F",
            LapChart::Dissipation => "D vs F_a",
        }
    }

    fn key(self) -> &'static str {
        match self {
            LapChart::Displacement => "delta-vs-f",
            LapChart::Zones => "zones-vs-f",
            LapChart::Shear => "lap-tau",
            LapChart::Slip => "lap-slip",
            LapChart::Loop => "lap-loop",
            LapChart::Dissipation => "lap-d-vs-fa",
        }
    }

    fn x_param(self) -> Option<Param> {
        match self {
            LapChart::Displacement | LapChart::Zones => Some(Param::Lap(LapParam::Force)),
            LapChart::Shear | LapChart::Slip | LapChart::Loop | LapChart::Dissipation => None,
        }
    }

    fn load_axis(self) -> bool {
        match self {
            LapChart::Displacement | LapChart::Zones | LapChart::Dissipation => true,
            LapChart::Shear | LapChart::Slip | LapChart::Loop => false,
        }
    }

    fn spans_decades(self) -> bool {
        match self {
            LapChart::Dissipation => true,
            LapChart::Displacement
            | LapChart::Zones
            | LapChart::Shear
            | LapChart::Slip
            | LapChart::Loop => false,
        }
    }
}

/// A chart of any model, as `microslip plot CHART` names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AnyChart {
    /// A chart of the twin beams.
    Beam(BeamChart),
    /// A chart of the plate.
    Plate(PlateChart),
    /// A chart of the lap joint.
    Lap(LapChart),
}

impl AnyChart {
    /// The parameter the chart runs along its x axis (F, K_T, mu), whose value a caption need not
    /// give; None where the x axis is no parameter (tau(x), the loop, P_r(x)).
    pub fn x_param(self) -> Option<Param> {
        match self {
            AnyChart::Beam(c) => c.x_param(),
            AnyChart::Plate(c) => c.x_param(),
            AnyChart::Lap(c) => c.x_param(),
        }
    }

    /// See [`ChartSet::load_axis`].
    pub fn load_axis(self) -> bool {
        match self {
            AnyChart::Beam(c) => c.load_axis(),
            AnyChart::Plate(c) => c.load_axis(),
            AnyChart::Lap(c) => c.load_axis(),
        }
    }

    /// See [`ChartSet::spans_decades`].
    pub fn spans_decades(self) -> bool {
        match self {
            AnyChart::Beam(c) => c.spans_decades(),
            AnyChart::Plate(c) => c.spans_decades(),
            AnyChart::Lap(c) => c.spans_decades(),
        }
    }

    /// Every chart: the beams', the plate's, then the lap joint's (each model's in cycling
    /// order).
    pub const ALL: &'static [AnyChart] = &[
        AnyChart::Beam(BeamChart::Deflection),
        AnyChart::Beam(BeamChart::SlipBoundary),
        AnyChart::Beam(BeamChart::Shear),
        AnyChart::Beam(BeamChart::Loop),
        AnyChart::Beam(BeamChart::Dissipation),
        AnyChart::Plate(PlateChart::Displacement),
        AnyChart::Plate(PlateChart::SlipBoundary),
        AnyChart::Plate(PlateChart::ContactPressure),
        AnyChart::Lap(LapChart::Displacement),
        AnyChart::Lap(LapChart::Zones),
        AnyChart::Lap(LapChart::Shear),
        AnyChart::Lap(LapChart::Slip),
        AnyChart::Lap(LapChart::Loop),
        AnyChart::Lap(LapChart::Dissipation),
    ];

    /// Every chart, as [`AnyChart::ALL`].
    pub fn all() -> impl Iterator<Item = AnyChart> + Clone {
        Self::ALL.iter().copied()
    }

    /// The name on the command line (unique over every problem).
    pub fn key(self) -> &'static str {
        match self {
            AnyChart::Beam(c) => c.key(),
            AnyChart::Plate(c) => c.key(),
            AnyChart::Lap(c) => c.key(),
        }
    }

    /// The short title.
    pub fn title(self) -> &'static str {
        match self {
            AnyChart::Beam(c) => c.title(),
            AnyChart::Plate(c) => c.title(),
            AnyChart::Lap(c) => c.title(),
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
            AnyChart::Lap(_) => ModelKind::Lap,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every problem has charts, and its first one is its response's (the chart the TUI opens on
    /// and shows loaded external points on).
    #[test]
    fn each_problem_opens_on_the_chart_of_its_response() {
        for kind in ModelKind::ALL {
            let first = AnyChart::all().find(|c| c.kind() == kind);
            let response = crate::problems::Quantity::Response.name(kind);
            assert!(
                first.is_some_and(|c| c.title().starts_with(response)),
                "{kind}: {first:?}"
            );
        }
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
            AnyChart::Plate(_) | AnyChart::Lap(_) => None,
        });
        assert!(beams.eq(BeamChart::ALL.iter().copied()));
        let plates = AnyChart::all().filter_map(|c| match c {
            AnyChart::Plate(p) => Some(p),
            AnyChart::Beam(_) | AnyChart::Lap(_) => None,
        });
        assert!(plates.eq(PlateChart::ALL.iter().copied()));
        let laps = AnyChart::all().filter_map(|c| match c {
            AnyChart::Lap(p) => Some(p),
            AnyChart::Beam(_) | AnyChart::Plate(_) => None,
        });
        assert!(laps.eq(LapChart::ALL.iter().copied()));
    }
}
