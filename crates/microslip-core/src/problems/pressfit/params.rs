//! The inputs of the press fit: keys, units, meanings, domains and steps, the checked
//! constructor's rules (ri < r < ro besides each field's own domain), and the members' section
//! properties that the closed forms and the discretized solver both start from.

use std::f64::consts::PI;
use std::fmt;

use crate::kernel::params::{
    Domain, FACTOR, FRICTION, POISSON, ParamError, ParamSpec, STIFFNESS, Scale, Unit, spec,
};

/// The torque's domain (N mm): 0 to 1e15, the force's 1e12 N at an arm of 1 m.
pub const TORQUE: Domain = Domain::NonNegative { max: 1e15 };

/// The inputs of the press fit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PressFitParam {
    /// Fit radius r (mm): the shaft's outer and the hub's inner radius.
    FitRadius,
    /// Bore radius ri of a hollow shaft (mm), 0 for a solid one.
    BoreRadius,
    /// Outer radius ro of the hub (mm).
    OuterRadius,
    /// Fit length L (mm).
    Length,
    /// Young's modulus Es of the shaft (MPa).
    ShaftModulus,
    /// Poisson's ratio nus of the shaft (-).
    ShaftPoisson,
    /// Young's modulus Eh of the hub (MPa).
    HubModulus,
    /// Poisson's ratio nuh of the hub (-).
    HubPoisson,
    /// Radial interference delta (mm, on the radius).
    Interference,
    /// Friction coefficient mu (-).
    Friction,
    /// Tangential contact stiffness K_T (MPa/mm).
    Stiffness,
    /// Push-out force F on the shaft's end face (N).
    Force,
    /// Torque T on the shaft's end (N mm), the torsional load.
    Torque,
}

impl PressFitParam {
    /// Every key, in display order (the issue's order, the torque last).
    pub const ALL: [PressFitParam; 13] = [
        PressFitParam::FitRadius,
        PressFitParam::BoreRadius,
        PressFitParam::OuterRadius,
        PressFitParam::Length,
        PressFitParam::ShaftModulus,
        PressFitParam::ShaftPoisson,
        PressFitParam::HubModulus,
        PressFitParam::HubPoisson,
        PressFitParam::Interference,
        PressFitParam::Friction,
        PressFitParam::Stiffness,
        PressFitParam::Force,
        PressFitParam::Torque,
    ];

    /// The fit's own keys, r to delta: what the loads and the interface (mu, K_T) leave.
    pub const STRUCTURE: &'static [PressFitParam] = Self::ALL.split_at(9).0;

    /// The push-out's keys, r to F: all but the torque.
    pub const PUSH_OUT: &'static [PressFitParam] = Self::ALL.split_at(12).0;

    /// The torque's keys, r to K_T and T: all but the push-out force (the twisted fit's
    /// problem: the folder's module docs).
    pub const TORQUE_KEYS: [PressFitParam; 12] = {
        let mut keys = [PressFitParam::Torque; 12];
        let mut i = 0;
        while i < 11 {
            keys[i] = Self::ALL[i];
            i += 1;
        }
        keys
    };

    /// Key, unit, meaning, domain and step.
    pub fn spec(self) -> ParamSpec {
        const LENGTH: Domain = Domain::LENGTH;
        match self {
            PressFitParam::FitRadius => {
                spec("r", Unit::Millimetre, "fit radius", LENGTH, FACTOR).usual(0.5, 2e3)
            }
            PressFitParam::BoreRadius => spec(
                "ri",
                Unit::Millimetre,
                "shaft's bore radius (0: solid shaft)",
                Domain::NonNegative { max: 1e6 },
                Scale::Add {
                    fine: 0.1,
                    coarse: 1.0,
                    min: 0.0,
                    max: 1e6,
                },
            )
            .usual(0.0, 2e3),
            PressFitParam::OuterRadius => {
                spec("ro", Unit::Millimetre, "hub's outer radius", LENGTH, FACTOR).usual(0.6, 4e3)
            }
            PressFitParam::Length => {
                spec("L", Unit::Millimetre, "fit length", LENGTH, FACTOR).usual(0.5, 4e3)
            }
            PressFitParam::ShaftModulus => spec(
                "Es",
                Unit::Megapascal,
                "shaft's Young's modulus",
                Domain::MODULUS,
                FACTOR,
            )
            .usual(1.0, 1.2e6),
            PressFitParam::ShaftPoisson => ParamSpec {
                name: "nus",
                meaning: "shaft's Poisson ratio",
                ..POISSON
            },
            PressFitParam::HubModulus => spec(
                "Eh",
                Unit::Megapascal,
                "hub's Young's modulus",
                Domain::MODULUS,
                FACTOR,
            )
            .usual(1.0, 1.2e6),
            PressFitParam::HubPoisson => ParamSpec {
                name: "nuh",
                meaning: "hub's Poisson ratio",
                ..POISSON
            },
            PressFitParam::Interference => spec(
                "delta",
                Unit::Millimetre,
                "radial interference (on the radius)",
                LENGTH,
                FACTOR,
            )
            .usual(1e-4, 1.0),
            PressFitParam::Friction => FRICTION,
            PressFitParam::Stiffness => STIFFNESS,
            PressFitParam::Force => spec(
                "F",
                Unit::Newton,
                "push-out force on the shaft's end face",
                Domain::FORCE,
                Scale::FractionOfScale {
                    fine: 0.01,
                    coarse: 0.1,
                },
            )
            .usual(0.0, 1e8),
            PressFitParam::Torque => spec(
                "T",
                Unit::NewtonMillimetre,
                "torque on the shaft's end",
                TORQUE,
                Scale::FractionOfScale {
                    fine: 0.01,
                    coarse: 0.1,
                },
            )
            .usual(0.0, 1e11),
        }
    }

    /// Checks `value` against this parameter's own domain (ri < r < ro and the loads' bounds
    /// F_gross and T_gross depend on the other parameters: [`PressFitParams::check`] and
    /// [`PressFit::force`](super::closed_form::PressFit::force)).
    ///
    /// # Errors
    /// [`ParamError`] naming the key, the value and the allowed range.
    pub fn check(self, value: f64) -> Result<f64, ParamError> {
        let spec = self.spec();
        spec.domain.check(spec.name, value, spec.unit)
    }
}

impl fmt::Display for PressFitParam {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.spec().name)
    }
}

/// Raw inputs of the press fit's members and interface (mm, MPa, MPa/mm); validated by
/// [`PressFitParams::check`] (and so by
/// [`PressFit::new`](super::closed_form::PressFit::new)). The loads are not properties of the
/// fit and are kept apart, as the lap joint's force is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressFitParams {
    /// Fit radius r (mm).
    pub fit_radius: f64,
    /// Bore radius ri (mm), 0 for a solid shaft.
    pub bore_radius: f64,
    /// Hub's outer radius ro (mm).
    pub outer_radius: f64,
    /// Fit length L (mm).
    pub length: f64,
    /// Shaft's Young's modulus Es (MPa).
    pub shaft_modulus: f64,
    /// Shaft's Poisson ratio nus (-).
    pub shaft_poisson: f64,
    /// Hub's Young's modulus Eh (MPa).
    pub hub_modulus: f64,
    /// Hub's Poisson ratio nuh (-).
    pub hub_poisson: f64,
    /// Radial interference delta (mm, on the radius).
    pub interference: f64,
    /// Friction coefficient mu (-).
    pub friction: f64,
    /// Tangential contact stiffness K_T (MPa/mm).
    pub tangential_stiffness: f64,
}

impl PressFitParams {
    /// The bundled fit (presets/pressfit-ccx98.toml, docs/theory.md section 18): CalculiX issue
    /// #98's geometry, a hollow steel shaft of diameters 20/40.005 mm in a steel hub of
    /// 40.000/60 mm (r = 20, ri = 10, ro = 30 mm, delta = 0.0025 mm on the radius), E = 210000
    /// MPa, nu = 0.3, mu = 0.1, K_T = 1e4 MPa/mm. The issue does not give the fit length: L is
    /// the one at which F_gross = mu p 2 pi r L is the issue's 1371 N with Lamé's plane-stress
    /// p = 6.1523 MPa, 17.7332 mm (theory.md says how the issue's p = 5.74 MPa arose).
    pub const CCX98: PressFitParams = PressFitParams {
        fit_radius: 20.0,
        bore_radius: 10.0,
        outer_radius: 30.0,
        length: 17.7332,
        shaft_modulus: 210_000.0,
        shaft_poisson: 0.3,
        hub_modulus: 210_000.0,
        hub_poisson: 0.3,
        interference: 0.0025,
        friction: 0.1,
        tangential_stiffness: 1e4,
    };

    /// The field that holds `param`, or `None` for the loads, which are not properties of the
    /// fit.
    pub(crate) fn value_mut(&mut self, param: PressFitParam) -> Option<&mut f64> {
        Some(match param {
            PressFitParam::FitRadius => &mut self.fit_radius,
            PressFitParam::BoreRadius => &mut self.bore_radius,
            PressFitParam::OuterRadius => &mut self.outer_radius,
            PressFitParam::Length => &mut self.length,
            PressFitParam::ShaftModulus => &mut self.shaft_modulus,
            PressFitParam::ShaftPoisson => &mut self.shaft_poisson,
            PressFitParam::HubModulus => &mut self.hub_modulus,
            PressFitParam::HubPoisson => &mut self.hub_poisson,
            PressFitParam::Interference => &mut self.interference,
            PressFitParam::Friction => &mut self.friction,
            PressFitParam::Stiffness => &mut self.tangential_stiffness,
            PressFitParam::Force | PressFitParam::Torque => return None,
        })
    }

    /// Checks every field against its domain, in display order, then the radii against one
    /// another: the bore inside the fit radius (ri < r) and the hub's outside beyond it (ro > r),
    /// so that both members have a wall.
    ///
    /// # Errors
    /// The first field outside its domain, with its value and range; then `ri` with the range
    /// [0, r] or `ro` with [r, 1e6] mm and why (equality is refused too: a wall of no
    /// thickness).
    ///
    /// # Examples
    /// ```
    /// use microslip_core::problems::pressfit::params::PressFitParams;
    /// let thin = PressFitParams { bore_radius: 20.0, ..PressFitParams::CCX98 };
    /// assert_eq!(
    ///     thin.check().unwrap_err().to_string(),
    ///     "invalid ri = 20: must be in [0, 20] mm (ri < r: the shaft needs a wall; \
    ///      equal radii are refused)"
    /// );
    /// ```
    pub fn check(&self) -> Result<(), ParamError> {
        let mut fields = *self;
        for param in PressFitParam::ALL {
            if let Some(&mut value) = fields.value_mut(param) {
                param.check(value)?;
            }
        }
        let r = self.fit_radius;
        if self.bore_radius >= r {
            let spec = PressFitParam::BoreRadius.spec();
            return Err(ParamError {
                field: spec.name,
                value: self.bore_radius,
                domain: Domain::NonNegative { max: r },
                unit: spec.unit,
                reason: None,
            }
            .because("ri < r: the shaft needs a wall; equal radii are refused"));
        }
        if self.outer_radius <= r {
            let spec = PressFitParam::OuterRadius.spec();
            let max = Domain::LENGTH.max();
            return Err(ParamError {
                field: spec.name,
                value: self.outer_radius,
                domain: Domain::Positive { min: r, max },
                unit: spec.unit,
                reason: None,
            }
            .because("ro > r: the hub needs a wall; equal radii are refused"));
        }
        Ok(())
    }

    /// The shaft's cross-section As = pi (r^2 - ri^2) (mm^2).
    pub fn shaft_area(&self) -> f64 {
        let (r, ri) = (self.fit_radius, self.bore_radius);
        PI * (r - ri) * (r + ri)
    }

    /// The hub's cross-section Ah = pi (ro^2 - r^2) (mm^2).
    pub fn hub_area(&self) -> f64 {
        let (r, ro) = (self.fit_radius, self.outer_radius);
        PI * (ro - r) * (ro + r)
    }

    /// The shaft's polar moment Js = pi/2 (r^4 - ri^4) (mm^4).
    pub fn shaft_polar_moment(&self) -> f64 {
        let (r, ri) = (self.fit_radius, self.bore_radius);
        0.5 * PI * (r - ri) * (r + ri) * (r * r + ri * ri)
    }

    /// The hub's polar moment Jh = pi/2 (ro^4 - r^4) (mm^4).
    pub fn hub_polar_moment(&self) -> f64 {
        let (r, ro) = (self.fit_radius, self.outer_radius);
        0.5 * PI * (ro - r) * (ro + r) * (ro * ro + r * r)
    }

    /// The interface's width w = 2 pi r (mm): the circumference the shear acts along.
    pub fn interface_width(&self) -> f64 {
        2.0 * PI * self.fit_radius
    }

    /// The shaft's shear modulus Gs = Es / (2 (1 + nus)) (MPa).
    pub fn shaft_shear_modulus(&self) -> f64 {
        self.shaft_modulus / (2.0 * (1.0 + self.shaft_poisson))
    }

    /// The hub's shear modulus Gh = Eh / (2 (1 + nuh)) (MPa).
    pub fn hub_shear_modulus(&self) -> f64 {
        self.hub_modulus / (2.0 * (1.0 + self.hub_poisson))
    }

    /// The members' rigidities under `load` (N), [shaft, hub]: Es As and Eh Ah for the push-out,
    /// the equivalent G J / r^2 for the torque (section 18, (S6)).
    pub fn rigidities(&self, load: FitLoad) -> [f64; 2] {
        match load {
            FitLoad::Axial => [
                self.shaft_modulus * self.shaft_area(),
                self.hub_modulus * self.hub_area(),
            ],
            FitLoad::Torque => {
                let r2 = self.fit_radius * self.fit_radius;
                [
                    self.shaft_shear_modulus() * self.shaft_polar_moment() / r2,
                    self.hub_shear_modulus() * self.hub_polar_moment() / r2,
                ]
            }
        }
    }
}

/// How the fit is loaded: pushed out along its axis by F, or twisted by T.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FitLoad {
    /// An axial force F (N) on the shaft's end face; the response is Delta (mm).
    Axial,
    /// A torque T (N mm) on the shaft's end; the response is the twist theta (rad).
    Torque,
}

impl FitLoad {
    /// The lever from the equivalent axial force on the interface to the load: 1 for the
    /// push-out, r for the torque (T = N r), (S6).
    pub fn arm(self, params: &PressFitParams) -> f64 {
        match self {
            FitLoad::Axial => 1.0,
            FitLoad::Torque => params.fit_radius,
        }
    }

    /// The load's key: `F` or `T`.
    pub fn param(self) -> PressFitParam {
        match self {
            FitLoad::Axial => PressFitParam::Force,
            FitLoad::Torque => PressFitParam::Torque,
        }
    }
}
