//! The kinematics an FE run was made with (issue 33, item 4): `NLGEOM` on a deck's `*STEP` cards
//! or not. The beams' envelope (V2) was calibrated on `NLGEOM` decks; on an independent model
//! outside the calibration set, linear geometry moved the FE w(L) by -1.3 % against -0.1 % with
//! `NLGEOM` (issue 33), beyond the bound: so a verdict names the kinematics it judged, and an
//! envelope is not applied to kinematics it was not calibrated on.

use std::fmt;

/// The kinematics of an FE run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kinematics {
    /// Every step `NLGEOM`: large rotations (the faces and the pressure rotate with the body).
    Nlgeom,
    /// No step `NLGEOM`: linear (small-displacement) geometry.
    Linear,
    /// Some steps one, some the other.
    Mixed,
    /// Nobody said (a CSV without `--kinematics`).
    NotStated,
}

impl Kinematics {
    /// The words a verdict names it with.
    pub fn words(self) -> &'static str {
        match self {
            Kinematics::Nlgeom => "NLGEOM (large rotations)",
            Kinematics::Linear => "linear geometry",
            Kinematics::Mixed => "mixed (NLGEOM on some steps only)",
            Kinematics::NotStated => "not stated",
        }
    }

    /// A key for JSON.
    pub fn label(self) -> &'static str {
        match self {
            Kinematics::Nlgeom => "nlgeom",
            Kinematics::Linear => "linear",
            Kinematics::Mixed => "mixed",
            Kinematics::NotStated => "not stated",
        }
    }

    /// The kinematics of a deck: `NLGEOM` (or `NLGEOM=YES`) on every `*STEP` card, on none
    /// (`NLGEOM=NO` counts as none), or on some. A deck without a `*STEP` card is
    /// [`Kinematics::NotStated`].
    pub fn of_deck(deck: &str) -> Kinematics {
        let mut steps = deck.lines().map(str::trim).filter(|l| {
            l.split(',')
                .next()
                .is_some_and(|k| k.trim().eq_ignore_ascii_case("*STEP"))
        });
        let nlgeom = |card: &str| {
            card.split(',').skip(1).any(|p| {
                let (key, value) = p.split_once('=').unwrap_or((p, "YES"));
                key.trim().eq_ignore_ascii_case("NLGEOM")
                    && !value.trim().eq_ignore_ascii_case("NO")
            })
        };
        let Some(first) = steps.next() else {
            return Kinematics::NotStated;
        };
        let first = nlgeom(first);
        if steps.any(|s| nlgeom(s) != first) {
            Kinematics::Mixed
        } else if first {
            Kinematics::Nlgeom
        } else {
            Kinematics::Linear
        }
    }
}

impl fmt::Display for Kinematics {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.words())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nlgeom_is_read_from_every_step() {
        let nl = "*STEP, NLGEOM, INC=1000\n*STATIC\n*END STEP\n*step,nlgeom=yes\n";
        assert_eq!(Kinematics::of_deck(nl), Kinematics::Nlgeom);
        let linear = "** *STEP, NLGEOM\n*STEP, INC=1000\n*STEP, NLGEOM=NO\n";
        assert_eq!(Kinematics::of_deck(linear), Kinematics::Linear);
        assert_eq!(
            Kinematics::of_deck("*STEP, NLGEOM\n*STEP\n"),
            Kinematics::Mixed
        );
        assert_eq!(Kinematics::of_deck("*NODE\n"), Kinematics::NotStated);
        // A *STEPxx keyword is not a step.
        assert_eq!(
            Kinematics::of_deck("*STEPS, NLGEOM\n*STEP\n"),
            Kinematics::Linear
        );
    }
}
