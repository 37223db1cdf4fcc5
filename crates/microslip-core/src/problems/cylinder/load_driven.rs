//! The cylinder as a load-driven problem ([`LoadDriven`]): the tangential line load Q (N/mm) in
//! [0, mu P]; the edge slip s(a) (mm), the fretting slip amplitude, its response; mu P its
//! regime scale; the Masing cycle of [`CylinderCycle`].
//!
//! Why s(a) and not a load-point displacement: the rigid shift of two elastic half-planes under
//! a line load is not defined (their displacements grow like ln of the distance, (H5)), so the
//! cylinder's only well-defined displacement answers are relative slips; s(a) is the one that
//! fretting analyses quote. It grows with Q (c shrinks and the slip zones widen) and falls with
//! K_T towards Mindlin's (docs/theory.md (H16)), as the generic tolerance search needs.
//!
//! TODO(c1b): declared in `mod.rs` together with `cycle.rs`, whose `CylinderCycle` (a
//! [`MasingCycle`](crate::problems::load_driven::MasingCycle) + `Copy`, built by
//! `CylinderCycle::new(&Cylinder, Law, TangentialLoad)`) this impl hands out; then
//! `problem.rs`'s `FACES` holds `load_driven: Some(&LoadDrivenOf::<CylinderProblem>::NEW)`.

use super::closed_form::{Cylinder, TangentialLoad};
use super::cycle::CylinderCycle;
use super::params::CylinderParam;
use super::point::{CylinderPoint, cylinder_point};
use super::problem::{CylinderModel, CylinderProblem};
use crate::kernel::params::ParamError;
use crate::kernel::regime::Law;
use crate::problems::Param;
use crate::problems::load_driven::LoadDriven;

impl LoadDriven for CylinderProblem {
    type Structure = Cylinder;
    type Force = TangentialLoad;
    type Cycle = CylinderCycle;
    type Point = CylinderPoint;

    const FORCE: Param = Param::Cylinder(CylinderParam::TangentialLoad);
    const STIFFNESS: Param = Param::Cylinder(CylinderParam::Stiffness);

    fn structure(model: &CylinderModel) -> Cylinder {
        model.cylinder
    }

    fn applied_force(model: &CylinderModel) -> TangentialLoad {
        model.load
    }

    fn at_force(cylinder: &Cylinder, load: TangentialLoad) -> CylinderModel {
        CylinderModel {
            cylinder: *cylinder,
            load,
        }
    }

    /// A load in Q's domain and at most mu P (gross slip: no static state beyond).
    fn force(cylinder: &Cylinder, newtons_per_mm: f64) -> Result<TangentialLoad, ParamError> {
        cylinder.load(newtons_per_mm)
    }

    fn clamped_force(cylinder: &Cylinder, newtons_per_mm: f64) -> TangentialLoad {
        cylinder.clamped_load(newtons_per_mm)
    }

    /// The load in N/mm (the generic layers print the load parameter's own unit).
    fn load_value(load: TangentialLoad) -> f64 {
        load.newtons_per_mm()
    }

    /// mu P, where the whole contact slides.
    fn force_scale(cylinder: &Cylinder) -> f64 {
        cylinder.gross_slip_load()
    }

    /// Only mu P: under both laws the regime is the same from the first newton per mm to gross
    /// slip (stick or microslip at the centre, sliding at the edges, for every 0 < Q < mu P).
    fn regime_changes(cylinder: &Cylinder) -> Vec<f64> {
        vec![cylinder.gross_slip_load()]
    }

    /// The edge slip s(a) (mm).
    fn response(cylinder: &Cylinder, law: Law, load: TangentialLoad) -> f64 {
        match law {
            Law::Coulomb => cylinder.coulomb(load).edge_slip(),
            Law::Regularized => cylinder.regularized(load).edge_slip(),
        }
    }

    fn point(cylinder: &Cylinder, load: TangentialLoad) -> CylinderPoint {
        cylinder_point(cylinder, load)
    }

    /// From the centre to the stick (Coulomb) or microslip (regularized) zone's edge c.
    fn holding_zone(cylinder: &Cylinder, law: Law, load: TangentialLoad) -> [f64; 2] {
        let edge = match law {
            Law::Coulomb => cylinder.coulomb(load).stick_half_width(),
            Law::Regularized => cylinder.regularized(load).micro_half_width(),
        };
        [0.0, edge]
    }

    fn cycle(cylinder: &Cylinder, law: Law, amplitude: TangentialLoad) -> CylinderCycle {
        CylinderCycle::new(cylinder, law, amplitude)
    }

    fn tangential_stiffness(cylinder: &Cylinder) -> f64 {
        cylinder.params().tangential_stiffness
    }

    fn with_tangential_stiffness(cylinder: &Cylinder, kt: f64) -> Result<Cylinder, ParamError> {
        cylinder.with_tangential_stiffness(kt)
    }

    /// mu p0 (MPa), at the centre, where the pressure peaks.
    fn interface_strength(cylinder: &Cylinder) -> f64 {
        cylinder.params().friction * cylinder.peak_pressure()
    }

    /// E of both bodies.
    fn modulus(cylinder: &Cylinder) -> f64 {
        cylinder.params().modulus
    }

    /// As Q -> 0 the regularized s(a) is the elastic interface's, linear in Q (docs/theory.md
    /// (H18)), and Mindlin's grows as Q^(3/2) (H9a): their ratio grows as Q^(-1/2) at every
    /// finite K_T, so no K_T holds over a range from 0 ([`LoadDriven::unbounded_at_zero`]), and
    /// over a range from Q_1 > 0 the worst load is Q_1, which the range's ends include.
    fn unbounded_at_zero(_cylinder: &Cylinder) -> Option<&'static str> {
        Some(
            "as Q -> 0 the regularized s(a) is linear in Q (the interface's elastic compliance, \
             docs/theory.md (H18)) while Mindlin's grows as Q^(3/2), so their ratio grows without \
             bound at every finite K_T; start the range above 0 (--from)",
        )
    }
}
