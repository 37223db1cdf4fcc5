//! Where a closed form stands against continuum mechanics: the verdict every problem's validity
//! envelope gives (each problem's envelope is in its own folder, `validity.rs`). The envelopes were
//! measured against continuum finite elements: CalculiX 2.20 (`validation/calculix/`) and the
//! project's own plane-strain solver; calibration, cases and tables are in docs/theory.md,
//! "Validity of the closed forms".

/// Where a closed form stands against continuum mechanics.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Validity {
    /// Expected within 2 % of a continuum model.
    Holds,
    /// Expected within 10 %.
    Approximate,
    /// Expected off by more than 10 %: use a continuum model.
    Outside,
    /// No calibrated bound reaches this case (measured between under 1 % and 540 %): the
    /// envelope cannot decide; use a continuum model.
    NotCalibrated,
    /// No bound from above reaches this case, but every calibration case of its region was
    /// measured off by more than a stated amount (the plate's (V1c)): wrong, not merely
    /// uncalibrated; use a continuum model.
    MeasuredWrong,
}

impl Validity {
    /// Expected relative error at or below which the closed form [`Validity::Holds`].
    pub const HOLDS: f64 = 0.02;
    /// Expected relative error at or below which it is [`Validity::Approximate`].
    pub const APPROXIMATE: f64 = 0.10;

    /// The level of an expected relative error.
    pub fn of_error(error: f64) -> Validity {
        if error <= Self::HOLDS {
            Validity::Holds
        } else if error <= Self::APPROXIMATE {
            Validity::Approximate
        } else {
            Validity::Outside
        }
    }

    /// A word for reports and CSV.
    pub fn label(self) -> &'static str {
        match self {
            Validity::Holds => "holds",
            Validity::Approximate => "approximate",
            Validity::Outside => "outside",
            Validity::NotCalibrated => "not calibrated",
            Validity::MeasuredWrong => "measured wrong",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn levels_change_at_their_bounds() {
        assert_eq!(Validity::of_error(0.02), Validity::Holds);
        assert_eq!(Validity::of_error(0.0201), Validity::Approximate);
        assert_eq!(Validity::of_error(0.1), Validity::Approximate);
        assert_eq!(Validity::of_error(0.1001), Validity::Outside);
    }
}
