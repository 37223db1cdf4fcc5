//! The header a deck starts with: a comment block a person reads (what the deck is, how to run it,
//! the closed-form values expected) and one machine-readable line that `microslip compare` reads
//! back, so that FE results are compared with the parameters that produced them.

use std::fmt::Write as _;

use super::deck::DeckMesh;
use super::face::deck_face;
use crate::Model;
use crate::kernel::params::{Compact, parse_number};
use crate::problems::inputs::Inputs;
use crate::problems::{ModelKind, Param};

/// The prefix of the machine-readable header line.
pub(crate) const HEADER_PREFIX: &str = "** microslip-deck:";

/// Which stick slope the deck gives CalculiX.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum StickSlope {
    /// The model's K_T: the regularized law as the closed forms assume it.
    #[default]
    Model,
    /// A stiff slope that makes the boundary layer a tenth of the beam's half-height h (1/k = h/10,
    /// K_T = 25 E / h) or of the plate's thickness (1/alpha = t_p/10): the plain Coulomb law to
    /// within what the mesh resolves, without the convergence trouble of a huge penalty.
    NearCoulomb,
}

impl StickSlope {
    /// The name in the header line.
    pub(crate) fn name(self) -> &'static str {
        match self {
            StickSlope::Model => "model",
            StickSlope::NearCoulomb => "near-coulomb",
        }
    }
}

/// What a deck was made from. `inputs` holds the stick slope actually written as K_T, so the closed
/// forms built from it are the ones the FE run should reproduce.
#[derive(Debug, Clone, PartialEq)]
pub struct DeckHeader {
    /// The parameters (K_T = the deck's stick slope; F = the last load for the beams).
    pub inputs: Inputs,
    /// Tip forces of the load steps (N), beams only.
    pub loads: Vec<f64>,
    /// The mesh.
    pub mesh: DeckMesh,
    /// Where the stick slope came from.
    pub stick_slope: StickSlope,
    /// Poisson ratio of the material (-); the plate's nu for the plate.
    pub poisson: f64,
}

/// A header line that cannot be read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("line {line}: {message}")]
pub struct HeaderError {
    /// 1-based line.
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

impl DeckHeader {
    /// The model the header describes, validated.
    ///
    /// # Errors
    /// A parameter out of its domain (a header edited by hand).
    pub fn model(&self) -> Result<Model, crate::ParamError> {
        self.inputs.validate()
    }

    /// The comment block that opens the deck.
    pub(crate) fn to_comment(&self) -> String {
        let kind = self.inputs.kind();
        let face = deck_face(kind);
        let source = face.source();
        let mut text = format!(
            "** microslip {}: CalculiX (ccx 2.20) deck for the {}{source}\n",
            env!("CARGO_PKG_VERSION"),
            kind.description().title,
        );
        text.push_str(&self.machine_line());
        text.push('\n');
        let job = kind.name();
        let compare = format!("microslip compare {job} JOB.dat");
        let _ = writeln!(
            text,
            "** Units: mm, N, MPa; stick slope K_T in MPa/mm.\n\
             ** Run it:      ccx -i JOB        (this file saved as JOB.inp)\n\
             ** Compare it:  {compare}"
        );
        if let Some(expected) = face.expected(self) {
            text.push_str(&expected);
        }
        text
    }

    /// The machine-readable line: `** microslip-deck: model=.. mesh=.. stick-slope=.. nu=..` then
    /// every parameter as KEY=VALUE (shortest round-trip digits) and, for the beams, `F=F1,F2,..`.
    fn machine_line(&self) -> String {
        let kind = self.inputs.kind();
        let mut line = format!(
            "{HEADER_PREFIX} model={} mesh={} stick-slope={} nu={:?}",
            kind.name(),
            self.mesh.name(),
            self.stick_slope.name(),
            self.poisson
        );
        let load = kind.description().load;
        for &param in kind.params() {
            // The load is the list of load steps below; nu is `nu=` above.
            if Some(param) == load || is_poisson(param) {
                continue;
            }
            if let Some(value) = self.inputs.get(param) {
                let _ = write!(line, " {}={value:?}", param.name());
            }
        }
        if let Some(load) = load {
            let loads: Vec<String> = self.loads.iter().map(|f| format!("{f:?}")).collect();
            let _ = write!(line, " {}={}", load.name(), loads.join(","));
        }
        line
    }

    /// Reads the header line of a deck, if `text` has one, and validates it as a preset is
    /// validated: every parameter in its domain (same messages), every key known and given once,
    /// the loads of a beam deck forces in their domain, increasing. A byte-order mark or spaces
    /// before the line do not hide it (an editor may add them).
    ///
    /// # Errors
    /// [`HeaderError`] with the line number when the line is there but malformed.
    pub fn parse(text: &str) -> Result<Option<DeckHeader>, HeaderError> {
        let Some((index, line)) = text.lines().enumerate().find_map(|(i, l)| {
            let l = l.trim_start_matches('\u{feff}').trim_start();
            l.starts_with(HEADER_PREFIX).then_some((i, l))
        }) else {
            return Ok(None);
        };
        let fail = |message: String| HeaderError {
            line: index + 1,
            message,
        };
        let mut fields = std::collections::BTreeMap::new();
        for field in line[HEADER_PREFIX.len()..].split_whitespace() {
            let (key, value) = field
                .split_once('=')
                .ok_or_else(|| fail(format!("'{field}' is not KEY=VALUE")))?;
            if fields.insert(key, value).is_some() {
                return Err(fail(format!("'{key}=' is given twice")));
            }
        }
        let take = |key: &str| {
            fields
                .get(key)
                .copied()
                .ok_or_else(|| fail(format!("'{key}=' is missing")))
        };
        let number_of = |key: &str, text: &str| {
            parse_number(text).ok_or_else(|| fail(format!("{key} = '{text}' is not a number")))
        };
        let kind: ModelKind = take("model")?
            .parse()
            .map_err(|e: crate::problems::UnknownModel| fail(e.to_string()))?;
        let mesh = take("mesh")?;
        let mesh = DeckMesh::from_name(mesh)
            .ok_or_else(|| fail(format!("mesh = '{mesh}': expected coarse, fine or finest")))?;
        let stick_slope = match take("stick-slope")? {
            "model" => StickSlope::Model,
            "near-coulomb" => StickSlope::NearCoulomb,
            other => {
                return Err(fail(format!(
                    "stick-slope = '{other}': expected model or near-coulomb"
                )));
            }
        };
        // `nu` is every deck's material's, a parameter of the problem or not (the lap joint's
        // closed forms have none).
        let mut known: Vec<&str> = ["model", "mesh", "stick-slope"]
            .into_iter()
            .chain(kind.params().iter().map(|p| p.name()))
            .collect();
        if !known.contains(&"nu") {
            known.push("nu");
        }
        if let Some(unknown) = fields.keys().find(|k| !known.contains(k)) {
            return Err(fail(format!(
                "unknown key '{unknown}' in a {} deck's header (known: {})",
                kind.name(),
                known.join(", ")
            )));
        }
        let poisson = number_of("nu", take("nu")?)?;
        let mut inputs = Inputs::paper(kind);
        let load = kind.description().load;
        for &param in kind.params() {
            if Some(param) == load {
                continue;
            }
            let value = if is_poisson(param) {
                poisson
            } else {
                number_of(param.name(), take(param.name())?)?
            };
            inputs.set(param, value).map_err(|e| fail(e.to_string()))?;
        }
        let mut loads: Vec<f64> = Vec::new();
        if let Some(load) = load {
            let (key, spec) = (load.name(), load.spec());
            for text in take(key)?.split(',') {
                let force = number_of(key, text)?;
                spec.domain
                    .check(key, force, spec.unit)
                    .map_err(|e| fail(e.to_string()))?;
                if let Some(&previous) = loads.last()
                    && force <= previous
                {
                    return Err(fail(format!(
                        "{key} = {}: the loads must increase from one step to the next (after {})",
                        Compact(force),
                        Compact(previous)
                    )));
                }
                loads.push(force);
            }
            inputs
                .set(load, *loads.last().unwrap_or(&0.0))
                .map_err(|e| fail(e.to_string()))?;
        }
        let header = DeckHeader {
            inputs,
            loads,
            mesh,
            stick_slope,
            poisson,
        };
        header.model().map_err(|e| fail(e.to_string()))?;
        Ok(Some(header))
    }
}

/// True for a problem's Poisson ratio: the header writes it once as `nu=` (a deck needs one for
/// its continuum elements even where the problem has none of its own).
fn is_poisson(param: Param) -> bool {
    param.name() == "nu"
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{PlateParams, SqueezedPlate, TipForce, TwinBeams, TwinBeamsParams};

    #[test]
    fn beam_header_reads_back_what_was_written() {
        let beams = TwinBeams::new(TwinBeamsParams {
            tangential_stiffness: 123.456789,
            poisson: 0.27,
            ..TwinBeamsParams::PAPER
        })
        .unwrap();
        let loads = [1e-3, 40.0, 100.5].map(|f| TipForce::new(f).unwrap());
        let header = crate::problems::twin_beams::deck::header(
            &beams,
            &loads,
            DeckMesh::Fine,
            StickSlope::Model,
        );
        let parsed = DeckHeader::parse(&header.to_comment()).unwrap().unwrap();
        assert_eq!(parsed, header);
    }

    #[test]
    fn a_timoshenko_preset_expects_the_shear_deflection_once() {
        use crate::problems::twin_beams::closed_form::BeamTheory;
        let euler = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let timoshenko = euler.with_theory(BeamTheory::Timoshenko);
        let loads = [TipForce::new(40.0).unwrap()];
        let text = |b: &TwinBeams| {
            let h = crate::problems::twin_beams::deck::header(
                b,
                &loads,
                DeckMesh::Coarse,
                StickSlope::Model,
            );
            deck_face(h.inputs.kind()).expected(&h).unwrap()
        };
        // w(L) regularized at 40 N (stick): 0.011121 mm Euler-Bernoulli, + shear 2.97e-4 mm.
        let expected = text(&timoshenko);
        assert_eq!(expected, text(&euler));
        let row = expected.lines().nth(3).unwrap();
        let w: Vec<f64> = row
            .split('|')
            .skip(1)
            .take(3)
            .map(|c| c.trim().parse().unwrap())
            .collect();
        assert!((w[1] - 0.011121).abs() < 1e-6, "{row}");
        assert!((w[2] - w[1] - 2.97e-4).abs() < 1e-6, "{row}");
    }

    #[test]
    fn near_coulomb_header_records_the_stiff_slope() {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let header = crate::problems::twin_beams::deck::header(
            &beams,
            &[TipForce::new(40.0).unwrap()],
            DeckMesh::Coarse,
            StickSlope::NearCoulomb,
        );
        // 1/k = h/10 with k = 2 sqrt(K_T / (E h)): K_T = 25 E / h.
        let Model::Beam(crate::problems::twin_beams::problem::BeamsModel { beams: stiff, .. }) =
            header.model().unwrap()
        else {
            panic!("a beam header")
        };
        assert!((1.0 / stiff.decay_rate() - 1.0).abs() < 1e-12);
        let parsed = DeckHeader::parse(&header.to_comment()).unwrap().unwrap();
        assert_eq!(parsed.stick_slope, StickSlope::NearCoulomb);
    }

    #[test]
    fn plate_header_reads_back_and_states_the_expected_values() {
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let header =
            crate::problems::plate::deck::header(&plate, DeckMesh::Coarse, StickSlope::Model);
        let text = header.to_comment();
        assert_eq!(DeckHeader::parse(&text).unwrap().unwrap(), header);
        assert!(text.contains("u(L) regularized 9.459"), "{text}");
    }

    /// A header edited by hand is validated like a preset (it used to accept negative and
    /// reversed loads, unknown and repeated keys, and to compare at F = 1e400 against 1e12).
    #[test]
    fn an_edited_header_is_refused_like_a_preset() {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let loads = [40.0, 60.0].map(|f| TipForce::new(f).unwrap());
        let good = crate::problems::twin_beams::deck::header(
            &beams,
            &loads,
            DeckMesh::Coarse,
            StickSlope::Model,
        )
        .to_comment();
        let edit = |from: &str, to: &str| {
            assert!(good.contains(from), "{from}");
            DeckHeader::parse(&good.replacen(from, to, 1))
                .unwrap_err()
                .to_string()
        };
        assert_eq!(
            edit("F=40.0,60.0", "F=-5,60"),
            "line 2: invalid F = -5: must be >= 0 and finite (N)"
        );
        assert_eq!(
            edit("F=40.0,60.0", "F=1e400,60"),
            "line 2: invalid F = (a number beyond 1.8e308): must be in [0, 1e12] N"
        );
        assert_eq!(
            edit("F=40.0,60.0", "F=60,40"),
            "line 2: F = 40: the loads must increase from one step to the next (after 60)"
        );
        assert_eq!(
            edit("F=40.0,60.0", "F=40,40"),
            "line 2: F = 40: the loads must increase from one step to the next (after 40)"
        );
        assert_eq!(edit(" mu=", " mu=0.2 mu="), "line 2: 'mu=' is given twice");
        assert!(
            edit(" mu=", " colour=red mu=")
                .starts_with("line 2: unknown key 'colour' in a beam deck's header (known:"),
        );
        assert_eq!(
            edit(" KT=600.0", " KT=1e13"),
            "line 2: invalid KT = 1e13: must be in [1e-6, 1e12] MPa/mm"
        );
        // A byte-order mark or indentation does not hide the header.
        let marked = format!(
            "\u{feff}{}",
            good.replacen("** microslip-deck:", "   ** microslip-deck:", 1)
        );
        let header = DeckHeader::parse(&marked).unwrap().unwrap();
        assert_eq!(header.loads, [40.0, 60.0]);
    }

    #[test]
    fn a_broken_header_names_its_line_and_field() {
        let text = "** other\n** microslip-deck: model=beam mesh=coarse stick-slope=model nu=0.3 \
                    L=200 b=20 h=ten E=1 P=1 mu=0.3 KT=1 F=1";
        let error = DeckHeader::parse(text).unwrap_err();
        assert_eq!(error.to_string(), "line 2: h = 'ten' is not a number");
        let missing = "** microslip-deck: model=plate mesh=coarse stick-slope=model nu=0.3";
        assert_eq!(
            DeckHeader::parse(missing).unwrap_err().message,
            "'L=' is missing"
        );
        assert_eq!(DeckHeader::parse("no header here").unwrap(), None);
        let negative = "** microslip-deck: model=plate mesh=coarse stick-slope=model nu=0.3 \
                        L=-1 tp=0.2 E=7e4 mu=0.3 P=10 KT=1e6";
        assert!(
            DeckHeader::parse(negative)
                .unwrap_err()
                .message
                .starts_with("invalid L = -1")
        );
    }
}
