//! The contact pressure of the shrink fit: Lamé's thick cylinders (docs/theory.md section 18,
//! (S2)). The hub, pressed open by p on its bore, and the shaft, pressed shut by p on its outside,
//! must together take up the radial interference delta: u_hub(r) - u_shaft(r) = delta.
//!
//! Plane stress (sigma_z = 0: short members free at their ends, the value the issue asks for) is
//! the one the closed forms use; plane strain (epsilon_z = 0: long members) is given beside it.
//! The assumptions are those of section 18: p uniform over L (no raised pressure near the hub's
//! faces), no Poisson coupling of the push-out's axial stress into p, no shear left at the
//! interface after assembly.

use super::params::PressFitParams;

/// Which of the two 2-D idealisations of the cylinders' axial direction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PlaneState {
    /// sigma_z = 0.
    Stress,
    /// epsilon_z = 0: E -> E / (1 - nu^2), nu -> nu / (1 - nu) in the plane-stress formulas.
    Strain,
}

impl PlaneState {
    /// (E, nu) as the plane-stress formulas take them.
    fn effective(self, modulus: f64, poisson: f64) -> (f64, f64) {
        match self {
            PlaneState::Stress => (modulus, poisson),
            PlaneState::Strain => (
                modulus / ((1.0 - poisson) * (1.0 + poisson)),
                poisson / (1.0 - poisson),
            ),
        }
    }
}

/// The radial compliances of the two members at the fit radius (mm/MPa): the hub's bore opens by
/// p c_hub and the shaft's outside closes by p c_shaft,
///
/// ```text
/// c_hub   = (r / Eh) [(ro^2 + r^2) / (ro^2 - r^2) + nuh],
/// c_shaft = (r / Es) [(r^2 + ri^2) / (r^2 - ri^2) - nus],
/// ```
///
/// with (E, nu) of `PlaneState::effective`. Both are positive on the accepted domain.
pub fn radial_compliances(params: &PressFitParams, state: PlaneState) -> (f64, f64) {
    let (r, ri, ro) = (params.fit_radius, params.bore_radius, params.outer_radius);
    let (eh, nuh) = state.effective(params.hub_modulus, params.hub_poisson);
    let (es, nus) = state.effective(params.shaft_modulus, params.shaft_poisson);
    // (ro^2 + r^2)/(ro^2 - r^2) with the difference as a product: a thin wall keeps its digits.
    let hub = (ro * ro + r * r) / ((ro - r) * (ro + r));
    let shaft = (r * r + ri * ri) / ((r - ri) * (r + ri));
    (r / eh * (hub + nuh), r / es * (shaft - nus))
}

/// Lamé's contact pressure p = delta / (c_hub + c_shaft) (MPa), (S2).
pub fn contact_pressure(params: &PressFitParams, state: PlaneState) -> f64 {
    let (hub, shaft) = radial_compliances(params, state);
    params.interference / (hub + shaft)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The general Lamé solution of one cylinder a <= rho <= b loaded by pressures p_a inside
    /// and p_b outside: sigma_rho = A - B / rho^2, sigma_theta = A + B / rho^2, with the two
    /// boundary conditions sigma_rho(a) = -p_a, sigma_rho(b) = -p_b solved here as a 2x2 system
    /// (not the closed compliances above); a solid cylinder (a = 0) has B = 0. Returns
    /// (sigma_rho, sigma_theta) at `rho`, after checking both boundary conditions.
    fn stresses(a: f64, b: f64, p_a: f64, p_b: f64, rho: f64) -> (f64, f64) {
        let (x, y) = (1.0 / (a * a), 1.0 / (b * b));
        let (aa, bb) = if a == 0.0 {
            (-p_b, 0.0)
        } else {
            let bb = (p_b - p_a) / (y - x);
            (-p_a + bb * x, bb)
        };
        let scale = 1.0 + p_a.abs() + p_b.abs();
        if a > 0.0 {
            assert!((aa - bb * x + p_a).abs() < 1e-9 * scale);
        }
        assert!((aa - bb * y + p_b).abs() < 1e-9 * scale);
        (aa - bb / (rho * rho), aa + bb / (rho * rho))
    }

    /// The radial displacement u = rho eps_theta at `rho` from Hooke's law in plane stress,
    /// eps_theta = (sigma_theta - nu sigma_rho) / E.
    fn displacement(a: f64, b: f64, p_a: f64, p_b: f64, e: f64, nu: f64, rho: f64) -> f64 {
        let (sr, st) = stresses(a, b, p_a, p_b, rho);
        rho * (st - nu * sr) / e
    }

    #[test]
    fn the_pressure_closes_the_interference_in_plane_stress_and_in_plane_strain() {
        let base = PressFitParams::CCX98;
        let cases = [
            base,
            PressFitParams {
                bore_radius: 0.0,
                ..base
            },
            PressFitParams {
                bore_radius: 19.0,
                outer_radius: 21.0,
                hub_modulus: 70_000.0,
                hub_poisson: 0.33,
                ..base
            },
            PressFitParams {
                fit_radius: 3.0,
                bore_radius: 0.5,
                outer_radius: 300.0,
                shaft_modulus: 1e3,
                shaft_poisson: 0.49,
                interference: 0.01,
                ..base
            },
        ];
        for params in cases {
            let (r, ri, ro) = (params.fit_radius, params.bore_radius, params.outer_radius);
            for state in [PlaneState::Stress, PlaneState::Strain] {
                let p = contact_pressure(&params, state);
                assert!(p > 0.0 && p.is_finite());
                let (eh, nuh) = state.effective(params.hub_modulus, params.hub_poisson);
                let (es, nus) = state.effective(params.shaft_modulus, params.shaft_poisson);
                let hub = displacement(r, ro, p, 0.0, eh, nuh, r);
                let shaft = displacement(ri, r, 0.0, p, es, nus, r);
                assert!(
                    ((hub - shaft) / params.interference - 1.0).abs() < 1e-12,
                    "{params:?} {state:?}: {hub} - {shaft}"
                );
            }
            // Plane strain's eps_z = 0 directly: u = rho (1 + nu)/E [(1 - nu) sigma_theta - nu
            // sigma_rho]: the same pressure as the substituted constants give.
            let p = contact_pressure(&params, PlaneState::Strain);
            let strain_u = |a: f64, b: f64, pa: f64, pb: f64, e: f64, nu: f64| {
                // sigma_theta - nu' sigma_rho with E': the plane-stress u of the effective
                // material equals (1 + nu)/E [(1 - nu) st - nu sr] rho.
                let (e1, nu1) = PlaneState::Strain.effective(e, nu);
                displacement(a, b, pa, pb, e1, nu1, r)
            };
            let direct = |a: f64, b: f64, pa: f64, pb: f64, e: f64, nu: f64| {
                let (sr, st) = stresses(a, b, pa, pb, r);
                r * (1.0 + nu) / e * ((1.0 - nu) * st - nu * sr)
            };
            for (a, b, pa, pb, e, nu) in [
                (r, ro, p, 0.0, params.hub_modulus, params.hub_poisson),
                (ri, r, 0.0, p, params.shaft_modulus, params.shaft_poisson),
            ] {
                let (one, two) = (strain_u(a, b, pa, pb, e, nu), direct(a, b, pa, pb, e, nu));
                assert!(((one - two) / two).abs() < 1e-12, "{one} {two}");
            }
        }
    }

    #[test]
    fn the_bundled_fit_s_pressure_by_hand() {
        // r = 20, ri = 10, ro = 30, delta = 0.0025, E = 210000, nu = 0.3: hub 1300/500 + 0.3 =
        // 2.9, shaft 500/300 - 0.3 = 41/30; p = 0.0025 * 210000 / (20 * (2.9 + 41/30)).
        let by_hand = 0.0025 * 210_000.0 / (20.0 * (2.9 + 41.0 / 30.0));
        let p = contact_pressure(&PressFitParams::CCX98, PlaneState::Stress);
        assert!((p / by_hand - 1.0).abs() < 1e-14, "{p} {by_hand}");
        assert!((p - 6.152_343_75).abs() < 1e-8, "{p}");
        // Plane strain, same moduli and ratios: the nu terms cancel in the sum (+nu' - nu'), so
        // p grows by 1 / (1 - nu^2) exactly.
        let strain = contact_pressure(&PressFitParams::CCX98, PlaneState::Strain);
        assert!((strain * (1.0 - 0.09) / p - 1.0).abs() < 1e-14);
    }
}
