//! The inputs of the squeezed-plate problem: keys, units, meanings, domains and steps.

use std::fmt;
use std::str::FromStr;

use crate::kernel::params::{
    Domain, FACTOR, FRICTION, MODULUS, POISSON, ParamError, ParamSpec, STIFFNESS, Unit, spec,
};
use crate::problems::{ModelKind, ParamKey, UnknownParam};

/// The inputs of the squeezed-plate problem.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PlateParam {
    /// Half-length L (mm).
    HalfLength,
    /// Thickness t_p (mm).
    Thickness,
    /// Young's modulus E (MPa).
    Modulus,
    /// Poisson ratio nu (-).
    Poisson,
    /// Friction coefficient mu (-).
    Friction,
    /// Applied pressure P (MPa).
    Pressure,
    /// Tangential contact stiffness K_T (MPa/mm).
    Stiffness,
}

impl PlateParam {
    /// Every plate parameter, in display order.
    pub const ALL: [PlateParam; 7] = [
        PlateParam::HalfLength,
        PlateParam::Thickness,
        PlateParam::Modulus,
        PlateParam::Poisson,
        PlateParam::Friction,
        PlateParam::Pressure,
        PlateParam::Stiffness,
    ];

    /// Key, unit, meaning, domain and step.
    pub fn spec(self) -> ParamSpec {
        match self {
            PlateParam::HalfLength => spec(
                "L",
                Unit::Millimetre,
                "half-length of the plate",
                Domain::LENGTH,
                FACTOR,
            )
            .usual(0.1, 1e4)
            .noted("half"),
            PlateParam::Thickness => spec(
                "tp",
                Unit::Millimetre,
                "plate thickness",
                Domain::LENGTH,
                FACTOR,
            )
            .usual(0.1, 1e4),
            PlateParam::Modulus => MODULUS,
            PlateParam::Poisson => POISSON,
            PlateParam::Friction => FRICTION,
            PlateParam::Pressure => spec(
                "P",
                Unit::Megapascal,
                "applied pressure",
                Domain::PRESSURE,
                FACTOR,
            )
            .usual(1e-3, 2e3),
            PlateParam::Stiffness => STIFFNESS,
        }
    }

    /// Checks `value` against this parameter's domain.
    ///
    /// # Errors
    /// [`ParamError`] naming the key, the value and the allowed range.
    pub fn check(self, value: f64) -> Result<f64, ParamError> {
        let spec = self.spec();
        spec.domain.check(spec.name, value, spec.unit)
    }
}

impl fmt::Display for PlateParam {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.spec().name)
    }
}

impl FromStr for PlateParam {
    type Err = UnknownParam;

    fn from_str(key: &str) -> Result<Self, Self::Err> {
        <PlateParam as ParamKey>::parse_key(key, ModelKind::Plate)
    }
}

/// Raw inputs of the squeezed-plate problem (mm, MPa, MPa/mm); validated by
/// [`SqueezedPlate::new`](crate::problems::plate::closed_form::SqueezedPlate::new).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlateParams {
    /// Half-length L (mm).
    pub half_length: f64,
    /// Thickness t_p (mm).
    pub thickness: f64,
    /// Young's modulus E (MPa).
    pub youngs_modulus: f64,
    /// Poisson ratio nu (-), 0 <= nu < 0.5.
    pub poisson: f64,
    /// Friction coefficient mu (-).
    pub friction: f64,
    /// Applied pressure P (MPa).
    pub pressure: f64,
    /// Tangential contact stiffness K_T (MPa/mm).
    pub tangential_stiffness: f64,
}

impl PlateParams {
    /// The paper's data set (section 2.2.3): L=10, t_p=0.2 mm, E=70000 MPa, nu=0.3, mu=0.3, P=10 MPa.
    /// The paper sweeps K_T; 1e6 MPa/mm (= 1000 MPa/um) is a default that shows both zones.
    pub const PAPER: PlateParams = PlateParams {
        half_length: 10.0,
        thickness: 0.2,
        youngs_modulus: 70_000.0,
        poisson: 0.3,
        friction: 0.3,
        pressure: 10.0,
        tangential_stiffness: 1e6,
    };

    /// Checks every field against its domain, in display order.
    ///
    /// # Errors
    /// The first field outside its domain, with its value and range.
    pub fn check(&self) -> Result<(), ParamError> {
        let mut fields = *self;
        for param in PlateParam::ALL {
            param.check(*fields.value_mut(param))?;
        }
        Ok(())
    }

    /// The field that holds `param`.
    pub(crate) fn value_mut(&mut self, param: PlateParam) -> &mut f64 {
        match param {
            PlateParam::HalfLength => &mut self.half_length,
            PlateParam::Thickness => &mut self.thickness,
            PlateParam::Modulus => &mut self.youngs_modulus,
            PlateParam::Poisson => &mut self.poisson,
            PlateParam::Friction => &mut self.friction,
            PlateParam::Pressure => &mut self.pressure,
            PlateParam::Stiffness => &mut self.tangential_stiffness,
        }
    }
}
