//! The press fit's FE deck ([`Deck`]): the axisymmetric CalculiX deck (`deck_writer.rs` says
//! what it models and why), the header it carries, the closed-form values it should reproduce,
//! its results (`ccx_read.rs`) and their comparison (`compare.rs`).

use std::fmt::Write as _;

use crate::fe::deck::{DeckMesh, DeckTooLarge};
use crate::fe::face::{Deck, DeckError, DeckRequest};
use crate::fe::header::{DeckHeader, StickSlope};
use crate::fe::results::{CcxRun, ResultsError};
use crate::fe::verdict::InterfaceMesh;
use crate::kernel::format::number;
use crate::kernel::params::{Domain, ParamError, Unit};
use crate::problems::Problem;

use super::ccx_read::{FIT_CURVE, PressFitFePoint, fit_points, fit_points_from_csv};
use super::closed_form::{CarriedLoad, PressFit};
use super::compare::PressFitCompared;
use super::deck_writer::{CAPACITY_PUSH, FitDeckInputs, Layout, fit_deck, sets};
use super::registered::problem::{PressFitInputs, PressFitModel, PressFitProblem};

/// The default load steps, as fractions of F_gross: the two loads (all microslip on the
/// #98 fit, and one face sliding).
pub const DEFAULT_LOADS: [f64; 2] = [0.3, 0.8];
/// The default largest force change per increment, as a fraction of F_gross (docs/theory.md
/// section 18, "CalculiX": halving it moved Delta and the capacity by the amounts measured
/// there).
pub const DEFAULT_STEP: f64 = 1.0 / 40.0;

/// The stick slope (MPa/mm) a deck of `fit` gives CalculiX: the model's K_T, or near Coulomb
/// the interface's decay length 1/lambda a tenth of the thinner wall (lambda^2 = w K_T (1/(Es
/// As) + 1/(Eh Ah)), docs/theory.md (S4)), as the lap joint's deck resolves its own.
pub fn stick_slope_of(stick_slope: StickSlope, fit: &PressFit) -> f64 {
    let p = fit.params();
    match stick_slope {
        StickSlope::Model => p.tangential_stiffness,
        StickSlope::NearCoulomb => {
            let wall = (p.fit_radius - p.bore_radius).min(p.outer_radius - p.fit_radius);
            let decay = 0.1 * wall;
            let compliance =
                1.0 / (p.shaft_modulus * p.shaft_area()) + 1.0 / (p.hub_modulus * p.hub_area());
            1.0 / (decay * decay * p.interface_width() * compliance)
        }
    }
}

/// `fit` at the deck's stick slope.
fn at_slope(fit: &PressFit, stick_slope: StickSlope) -> PressFit {
    fit.with_tangential_stiffness(stick_slope_of(stick_slope, fit))
        .unwrap_or(*fit)
}

/// The header of a press fit deck: K_T is the deck's stick slope, F the last load.
pub fn header(
    fit: &PressFit,
    loads: &[CarriedLoad],
    mesh: DeckMesh,
    stick_slope: StickSlope,
) -> DeckHeader {
    let mut structure = fit.params();
    structure.tangential_stiffness = stick_slope_of(stick_slope, fit);
    DeckHeader {
        inputs: PressFitProblem::to_inputs(PressFitInputs {
            structure,
            force: loads.last().map_or(0.0, |f| f.value()),
        }),
        loads: loads.iter().map(|f| f.value()).collect(),
        mesh,
        stick_slope,
        poisson: structure.shaft_poisson,
    }
}

/// The deck of `fit`: the interference, one step per load of `loads`, in increments of at most
/// `force_step` N (default F_gross / 40), and the capacity step, on `mesh`.
///
/// # Errors
/// [`DeckTooLarge`] (a fit many decay lengths long on the fine mesh).
pub fn write_fit_deck(
    fit: &PressFit,
    loads: &[CarriedLoad],
    mesh: DeckMesh,
    stick_slope: StickSlope,
    force_step: Option<f64>,
) -> Result<String, DeckTooLarge> {
    let refinement = mesh.refinement();
    let sloped = at_slope(fit, stick_slope);
    let layout = Layout::at(
        refinement,
        fit.params().length * sloped.axial().decay_rate(),
    );
    write_laid_out_deck(fit, loads, mesh, layout, stick_slope, force_step)
}

/// The deck of `fit` on `layout` (its header names `mesh`).
fn write_laid_out_deck(
    fit: &PressFit,
    loads: &[CarriedLoad],
    mesh: DeckMesh,
    layout: Layout,
    stick_slope: StickSlope,
    force_step: Option<f64>,
) -> Result<String, DeckTooLarge> {
    let p = fit.params();
    let sloped = at_slope(fit, stick_slope);
    let gross = sloped.axial().clamped(sloped.gross_slip_force());
    let inputs = FitDeckInputs {
        radii: [p.fit_radius, p.bore_radius, p.outer_radius],
        length: p.length,
        shaft: (p.shaft_modulus, p.shaft_poisson),
        hub: (p.hub_modulus, p.hub_poisson),
        interference: p.interference,
        friction: p.friction,
        stick_slope: stick_slope_of(stick_slope, fit),
        push: CAPACITY_PUSH * sloped.regularized(gross).response(),
    };
    let newtons: Vec<f64> = loads.iter().map(|f| f.value()).collect();
    fit_deck(
        &inputs,
        &newtons,
        layout,
        force_step.unwrap_or(DEFAULT_STEP * fit.gross_slip_force()),
        &header(fit, loads, mesh, stick_slope).to_comment(),
    )
}

/// The forces of a press fit deck's steps: `loads` (increasing, each at most F_gross), or 0.3
/// and 0.8 F_gross.
fn deck_loads(fit: &PressFit, loads: Option<&[f64]>) -> Result<Vec<CarriedLoad>, DeckError> {
    let Some(loads) = loads else {
        return Ok(DEFAULT_LOADS
            .iter()
            .map(|f| fit.axial().clamped(f * fit.gross_slip_force()))
            .collect());
    };
    DeckError::increasing_loads(loads, |f| fit.force(f))
}

impl Deck for PressFitProblem {
    const SOURCE: &'static str = " (docs/theory.md section 18; CalculiX issue #98's fit)";
    const INTERFACE_SET: &'static str = sets::SHAFT_FACE;
    type FePoint = PressFitFePoint;
    type Compared = Result<Vec<PressFitCompared>, ParamError>;

    fn expected(model: &PressFitModel, header: &DeckHeader) -> String {
        let fit = &model.fit;
        let mut text = format!(
            "** Expected from the closed forms (Lamé and the shear lag, docs/theory.md section 18):\n\
             **   p = {} MPa (plane stress; plane strain {} MPa)\n\
             **   F_1 = {} N, sliding first at {}; F_2 = {} N; F_gross = mu p 2 pi r L = {} N\n\
             **   F (N) | Delta Coulomb (mm) | Delta regularized (mm) | a from x = 0 (mm) | d from \
             x = L (mm) | regime\n",
            number(fit.contact_pressure()),
            number(fit.plane_strain_pressure()),
            number(fit.first_slip_force()),
            fit.first_slip_face().label(),
            number(fit.second_slip_force()),
            number(fit.gross_slip_force()),
        );
        for &f in &header.loads {
            // One solve per load step: a caller that cancels the deck stops here.
            crate::numeric::cancel::checkpoint();
            let force = fit.axial().clamped(f);
            let state = fit.regularized(force);
            let _ = writeln!(
                text,
                "**   {} | {} | {} | {} | {} | {}",
                number(f),
                number(fit.coulomb(force).response()),
                number(state.response()),
                number(state.slide_from_loaded_face()),
                number(state.slide_from_held_face()),
                state.regime().label()
            );
        }
        text
    }

    fn ccx_points(
        run: &CcxRun,
        params: &PressFitInputs,
    ) -> Result<Vec<PressFitFePoint>, ResultsError> {
        fit_points(run, params)
    }

    /// None: the deck's CAX4 elements are linear, along the axis (the second coordinate), and
    /// the comparison counts no difference in elements.
    fn interface_mesh(_run: &CcxRun) -> Result<Option<InterfaceMesh>, ResultsError> {
        Ok(None)
    }

    const CSV_CURVE: crate::measured::Curve = FIT_CURVE;

    fn csv_points(text: &str) -> Result<Vec<PressFitFePoint>, ResultsError> {
        fit_points_from_csv(text)
    }

    fn compare(
        model: &PressFitModel,
        points: &[PressFitFePoint],
        _mesh: Option<&InterfaceMesh>,
    ) -> Result<Vec<PressFitCompared>, ParamError> {
        super::compare::compare(model, points)
    }

    /// The capacity and pressure tolerances were measured on linear-geometry runs (the deck's).
    fn without_envelope(compared: &mut Result<Vec<PressFitCompared>, ParamError>) {
        for row in compared.iter_mut().flatten() {
            row.judged = false;
            row.continuum = None;
        }
    }

    fn write_deck(model: &PressFitModel, request: &DeckRequest) -> Result<String, DeckError> {
        let fit = &model.fit;
        let loads = deck_loads(fit, request.loads)?;
        let force_step = request
            .increment
            .map(|f| DeckError::check("--increment", f, Domain::FORCE_STEP, Unit::Newton))
            .transpose()?;
        Ok(write_fit_deck(
            fit,
            &loads,
            request.mesh,
            request.slope,
            force_step,
        )?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fe::face::written_deck;
    use crate::problems::pressfit::deck_writer::{
        ASSEMBLY_FRICTION, NODE_SLAVE_PAIR, SURFACE_PAIR,
    };
    use crate::problems::pressfit::params::PressFitParams;

    fn ccx98() -> PressFitModel {
        PressFitProblem::model(&PressFitProblem::paper()).unwrap()
    }

    fn deck(mesh: DeckMesh) -> String {
        let request = DeckRequest {
            loads: None,
            mesh,
            slope: StickSlope::Model,
            increment: None,
        };
        written_deck::<PressFitProblem>(&ccx98(), &request).unwrap()
    }

    /// The lines of the card `card` (its data lines up to the next card).
    fn card<'a>(deck: &'a str, card: &str) -> Vec<&'a str> {
        deck.split(&format!("{card}\n"))
            .nth(1)
            .unwrap_or_default()
            .lines()
            .take_while(|l| !l.starts_with('*'))
            .collect()
    }

    #[test]
    fn the_deck_is_axisymmetric_with_its_sets_steps_and_friction() {
        let text = deck(DeckMesh::Coarse);
        let header = DeckHeader::parse(&text).unwrap().unwrap();
        let gross = ccx98().fit.gross_slip_force();
        assert_eq!(header.loads, [0.3 * gross, 0.8 * gross]);
        assert_eq!(header.model().unwrap().kind(), crate::ModelKind::PressFit);
        // CAX4 only: 40 x (8 + 8) elements on the coarse mesh.
        assert_eq!(text.matches("*ELEMENT, TYPE=CAX4").count(), 2);
        assert!(!text.contains("C3D20R"));
        assert_eq!(card(&text, "*ELEMENT, TYPE=CAX4, ELSET=SHAFT").len(), 320);
        assert_eq!(card(&text, "*ELEMENT, TYPE=CAX4, ELSET=HUB").len(), 320);
        // The friction of the model is mu, K_T (what the stick-slope reader takes), changed to
        // 1e-5 mu in step 1 and back in step 2.
        assert_eq!(
            crate::fe::stick_slope::friction_card(&text),
            Some((0.1, 1e4))
        );
        assert_eq!(
            text.matches("*CHANGE FRICTION, INTERACTION=JENKINS")
                .count(),
            2
        );
        let steps: Vec<&str> = text.split("*STEP").skip(1).collect();
        assert_eq!(steps.len(), 4, "interference, two loads, capacity");
        assert!(steps[0].contains(&format!(
            "*FRICTION\n{:.6e}, 10000.0",
            ASSEMBLY_FRICTION * 0.1
        )));
        assert!(steps[0].contains("*BOUNDARY\nSHAFTFIX, 2, 2"));
        assert!(steps[1].contains("*FRICTION\n0.1, 10000.0"));
        for step in &steps[1..] {
            assert!(
                step.contains("*BOUNDARY, OP=NEW\nHUBHELD, 2, 2\n"),
                "{step}"
            );
        }
        assert!(steps[3].contains("SHAFTEND, 2, 2, "));
        assert!(steps[3].contains("*DLOAD, OP=NEW"));
        for step in &steps {
            for set in [sets::SHAFT_END, sets::SHAFT_FACE, sets::HUB_FACE] {
                assert!(step.contains(&format!("*NODE PRINT, NSET={set}, FREQUENCY=100000\nU\n")));
            }
            assert!(
                step.contains("*NODE PRINT, NSET=HUBHELD, TOTALS=ONLY, FREQUENCY=100000\nRF\n")
            );
            assert!(step.contains("*CONTACT PRINT, FREQUENCY=100000\nCSTR\n"));
        }
        // The surface-to-surface pair is the deck's; the node slave is named for #98.
        assert!(text.contains(&format!("\n{SURFACE_PAIR}\n")));
        assert!(!text.contains(&format!("\n{NODE_SLAVE_PAIR}\n")));
        assert!(text.contains("*SURFACE, NAME=NSHAFT, TYPE=NODE\nIFSHAFT\n"));
        assert!(text.contains("PRESSURE-OVERCLOSURE=LINEAR"));
    }

    #[test]
    fn the_push_out_traction_adds_up_to_each_load() {
        let text = deck(DeckMesh::Coarse);
        let p = ccx98().fit.params();
        let area = std::f64::consts::PI
            * ((p.fit_radius + p.interference).powi(2) - p.bore_radius.powi(2));
        let gross = ccx98().fit.gross_slip_force();
        let steps: Vec<&str> = text.split("*STEP").skip(1).collect();
        for (step, fraction) in steps[1..3].iter().zip(DEFAULT_LOADS) {
            let rows: Vec<f64> = card(step, "*DLOAD")
                .iter()
                .map(|l| l.split(", ").nth(2).unwrap().parse().unwrap())
                .collect();
            assert_eq!(rows.len(), 8, "one face per radial element");
            assert!((rows[0] * area / (fraction * gross) - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn the_expected_lines_name_p_f1_f2_and_f_gross() {
        let model = ccx98();
        let text = deck(DeckMesh::Coarse);
        let expected = text
            .lines()
            .filter(|l| l.starts_with("**"))
            .collect::<Vec<_>>()
            .join("\n");
        assert!(expected.contains("p = 6.1523"), "{expected}");
        assert!(expected.contains("plane strain 6.7608"), "{expected}");
        assert!(expected.contains("F_1 = 970.7"), "{expected}");
        assert!(expected.contains("x = 0 (the shaft's loaded face)"));
        assert!(expected.contains("F_2 = 1227.8"), "{expected}");
        assert!(
            expected.contains("F_gross = mu p 2 pi r L = 1371"),
            "{expected}"
        );
        let at = model
            .fit
            .axial()
            .clamped(0.8 * model.fit.gross_slip_force());
        assert!(expected.contains(&number(model.fit.regularized(at).response())));
        assert!(expected.contains(&number(model.fit.coulomb(at).response())));
    }

    #[test]
    fn the_fine_mesh_doubles_the_elements_each_way_and_loads_are_checked() {
        let count = |t: &str| t.lines().filter(|l| l.ends_with(", S2")).count();
        assert_eq!(count(&deck(DeckMesh::Coarse)), 40);
        assert_eq!(count(&deck(DeckMesh::Fine)), 80);
        let fit = PressFit::new(PressFitParams::CCX98).unwrap();
        let refused = deck_loads(&fit, Some(&[500.0, 400.0])).unwrap_err();
        assert!(refused.to_string().contains("must increase"), "{refused}");
        let refused = deck_loads(&fit, Some(&[2000.0])).unwrap_err();
        assert!(refused.to_string().contains("F_gross"), "{refused}");
    }
}

#[cfg(test)]
mod study {
    use super::*;
    use crate::problems::pressfit::params::PressFitParams;

    fn var(name: &str, default: f64) -> f64 {
        std::env::var(name).map_or(default, |v| v.parse().unwrap())
    }

    /// The decks of the CalculiX campaign (docs/theory.md section 18, "CalculiX"): the #98 fit on
    /// any layout (`FIT_AXIAL`, `FIT_RADIAL`) and force step (`FIT_STEP`, N), to `$FIT_DECK`.
    #[test]
    #[ignore = "writes a study deck to $FIT_DECK"]
    fn write_study_deck() {
        let fit = PressFit::new(PressFitParams::CCX98).unwrap();
        let loads: Vec<CarriedLoad> = DEFAULT_LOADS
            .iter()
            .map(|f| fit.axial().clamped(f * fit.gross_slip_force()))
            .collect();
        let radial = var("FIT_RADIAL", 8.0) as usize;
        let layout = Layout {
            axial: var("FIT_AXIAL", 40.0) as usize,
            shaft: radial,
            hub: radial,
        };
        let step = var("FIT_STEP", DEFAULT_STEP * fit.gross_slip_force());
        let deck = write_laid_out_deck(
            &fit,
            &loads,
            DeckMesh::Coarse,
            layout,
            StickSlope::Model,
            Some(step),
        )
        .unwrap();
        std::fs::write(std::env::var("FIT_DECK").unwrap(), deck).unwrap();
    }
}
