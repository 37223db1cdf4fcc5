//! The press fit's closed forms against its independent discretized solver, their limits and
//! their invariances (docs/theory.md section 18). No expected value here was read off the code's
//! own output: each is a hand formula, an independent solver, or a property.

use super::closed_form::{PressFit, SlipFace};
use super::discretized::PressFitFe;
use super::params::{FitLoad, PressFitParams};
use crate::kernel::regime::{Law, Regime, Zone};
use crate::numeric::MeshDensity;

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// Six fits from short and soft to long and stiff, solid and hollow shafts, each member the more
/// compliant in turn, and one of equal rigidities.
fn geometries() -> [(&'static str, PressFitParams); 6] {
    let steel = PressFitParams::CCX98;
    [
        ("ccx98 hollow steel", steel),
        (
            "short soft solid polymer",
            PressFitParams {
                fit_radius: 5.0,
                bore_radius: 0.0,
                outer_radius: 12.0,
                length: 3.0,
                shaft_modulus: 3000.0,
                shaft_poisson: 0.4,
                hub_modulus: 3000.0,
                hub_poisson: 0.4,
                interference: 0.01,
                friction: 0.3,
                tangential_stiffness: 100.0,
            },
        ),
        (
            "long stiff solid steel",
            PressFitParams {
                fit_radius: 25.0,
                bore_radius: 0.0,
                outer_radius: 60.0,
                length: 120.0,
                interference: 0.02,
                friction: 0.15,
                tangential_stiffness: 1e5,
                ..steel
            },
        ),
        (
            "thin aluminium tube in a steel hub",
            PressFitParams {
                bore_radius: 18.0,
                outer_radius: 40.0,
                length: 30.0,
                shaft_modulus: 70_000.0,
                shaft_poisson: 0.33,
                interference: 0.01,
                friction: 0.2,
                tangential_stiffness: 3e3,
                ..steel
            },
        ),
        (
            "steel pin in a thin aluminium ring",
            PressFitParams {
                fit_radius: 10.0,
                bore_radius: 0.0,
                outer_radius: 11.0,
                length: 20.0,
                hub_modulus: 70_000.0,
                hub_poisson: 0.33,
                interference: 0.005,
                friction: 0.12,
                tangential_stiffness: 1e4,
                ..steel
            },
        ),
        (
            "equal sections, solid",
            PressFitParams {
                bore_radius: 0.0,
                outer_radius: 20.0 * std::f64::consts::SQRT_2,
                length: 25.0,
                ..steel
            },
        ),
    ]
}

/// The discretized solver's answers at `loads` (and its own F_1) on `elements` elements, then on
/// twice as many, extrapolated to zero element size (Richardson: the error falls as h^2,
/// measured in the lap joint's solver, docs/theory.md section 5): (F_1, [(Delta, zone from x =
/// 0, zone from x = L)]).
fn extrapolated(
    params: PressFitParams,
    load: FitLoad,
    loads: &[f64],
    elements: usize,
) -> (f64, Vec<[f64; 3]>) {
    let solve = |n: usize| {
        let mut fe = PressFitFe::new(params, load, MeshDensity::with_elements(n));
        // Linear below F_1: mu p over the largest shear at a small load, times that load.
        let probe = 1e-3 * loads[0];
        fe.load_to(probe, 1).unwrap();
        let mu_p = params.friction
            * super::lame::contact_pressure(&params, super::lame::PlaneState::Stress);
        let first = mu_p / fe.peak_shear() * probe;
        let mut rows = Vec::new();
        for &f in loads {
            fe.load_to(f, 2).unwrap();
            let (a, d) = fe.sliding_zones();
            rows.push([fe.response(), a, d]);
        }
        (first, rows)
    };
    let (coarse, fine) = (solve(elements), solve(2 * elements));
    let richardson = |c: f64, f: f64| (4.0 * f - c) / 3.0;
    let rows = coarse
        .1
        .iter()
        .zip(&fine.1)
        .map(|(c, f)| std::array::from_fn(|i| richardson(c[i], f[i])))
        .collect();
    (richardson(coarse.0, fine.0), rows)
}

#[test]
fn the_closed_forms_agree_with_the_discretized_solver_to_1e_6() {
    for (name, params) in geometries() {
        let fit = PressFit::new(params).unwrap();
        for axis in [fit.axial(), fit.torsion()] {
            let gross = axis.gross_load();
            let f1 = axis.first_slip_load();
            let mut loads = [0.5 * f1, 0.3 * gross, 0.8 * gross];
            loads.sort_by(f64::total_cmp);
            let (fe_first, rows) = extrapolated(params, axis.load_kind(), &loads, 1600);
            let kind = axis.load_kind();
            assert!(
                rel(fe_first, f1) < 1e-6,
                "{name} {kind:?}: F_1 {f1} FE {fe_first}"
            );
            for (&f, [delta, a, d]) in loads.iter().zip(rows) {
                let state = axis.regularized(axis.load(f).unwrap());
                assert!(
                    rel(delta, state.response()) < 1e-6,
                    "{name} {kind:?} at {f}: Delta {} FE {delta} ({:.2e})",
                    state.response(),
                    rel(delta, state.response())
                );
                let off = (a - state.slide_from_loaded_face())
                    .abs()
                    .max((d - state.slide_from_held_face()).abs());
                assert!(
                    off < 1e-4 * params.length,
                    "{name} {kind:?} at {f}: zones off {off}"
                );
            }
        }
    }
}

/// Each load by hand, (S6): (load, arm, the shaft's and the hub's rigidities as bars on the
/// interface): E A pushed out; G J / r^2 twisted, with G = E / (2 (1 + nu)), J = pi/2 (r^4 - ri^4).
fn loadings_by_hand(params: &PressFitParams) -> [(FitLoad, f64, f64, f64); 2] {
    use std::f64::consts::PI;
    let (ri, r, ro) = (params.bore_radius, params.fit_radius, params.outer_radius);
    let g = |e: f64, nu: f64| e / (2.0 * (1.0 + nu));
    [
        (
            FitLoad::Axial,
            1.0,
            params.shaft_modulus * PI * (r * r - ri * ri),
            params.hub_modulus * PI * (ro * ro - r * r),
        ),
        (
            FitLoad::Torque,
            r,
            g(params.shaft_modulus, params.shaft_poisson) * PI / 2.0 * (r.powi(4) - ri.powi(4))
                / (r * r),
            g(params.hub_modulus, params.hub_poisson) * PI / 2.0 * (ro.powi(4) - r.powi(4))
                / (r * r),
        ),
    ]
}

/// (L7) in the fit's words, by hand: under Coulomb the zone from each face carries the load the
/// member that is loaded there hands on, in proportion to the other member's rigidity:
/// a (loaded face) = F Eh Ah / ((Es As + Eh Ah) w mu p), d (held face) = F Es As / (...), and the
/// slip at each face is its slope times its zone over 2. Twisted, the same with the equivalent
/// force N = T / r and the equivalent bars' rigidities G J / r^2 (S6): T_gross = mu p 2 pi r^2 L,
/// the slip circumferential (mm) and theta = Delta_eq / r.
#[test]
fn coulomb_by_hand_and_as_the_limit_of_the_regularized_law() {
    use std::f64::consts::PI;
    for (name, params) in geometries() {
        let fit = PressFit::new(params).unwrap();
        let p = super::lame::contact_pressure(&params, super::lame::PlaneState::Stress);
        let w = 2.0 * PI * params.fit_radius;
        for (load, arm, shaft, hub) in loadings_by_hand(&params) {
            let axis = fit.axis(load);
            let gross = params.friction * p * w * params.length * arm;
            assert!(rel(axis.gross_load(), gross) < 1e-13, "{name}");
            for fraction in [0.1, 0.3, 0.8] {
                let f = fraction * gross / arm;
                let state = axis.coulomb(axis.load(f * arm).unwrap());
                let a = f * hub / ((shaft + hub) * w * params.friction * p);
                let d = f * shaft / ((shaft + hub) * w * params.friction * p);
                assert!(rel(state.slide_from_loaded_face(), a) < 1e-12, "{name}");
                assert!(rel(state.slide_from_held_face(), d) < 1e-12, "{name}");
                let (s_loaded, s_held) = (f / shaft * a / 2.0, f / hub * d / 2.0);
                // The slip is the equivalent bars' (mm): r (phi_shaft - phi_hub) twisted.
                assert!(rel(state.slip_at(0.0), s_loaded) < 1e-12, "{name}");
                assert!(rel(state.slip_at(params.length), s_held) < 1e-12, "{name}");
                let delta = hub / (shaft + hub) * s_loaded
                    + shaft / (shaft + hub) * s_held
                    + f * params.length / (shaft + hub);
                assert!(rel(state.response() * arm, delta) < 1e-12, "{name}");
                assert_eq!(
                    state.regime(),
                    Regime::from_zones(&[Zone::Macroslip, Zone::Stick, Zone::Macroslip])
                );
                // K_T -> infinity: the gap to Coulomb falls as 1/K_T (x100 per x100).
                let gap = |kt: f64| {
                    let stiff = fit.with_tangential_stiffness(kt).unwrap();
                    let axis = stiff.axis(load);
                    axis.regularized(axis.load(f * arm).unwrap()).response() * arm / delta - 1.0
                };
                let (g1, g2) = (gap(1e8), gap(1e10));
                assert!(g1 > 0.0 && g2 > 0.0, "{name}");
                assert!((g1 / g2 / 100.0 - 1.0).abs() < 0.02, "{name}: {g1} {g2}");
                assert!(g2 < 1e-4, "{name}: {g2}");
            }
        }
    }
}

/// Delta and its slope dDelta/dF are continuous where the regime changes, at F_1 and F_2.
#[test]
fn delta_and_its_slope_are_continuous_at_each_regime_change() {
    for (name, params) in geometries() {
        let fit = PressFit::new(params).unwrap();
        for axis in [fit.axial(), fit.torsion()] {
            let at = |f: f64| axis.regularized(axis.load(f).unwrap()).response();
            for change in [axis.first_slip_load(), axis.second_slip_load()] {
                if change >= 0.999 * axis.gross_load() {
                    continue;
                }
                let h = 1e-6 * change;
                let (below, above) = (at(change - h), at(change + h));
                assert!(rel(above, below) < 1e-5, "{name}: {below} {above}");
                let left = (at(change - h) - at(change - 2.0 * h)) / h;
                let right = (at(change + 2.0 * h) - at(change + h)) / h;
                assert!(
                    rel(right, left) < 1e-4,
                    "{name} at {change}: {left} {right}"
                );
                // And the regime does change there.
                let (r0, r1) = (
                    axis.regularized(axis.load(change - h).unwrap()).regime(),
                    axis.regularized(axis.load(change + h).unwrap()).regime(),
                );
                assert_ne!(r0, r1, "{name} at {change}");
            }
        }
    }
}

#[test]
fn delta_grows_with_the_load_and_falls_with_k_t_and_the_zones_grow() {
    for (name, params) in geometries() {
        let fit = PressFit::new(params).unwrap();
        for axis in [fit.axial(), fit.torsion()] {
            for law in [Law::Coulomb, Law::Regularized] {
                let mut last = (0.0, 0.0, 0.0);
                for i in 1..=200 {
                    let f = axis.gross_load() * i as f64 / 200.0;
                    let s = axis.solve(law, axis.clamped(f));
                    let now = (
                        s.response(),
                        s.slide_from_loaded_face(),
                        s.slide_from_held_face(),
                    );
                    assert!(now.0 > last.0, "{name} {law:?} {i}");
                    assert!(now.1 >= last.1 && now.2 >= last.2, "{name} {law:?} {i}");
                    last = now;
                }
            }
            let mut last = f64::INFINITY;
            for k in -2..=10 {
                let stiff = fit.with_tangential_stiffness(10f64.powi(k)).unwrap();
                let axis = stiff.axis(axis.load_kind());
                let delta = axis
                    .regularized(axis.load(0.6 * axis.gross_load()).unwrap())
                    .response();
                assert!(delta < last, "{name} K_T 1e{k}");
                last = delta;
            }
        }
    }
}

/// Lengths times k and K_T over k leave p and every stress alone: forces grow as k^2, Delta as
/// k. Moduli, K_T and the load times s leave Delta alone (p grows as s).
#[test]
fn the_answers_scale_as_dimensional_analysis_says() {
    for (name, params) in geometries() {
        let fit = PressFit::new(params).unwrap();
        let k = 3.7;
        let longer = PressFit::new(PressFitParams {
            fit_radius: k * params.fit_radius,
            bore_radius: k * params.bore_radius,
            outer_radius: k * params.outer_radius,
            length: k * params.length,
            interference: k * params.interference,
            tangential_stiffness: params.tangential_stiffness / k,
            ..params
        })
        .unwrap();
        let s = 0.37;
        let softer = PressFit::new(PressFitParams {
            shaft_modulus: s * params.shaft_modulus,
            hub_modulus: s * params.hub_modulus,
            tangential_stiffness: s * params.tangential_stiffness,
            ..params
        })
        .unwrap();
        assert!(rel(longer.contact_pressure(), fit.contact_pressure()) < 1e-13);
        assert!(rel(softer.contact_pressure(), s * fit.contact_pressure()) < 1e-13);
        for (one, other, force, response) in [(&fit, &longer, k * k, k), (&fit, &softer, s, 1.0)] {
            assert!(rel(other.gross_slip_force(), force * one.gross_slip_force()) < 1e-12);
            assert!(rel(other.first_slip_force(), force * one.first_slip_force()) < 1e-12);
            assert!(rel(other.second_slip_force(), force * one.second_slip_force()) < 1e-10);
            for fraction in [0.3, 0.8] {
                let f = fraction * one.gross_slip_force();
                for law in [Law::Coulomb, Law::Regularized] {
                    let a = one.axial().solve(law, one.force(f).unwrap());
                    let b = other.axial().solve(law, other.axial().clamped(force * f));
                    assert!(rel(b.response(), response * a.response()) < 1e-10, "{name}");
                }
            }
        }
    }
}

/// The torque is the push-out of members whose axial rigidities are G J / r^2, loaded by T / r,
/// with theta = Delta / r: checked by building that push-out from the inputs (moduli chosen so
/// that E A = G J / r^2, the interference so that Lamé's p stays) and comparing; and the bonded
/// twist by hand, theta = T L / (Gs Js + Gh Jh).
#[test]
fn the_torque_is_the_push_out_with_the_equivalent_rigidities() {
    use std::f64::consts::PI;
    for (name, params) in geometries() {
        let fit = PressFit::new(params).unwrap();
        let (ri, r, ro) = (params.bore_radius, params.fit_radius, params.outer_radius);
        let g = |e: f64, nu: f64| e / (2.0 * (1.0 + nu));
        let js = PI / 2.0 * (r.powi(4) - ri.powi(4));
        let jh = PI / 2.0 * (ro.powi(4) - r.powi(4));
        let (gjs, gjh) = (
            g(params.shaft_modulus, params.shaft_poisson) * js,
            g(params.hub_modulus, params.hub_poisson) * jh,
        );
        let (a_s, a_h) = (PI * (r * r - ri * ri), PI * (ro * ro - r * r));
        let mut equivalent = PressFitParams {
            shaft_modulus: gjs / (r * r * a_s),
            hub_modulus: gjh / (r * r * a_h),
            ..params
        };
        // The same p: delta in proportion to the new radial compliance.
        let p = fit.contact_pressure();
        equivalent.interference = p * params.interference
            / super::lame::contact_pressure(&equivalent, super::lame::PlaneState::Stress);
        let pushed = PressFit::new(equivalent).unwrap();
        assert!(rel(pushed.contact_pressure(), p) < 1e-13, "{name}");
        let twist = fit.torsion();
        assert!(rel(twist.gross_load(), r * pushed.gross_slip_force()) < 1e-12);
        assert!(
            rel(
                twist.gross_load(),
                params.friction * p * 2.0 * PI * r * r * params.length
            ) < 1e-12
        );
        assert!(
            rel(twist.first_slip_load(), r * pushed.first_slip_force()) < 1e-10,
            "{name}"
        );
        assert!(
            rel(twist.second_slip_load(), r * pushed.second_slip_force()) < 1e-10,
            "{name}"
        );
        assert!(rel(twist.bonded_compliance(), params.length / (gjs + gjh)) < 1e-12);
        for fraction in [0.1, 0.5, 0.9] {
            let t = fraction * twist.gross_load();
            for law in [Law::Coulomb, Law::Regularized] {
                let theta = twist.solve(law, twist.load(t).unwrap());
                let delta = pushed.axial().solve(law, pushed.axial().clamped(t / r));
                assert!(
                    rel(theta.response() * r, delta.response()) < 1e-10,
                    "{name}"
                );
                assert!(
                    rel(
                        theta.slide_from_loaded_face() + 1.0,
                        delta.slide_from_loaded_face() + 1.0
                    ) < 1e-10
                );
            }
        }
    }
}

/// (L8) for the fit: a rigid hub (Eh -> infinity) leaves the shaft alone against a rough base:
/// F_1 = mu p w tanh(lambda L) / lambda with lambda^2 = w K_T / (Es As), and sliding starts at
/// the loaded face. Twisted, the shaft is the equivalent bar of rigidity Gs Js / r^2 carrying
/// N = T / r: T_1 = r mu p w tanh(lambda L) / lambda with lambda^2 = w K_T r^2 / (Gs Js).
#[test]
fn a_rigid_hub_gives_the_bar_on_a_rough_base() {
    let params = PressFitParams {
        hub_modulus: 1e7,
        ..PressFitParams::CCX98
    };
    let fit = PressFit::new(params).unwrap();
    let p = fit.contact_pressure();
    let w = 2.0 * std::f64::consts::PI * params.fit_radius;
    for (load, arm, shaft, hub) in loadings_by_hand(&params) {
        let lambda = (w * params.tangential_stiffness / shaft).sqrt();
        let by_hand = arm * params.friction * p * w * (lambda * params.length).tanh() / lambda;
        // The hub is 48 x the shaft's modulus (x 4.3 its J, x 1.7 its area): the first slip
        // within the hub's share of the compliance.
        let axis = fit.axis(load);
        assert!(
            rel(axis.first_slip_load(), by_hand) < 2.0 * shaft / hub,
            "{load:?}"
        );
        assert_eq!(axis.first_slip_face(), SlipFace::Loaded);
    }
}

#[test]
fn errors_name_the_field_the_value_and_the_range() {
    let base = PressFitParams::CCX98;
    let outside = PressFitParams {
        outer_radius: 20.0,
        ..base
    };
    assert_eq!(
        PressFit::new(outside).unwrap_err().to_string(),
        "invalid ro = 20: must be in [20, 1e6] mm (ro > r: the hub needs a wall; equal radii are \
         refused)"
    );
    let negative = PressFitParams {
        interference: -0.001,
        ..base
    };
    assert_eq!(
        PressFit::new(negative).unwrap_err().to_string(),
        "invalid delta = -0.001: must be > 0 and finite (mm)"
    );
    let fit = PressFit::new(base).unwrap();
    let message = fit.force(2000.0).unwrap_err().to_string();
    assert!(
        message.starts_with("invalid F = 2000: must be in [0, 1371")
            && message.ends_with("N (F_gross = mu p 2 pi r L: the shaft slides out beyond it)"),
        "{message}"
    );
    let message = fit.torsion().load(1e6).unwrap_err().to_string();
    assert!(
        message.starts_with("invalid T = 1e6: must be in [0, 27420"),
        "{message}"
    );
    assert!(
        message.contains("N mm (T_gross = mu p 2 pi r^2 L"),
        "{message}"
    );
}

/// The bundled fit: its slip starts at the loaded face (the hollow shaft, Es As = 1.98e8 N,
/// is softer than the hub, Eh Ah = 3.30e8 N), and the smallest K_T within 1 % of Coulomb's Delta
/// at 0.5 F_gross gives exactly 1 % there.
#[test]
fn the_bundled_fit_and_its_stiffness_for_a_tolerance() {
    let fit = PressFit::new(PressFitParams::CCX98).unwrap();
    assert_eq!(fit.first_slip_face(), SlipFace::Loaded);
    assert!(fit.first_slip_force() < fit.second_slip_force());
    assert!((fit.plane_strain_pressure() - 6.152_343_75 / 0.91).abs() < 1e-9);
    let force = fit.force(0.5 * fit.gross_slip_force()).unwrap();
    let kt = fit.axial().stiffness_within(force, 0.01).unwrap();
    let at = fit.with_tangential_stiffness(kt).unwrap();
    let ratio = at.regularized(force).response() / fit.coulomb(force).response();
    assert!((ratio - 1.01).abs() < 1e-9, "{kt} {ratio}");
    let found = fit
        .axial()
        .stiffness_for_response(force, at.regularized(force).response())
        .unwrap();
    assert!(rel(found, kt) < 1e-6, "{found} {kt}");
}

/// The preset file beside this folder holds [`PressFitParams::CCX98`], key by key (a plain
/// `key = number` reading: the core has no TOML reader), and a load the fit carries.
#[test]
fn the_preset_file_is_the_bundled_fit() {
    use super::params::PressFitParam;
    let text = include_str!("../../../../../presets/pressfit-ccx98.toml");
    let value = |key: &str| {
        text.lines()
            .filter_map(|l| l.split_once('='))
            .find(|(k, _)| k.trim() == key)
            .and_then(|(_, v)| v.trim().parse::<f64>().ok())
            .unwrap_or_else(|| panic!("no {key}"))
    };
    let mut params = PressFitParams::CCX98;
    for param in PressFitParam::ALL {
        let key = param.spec().name;
        if let Some(field) = params.value_mut(param) {
            assert_eq!(*field, value(key), "{key}");
        }
    }
    let fit = PressFit::new(params).unwrap();
    assert!(fit.force(value("F")).is_ok());
    assert!((fit.gross_slip_force() - 1371.0).abs() < 1e-3);
}

/// The quantities a target can be set on are the states' own numbers, pushed out and twisted.
#[test]
fn the_quantities_are_the_states_numbers() {
    use crate::problems::Quantity;
    use crate::problems::load_driven::MasingCycle;
    let fit = PressFit::new(PressFitParams::CCX98).unwrap();
    for axis in [fit.axial(), fit.torsion()] {
        let load = axis.load(0.9 * axis.gross_load()).unwrap();
        let (coulomb, regularized) = (axis.coulomb(load), axis.regularized(load));
        let cycle = super::cycle::FitCycle::new(axis, Law::Regularized, load);
        let q = |quantity| super::quantity(axis, load, quantity).unwrap();
        assert_eq!(q(Quantity::Response), regularized.response());
        assert_eq!(
            q(Quantity::SlideFromStart),
            regularized.slide_from_loaded_face()
        );
        assert_eq!(
            q(Quantity::SlideFromEnd),
            regularized.slide_from_held_face()
        );
        assert_eq!(
            q(Quantity::Ratio),
            regularized.response() / coulomb.response()
        );
        assert_eq!(q(Quantity::FirstMacroslipForce), axis.first_slip_load());
        assert_eq!(q(Quantity::Dissipation), regularized.cycle_dissipation());
        assert_eq!(q(Quantity::DampingRatio), cycle.damping_ratio());
        assert!(q(Quantity::Dissipation) > 0.0);
        assert_eq!(super::quantity(axis, load, Quantity::MicroEnd), None);
        // Zero load: no ratio.
        let zero = axis.load(0.0).unwrap();
        assert_eq!(super::quantity(axis, zero, Quantity::Ratio), None);
    }
    // T_gross = r F_gross (S6): the gross load does not depend on the members' rigidities.
    let r = PressFitParams::CCX98.fit_radius;
    assert!(rel(fit.torsion().gross_load(), r * fit.gross_slip_force()) < 1e-13);
}

/// The twisted fit's keys are the push-out's with T for F; its quantities name theta (rad) and
/// T_1 (N mm) where the push-out's name Delta (mm) and F_1 (N), and the same zones.
#[test]
fn the_torque_keys_and_quantities_are_the_push_outs_with_t_for_f() {
    use super::params::PressFitParam;
    let names = |keys: &[PressFitParam]| {
        keys.iter()
            .map(|k| k.spec().name)
            .collect::<Vec<_>>()
            .join(" ")
    };
    assert_eq!(
        names(&PressFitParam::TORQUE_KEYS),
        "r ri ro L Es nus Eh nuh delta mu KT T"
    );
    assert_eq!(
        names(PressFitParam::PUSH_OUT),
        "r ri ro L Es nus Eh nuh delta mu KT F"
    );
    let words = |q: &[crate::problems::QuantityName]| {
        q.iter()
            .map(|n| format!("{} ({})", n.name, n.unit))
            .collect::<Vec<_>>()
            .join(", ")
    };
    assert_eq!(
        words(&super::TORQUE_QUANTITIES),
        "theta (rad), a (mm), d (mm), ratio (), T_1 (N mm), D (N mm), zeta ()"
    );
    for (push, twist) in super::QUANTITIES.iter().zip(&super::TORQUE_QUANTITIES) {
        assert_eq!(push.quantity, twist.quantity);
    }
}
