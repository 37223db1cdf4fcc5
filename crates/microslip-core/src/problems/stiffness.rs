//! Tangential contact stiffness: estimates and unit conversions.
//!
//! microslip works in MPa/mm internally; the paper's nomenclature quotes K_T in MPa/um, and so do many
//! measurements, so the UI may show both.

use crate::kernel::params::{Domain, FRICTION, POISSON, ParamError, ParamSpec, STIFFNESS, Unit};

/// `value` checked against a shared parameter spec (its name, domain and unit): these
/// conversions belong to no problem, so they check against the kernel's specs, which every
/// problem's nu, mu and K_T are, rather than against one problem's parameters.
fn checked(spec: ParamSpec, value: f64) -> Result<f64, ParamError> {
    spec.domain.check(spec.name, value, spec.unit)
}

/// The contact pressure P (MPa) checked against its domain (each problem words its own P).
fn checked_pressure(value: f64) -> Result<f64, ParamError> {
    Domain::PRESSURE.check("P", value, Unit::Megapascal)
}

/// Number of micrometres in a millimetre.
const UM_PER_MM: f64 = 1000.0;

/// K_T / K_N = pi (1 - nu) / (2 (2 - nu)) for a Greenwood-Williamson rough surface (paper eq. 4,
/// after Sherif & Kossa, 1991). It gives 0.647 at nu = 0.3, inside the 0.5-0.7 range measured by
/// Gonzalez-Valadez et al. (paper refs. 17-19).
///
/// # Errors
/// [`ParamError`] when nu is outside [0, 0.5).
pub fn tangential_to_normal_ratio(nu: f64) -> Result<f64, ParamError> {
    let nu = checked(POISSON, nu)?;
    Ok(std::f64::consts::PI * (1.0 - nu) / (2.0 * (2.0 - nu)))
}

/// K_T (MPa/mm) from a normal contact stiffness K_N (MPa/mm), paper eq. 4.
///
/// # Errors
/// [`ParamError`] when K_N is outside the stiffness domain, or nu is outside [0, 0.5).
pub fn tangential_from_normal(kn: f64, nu: f64) -> Result<f64, ParamError> {
    let kn = Domain::STIFFNESS.check("KN", kn, Unit::MegapascalPerMillimetre)?;
    Ok(tangential_to_normal_ratio(nu)? * kn)
}

/// Saturation slip mu P / K_T (mm): the elastic slip at which the regularized law reaches mu P.
///
/// # Errors
/// [`ParamError`] naming the first of mu, P, K_T outside its domain.
pub fn saturation_slip(mu: f64, pressure: f64, kt: f64) -> Result<f64, ParamError> {
    let mu = checked(FRICTION, mu)?;
    let p = checked_pressure(pressure)?;
    let kt = checked(STIFFNESS, kt)?;
    Ok(mu * p / kt)
}

/// K_T needed for a given saturation slip (mm): K_T = mu P / slip (MPa/mm). The paper's beam data set
/// is built this way: 0.3 * 1 MPa / 5e-4 mm = 600 MPa/mm.
///
/// # Errors
/// [`ParamError`] naming the first of slip, mu, P outside its domain (the slip: > 0 and finite),
/// or `KT` when the K_T it gives is outside the K_T domain.
pub fn stiffness_for_saturation_slip(mu: f64, pressure: f64, slip: f64) -> Result<f64, ParamError> {
    if !(slip.is_finite() && slip > 0.0) {
        let any_positive = Domain::Positive {
            min: f64::MIN_POSITIVE,
            max: f64::MAX,
        };
        return any_positive.check("slip", slip, Unit::Millimetre);
    }
    let mu = checked(FRICTION, mu)?;
    let p = checked_pressure(pressure)?;
    checked(STIFFNESS, mu * p / slip)
}

/// MPa/mm to MPa/um.
pub fn mpa_per_mm_to_mpa_per_um(kt: f64) -> f64 {
    kt / UM_PER_MM
}

/// MPa/um to MPa/mm.
pub fn mpa_per_um_to_mpa_per_mm(kt: f64) -> f64 {
    kt * UM_PER_MM
}

/// mm to um.
pub fn mm_to_um(length: f64) -> f64 {
    length * UM_PER_MM
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sherif_kossa_ratio_at_common_poisson_ratios() {
        // nu = 0: pi / 4; nu = 0.3: 0.7 pi / 3.4.
        assert!(
            (tangential_to_normal_ratio(0.0).unwrap() - std::f64::consts::FRAC_PI_4).abs() < 1e-15
        );
        let r = tangential_to_normal_ratio(0.3).unwrap();
        assert!((r - 0.7 * std::f64::consts::PI / 3.4).abs() < 1e-15);
        assert!((0.5..0.7).contains(&r));
        assert!((tangential_from_normal(1000.0, 0.3).unwrap() - 1000.0 * r).abs() < 1e-12);
        assert_eq!(tangential_from_normal(-1.0, 0.3).unwrap_err().field, "KN");
        assert_eq!(tangential_from_normal(1.0, 0.5).unwrap_err().field, "nu");
    }

    #[test]
    fn paper_beam_stiffness_from_its_saturation_slip() {
        assert!((stiffness_for_saturation_slip(0.3, 1.0, 5e-4).unwrap() - 600.0).abs() < 1e-9);
        assert!((saturation_slip(0.3, 1.0, 600.0).unwrap() - 5e-4).abs() < 1e-18);
    }

    #[test]
    fn conversions_round_trip() {
        assert_eq!(mpa_per_mm_to_mpa_per_um(600.0), 0.6);
        assert_eq!(mpa_per_um_to_mpa_per_mm(0.6), 600.0);
        assert_eq!(mm_to_um(5e-4), 0.5);
    }
}
