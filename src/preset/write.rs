//! Writing presets: the TOML text the TUI saves, every parameter with its meaning and unit in a
//! comment, so that a saved file documents itself and parses back to the same inputs.

use std::fmt::Write;

use crate::problems::inputs::Inputs;

/// A preset file's text for `inputs`: every key, with units in comments.
pub fn to_toml(inputs: &Inputs, description: &str) -> String {
    let mut text = String::from("# microslip preset. Units: mm, N, MPa; KT in MPa/mm.\n");
    let _ = writeln!(text, "description = {}", toml::Value::from(description));
    let _ = writeln!(text, "model = \"{}\"", inputs.kind().name());
    // The settings that take a name (the beams' theory), before the numbers.
    for choice in inputs.kind().problem().faces().choices {
        if let Some(value) = choice.get(inputs) {
            let _ = writeln!(
                text,
                "{} = \"{value}\"  # {}",
                choice.key(),
                choice.comment()
            );
        }
    }
    for &param in inputs.kind().params() {
        let spec = param.spec();
        // `get` cannot miss: the parameters come from the inputs' own model.
        let value = inputs.get(param).unwrap_or(f64::NAN);
        let _ = writeln!(
            text,
            "{} = {value:?}  # {} ({})",
            spec.name, spec.meaning, spec.unit
        );
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::preset::{Preset, PresetSource};
    use crate::problems::ModelKind;

    #[test]
    fn written_text_parses_back_to_the_same_inputs() {
        for kind in ModelKind::ALL {
            let mut inputs = Inputs::paper(kind);
            for (i, &param) in kind.params().iter().enumerate() {
                let value = inputs.get(param).unwrap() * (1.0 + 0.01 * i as f64) / 3.0;
                inputs.set(param, value).unwrap();
            }
            // The lap joint's force must stay within its (now smaller) F_gross: 37 % of it, an
            // odd number that still round-trips.
            if let Some(load) = kind.description().load {
                inputs.set(load, 0.0).unwrap();
                let scale = inputs.validate().unwrap().regime_scale().unwrap();
                inputs.set(load, 0.37 * scale).unwrap();
            }
            let text = to_toml(&inputs, "a \"quoted\" description");
            let back = Preset::parse(&text, "x", PresetSource::Bundled).unwrap();
            assert_eq!(back.inputs, inputs);
            assert_eq!(back.description, "a \"quoted\" description");
        }
    }
}
