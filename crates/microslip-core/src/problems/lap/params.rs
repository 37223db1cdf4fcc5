//! The inputs of the clamped double-lap joint: keys, units, meanings, domains and steps.

use std::fmt;
use std::str::FromStr;

use crate::kernel::params::{
    Domain, FACTOR, FRICTION, ParamError, ParamSpec, STIFFNESS, Scale, Unit, spec,
};
use crate::problems::{ModelKind, ParamKey, UnknownParam};

/// Poisson's ratio of both plates wherever a continuum stands in for the joint (the CalculiX deck,
/// the 2-D continuum solver, the shear-lag envelope that was measured with them): the joint's keys
/// have none, as the 1-D theory needs none; nu = 0 instead of 0.3 moved CalculiX's Delta by at
/// most 0.06 % on the bundled joint (docs/theory.md (L12)).
pub const LAP_POISSON: f64 = 0.3;

/// The inputs of the double-lap joint.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LapParam {
    /// Overlap length L (mm).
    Length,
    /// Width b of every plate (mm).
    Width,
    /// Thickness t1 of the inner plate (mm).
    InnerThickness,
    /// Thickness t2 of each cover plate (mm).
    CoverThickness,
    /// Young's modulus E1 of the inner plate (MPa).
    InnerModulus,
    /// Young's modulus E2 of the cover plates (MPa).
    CoverModulus,
    /// Clamping pressure P on both interfaces (MPa).
    Pressure,
    /// Friction coefficient mu (-).
    Friction,
    /// Tangential contact stiffness K_T (MPa/mm).
    Stiffness,
    /// Force F through the joint (N), each interface transferring F/2.
    Force,
}

impl LapParam {
    /// Every lap-joint parameter, in display order (the key order).
    pub const ALL: [LapParam; 10] = [
        LapParam::Length,
        LapParam::Width,
        LapParam::InnerThickness,
        LapParam::CoverThickness,
        LapParam::InnerModulus,
        LapParam::CoverModulus,
        LapParam::Pressure,
        LapParam::Friction,
        LapParam::Stiffness,
        LapParam::Force,
    ];

    /// Key, unit, meaning, domain and step.
    pub fn spec(self) -> ParamSpec {
        const LENGTH: Domain = Domain::LENGTH;
        match self {
            LapParam::Length => {
                spec("L", Unit::Millimetre, "overlap length", LENGTH, FACTOR).usual(0.1, 1e4)
            }
            LapParam::Width => {
                spec("b", Unit::Millimetre, "joint width", LENGTH, FACTOR).usual(0.1, 1e4)
            }
            LapParam::InnerThickness => spec(
                "t1",
                Unit::Millimetre,
                "inner plate thickness",
                LENGTH,
                FACTOR,
            )
            .usual(0.01, 1e3),
            LapParam::CoverThickness => spec(
                "t2",
                Unit::Millimetre,
                "thickness of each cover plate",
                LENGTH,
                FACTOR,
            )
            .usual(0.01, 1e3),
            LapParam::InnerModulus => spec(
                "E1",
                Unit::Megapascal,
                "inner plate's Young's modulus",
                Domain::MODULUS,
                FACTOR,
            )
            .usual(1.0, 1.2e6),
            LapParam::CoverModulus => spec(
                "E2",
                Unit::Megapascal,
                "cover plates' Young's modulus",
                Domain::MODULUS,
                FACTOR,
            )
            .usual(1.0, 1.2e6),
            LapParam::Pressure => spec(
                "P",
                Unit::Megapascal,
                "clamping pressure",
                Domain::PRESSURE,
                FACTOR,
            )
            .usual(1e-3, 2e3),
            LapParam::Friction => FRICTION,
            LapParam::Stiffness => STIFFNESS,
            LapParam::Force => spec(
                "F",
                Unit::Newton,
                "force through the joint",
                Domain::FORCE,
                Scale::FractionOfScale {
                    fine: 0.01,
                    coarse: 0.1,
                },
            )
            .usual(0.0, 1e7),
        }
    }

    /// Checks `value` against this parameter's domain (the force's bound F_gross, which depends
    /// on the other parameters, is checked by
    /// [`LapJoint::force`](crate::problems::lap::closed_form::LapJoint::force)).
    ///
    /// # Errors
    /// [`ParamError`] naming the key, the value and the allowed range.
    pub fn check(self, value: f64) -> Result<f64, ParamError> {
        let spec = self.spec();
        spec.domain.check(spec.name, value, spec.unit)
    }
}

impl fmt::Display for LapParam {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.spec().name)
    }
}

impl FromStr for LapParam {
    type Err = UnknownParam;

    fn from_str(key: &str) -> Result<Self, Self::Err> {
        <LapParam as ParamKey>::parse_key(key, ModelKind::Lap)
    }
}

/// Raw inputs of the double-lap joint's structure and interface (mm, MPa, MPa/mm); validated by
/// [`LapJoint::new`](crate::problems::lap::closed_form::LapJoint::new). The force is not a
/// property of the structure and is kept apart, as the beams' tip force is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapParams {
    /// Overlap length L (mm).
    pub length: f64,
    /// Width b of every plate (mm).
    pub width: f64,
    /// Inner plate thickness t1 (mm).
    pub inner_thickness: f64,
    /// Thickness t2 of each cover plate (mm).
    pub cover_thickness: f64,
    /// Inner plate's Young's modulus E1 (MPa).
    pub inner_modulus: f64,
    /// Cover plates' Young's modulus E2 (MPa).
    pub cover_modulus: f64,
    /// Clamping pressure P on both interfaces (MPa).
    pub pressure: f64,
    /// Friction coefficient mu (-).
    pub friction: f64,
    /// Tangential contact stiffness K_T (MPa/mm).
    pub tangential_stiffness: f64,
}

impl LapParams {
    /// The bundled aluminium joint (presets/lap-aluminium.toml, docs/theory.md section 9): a 3 mm
    /// inner strap between two 2 mm covers, 25 mm wide, overlapping 40 mm, all E = 70000 MPa,
    /// clamped at 10 MPa, mu = 0.3, K_T = 1000 MPa/mm (a saturation slip mu P / K_T of 3 um). The
    /// inner plate (E1 t1 = 210000 N/mm) is more compliant than the two covers (2 E2 t2 = 280000
    /// N/mm), so the x = L end slides first and the joint shows every regime.
    pub const ALUMINIUM: LapParams = LapParams {
        length: 40.0,
        width: 25.0,
        inner_thickness: 3.0,
        cover_thickness: 2.0,
        inner_modulus: 70_000.0,
        cover_modulus: 70_000.0,
        pressure: 10.0,
        friction: 0.3,
        tangential_stiffness: 1000.0,
    };

    /// The field that holds `param`, or `None` for the force, which is not a property of the
    /// structure.
    pub(crate) fn value_mut(&mut self, param: LapParam) -> Option<&mut f64> {
        Some(match param {
            LapParam::Length => &mut self.length,
            LapParam::Width => &mut self.width,
            LapParam::InnerThickness => &mut self.inner_thickness,
            LapParam::CoverThickness => &mut self.cover_thickness,
            LapParam::InnerModulus => &mut self.inner_modulus,
            LapParam::CoverModulus => &mut self.cover_modulus,
            LapParam::Pressure => &mut self.pressure,
            LapParam::Friction => &mut self.friction,
            LapParam::Stiffness => &mut self.tangential_stiffness,
            LapParam::Force => return None,
        })
    }

    /// Checks every field against its domain, in display order.
    ///
    /// # Errors
    /// The first field outside its domain, with its value and range.
    pub fn check(&self) -> Result<(), ParamError> {
        let mut fields = *self;
        for param in LapParam::ALL {
            if let Some(&mut value) = fields.value_mut(param) {
                param.check(value)?;
            }
        }
        Ok(())
    }

    /// Axial stiffness per unit width of the inner plate, k1 = E1 t1 (N/mm).
    pub fn inner_stiffness(&self) -> f64 {
        self.inner_modulus * self.inner_thickness
    }

    /// Axial stiffness per unit width of both covers together, K2 = 2 E2 t2 (N/mm).
    pub fn covers_stiffness(&self) -> f64 {
        2.0 * self.cover_modulus * self.cover_thickness
    }

    /// The gross-slip force F_gross = 2 b mu P L (N), (L6): both interfaces sliding over the
    /// whole overlap; no larger force can be carried.
    pub fn gross_slip_force(&self) -> f64 {
        2.0 * self.width * self.friction * self.pressure * self.length
    }
}
