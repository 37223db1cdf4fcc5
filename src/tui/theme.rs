//! Colours, characters and the choices that keep the TUI readable over any terminal: a 16-colour
//! palette, `NO_COLOR`, and an ASCII-only character set.

use ratatui::style::{Color, Modifier, Style};
use ratatui::symbols::border;

use crate::chart::SeriesRole;
use crate::study::curves::Zone;

/// Which characters may be drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Charset {
    /// Box drawing, Braille curves.
    Unicode,
    /// 7-bit ASCII only (old terminals, odd fonts, logs).
    Ascii,
}

/// What an element of the screen is, so that styles are chosen in one place.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    /// Pane titles.
    Title,
    /// The selected row.
    Selected,
    /// Units and secondary text.
    Muted,
    /// Error messages.
    Error,
    /// Informational messages.
    Info,
    /// The cursor line on charts.
    Cursor,
    /// A regime name.
    Regime,
}

/// Character set and colour choice.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Theme {
    /// Character set.
    pub charset: Charset,
    /// False when `NO_COLOR` is set (or colour is off).
    pub color: bool,
}

/// Family members' colours, from the 16-colour palette that every terminal has.
const FAMILY_COLORS: [Color; 6] = [
    Color::Yellow,
    Color::Cyan,
    Color::Green,
    Color::Magenta,
    Color::LightRed,
    Color::LightBlue,
];
/// Pinned curves are drawn with their number; their colours are set apart from the series'.
const PIN_SYMBOLS: [&str; 4] = ["1", "2", "3", "4"];
const PIN_COLORS: [Color; 4] = [
    Color::White,
    Color::LightMagenta,
    Color::LightCyan,
    Color::LightGreen,
];
/// Family members are drawn with a letter (they never share a chart with pins).
const FAMILY_SYMBOLS: [&str; 6] = ["a", "b", "c", "d", "e", "f"];

impl Theme {
    /// Reads `NO_COLOR` (any non-empty value turns colour off, see no-color.org).
    pub fn from_env(charset: Charset) -> Self {
        let no_color = std::env::var_os("NO_COLOR").is_some_and(|v| !v.is_empty());
        Theme {
            charset,
            color: !no_color,
        }
    }

    /// Style of a role.
    pub fn style(&self, role: Role) -> Style {
        let base = Style::default();
        if !self.color {
            return match role {
                Role::Title | Role::Selected | Role::Error => base.add_modifier(Modifier::BOLD),
                _ => base,
            };
        }
        match role {
            Role::Title => base.fg(Color::Cyan).add_modifier(Modifier::BOLD),
            Role::Selected => base.fg(Color::Black).bg(Color::Cyan),
            Role::Muted => base.fg(Color::Gray),
            Role::Error => base.fg(Color::LightRed).add_modifier(Modifier::BOLD),
            Role::Info => base.fg(Color::Green),
            Role::Cursor => base.fg(Color::Gray),
            Role::Regime => base.fg(Color::Yellow),
        }
    }

    /// Style of a series of `role`: one colour per role on every chart (none without colour).
    pub fn series_style(&self, role: SeriesRole) -> Style {
        if !self.color {
            return Style::default();
        }
        let nth =
            |palette: &[Color], n: u8| palette[usize::from(n.saturating_sub(1)) % palette.len()];
        let colour = match role {
            SeriesRole::Current => Color::Cyan,
            SeriesRole::Coulomb => Color::Yellow,
            SeriesRole::Softer => Color::Green,
            SeriesRole::Stiffer => Color::Magenta,
            SeriesRole::Limit | SeriesRole::Cursor => Color::Gray,
            SeriesRole::FiniteElements => Color::LightRed,
            SeriesRole::Continuum => Color::LightBlue,
            SeriesRole::Measured => Color::LightYellow,
            SeriesRole::External => Color::Blue,
            SeriesRole::Pin(n) => nth(&PIN_COLORS, n),
            SeriesRole::Family(n) => nth(&FAMILY_COLORS, n),
        };
        Style::default().fg(colour)
    }

    /// True when curves must be told apart by their symbols, not their colours.
    pub fn symbol_mode(&self) -> bool {
        self.charset == Charset::Ascii || !self.color
    }

    /// The plotting symbol of a series of `role` in symbol mode: one per role on every chart, so
    /// that `x` is the current K_T's curve wherever it is drawn and `*` always Coulomb. The
    /// finite-element points (`#`) and the plate's continuum points (`@`) differ, as do measured
    /// (`%`) and external (`&`) points. A pinned curve is drawn with its number in every charset
    /// and colour mode, so the legend's `1 mu 0.3->0.2` and the curve's 1s match; a family
    /// member with its letter.
    pub fn series_symbol(&self, role: SeriesRole) -> &'static str {
        let nth = |symbols: &[&'static str], n: u8| {
            symbols[usize::from(n.saturating_sub(1)) % symbols.len()]
        };
        let ascii = self.charset == Charset::Ascii;
        match role {
            SeriesRole::Current if ascii => "x",
            SeriesRole::Current => "×",
            SeriesRole::Coulomb if ascii => "*",
            SeriesRole::Coulomb => "•",
            SeriesRole::Softer => "o",
            SeriesRole::Stiffer => "+",
            SeriesRole::Limit if ascii => "-",
            SeriesRole::Limit => "╌",
            SeriesRole::FiniteElements if ascii => "#",
            SeriesRole::FiniteElements => "■",
            SeriesRole::Continuum if ascii => "@",
            SeriesRole::Continuum => "◆",
            SeriesRole::Measured if ascii => "%",
            SeriesRole::Measured => "▲",
            SeriesRole::External if ascii => "&",
            SeriesRole::External => "▼",
            SeriesRole::Cursor => self.cursor_symbol(),
            SeriesRole::Pin(n) => nth(&PIN_SYMBOLS, n),
            SeriesRole::Family(n) => nth(&FAMILY_SYMBOLS, n),
        }
    }

    /// The cursor line's symbol.
    pub fn cursor_symbol(&self) -> &'static str {
        match self.charset {
            Charset::Ascii => "|",
            Charset::Unicode => "│",
        }
    }

    /// The zone strip's symbol of a zone: the same shapes in both charsets, so that the ASCII
    /// legend (`=` stick, `~` microslip, `#` macroslip) reads the same as the Unicode one.
    pub fn zone_symbol(&self, zone: Zone) -> &'static str {
        match (self.charset, zone) {
            (Charset::Ascii, Zone::Stick) => "=",
            (Charset::Ascii, Zone::Microslip) => "~",
            (Charset::Ascii, Zone::Macroslip) => "#",
            (Charset::Ascii, Zone::Unloaded) => "-",
            (Charset::Unicode, Zone::Stick) => "═",
            (Charset::Unicode, Zone::Microslip) => "≈",
            (Charset::Unicode, Zone::Macroslip) => "█",
            (Charset::Unicode, Zone::Unloaded) => "─",
        }
    }

    /// The zone strip's colour of a zone (none without colour: the symbols tell them apart).
    pub fn zone_style(&self, zone: Zone) -> Style {
        if !self.color {
            return Style::default();
        }
        let colour = match zone {
            Zone::Stick => Color::Green,
            Zone::Microslip => Color::Yellow,
            Zone::Macroslip => Color::LightRed,
            Zone::Unloaded => Color::Gray,
        };
        Style::default().fg(colour)
    }

    /// Sparkline levels from 0 to full, none of them a zone symbol.
    pub fn spark_levels(&self) -> &'static [&'static str] {
        match self.charset {
            Charset::Ascii => &[" ", ".", ":", ";", "+", "*", "%", "@"],
            Charset::Unicode => &[" ", "▁", "▂", "▃", "▄", "▅", "▆", "▇", "█"],
        }
    }

    /// Border characters.
    pub fn border_set(&self) -> border::Set<'static> {
        match self.charset {
            Charset::Unicode => border::PLAIN,
            Charset::Ascii => border::Set {
                top_left: "+",
                top_right: "+",
                bottom_left: "+",
                bottom_right: "+",
                vertical_left: "|",
                vertical_right: "|",
                horizontal_top: "-",
                horizontal_bottom: "-",
            },
        }
    }
}

/// ASCII stand-in for a symbol that ratatui widgets draw on their own (chart axes, Braille):
/// box-drawing lines become `|`, `-` or `+`; anything else non-ASCII becomes `*`.
pub fn ascii_fallback(symbol: &str) -> &'static str {
    match symbol {
        "│" | "┃" | "║" | "╎" | "┆" => "|",
        "─" | "━" | "═" | "╌" | "┄" => "-",
        "└" | "┘" | "┌" | "┐" | "├" | "┤" | "┬" | "┴" | "┼" | "╭" | "╮" | "╰" | "╯" => {
            "+"
        }
        _ => "*",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ascii_theme_draws_only_ascii() {
        let theme = Theme {
            charset: Charset::Ascii,
            color: true,
        };
        let set = theme.border_set();
        for s in [
            set.top_left,
            set.vertical_left,
            set.horizontal_top,
            theme.cursor_symbol(),
        ] {
            assert!(s.is_ascii());
        }
        let roles = SeriesRole::CHART_ROLES
            .into_iter()
            .chain((1..=4).map(SeriesRole::Pin))
            .chain((1..=6).map(SeriesRole::Family));
        let mut seen = std::collections::HashSet::new();
        for role in roles {
            let symbol = theme.series_symbol(role);
            assert!(symbol.is_ascii(), "{role:?}");
            assert!(seen.insert(symbol), "{role:?}: {symbol} taken twice");
        }
        assert_eq!(ascii_fallback("└"), "+");
        assert_eq!(ascii_fallback("⣿"), "*");
    }

    #[test]
    fn no_color_uses_no_colours() {
        let theme = Theme {
            charset: Charset::Unicode,
            color: false,
        };
        for role in [Role::Title, Role::Selected, Role::Error, Role::Cursor] {
            assert_eq!(theme.style(role).fg, None);
            assert_eq!(theme.style(role).bg, None);
        }
        assert!(theme.symbol_mode());
    }
}
