//! Typed parameters, as any problem describes them: units, accepted domains, arrow-key steps, the
//! error that names a field, its value and its range, and how numbers are echoed and parsed. The
//! parameters of each problem (its keys, meanings and domains) live in that problem's folder and
//! are built from these pieces; this module knows no problem.

use std::fmt;

use thiserror::Error;

/// Physical unit of a parameter, as shown to users.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unit {
    /// Millimetre.
    Millimetre,
    /// Newton.
    Newton,
    /// Megapascal (N/mm^2).
    Megapascal,
    /// Megapascal per millimetre (stiffness per unit area).
    MegapascalPerMillimetre,
    /// Newton per millimetre: a line load, per unit length of a plane-strain body (the
    /// Hertzian cylinder's P and Q).
    NewtonPerMillimetre,
    /// Newton millimetre: a torque (the press fit's T).
    NewtonMillimetre,
    /// No unit.
    Dimensionless,
}

impl Unit {
    /// The symbol: `mm`, `N`, `MPa`, `MPa/mm`, `N/mm`, `N mm`, or `-` for dimensionless.
    pub fn symbol(self) -> &'static str {
        match self {
            Unit::Millimetre => "mm",
            Unit::Newton => "N",
            Unit::Megapascal => "MPa",
            Unit::MegapascalPerMillimetre => "MPa/mm",
            Unit::NewtonPerMillimetre => "N/mm",
            Unit::NewtonMillimetre => "N mm",
            Unit::Dimensionless => "-",
        }
    }

    /// The unit after a number in text: its symbol, empty when dimensionless.
    pub fn in_text(self) -> &'static str {
        match self {
            Unit::Dimensionless => "",
            other => other.symbol(),
        }
    }

    /// The unit as a JSON key or CSV header ends (`Q_N_per_mm`, `KT_MPa_per_mm`, `T_Nmm`): `/`
    /// as `_per_`, N mm as `Nmm` (as the energies' `D_Nmm`), and nothing for dimensionless.
    pub fn key(self) -> &'static str {
        match self {
            Unit::Millimetre => "mm",
            Unit::Newton => "N",
            Unit::Megapascal => "MPa",
            Unit::MegapascalPerMillimetre => "MPa_per_mm",
            Unit::NewtonPerMillimetre => "N_per_mm",
            Unit::NewtonMillimetre => "Nmm",
            Unit::Dimensionless => "",
        }
    }

    /// The unit as range messages spell it (`dimensionless` rather than `-`).
    fn in_words(self) -> &'static str {
        match self {
            Unit::Dimensionless => "dimensionless",
            other => other.symbol(),
        }
    }
}

impl fmt::Display for Unit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.symbol())
    }
}

/// The values a parameter may take: a closed interval of finite numbers (half-open for the Poisson
/// ratio). Every domain excludes NaN and infinities, and every one is bounded, so that every derived
/// quantity of every accepted input is a finite f64: the bounds and the reasons for them are in
/// docs/theory.md, "Accepted domain".
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Domain {
    /// Strictly positive, from `min` to `max` inclusive, `0 < min < max` (lengths, moduli,
    /// pressures, friction, stiffness).
    Positive {
        /// Smallest accepted value.
        min: f64,
        /// Largest accepted value.
        max: f64,
    },
    /// From 0 to `max` inclusive (loads).
    NonNegative {
        /// Largest accepted value.
        max: f64,
    },
    /// 0 <= nu < 0.5: a stable isotropic solid that does not expand under compression (0.5 is
    /// incompressible and makes the plane-strain compliance singular).
    PoissonRatio,
    /// From `-max` to `max` inclusive (displacements read from FE results, of either sign).
    Symmetric {
        /// Largest accepted magnitude.
        max: f64,
    },
}

impl Domain {
    /// Lengths (mm): 1 nm to 1 km.
    pub const LENGTH: Domain = Domain::Positive {
        min: 1e-6,
        max: 1e6,
    };
    /// Young's modulus (MPa): 100 Pa (soft gels) to 10 TPa (beyond diamond).
    pub const MODULUS: Domain = Domain::Positive {
        min: 1e-4,
        max: 1e7,
    };
    /// Pressures (MPa): 1 Pa to 10 GPa.
    pub const PRESSURE: Domain = Domain::Positive {
        min: 1e-6,
        max: 1e4,
    };
    /// Friction coefficient (-): 1e-6 (superlubricity and below) to 10 (adhesive contacts).
    pub const FRICTION: Domain = Domain::Positive {
        min: 1e-6,
        max: 10.0,
    };
    /// Tangential and normal contact stiffness (MPa/mm): 1e-6 to 1e12 (1e9 MPa/um).
    pub const STIFFNESS: Domain = Domain::Positive {
        min: 1e-6,
        max: 1e12,
    };
    /// Tip force or cycle amplitude (N): 0 to 1e12 N.
    pub const FORCE: Domain = Domain::NonNegative { max: 1e12 };
    /// A displacement read from FE results (mm): no larger in magnitude than the longest accepted
    /// length, 1 km. A small-displacement FE result beyond that is not a result (an overflowed or
    /// corrupted file), and comparing it would print numbers that mean nothing.
    pub const DISPLACEMENT: Domain = Domain::Symmetric { max: 1e6 };
    /// A deck's force step per increment (N): positive, up to the largest tip force.
    pub const FORCE_STEP: Domain = Domain::Positive {
        min: 1e-12,
        max: 1e12,
    };
    /// FE contact element length (mm): down to a hundredth of the shortest accepted length, the
    /// default L/100 of `microslip kt`.
    pub const ELEMENT_SIZE: Domain = Domain::Positive {
        min: 1e-8,
        max: 1e6,
    };

    /// The smallest accepted value (0 for loads and the Poisson ratio).
    pub fn min(self) -> f64 {
        match self {
            Domain::Positive { min, .. } => min,
            Domain::NonNegative { .. } | Domain::PoissonRatio => 0.0,
            Domain::Symmetric { max } => -max,
        }
    }

    /// The largest accepted value, or for the Poisson ratio the excluded upper end 0.5.
    pub fn max(self) -> f64 {
        match self {
            Domain::Positive { max, .. }
            | Domain::NonNegative { max }
            | Domain::Symmetric { max } => max,
            Domain::PoissonRatio => 0.5,
        }
    }

    /// True when `value` is allowed.
    pub fn contains(self, value: f64) -> bool {
        value.is_finite()
            && match self {
                Domain::Positive { min, max } => (min..=max).contains(&value),
                Domain::NonNegative { max } => (0.0..=max).contains(&value),
                Domain::PoissonRatio => (0.0..0.5).contains(&value),
                Domain::Symmetric { max } => (-max..=max).contains(&value),
            }
    }

    /// `value` moved into the domain: the nearest accepted value (for the Poisson ratio, the
    /// largest f64 below 0.5 at the top). NaN maps to the smallest accepted value.
    pub fn clamp(self, value: f64) -> f64 {
        if value.is_nan() {
            return self.min();
        }
        match self {
            Domain::PoissonRatio => value.clamp(0.0, 0.5_f64.next_down()),
            other => value.clamp(other.min(), other.max()),
        }
    }

    /// The allowed range in words, with the unit: `must be in [1e-6, 1e6] mm`.
    pub fn describe(self, unit: Unit) -> String {
        let range = match self {
            Domain::PoissonRatio => "[0, 0.5)".to_string(),
            other => format!(
                "[{}, {}]",
                inward(other.min(), Inward::Up),
                inward(other.max(), Inward::Down)
            ),
        };
        match unit {
            Unit::Dimensionless => format!("must be in {range} (dimensionless)"),
            unit => format!("must be in {range} {unit}"),
        }
    }

    /// Why `value` is refused, in words: the sign rule for NaN, infinities and values of the wrong
    /// sign (`must be > 0 and finite (mm)`), the range otherwise ([`Domain::describe`]).
    pub fn refusal(self, value: f64, unit: Unit) -> String {
        let words = unit.in_words();
        match self {
            // A number too large for an f64 (`1e400`) is too large, not of the wrong sign: the range.
            Domain::Positive { .. } if value.is_nan() || value <= 0.0 => {
                format!("must be > 0 and finite ({words})")
            }
            Domain::NonNegative { .. } if value.is_nan() || value < 0.0 => {
                format!("must be >= 0 and finite ({words})")
            }
            Domain::PoissonRatio => format!("must be in [0, 0.5) ({words})"),
            _ => self.describe(unit),
        }
    }

    /// Passes `value` through when allowed, otherwise names `field`, the value and the range.
    ///
    /// # Errors
    /// [`ParamError`] when `value` is outside the domain.
    pub fn check(self, field: &'static str, value: f64, unit: Unit) -> Result<f64, ParamError> {
        if self.contains(value) {
            // -0 passes as 0, and is 0 from here on (never "-0.0" in JSON or a deck header).
            Ok(value + 0.0)
        } else {
            Err(ParamError {
                field,
                value,
                domain: self,
                unit,
                reason: None,
            })
        }
    }
}

/// A bound of a domain as range messages write it: plain between 1e-3 and 1e6 (`10`, `0.5`),
/// exponent form outside (`1e-6`, `1e12`), as ranges are usually written.
/// Which way a range's end is rounded to stay inside the range.
#[derive(Clone, Copy)]
enum Inward {
    /// A lower end: rounded up.
    Up,
    /// An upper end: rounded down.
    Down,
}

/// A range's end as a message prints it: as [`bound`] where that is short (a domain's own ends,
/// `1e6`, `0.5`), else to 6 significant digits rounded toward the inside of the range, so that
/// every number the message shows as allowed is allowed (an end the other inputs set, F_gross =
/// 264.53439240351895 N, reads `264.534`; `0.29999993999999996` reads `0.299999`).
fn inward(value: f64, way: Inward) -> String {
    let exact = bound(value);
    let digits = exact
        .split(['e', 'E'])
        .next()
        .unwrap_or_default()
        .chars()
        .filter(char::is_ascii_digit)
        .collect::<String>();
    if !value.is_finite() || value == 0.0 || digits.trim_start_matches('0').len() <= 7 {
        return exact;
    }
    let step = 10f64.powi(value.abs().log10().floor() as i32 - 5);
    let rounded = match way {
        Inward::Up => (value / step).ceil() * step,
        Inward::Down => (value / step).floor() * step,
    };
    let text = format!("{rounded:.5e}");
    let shown: f64 = text.parse().unwrap_or(rounded);
    bound(shown)
}

fn bound(value: f64) -> String {
    if value.is_finite() && value != 0.0 && !(1e-3..1e6).contains(&value.abs()) {
        format!("{value:e}")
    } else {
        format!("{value}")
    }
}

/// A number echoed in a message, short whatever its size: as Rust's shortest round-trip form prints
/// it (`-3`, `0.25`, `123456`) unless that is more than three characters longer than the exponent
/// form, which is then used (`1e6`, `-1e308` rather than 309 digits, `1.5e-7`). For a number typed
/// by a user this gives back what was typed, or its shortest equivalent.
///
/// # Examples
/// ```
/// use microslip_core::kernel::params::Compact;
/// assert_eq!(Compact(-3.0).to_string(), "-3");
/// assert_eq!(Compact(0.25).to_string(), "0.25");
/// assert_eq!(Compact(-1e308).to_string(), "-1e308");
/// assert_eq!(Compact(2.5e-9).to_string(), "2.5e-9");
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Compact(pub f64);

impl fmt::Display for Compact {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let plain = self.0.to_string();
        let exponent = format!("{:e}", self.0);
        if plain.len() <= exponent.len() + 3 {
            f.pad(&plain)
        } else {
            f.pad(&exponent)
        }
    }
}

/// A computed number in a message, rounded to `digits` significant digits and written as
/// [`Compact`] writes it ("1.714", "1.75e10", "0.0952381"): not the 17 digits of a round trip.
///
/// # Examples
/// ```
/// use microslip_core::kernel::params::significant;
/// assert_eq!(significant(0.09523809306122456, 6), "0.0952381");
/// assert_eq!(significant(1.75e10, 4), "1.75e10");
/// ```
pub fn significant(x: f64, digits: usize) -> String {
    let rounded: f64 = format!("{x:.*e}", digits.saturating_sub(1))
        .parse()
        .unwrap_or(x);
    Compact(rounded).to_string()
}

/// A rejected value as a message echoes it: [`Compact`], except that a number too large for an f64
/// (typed `1e400`, which parses as infinity) is not echoed as "inf", which nobody typed.
struct Echo(f64);

impl fmt::Display for Echo {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.0.is_infinite() {
            let sign = if self.0 < 0.0 { "-" } else { "" };
            write!(f, "{sign}(a number beyond 1.8e308)")
        } else {
            Compact(self.0).fmt(f)
        }
    }
}

/// A rejected input value: the field as users write it, the value and the allowed range.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("invalid {field} = {}: {}", Echo(*value), self.allowed())]
pub struct ParamError {
    /// Field name as the user writes it (preset key), e.g. `KT`.
    pub field: &'static str,
    /// The rejected value (may be NaN or infinite).
    pub value: f64,
    /// What is allowed.
    pub domain: Domain,
    /// The field's unit.
    pub unit: Unit,
    /// Why the range is what it is, where the domain alone does not say it (the lap joint's
    /// force bound F_gross); None for a parameter's own domain.
    pub reason: Option<&'static str>,
}

impl ParamError {
    /// What is allowed, and why where the error says it: the message after `invalid F = 7000: `,
    /// for a caller that names the value its own way (a flag, a sweep's end).
    pub fn allowed(&self) -> String {
        let refusal = self.domain.refusal(self.value, self.unit);
        match self.reason {
            Some(reason) => format!("{refusal} ({reason})"),
            None => refusal,
        }
    }

    /// The same error, saying why the range is what it is.
    pub fn because(self, reason: &'static str) -> ParamError {
        ParamError {
            reason: Some(reason),
            ..self
        }
    }
}

/// A parameter's natural scale: whether it varies by factors (it spans decades and stays
/// positive), by sums within a range (nu), or by fractions of a model scale (the force, in
/// fractions of F_thre). It is a property of the parameter, not of a screen: the chart of a
/// response against the parameter (`v`, `sweep --vary` ranges) takes its axis (logarithmic or
/// linear) and its span from it, and interactive stepping (the TUI's arrow keys) moves by its fine
/// and coarse steps. (Issue 23 asked for the TUI's `Step` to leave the core types; it was renamed
/// and kept here for that reason: the chart layer needs it as much as the TUI.)
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Scale {
    /// Multiply or divide by a factor (quantities that span decades and stay positive).
    Factor {
        /// Fine step factor.
        fine: f64,
        /// Coarse step factor.
        coarse: f64,
    },
    /// Add or subtract, then clamp to `[min, max]`.
    Add {
        /// Fine step.
        fine: f64,
        /// Coarse step.
        coarse: f64,
        /// Smallest value reached by stepping.
        min: f64,
        /// Largest value reached by stepping.
        max: f64,
    },
    /// Add or subtract a fraction of a model scale (the twin beams' F_thre for the force, so that F
    /// can reach and leave 0 in steps that mean the same for every geometry), never below zero.
    FractionOfScale {
        /// Fine fraction.
        fine: f64,
        /// Coarse fraction.
        coarse: f64,
    },
}

impl Scale {
    /// The value one fine or `coarse` step up (`up`) or down; `scale` is used by
    /// [`Scale::FractionOfScale`].
    pub fn step(self, value: f64, up: bool, coarse: bool, scale: f64) -> f64 {
        let sign = if up { 1.0 } else { -1.0 };
        match self {
            Scale::Factor { fine, coarse: big } => {
                let factor = if coarse { big } else { fine };
                if up { value * factor } else { value / factor }
            }
            Scale::Add {
                fine,
                coarse: big,
                min,
                max,
            } => (value + sign * if coarse { big } else { fine }).clamp(min, max),
            Scale::FractionOfScale { fine, coarse: big } => {
                (value + sign * scale * if coarse { big } else { fine }).max(0.0)
            }
        }
    }
}

/// Relative fine and coarse steps of multiplicative parameters.
pub(crate) const FACTOR: Scale = Scale::Factor {
    fine: 1.02,
    coarse: 1.25,
};

/// Everything users see of one parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParamSpec {
    /// Key in preset files, `--set` and the TUI (`KT`).
    pub name: &'static str,
    /// Unit.
    pub unit: Unit,
    /// What the value means.
    pub meaning: &'static str,
    /// Allowed values.
    pub domain: Domain,
    /// Its natural scale: the axis of a chart against it, and its arrow-key steps.
    pub scale: Scale,
    /// The values engineers usually give this parameter, `[low, high]` in its unit: a value inside
    /// the accepted domain but outside this range is accepted with a warning (a slip of the
    /// keyboard, `mu = 4.5` for 0.45, or a unit mix-up, L in um). Wider than any benchmark in the
    /// literature, narrower than the domain. Set with [`ParamSpec::usual`].
    pub usual: (f64, f64),
    /// A word shown beside the value where the key alone misleads (`half` for the plate's `L`,
    /// which is a half-length where the beams' `L` is a whole length); empty for most.
    pub note: &'static str,
}

impl ParamSpec {
    /// The same spec with `note` shown beside its value.
    pub(crate) const fn noted(self, note: &'static str) -> ParamSpec {
        ParamSpec { note, ..self }
    }

    /// The refusal of `value`, inside this parameter's own domain but above `max`, a bound the
    /// other inputs set (the lap joint's and the press fit's F_gross), with `reason` saying it:
    /// `invalid F = 7000: must be in [0, 6000] N (F_gross = ...: ...)`.
    pub fn above(self, value: f64, max: f64, reason: &'static str) -> ParamError {
        ParamError {
            field: self.name,
            value,
            domain: Domain::NonNegative { max },
            unit: self.unit,
            reason: Some(reason),
        }
    }

    /// The same spec with its usual range set to `[low, high]`.
    pub const fn usual(self, low: f64, high: f64) -> ParamSpec {
        ParamSpec {
            usual: (low, high),
            ..self
        }
    }
}

/// A [`ParamSpec`] in one line, for the problems' tables of parameters; its usual range is
/// unbounded until [`ParamSpec::usual`] sets it (a test requires every problem's to be set).
pub(crate) const fn spec(
    name: &'static str,
    unit: Unit,
    meaning: &'static str,
    domain: Domain,
    scale: Scale,
) -> ParamSpec {
    ParamSpec {
        name,
        unit,
        meaning,
        domain,
        scale,
        usual: (f64::NEG_INFINITY, f64::INFINITY),
        note: "",
    }
}

pub(crate) const MODULUS: ParamSpec = spec(
    "E",
    Unit::Megapascal,
    "Young's modulus",
    Domain::MODULUS,
    FACTOR,
)
.usual(1.0, 1.2e6);
pub(crate) const FRICTION: ParamSpec = spec(
    "mu",
    Unit::Dimensionless,
    "friction coefficient",
    Domain::FRICTION,
    FACTOR,
)
.usual(0.01, 2.0);
/// The Poisson ratio; stepping stops just short of the excluded 0.5.
pub(crate) const POISSON: ParamSpec = spec(
    "nu",
    Unit::Dimensionless,
    "Poisson ratio",
    Domain::PoissonRatio,
    Scale::Add {
        fine: 0.005,
        coarse: 0.05,
        min: 0.0,
        max: 0.499,
    },
)
.usual(0.0, 0.5);
/// K_T spans decades: its coarse step is a quarter decade.
pub(crate) const STIFFNESS: ParamSpec = spec(
    "KT",
    Unit::MegapascalPerMillimetre,
    "tangential contact stiffness",
    Domain::STIFFNESS,
    Scale::Factor {
        fine: 1.02,
        coarse: 1.778_279_410_038_922_8, // 10^0.25
    },
)
.usual(0.1, 1e9);

/// Parses a number as users type it: `1e6`, `600`, `0.3`; rejects NaN and infinities spelled out.
pub fn parse_number(text: &str) -> Option<f64> {
    let value: f64 = text.parse().ok()?;
    // "nan" and "inf" parse in Rust; they are never what a user means. Range checks catch the rest.
    if value.is_nan() || text.to_ascii_lowercase().contains("inf") {
        None
    } else {
        // "-0" is 0: a negative zero would be echoed as "-0.0" in JSON and deck headers.
        Some(value + 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A range's computed end prints short and inside the range; a short one prints exactly.
    #[test]
    fn computed_range_ends_print_short_and_inside() {
        let range = |lo: f64, hi: f64| {
            let domain = if lo == 0.0 {
                Domain::NonNegative { max: hi }
            } else {
                Domain::Positive { min: lo, max: hi }
            };
            domain.describe(Unit::Newton)
        };
        assert_eq!(
            range(0.0, 264.534_392_403_518_95),
            "must be in [0, 264.534] N"
        );
        assert_eq!(
            range(0.0, 0.299_999_939_999_999_96),
            "must be in [0, 0.299999] N"
        );
        assert_eq!(
            range(0.300_000_000_000_000_04, 6000.0),
            "must be in [0.300001, 6000] N"
        );
        assert_eq!(
            range(0.0, 4_531_143.250_369_892),
            "must be in [0, 4.53114e6] N"
        );
        assert_eq!(range(1e-3, 1e6), "must be in [0.001, 1e6] N");
        for (lo, hi) in [
            (0.123_456_789_123, 9.876_543_212_345e7),
            (1.000_000_1, 1.000_000_9),
        ] {
            let text = range(lo, hi);
            let inner = text
                .trim_start_matches("must be in [")
                .trim_end_matches("] N");
            let (a, b) = inner.split_once(", ").unwrap();
            assert!(
                a.parse::<f64>().unwrap() >= lo && b.parse::<f64>().unwrap() <= hi,
                "{text}"
            );
        }
    }

    #[test]
    fn echoed_numbers_are_plain_when_short_and_exponential_when_long() {
        let shown = |x: f64| Compact(x).to_string();
        assert_eq!(shown(-1.0), "-1");
        assert_eq!(shown(600.0), "600");
        assert_eq!(shown(0.3), "0.3");
        assert_eq!(shown(100_000.0), "100000");
        assert_eq!(shown(123_456_789.0), "123456789");
        assert_eq!(shown(1e6), "1e6");
        assert_eq!(shown(1e-5), "0.00001");
        assert_eq!(shown(1e-6), "1e-6");
        assert_eq!(shown(-1e308), "-1e308");
        assert_eq!(shown(f64::MAX), "1.7976931348623157e308");
        assert_eq!(shown(5e-324), "5e-324");
        assert_eq!(shown(f64::NAN), "NaN");
        assert_eq!(shown(f64::NEG_INFINITY), "-inf");
        // Round trip: what is shown parses back to the same number.
        for x in [1e308, -2.5e-17, 0.1 + 0.2, 7.0 / 3.0, 1e21, 123.456e10] {
            assert_eq!(shown(x).parse::<f64>().unwrap(), x, "{x}");
            assert!(shown(x).len() <= 24, "{}", shown(x));
        }
    }

    #[test]
    fn messages_print_huge_and_tiny_numbers_in_exponent_form() {
        assert_eq!(bound(-3.0), "-3");
        assert_eq!(bound(0.7), "0.7");
        assert_eq!(bound(123_456.5), "123456.5");
        assert_eq!(bound(1e6), "1e6");
        assert_eq!(bound(1.25e-7), "1.25e-7");
        assert_eq!(bound(1e308), "1e308");
        assert_eq!(bound(0.0), "0");
        assert_eq!(bound(f64::NEG_INFINITY), "-inf");
    }

    #[test]
    fn numbers_refuse_nan_and_infinities() {
        assert_eq!(parse_number("1e6"), Some(1e6));
        assert!(parse_number("-0").unwrap().is_sign_positive());
        assert_eq!(parse_number("NaN"), None);
        assert_eq!(parse_number("inf"), None);
        assert_eq!(parse_number("-Infinity"), None);
        assert_eq!(parse_number("abc"), None);
    }
}
