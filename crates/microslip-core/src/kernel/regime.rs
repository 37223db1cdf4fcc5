//! The friction regime of an interface (which zones exist, listed from x = 0 outward), and the
//! law that decides it.

use std::fmt;

/// Zones present along the interface, from x = 0 (clamp, plate centre, or the lap joint's inner
/// plate end) outward.
///
/// The labels are part of the CLI's CSV contract (`stick+macroslip`, ...), so they live here, next to
/// the enum, rather than in each output format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Regime {
    /// Coulomb law, no relative displacement anywhere.
    Stick,
    /// Regularized law, the whole interface on the elastic branch (tau = K_T slip < mu P).
    Microslip,
    /// The whole interface slides at tau = mu P.
    Macroslip,
    /// Coulomb law: a sticking zone near x = 0, a sliding zone beyond.
    StickMacroslip,
    /// Regularized law: an elastic microslip zone near x = 0, a sliding zone beyond.
    MicroslipMacroslip,
    /// Coulomb law, the lap joint: sliding zones at both ends, sticking between them.
    MacroslipStickMacroslip,
    /// Coulomb law, the lap joint: a sliding zone at x = 0 only, sticking beyond.
    MacroslipStick,
    /// Regularized law, the lap joint: sliding zones at both ends, elastic between them.
    MacroslipMicroslipMacroslip,
    /// Regularized law, the lap joint: a sliding zone at x = 0 only, elastic beyond.
    MacroslipMicroslip,
    /// No tangential load (the twin beams at F = 0, the plate at nu = 0, which the pressure does
    /// not squeeze sideways): the interface carries no shear and nothing slips, whatever the law.
    Unloaded,
}

impl Regime {
    /// The zone list joined by `+`, as written in reports and CSV files.
    pub fn label(self) -> &'static str {
        match self {
            Regime::Stick => "stick",
            Regime::Microslip => "microslip",
            Regime::Macroslip => "macroslip",
            Regime::StickMacroslip => "stick+macroslip",
            Regime::MicroslipMacroslip => "microslip+macroslip",
            Regime::MacroslipStickMacroslip => "macroslip+stick+macroslip",
            Regime::MacroslipStick => "macroslip+stick",
            Regime::MacroslipMicroslipMacroslip => "macroslip+microslip+macroslip",
            Regime::MacroslipMicroslip => "macroslip+microslip",
            Regime::Unloaded => "unloaded",
        }
    }

    /// The label where a screen has room for 19 characters (the TUI's regime pane at 80x24):
    /// the three-zone regimes of the lap joint as `macro+stick+macro`, `macro+micro+macro`;
    /// every other regime as [`Regime::label`].
    pub fn short_label(self) -> &'static str {
        match self {
            Regime::MacroslipStickMacroslip => "macro+stick+macro",
            Regime::MacroslipMicroslipMacroslip => "macro+micro+macro",
            other => other.label(),
        }
    }

    /// True when some part of the interface slides at the Coulomb stress mu P.
    pub fn has_macroslip(self) -> bool {
        matches!(
            self,
            Regime::Macroslip
                | Regime::StickMacroslip
                | Regime::MicroslipMacroslip
                | Regime::MacroslipStickMacroslip
                | Regime::MacroslipStick
                | Regime::MacroslipMicroslipMacroslip
                | Regime::MacroslipMicroslip
        )
    }
}

impl fmt::Display for Regime {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.label())
    }
}

/// Which friction law: every problem is solved under both, and its loops are built for each.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Law {
    /// Plain Coulomb.
    Coulomb,
    /// Regularized Coulomb (tau = K_T slip up to mu P).
    Regularized,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn labels_name_zones_from_the_origin_outward() {
        assert_eq!(Regime::StickMacroslip.to_string(), "stick+macroslip");
        assert_eq!(Regime::MicroslipMacroslip.label(), "microslip+macroslip");
        assert!(!Regime::Microslip.has_macroslip());
        assert!(!Regime::Stick.has_macroslip());
        assert!(Regime::Macroslip.has_macroslip());
        for regime in [
            Regime::Stick,
            Regime::Microslip,
            Regime::Macroslip,
            Regime::StickMacroslip,
            Regime::MicroslipMacroslip,
            Regime::MacroslipStickMacroslip,
            Regime::MacroslipStick,
            Regime::MacroslipMicroslipMacroslip,
            Regime::MacroslipMicroslip,
            Regime::Unloaded,
        ] {
            assert!(regime.short_label().len() <= 19, "{regime}");
        }
    }
}
