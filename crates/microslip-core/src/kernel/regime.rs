//! The friction regime of an interface (which zones exist, listed from x = 0 outward), and the
//! law that decides it.
//!
//! A regime is a sequence of [`Zone`]s, whatever the problem: the kernel names no problem's
//! regimes. Its label joins the zones' names with `+` (`stick+macroslip`), so a problem with a new
//! zone pattern (the lap joint's `macroslip+stick+macroslip`) needs no new variant here.

use std::fmt;
use std::sync::OnceLock;

/// One zone of an interface: how the points in it carry shear.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Zone {
    /// Coulomb law, no relative displacement.
    Stick,
    /// Regularized law, on the elastic branch (tau = K_T slip < mu P).
    Microslip,
    /// Sliding at tau = mu P.
    Macroslip,
}

impl Zone {
    /// The zone's name in reports and CSV files.
    pub fn name(self) -> &'static str {
        match self {
            Zone::Stick => "stick",
            Zone::Microslip => "microslip",
            Zone::Macroslip => "macroslip",
        }
    }

    /// The name where a screen is short of room: `micro`, `macro` (`stick` is short already).
    fn short_name(self) -> &'static str {
        match self {
            Zone::Stick => "stick",
            Zone::Microslip => "micro",
            Zone::Macroslip => "macro",
        }
    }
}

/// Most zones a regime lists: the lap joint's sliding zones at both ends around a middle one.
pub const MAX_ZONES: usize = 3;

/// Widest label the TUI's regime pane shows at 80x24 (characters): a longer one is written with
/// the short zone names.
const SHORT_WIDTH: usize = 19;

/// Zones present along the interface, from x = 0 (clamp, plate centre, or the lap joint's inner
/// plate end) outward; none when nothing is loaded.
///
/// The labels are part of the CLI's CSV contract (`stick+macroslip`, ...): [`Regime::label`]
/// writes them, rather than each output format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Regime {
    /// The zones from x = 0 outward, packed at the front; None after the last.
    zones: [Option<Zone>; MAX_ZONES],
}

impl Regime {
    /// No tangential load (the twin beams at F = 0, the plate at nu = 0, which the pressure does
    /// not squeeze sideways): the interface carries no shear and nothing slips, whatever the law.
    pub const UNLOADED: Regime = Regime::from_zones(&[]);
    /// Coulomb law, no relative displacement anywhere.
    pub const STICK: Regime = Regime::from_zones(&[Zone::Stick]);
    /// Regularized law, the whole interface on the elastic branch.
    pub const MICROSLIP: Regime = Regime::from_zones(&[Zone::Microslip]);
    /// The whole interface slides at tau = mu P.
    pub const MACROSLIP: Regime = Regime::from_zones(&[Zone::Macroslip]);
    /// Coulomb law: a sticking zone near x = 0, a sliding zone beyond.
    pub const STICK_MACROSLIP: Regime = Regime::from_zones(&[Zone::Stick, Zone::Macroslip]);
    /// Regularized law: an elastic microslip zone near x = 0, a sliding zone beyond.
    pub const MICROSLIP_MACROSLIP: Regime = Regime::from_zones(&[Zone::Microslip, Zone::Macroslip]);

    /// The regime of `zones`, listed from x = 0 outward; an empty list is [`Regime::UNLOADED`].
    ///
    /// # Panics
    ///
    /// With more than [`MAX_ZONES`] zones: zone patterns are fixed by each problem's closed
    /// form, never by input, and in a `const` the check fails the build.
    pub const fn from_zones(zones: &[Zone]) -> Regime {
        assert!(
            zones.len() <= MAX_ZONES,
            "a regime lists at most MAX_ZONES zones"
        );
        let mut packed = [None; MAX_ZONES];
        let mut i = 0;
        while i < zones.len() {
            packed[i] = Some(zones[i]);
            i += 1;
        }
        Regime { zones: packed }
    }

    /// The zones from x = 0 outward (empty when unloaded).
    pub fn zones(&self) -> impl Iterator<Item = Zone> + '_ {
        self.zones.iter().map_while(|z| *z)
    }

    /// The zone names joined by `+` (`unloaded` without zones), as written in reports and CSV
    /// files.
    pub fn label(self) -> &'static str {
        &labels()[self.index()].0
    }

    /// The label where a screen has room for 19 characters (the TUI's regime pane at 80x24): a
    /// longer label (the lap joint's three zones) with the short zone names
    /// (`macro+stick+macro`), every other as [`Regime::label`].
    pub fn short_label(self) -> &'static str {
        &labels()[self.index()].1
    }

    /// The regime's row in [`labels`]: its zones as the digits of a base-4 number (0 for no
    /// zone), from the first.
    fn index(self) -> usize {
        self.zones.iter().fold(0, |index, zone| {
            index * 4 + zone.map_or(0, |z| z as usize + 1)
        })
    }

    /// The zones' names by `name`, joined by `+`; `unloaded` without zones.
    fn joined(self, name: fn(Zone) -> &'static str) -> String {
        if self == Regime::UNLOADED {
            return "unloaded".to_string();
        }
        self.zones().map(name).collect::<Vec<_>>().join("+")
    }

    /// True when some part of the interface slides at the Coulomb stress mu P.
    pub fn has_macroslip(self) -> bool {
        self.zones().any(|z| z == Zone::Macroslip)
    }
}

impl fmt::Display for Regime {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.label())
    }
}

/// Every regime's (label, short label), by [`Regime::index`]: written once by the joining rule,
/// so that reports get `&'static str` labels as they did when each regime was a variant.
fn labels() -> &'static [(String, String)] {
    static LABELS: OnceLock<Vec<(String, String)>> = OnceLock::new();
    LABELS.get_or_init(|| {
        let zone = |digit: usize| {
            [Zone::Stick, Zone::Microslip, Zone::Macroslip]
                .get(digit.wrapping_sub(1))
                .copied()
        };
        (0..4usize.pow(MAX_ZONES as u32))
            .map(|index| {
                let mut zones = [None; MAX_ZONES];
                let mut rest = index;
                for slot in zones.iter_mut().rev() {
                    *slot = zone(rest % 4);
                    rest /= 4;
                }
                let regime = Regime { zones };
                let label = regime.joined(Zone::name);
                let short = if label.len() <= SHORT_WIDTH {
                    label.clone()
                } else {
                    regime.joined(Zone::short_name)
                };
                (label, short)
            })
            .collect()
    })
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
        assert_eq!(Regime::STICK_MACROSLIP.to_string(), "stick+macroslip");
        assert_eq!(Regime::MICROSLIP_MACROSLIP.label(), "microslip+macroslip");
        assert_eq!(Regime::UNLOADED.label(), "unloaded");
        assert_eq!(format!("{:>9}", Regime::STICK), "    stick");
        assert!(!Regime::MICROSLIP.has_macroslip());
        assert!(!Regime::STICK.has_macroslip());
        assert!(!Regime::UNLOADED.has_macroslip());
        assert!(Regime::MACROSLIP.has_macroslip());
        let ends = Regime::from_zones(&[Zone::Macroslip, Zone::Stick, Zone::Macroslip]);
        assert_eq!(ends.label(), "macroslip+stick+macroslip");
        assert_eq!(ends.short_label(), "macro+stick+macro");
        let elastic = Regime::from_zones(&[Zone::Macroslip, Zone::Microslip, Zone::Macroslip]);
        assert_eq!(elastic.short_label(), "macro+micro+macro");
        // 19 characters: short enough to keep its full names.
        assert_eq!(
            Regime::MICROSLIP_MACROSLIP.short_label(),
            "microslip+macroslip"
        );
        let mut all = vec![Regime::UNLOADED];
        for a in [Zone::Stick, Zone::Microslip, Zone::Macroslip] {
            all.push(Regime::from_zones(&[a]));
            for b in [Zone::Stick, Zone::Microslip, Zone::Macroslip] {
                all.push(Regime::from_zones(&[a, b]));
                for c in [Zone::Stick, Zone::Microslip, Zone::Macroslip] {
                    all.push(Regime::from_zones(&[a, b, c]));
                }
            }
        }
        for regime in all {
            assert!(regime.short_label().len() <= SHORT_WIDTH, "{regime}");
            assert_eq!(regime.zones().count() == 0, regime == Regime::UNLOADED);
        }
    }
}
