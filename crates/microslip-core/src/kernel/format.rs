//! Numbers for people, shared by every output (reports, deck headers, the TUI): the lowest layer,
//! so that a deck's header and a report print the same value the same way.

/// A number for people: 6 significant digits, plain notation between 1e-3 and 1e6, exponent outside,
/// trailing zeros dropped. Never prints NaN: a non-finite value (which the core does not produce)
/// shows as "n/a".
pub fn number(x: f64) -> String {
    number_with(x, 6)
}

/// [`number`] with `digits` significant digits (at least 1); charts use 3 for tick labels.
pub fn number_with(x: f64, digits: u32) -> String {
    let digits = digits.max(1) as i32;
    if !x.is_finite() {
        return "n/a".to_string();
    }
    if x == 0.0 {
        return "0".to_string();
    }
    let magnitude = x.abs();
    if (1e-3..1e6).contains(&magnitude) {
        let decimals = (digits - 1 - magnitude.log10().floor() as i32).max(0) as usize;
        let text = format!("{x:.decimals$}");
        if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            text
        }
    } else {
        let text = format!("{x:.*e}", (digits - 1) as usize);
        match text.split_once('e') {
            Some((mantissa, exponent)) if mantissa.contains('.') => {
                format!(
                    "{}e{exponent}",
                    mantissa.trim_end_matches('0').trim_end_matches('.')
                )
            }
            _ => text,
        }
    }
}
