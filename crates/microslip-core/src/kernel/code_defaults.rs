//! The tangential stiffness that finite-element codes assume when the user does not give one.
//!
//! Most codes regularize Coulomb friction with a penalty: an "allowable elastic slip" before sliding,
//! which is exactly the saturation slip mu P / K_T of the regularized law. The implied K_T therefore
//! depends on the mesh (a fraction of an element or contact-face length) and on the contact pressure,
//! which is the paper's warning (section 2.1.3). Each entry says where the default was read and
//! whether it could be confirmed in the code's own text; sources are listed in docs/theory.md,
//! section 3.

/// How a code's default turns into K_T.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DefaultRule {
    /// Allowable elastic slip = fraction x element (contact-face) length: K_T = mu P / (f l_e).
    ElasticSlipFraction(f64),
    /// A stick slope equal to E divided by this number, in the model's own units (MPa/mm here).
    ModulusOver(f64),
    /// A penalty E / (divisor x h_min), h_min the smallest element size on the contact boundary.
    ModulusOverSize(f64),
    /// The user must supply the friction penalty: no silent default.
    UserSupplied,
    /// The default could not be found in the code's public documentation.
    Unknown,
}

/// How sure we are of a default.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Confirmation {
    /// Read in the code's documentation or source.
    Confirmed,
    /// Seen indirectly (e.g. in solver output), not in the manual.
    Indirect,
    /// Not found.
    NotConfirmed,
}

impl Confirmation {
    /// Plain words for the UI.
    pub fn label(self) -> &'static str {
        match self {
            Confirmation::Confirmed => "confirmed in its documentation",
            Confirmation::Indirect => "seen in solver output, not in the manual",
            Confirmation::NotConfirmed => "could NOT be confirmed",
        }
    }
}

/// One code's default friction penalty.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CodeDefault {
    /// The code.
    pub code: &'static str,
    /// A name of at most 10 characters for narrow tables.
    pub short: &'static str,
    /// The rule.
    pub rule: DefaultRule,
    /// The rule in words.
    pub description: &'static str,
    /// How sure we are.
    pub confirmation: Confirmation,
}

/// The codes microslip knows, most used first.
pub const CODE_DEFAULTS: &[CodeDefault] = &[
    CodeDefault {
        code: "Abaqus/Standard",
        short: "Abaqus",
        rule: DefaultRule::ElasticSlipFraction(0.005),
        description: "SLIP TOLERANCE 0.005 x characteristic contact face length",
        confirmation: Confirmation::Confirmed,
    },
    CodeDefault {
        code: "Ansys MAPDL",
        short: "Ansys",
        rule: DefaultRule::ElasticSlipFraction(0.01),
        description: "SLTO 0.01 x average contact surface length",
        confirmation: Confirmation::Indirect,
    },
    CodeDefault {
        code: "CalculiX",
        short: "CalculiX",
        rule: DefaultRule::ModulusOver(2.0),
        description: "stick slope lambda = E / 2 (E of the first material; units of the deck)",
        confirmation: Confirmation::Confirmed,
    },
    CodeDefault {
        code: "COMSOL 5.6",
        short: "COMSOL",
        rule: DefaultRule::ModulusOverSize(3.0),
        description: "friction penalty p_t = E / (3 h_min)",
        confirmation: Confirmation::Confirmed,
    },
    CodeDefault {
        code: "Code_Aster",
        short: "Code_Aster",
        rule: DefaultRule::UserSupplied,
        description: "E_T / COEF_PENA_FROT must be given (no silent default)",
        confirmation: Confirmation::Confirmed,
    },
    CodeDefault {
        code: "LS-DYNA",
        short: "LS-DYNA",
        rule: DefaultRule::Unknown,
        description: "default not found in public documentation",
        confirmation: Confirmation::NotConfirmed,
    },
];

impl CodeDefault {
    /// The K_T (MPa/mm) this default implies for friction `mu`, contact pressure `pressure` (MPa),
    /// Young's modulus `modulus` (MPa) and contact element length `element` (mm); None when the code
    /// has no silent default or it is unknown.
    pub fn implied_stiffness(
        &self,
        mu: f64,
        pressure: f64,
        modulus: f64,
        element: f64,
    ) -> Option<f64> {
        match self.rule {
            DefaultRule::ElasticSlipFraction(f) => Some(mu * pressure / (f * element)),
            DefaultRule::ModulusOver(d) => Some(modulus / d),
            DefaultRule::ModulusOverSize(d) => Some(modulus / (d * element)),
            DefaultRule::UserSupplied | DefaultRule::Unknown => None,
        }
        .filter(|k| k.is_finite() && *k > 0.0)
    }
}

/// The measured K_T / K_N range the paper quotes (Gonzalez-Valadez et al.): 0.5 to 0.7.
pub const MEASURED_RATIO_RANGE: (f64, f64) = (0.5, 0.7);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elastic_slip_rules_give_k_t_inverse_to_the_element_size() {
        let abaqus = CODE_DEFAULTS[0];
        // mu P = 0.3 MPa, element 1 mm: allowed slip 5 um -> K_T = 0.3 / 0.005 = 60 MPa/mm.
        assert!((abaqus.implied_stiffness(0.3, 1.0, 210_000.0, 1.0).unwrap() - 60.0).abs() < 1e-9);
        assert!((abaqus.implied_stiffness(0.3, 1.0, 210_000.0, 0.5).unwrap() - 120.0).abs() < 1e-9);
        let calculix = CODE_DEFAULTS[2];
        assert_eq!(
            calculix.implied_stiffness(0.3, 1.0, 210_000.0, 1.0),
            Some(105_000.0)
        );
        let comsol = CODE_DEFAULTS[3];
        assert_eq!(
            comsol.implied_stiffness(0.3, 1.0, 210_000.0, 2.0),
            Some(35_000.0)
        );
        assert_eq!(CODE_DEFAULTS[4].implied_stiffness(0.3, 1.0, 1.0, 1.0), None);
        assert_eq!(
            CODE_DEFAULTS[5].confirmation.label(),
            "could NOT be confirmed"
        );
    }
}
