//! The closed forms against independent discretized solutions of the paper's two data sets
//! (`tests/data/`, copied from the project's shared reference; see the files' headers for how they
//! were computed and how accurate they are).

mod common;

use common::{reference_rows, relative_error};
use microslip::{PlateParams, Regime, SqueezedPlate, TipForce, TwinBeams, TwinBeamsParams};

fn paper_beams(kt: f64) -> TwinBeams {
    TwinBeams::new(TwinBeamsParams {
        tangential_stiffness: kt,
        ..TwinBeamsParams::PAPER
    })
    .unwrap()
}

#[test]
fn twin_beams_match_the_finite_element_reference() {
    let rows = reference_rows("twin-beams-paper-fe.csv");
    assert_eq!(rows.len(), 30);
    for row in rows {
        let (kt, f, w_ref, x_ref) = (row[0], row[1], row[2], row[3]);
        let state = paper_beams(kt).regularized(TipForce::new(f).unwrap());
        // The reference is good to ~3e-10 on w(L) and 2e-7 mm on X.
        let w = state.tip_deflection();
        assert!(
            relative_error(w, w_ref) < 2e-9,
            "K_T={kt} F={f}: w(L) = {w}, reference {w_ref}"
        );
        let x = state.micro_zone_end();
        assert!(
            (x - x_ref).abs() < 4e-7,
            "K_T={kt} F={f}: X = {x}, reference {x_ref}"
        );
        let expected = if x_ref < 200.0 {
            Regime::MICROSLIP_MACROSLIP
        } else {
            Regime::MICROSLIP
        };
        assert_eq!(state.regime(), expected);
    }
}

#[test]
fn first_macroslip_forces_match_the_reference_header() {
    // From the header of twin-beams-paper-fe.csv: F_1(K_T=600)=80.1856776 N, F_1(K_T=120)=88.5946673 N.
    assert!((paper_beams(600.0).first_macroslip_force() - 80.185_677_6).abs() < 1e-6);
    assert!((paper_beams(120.0).first_macroslip_force() - 88.594_667_3).abs() < 1e-6);
}

#[test]
fn plate_matches_the_finite_difference_reference() {
    let rows = reference_rows("plate-paper-fd.csv");
    assert_eq!(rows.len(), 8);
    for row in rows {
        let (kt, u_ref, x_ref) = (row[0], row[1], row[2]);
        let plate = SqueezedPlate::new(PlateParams {
            tangential_stiffness: kt,
            ..PlateParams::PAPER
        })
        .unwrap();
        let state = plate.regularized();
        let u = state.end_displacement();
        assert!(
            relative_error(u, u_ref) < 1e-9,
            "K_T={kt}: u(L) = {u}, reference {u_ref}"
        );
        // The reference's own finite-difference/shooting agreement is 1e-9 relative; at K_T = 1e7 its
        // X_r is 1.8e-10 relative below the 40-digit root of (P6) (checked with mpmath).
        let x = state.micro_zone_end();
        assert!(
            relative_error(x, x_ref) < 1e-9,
            "K_T={kt}: X_r = {x}, reference {x_ref}"
        );
    }
}

#[test]
fn plate_coulomb_limit_matches_the_reference_header() {
    // Header of plate-paper-fd.csv: u(L)=7.9591836735e-06 mm, X_s=9.7142857143 mm.
    let coulomb = SqueezedPlate::new(PlateParams::PAPER).unwrap().coulomb();
    assert!(relative_error(coulomb.end_displacement(), 7.959_183_673_5e-6) < 1e-10);
    assert!((coulomb.stick_end() - 9.714_285_714_3).abs() < 1e-10);
}
