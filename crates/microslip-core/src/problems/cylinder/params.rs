//! The inputs of the Hertzian cylinder on a flat: keys, units, meanings, domains and steps.
//!
//! Plane strain: the normal load P and the tangential load Q are **line loads**, N per mm of the
//! cylinder's length (N/mm), not forces; every description says so.

use std::fmt;

use crate::kernel::params::{
    Domain, FACTOR, FRICTION, MODULUS, POISSON, ParamError, ParamSpec, STIFFNESS, Scale, Unit, spec,
};
use crate::problems::ParamKey;

/// A normal line load P (N/mm): strictly positive (a contact needs a normal load), up to 1e9
/// N/mm, so that the Hertz half-width of every accepted input is a finite number.
pub const LINE_LOAD: Domain = Domain::Positive {
    min: 1e-6,
    max: 1e9,
};

/// A tangential line load Q (N/mm): from 0 up to 1e9 N/mm; the cylinder itself bounds it by its
/// gross-slip load mu P ([`Cylinder::load`](super::closed_form::Cylinder::load)).
pub const TANGENTIAL_LINE_LOAD: Domain = Domain::NonNegative { max: 1e9 };

/// The inputs of the cylinder on its flat.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CylinderParam {
    /// Radius R of the cylinder (mm).
    Radius,
    /// Young's modulus E of the cylinder and of the flat (MPa).
    Modulus,
    /// Poisson's ratio nu of the cylinder and of the flat (-).
    Poisson,
    /// Normal line load P (N/mm).
    NormalLoad,
    /// Friction coefficient mu (-).
    Friction,
    /// Tangential contact stiffness K_T (MPa/mm).
    Stiffness,
    /// Tangential line load Q (N/mm), applied after P and growing from 0.
    TangentialLoad,
}

impl CylinderParam {
    /// Every cylinder parameter, in display order (the issue's key order `R E nu P mu KT Q`).
    pub const ALL: [CylinderParam; 7] = [
        CylinderParam::Radius,
        CylinderParam::Modulus,
        CylinderParam::Poisson,
        CylinderParam::NormalLoad,
        CylinderParam::Friction,
        CylinderParam::Stiffness,
        CylinderParam::TangentialLoad,
    ];

    /// Key, unit, meaning, domain and step.
    pub fn spec(self) -> ParamSpec {
        match self {
            CylinderParam::Radius => spec(
                "R",
                Unit::Millimetre,
                "cylinder radius",
                Domain::LENGTH,
                FACTOR,
            )
            .usual(0.1, 1e4),
            CylinderParam::Modulus => ParamSpec {
                meaning: "Young's modulus of the cylinder and the flat",
                ..MODULUS
            },
            CylinderParam::Poisson => ParamSpec {
                meaning: "Poisson ratio of the cylinder and the flat",
                ..POISSON
            },
            CylinderParam::NormalLoad => spec(
                "P",
                Unit::NewtonPerMillimetre,
                "normal line load (N per mm of cylinder length)",
                LINE_LOAD,
                FACTOR,
            )
            .usual(1e-2, 1e5),
            CylinderParam::Friction => FRICTION,
            CylinderParam::Stiffness => STIFFNESS,
            CylinderParam::TangentialLoad => spec(
                "Q",
                Unit::NewtonPerMillimetre,
                "tangential line load (N per mm of cylinder length)",
                TANGENTIAL_LINE_LOAD,
                Scale::FractionOfScale {
                    fine: 0.01,
                    coarse: 0.1,
                },
            )
            .usual(0.0, 1e5),
        }
    }

    /// Checks `value` against this parameter's own domain (Q's bound mu P, which depends on the
    /// other parameters, is checked by
    /// [`Cylinder::load`](super::closed_form::Cylinder::load)).
    ///
    /// # Errors
    /// [`ParamError`] naming the key, the value and the allowed range.
    pub fn check(self, value: f64) -> Result<f64, ParamError> {
        let spec = self.spec();
        spec.domain.check(spec.name, value, spec.unit)
    }
}

impl fmt::Display for CylinderParam {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.spec().name)
    }
}

impl ParamKey for CylinderParam {
    // `ALL` is the description's order (`param_list!`).
    const KEYS: &'static [CylinderParam] = &CylinderParam::ALL;

    fn spec(self) -> ParamSpec {
        CylinderParam::spec(self)
    }
}

/// Raw inputs of the cylinder and its flat (mm, MPa, N/mm, MPa/mm), without the tangential
/// load, which is not a property of the contact and is kept apart (as the lap joint's force);
/// validated by [`Cylinder::new`](super::closed_form::Cylinder::new).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderParams {
    /// Radius R of the cylinder (mm).
    pub radius: f64,
    /// Young's modulus E of both bodies (MPa).
    pub modulus: f64,
    /// Poisson's ratio nu of both bodies (-).
    pub poisson: f64,
    /// Normal line load P (N/mm, per mm of the cylinder's length).
    pub normal_load: f64,
    /// Friction coefficient mu (-).
    pub friction: f64,
    /// Tangential contact stiffness K_T (MPa/mm).
    pub tangential_stiffness: f64,
}

impl CylinderParams {
    /// The bundled steel fretting pad (docs/theory.md, "The Hertzian cylinder"): a cylindrical
    /// pad of radius 50 mm on a flat, both steel (E = 210000 MPa, nu = 0.3), pressed by 1000
    /// N/mm, mu = 0.6, K_T = 1e5 MPa/mm. Hertz gives a = 0.743 mm and p0 = 857 MPa; K_T a / E*
    /// = 0.64, so the interface is as compliant as the bodies over the contact and the
    /// regularized answer departs from Mindlin's.
    pub const STEEL_PAD: CylinderParams = CylinderParams {
        radius: 50.0,
        modulus: 210_000.0,
        poisson: 0.3,
        normal_load: 1000.0,
        friction: 0.6,
        tangential_stiffness: 1e5,
    };

    /// The field that holds `param`, or `None` for the tangential load, which is not a property
    /// of the contact.
    pub(crate) fn value_mut(&mut self, param: CylinderParam) -> Option<&mut f64> {
        Some(match param {
            CylinderParam::Radius => &mut self.radius,
            CylinderParam::Modulus => &mut self.modulus,
            CylinderParam::Poisson => &mut self.poisson,
            CylinderParam::NormalLoad => &mut self.normal_load,
            CylinderParam::Friction => &mut self.friction,
            CylinderParam::Stiffness => &mut self.tangential_stiffness,
            CylinderParam::TangentialLoad => return None,
        })
    }

    /// Checks every field against its domain, in display order.
    ///
    /// # Errors
    /// The first field outside its domain, with its value and range.
    pub fn check(&self) -> Result<(), ParamError> {
        let mut fields = *self;
        for param in CylinderParam::ALL {
            if let Some(&mut value) = fields.value_mut(param) {
                param.check(value)?;
            }
        }
        Ok(())
    }

    /// The gross-slip load mu P (N/mm): the whole contact slides, no larger Q can be carried.
    pub fn gross_slip_load(&self) -> f64 {
        self.friction * self.normal_load
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_name_the_field_the_value_and_the_range_with_its_unit() {
        assert_eq!(
            CylinderParam::NormalLoad
                .check(-1.0)
                .unwrap_err()
                .to_string(),
            "invalid P = -1: must be > 0 and finite (N/mm)"
        );
        assert_eq!(
            CylinderParam::TangentialLoad
                .check(f64::NAN)
                .unwrap_err()
                .to_string(),
            "invalid Q = NaN: must be >= 0 and finite (N/mm)"
        );
        assert_eq!(
            CylinderParam::Radius.check(0.0).unwrap_err().to_string(),
            "invalid R = 0: must be > 0 and finite (mm)"
        );
        assert_eq!(
            CylinderParam::NormalLoad
                .check(2e9)
                .unwrap_err()
                .to_string(),
            "invalid P = 2e9: must be in [1e-6, 1e9] N/mm"
        );
        assert_eq!(CylinderParam::Poisson.check(0.5).unwrap_err().field, "nu");
        let mut bad = CylinderParams::STEEL_PAD;
        bad.tangential_stiffness = f64::INFINITY;
        assert_eq!(bad.check().unwrap_err().field, "KT");
        assert!(CylinderParams::STEEL_PAD.check().is_ok());
    }

    #[test]
    fn keys_are_the_issue_s_in_its_order_and_line_loads_say_so() {
        let keys: Vec<&str> = CylinderParam::ALL.iter().map(|p| p.spec().name).collect();
        assert_eq!(keys, ["R", "E", "nu", "P", "mu", "KT", "Q"]);
        for load in [CylinderParam::NormalLoad, CylinderParam::TangentialLoad] {
            let spec = load.spec();
            assert_eq!(spec.unit.symbol(), "N/mm");
            assert!(spec.meaning.contains("per mm"), "{}", spec.meaning);
        }
    }
}
