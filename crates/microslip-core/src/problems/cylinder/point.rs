//! The cylinder at one tangential load, for the reports and sweeps ([`Pointwise`]).

use super::closed_form::{Cylinder, TangentialLoad};
use super::problem::{CylinderModel, CylinderProblem};
use crate::kernel::regime::Regime;
use crate::problems::pointwise::Pointwise;

/// Everything the reports show about the cylinder at one tangential load, for both laws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderPoint {
    /// Tangential line load Q (N/mm).
    pub load: f64,
    /// Q / (mu P) (-).
    pub load_ratio: f64,
    /// Hertz half-width a (mm).
    pub half_width: f64,
    /// Hertz peak pressure p0 (MPa).
    pub peak_pressure: f64,
    /// K_T a / E* (-): how compliant the interface is beside the bodies.
    pub stiffness_group: f64,
    /// Mindlin's stick-zone half-width c (mm).
    pub zone_coulomb: f64,
    /// The regularized microslip zone's half-width c (mm).
    pub zone_regularized: f64,
    /// Edge slip s(a) under Mindlin (mm).
    pub edge_slip_coulomb: f64,
    /// Edge slip s(a) under the regularized law (mm): the fretting slip amplitude.
    pub edge_slip_regularized: f64,
    /// Centre slip s(0) under the regularized law (mm); 0 under Mindlin below gross slip.
    pub centre_slip_regularized: f64,
    /// The largest q / (mu p0) under Mindlin (-).
    pub peak_shear_coulomb: f64,
    /// The largest q / (mu p0) under the regularized law (-).
    pub peak_shear_regularized: f64,
    /// Coulomb regime.
    pub regime_coulomb: Regime,
    /// Regularized regime.
    pub regime_regularized: Regime,
}

/// The cylinder at one tangential load.
pub fn cylinder_point(cylinder: &Cylinder, load: TangentialLoad) -> CylinderPoint {
    let (coulomb, regularized) = (cylinder.coulomb(load), cylinder.regularized(load));
    CylinderPoint {
        load: load.newtons_per_mm(),
        load_ratio: load.newtons_per_mm() / cylinder.gross_slip_load(),
        half_width: cylinder.half_width(),
        peak_pressure: cylinder.peak_pressure(),
        stiffness_group: cylinder.stiffness_group(),
        zone_coulomb: coulomb.stick_half_width(),
        zone_regularized: regularized.micro_half_width(),
        edge_slip_coulomb: coulomb.edge_slip(),
        edge_slip_regularized: regularized.edge_slip(),
        centre_slip_regularized: regularized.centre_slip(),
        peak_shear_coulomb: coulomb.peak_shear_ratio(),
        peak_shear_regularized: regularized.peak_shear_ratio(),
        regime_coulomb: coulomb.regime(),
        regime_regularized: regularized.regime(),
    }
}

impl Pointwise for CylinderProblem {
    type Point = CylinderPoint;

    fn point(model: &CylinderModel) -> CylinderPoint {
        cylinder_point(&model.cylinder, model.load)
    }
}
