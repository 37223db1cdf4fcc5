//! `g` and `G`: parameters kept for comparison, drawn on every chart of their problem.

use super::{App, Pin};
use crate::chart::pins;

impl App {
    /// `g`: keeps the current parameters as a pin (the oldest goes beyond [`pins::MAX_PINS`]).
    pub(super) fn pin(&mut self) {
        if self.y_key().is_none() {
            return self.error("g: a table has no curves to pin; pins show on every chart (c)");
        }
        if self.model().is_none() {
            return self.error("g: the parameters are not valid, nothing to pin");
        }
        let inputs = self.inputs();
        let kind = self.kind;
        let state = self.state_mut();
        if let Some(pin) = state.pins.iter().find(|p| p.inputs == inputs) {
            let number = pin.number;
            return self.info(format!("these values are pin {number} already"));
        }
        let dropped = if state.pins.len() >= pins::MAX_PINS {
            Some(state.pins.remove(0).number)
        } else {
            None
        };
        let number = (1..=pins::MAX_PINS as u8)
            .find(|n| state.pins.iter().all(|p| p.number != *n))
            .unwrap_or(1);
        state.pins.push(Pin {
            number,
            inputs,
            chart: None,
        });
        self.recompute();
        let replaced = dropped.map_or(String::new(), |n| {
            format!(
                " (replaces pin {n}, the oldest: at most {})",
                pins::MAX_PINS
            )
        });
        self.info(format!(
            "pin {number}{replaced}: drawn as {number}s on every {kind} chart; change a value to \
             compare, G clears"
        ));
    }
    /// `G`: removes every pin of the active model.
    pub(super) fn clear_pins(&mut self) {
        let count = std::mem::take(&mut self.state_mut().pins).len();
        if count == 0 {
            return self.info("no pins to clear (g pins the curves)");
        }
        self.recompute();
        self.info(format!("{count} pin(s) cleared"));
    }
}
