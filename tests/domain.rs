//! The accepted domain of both models (docs/theory.md, "Accepted domain"), sampled log-uniformly
//! between its bounds and at its corners: every output finite, regimes consistent with the
//! thresholds, the ordering the theory proves between the two laws, and exact dimensional scaling.
//!
//! Change of units: lengths x s and stresses (E, P) x sigma leave mu and nu alone and give
//! F x sigma s^2, K_T x sigma / s (a stress per length); then every length the models return (X, X_s,
//! X_r, w, u, slip) scales by s, every stress (tau) by sigma, every force (F_thre, F_1) by sigma s^2,
//! every energy (D, U in N mm) by sigma s^3, a stiffness in N/mm by sigma s, and dimensionless
//! numbers (P_r/P, zeta) not at all. The dimensionless groups the closed forms depend on, k L,
//! alpha L, alpha l, F / F_thre, are unchanged, so the regimes are too.

mod common;

use microslip::kernel::params::Domain;
use microslip::problems::twin_beams::closed_form::BeamTheory;
use microslip::problems::twin_beams::cycle::{BeamsCycle, Law, MasingCycle};
use microslip::problems::{BeamParam, PlateParam};
use microslip::{PlateParams, Regime, SqueezedPlate, TipForce, TwinBeams, TwinBeamsParams};
use proptest::prelude::*;

const CASES: u32 = 400;

/// A value of `domain`: either end, or log-uniform between them.
fn in_domain(domain: Domain) -> impl Strategy<Value = f64> {
    let (min, max) = (domain.min(), domain.max());
    prop_oneof![
        1 => Just(min),
        1 => Just(max),
        6 => (0.0..=1.0_f64).prop_map(move |t| domain.clamp(min * (max / min).powf(t))),
    ]
}

/// Poisson ratio: either end (0 and the largest f64 below 0.5), or uniform.
fn poisson() -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => Just(0.0),
        1 => Just(0.5_f64.next_down()),
        6 => 0.0..0.5_f64,
    ]
}

fn beam_params() -> impl Strategy<Value = TwinBeamsParams> {
    (
        in_domain(BeamParam::Length.spec().domain),
        in_domain(BeamParam::Width.spec().domain),
        in_domain(BeamParam::HalfHeight.spec().domain),
        in_domain(BeamParam::Modulus.spec().domain),
        in_domain(BeamParam::Pressure.spec().domain),
        in_domain(BeamParam::Friction.spec().domain),
        in_domain(BeamParam::Stiffness.spec().domain),
        poisson(),
        any::<bool>(),
    )
        .prop_map(
            |(length, width, half_height, e, p, mu, kt, nu, timoshenko)| TwinBeamsParams {
                length,
                width,
                half_height,
                youngs_modulus: e,
                pressure: p,
                friction: mu,
                tangential_stiffness: kt,
                poisson: nu,
                theory: if timoshenko {
                    BeamTheory::Timoshenko
                } else {
                    BeamTheory::EulerBernoulli
                },
            },
        )
}

fn plate_params() -> impl Strategy<Value = PlateParams> {
    (
        in_domain(PlateParam::HalfLength.spec().domain),
        in_domain(PlateParam::Thickness.spec().domain),
        in_domain(PlateParam::Modulus.spec().domain),
        poisson(),
        in_domain(PlateParam::Friction.spec().domain),
        in_domain(PlateParam::Pressure.spec().domain),
        in_domain(PlateParam::Stiffness.spec().domain),
    )
        .prop_map(|(l, t, e, nu, mu, p, kt)| PlateParams {
            half_length: l,
            thickness: t,
            youngs_modulus: e,
            poisson: nu,
            friction: mu,
            pressure: p,
            tangential_stiffness: kt,
        })
}

/// How a test force is picked: 0, the largest force, a multiple of F_thre or of F_1, or anywhere
/// log-uniform in [1e-30, F_max] N. The force is clamped into its domain.
#[derive(Debug, Clone, Copy)]
enum ForcePick {
    Zero,
    Max,
    OfThreshold(f64),
    OfFirstMacroslip(f64),
    Anywhere(f64),
}

fn force_pick() -> impl Strategy<Value = ForcePick> {
    let ratio = (-4.0..4.0_f64).prop_map(|e| 10f64.powf(e));
    prop_oneof![
        1 => Just(ForcePick::Zero),
        1 => Just(ForcePick::Max),
        1 => Just(ForcePick::OfThreshold(1.0)),
        1 => Just(ForcePick::OfFirstMacroslip(1.0)),
        3 => ratio.clone().prop_map(ForcePick::OfThreshold),
        3 => ratio.prop_map(ForcePick::OfFirstMacroslip),
        2 => (0.0..=1.0_f64).prop_map(|t| ForcePick::Anywhere(1e-30 * 1e42_f64.powf(t))),
    ]
}

fn pick_force(beams: &TwinBeams, pick: ForcePick) -> f64 {
    let force = match pick {
        ForcePick::Zero => 0.0,
        ForcePick::Max => Domain::FORCE.max(),
        ForcePick::OfThreshold(r) => r * beams.threshold_force(),
        ForcePick::OfFirstMacroslip(r) => r * beams.first_macroslip_force(),
        ForcePick::Anywhere(f) => f,
    };
    Domain::FORCE.clamp(force)
}

/// a = b x scale to `tolerance` (relative), exact zeros allowed on both sides.
fn scales(a: f64, b: f64, scale: f64, tolerance: f64) -> bool {
    let expected = b * scale;
    a == expected || (a - expected).abs() <= tolerance * a.abs().max(expected.abs())
}

/// `a` within `tolerance` relative of `b` or above.
fn at_least(a: f64, b: f64, tolerance: f64) -> bool {
    a >= b - tolerance * b.abs()
}

fn all_finite(values: &[f64]) -> bool {
    values.iter().all(|v| v.is_finite())
}

/// Checks one twin-beam case; returns a description of the first violation.
fn check_beams(params: TwinBeamsParams, f: f64) -> Result<(), String> {
    let beams = TwinBeams::new(params).map_err(|e| format!("refused: {e}"))?;
    let force = TipForce::new(f).map_err(|e| format!("refused: {e}"))?;
    let p = params;
    let (f_thre, f_1) = (beams.threshold_force(), beams.first_macroslip_force());
    let fail = |what: &str| Err(format!("{what} (F_thre={f_thre}, F_1={f_1})"));
    if !(all_finite(&[f_thre, f_1, beams.decay_rate(), beams.saturation_slip()])
        && f_thre > 0.0
        && f_1 >= f_thre)
    {
        return fail("thresholds");
    }
    let (c, r) = (beams.coulomb(force), beams.regularized(force));
    // Regimes follow the thresholds; F = 0 is unloaded under both laws.
    let coulomb_regime = if f == 0.0 {
        Regime::UNLOADED
    } else if f > f_thre {
        Regime::MACROSLIP
    } else {
        Regime::STICK
    };
    let regularized_regime = if f == 0.0 {
        Regime::UNLOADED
    } else if f > f_1 {
        Regime::MICROSLIP_MACROSLIP
    } else {
        Regime::MICROSLIP
    };
    if c.regime() != coulomb_regime || r.regime() != regularized_regime {
        return fail(&format!("regimes {} / {}", c.regime(), r.regime()));
    }
    let x = r.micro_zone_end();
    if !((0.0..=p.length).contains(&x) && (r.regime().has_macroslip() || x == p.length)) {
        return fail(&format!("X = {x}"));
    }
    // Bonded pair (the stiffest) <= either law <= the two beams bending alone (no shear transfer),
    // each plus the shear deflection under Timoshenko's theory (the same for all three, (B13)).
    let bh3 = p.width * p.half_height.powi(3);
    let shear = match p.theory {
        BeamTheory::EulerBernoulli => 0.0,
        BeamTheory::Timoshenko => beams.shear_deflection(force),
    };
    let bending = f * p.length.powi(3) / (8.0 * p.youngs_modulus * bh3);
    let (bonded, free) = (bending + shear, 4.0 * bending + shear);
    let (wc, wr) = (c.tip_deflection(), r.tip_deflection());
    if !all_finite(&[wc, wr]) {
        return fail(&format!("w(L) = {wc}, {wr}"));
    }
    for w in [wc, wr] {
        if !(at_least(w, bonded, 1e-9) && at_least(free, w, 1e-9)) {
            return fail(&format!("w(L) = {w} outside [{bonded}, {free}]"));
        }
    }
    // The elastic interface is softer than the sticking Coulomb one.
    if f <= f_thre && !at_least(wr, wc, 1e-9) {
        return fail(&format!("w_reg = {wr} below w_Coulomb = {wc} in stick"));
    }
    let mu_p = beams.coulomb_stress();
    for s in [0.0, 0.5 * x, x, 0.5 * (x + p.length), p.length] {
        let values = [r.deflection(s), r.shear_stress(s), r.slip(s), c.slip(s)];
        if !all_finite(&values) || values.iter().any(|v| *v < 0.0) {
            return fail(&format!("at x = {s}: {values:?}"));
        }
        if r.shear_stress(s) > mu_p * (1.0 + 1e-9) {
            return fail(&format!("tau({s}) = {} above mu P", r.shear_stress(s)));
        }
    }
    // Cycles: finite, non-negative, the regularized one dissipating less than Coulomb.
    let (cc, cr) = (
        BeamsCycle::new(&beams, Law::Coulomb, force),
        BeamsCycle::new(&beams, Law::Regularized, force),
    );
    for cycle in [&cc, &cr] {
        let values = [
            cycle.onset(),
            cycle.peak_deflection(),
            cycle.dissipation(),
            cycle.peak_energy(),
            cycle.damping_ratio(),
            cycle.secant_stiffness(),
            cycle.unloading(0.0),
            cycle.reloading(-0.5 * f),
        ];
        if !all_finite(&values) || values[..6].iter().any(|v| *v < 0.0) {
            return fail(&format!("cycle: {values:?}"));
        }
        if cycle.secant_stiffness() <= 0.0 {
            return fail("secant stiffness");
        }
    }
    if !at_least(cc.dissipation(), cr.dissipation(), 1e-9) {
        return fail(&format!(
            "D_reg = {} above D_Coulomb = {}",
            cr.dissipation(),
            cc.dissipation()
        ));
    }
    Ok(())
}

/// Checks one plate case; returns a description of the first violation.
fn check_plate(params: PlateParams) -> Result<(), String> {
    let plate = SqueezedPlate::new(params).map_err(|e| format!("refused: {e}"))?;
    let p = params;
    let (c, r, cp) = (
        plate.coulomb(),
        plate.regularized(),
        plate.contact_pressure(),
    );
    let l = p.half_length;
    // Slide length of the Coulomb law, nu t_p / (mu (1 - nu)) (P3).
    let slide = p.poisson * p.thickness / (p.friction * (1.0 - p.poisson));
    // nu = 0: nothing squeezes the plate sideways, so the interface carries no shear at all.
    let coulomb_regime = if p.poisson == 0.0 {
        Regime::UNLOADED
    } else if slide >= l {
        Regime::MACROSLIP
    } else {
        Regime::STICK_MACROSLIP
    };
    if c.regime() != coulomb_regime {
        return Err(format!("Coulomb regime {} (slide {slide})", c.regime()));
    }
    let (xs, xr) = (c.stick_end(), r.micro_zone_end());
    if !((0.0..=l).contains(&xs) && (0.0..=l).contains(&xr) && xr >= xs) {
        return Err(format!("X_s = {xs}, X_r = {xr}"));
    }
    if r.regime() == Regime::MICROSLIP && xr != l {
        return Err(format!("microslip with X_r = {xr}"));
    }
    let (uc, ur) = (c.end_displacement(), r.end_displacement());
    // Free plane-strain expansion bounds both; the elastic interface lets the plate expand more.
    let free = p.poisson * (1.0 + p.poisson) * p.pressure * l / p.youngs_modulus;
    if !(all_finite(&[uc, ur]) && uc >= 0.0 && at_least(free, ur, 1e-9) && at_least(ur, uc, 1e-9)) {
        return Err(format!("u_C = {uc}, u_reg = {ur}, free {free}"));
    }
    let mu_p = p.friction * p.pressure;
    for x in [0.0, 0.5 * xr, xr, 0.5 * (xr + l), l] {
        let values = [
            r.displacement(x),
            r.shear_stress(x),
            c.displacement(x),
            c.shear_stress(x),
            cp.ratio(x),
        ];
        if !all_finite(&values) || values.iter().any(|v| *v < 0.0) {
            return Err(format!("at x = {x}: {values:?}"));
        }
        if r.shear_stress(x) > mu_p * (1.0 + 1e-9) {
            return Err(format!("tau({x}) = {} above mu P", r.shear_stress(x)));
        }
    }
    if !(cp.mean_deviation().is_finite() && cp.mean_deviation() >= 0.0) {
        return Err(format!("mean deviation {}", cp.mean_deviation()));
    }
    Ok(())
}

/// A change of units (s, sigma) that keeps every input of `p` (and the force `f`) in its domain:
/// `t_s`, `t_sigma` in [0, 1] pick where in the allowed ranges.
fn beam_units(p: &TwinBeamsParams, f: f64, t_s: f64, t_sigma: f64) -> (f64, f64) {
    let within = |d: Domain, v: f64| (d.min() / v, d.max() / v);
    let pick = |(lo, hi): (f64, f64), t: f64| {
        if lo >= hi {
            1.0
        } else {
            lo * (hi / lo).powf(t)
        }
    };
    let mut sigma_range = (0.0_f64, f64::INFINITY);
    for (d, v) in [
        (Domain::MODULUS, p.youngs_modulus),
        (Domain::PRESSURE, p.pressure),
    ] {
        let (lo, hi) = within(d, v);
        sigma_range = (sigma_range.0.max(lo), sigma_range.1.min(hi));
    }
    let sigma = pick(sigma_range, t_sigma);
    let mut s_range = (0.0_f64, f64::INFINITY);
    for v in [p.length, p.width, p.half_height] {
        let (lo, hi) = within(Domain::LENGTH, v);
        s_range = (s_range.0.max(lo), s_range.1.min(hi));
    }
    // K_T sigma / s in its domain, F sigma s^2 at most F_max.
    let (lo, hi) = within(Domain::STIFFNESS, p.tangential_stiffness);
    s_range = (s_range.0.max(sigma / hi), s_range.1.min(sigma / lo));
    if f > 0.0 {
        s_range.1 = s_range.1.min((Domain::FORCE.max() / (f * sigma)).sqrt());
    }
    if s_range.0 > s_range.1 {
        return (1.0, 1.0);
    }
    (pick(s_range, t_s), sigma)
}

fn scaled_beams(p: &TwinBeamsParams, s: f64, sigma: f64) -> TwinBeamsParams {
    TwinBeamsParams {
        length: p.length * s,
        width: p.width * s,
        half_height: p.half_height * s,
        youngs_modulus: p.youngs_modulus * sigma,
        pressure: p.pressure * sigma,
        friction: p.friction,
        tangential_stiffness: p.tangential_stiffness * sigma / s,
        ..*p
    }
}

/// True when `f` sits within round-off of a threshold, where the regime may legitimately differ
/// between two unit systems.
fn near(f: f64, threshold: f64) -> bool {
    (f - threshold).abs() <= 1e-12 * threshold
}

fn check_beam_scaling(p: TwinBeamsParams, f: f64, s: f64, sigma: f64) -> Result<(), String> {
    let q = scaled_beams(&p, s, sigma);
    let (a, b) = (
        TwinBeams::new(p).map_err(|e| e.to_string())?,
        TwinBeams::new(q).map_err(|e| format!("scaled: {e}"))?,
    );
    let fq = Domain::FORCE.clamp(f * sigma * s * s);
    let (fa, fb) = (TipForce::new(f).unwrap(), TipForce::new(fq).unwrap());
    let force = sigma * s * s;
    let tol = 1e-9;
    let check = |what: &str, ok: bool| {
        if ok {
            Ok(())
        } else {
            Err(format!("{what} (s = {s}, sigma = {sigma})"))
        }
    };
    check(
        "F_thre",
        scales(b.threshold_force(), a.threshold_force(), force, 1e-13),
    )?;
    check(
        "F_1",
        scales(
            b.first_macroslip_force(),
            a.first_macroslip_force(),
            force,
            1e-12,
        ),
    )?;
    let (ra, rb) = (a.regularized(fa), b.regularized(fb));
    let (ca, cb) = (a.coulomb(fa), b.coulomb(fb));
    if !near(f, a.first_macroslip_force()) && !near(f, a.threshold_force()) {
        check(
            "regimes",
            ra.regime() == rb.regime() && ca.regime() == cb.regime(),
        )?;
    }
    check(
        "w_C(L)",
        scales(cb.tip_deflection(), ca.tip_deflection(), s, 1e-12),
    )?;
    check(
        "w_reg(L)",
        scales(rb.tip_deflection(), ra.tip_deflection(), s, tol),
    )?;
    if !near(f, a.first_macroslip_force()) {
        check(
            "X",
            scales(rb.micro_zone_end(), ra.micro_zone_end(), s, tol),
        )?;
        check(
            "slip(L)",
            scales(rb.slip(q.length), ra.slip(p.length), s, tol),
        )?;
    }
    check(
        "w_reg(L/2)",
        scales(
            rb.deflection(0.5 * q.length),
            ra.deflection(0.5 * p.length),
            s,
            tol,
        ),
    )?;
    check(
        "tau(L)",
        scales(
            rb.shear_stress(q.length),
            ra.shear_stress(p.length),
            sigma,
            tol,
        ),
    )?;
    let energy = sigma * s * s * s;
    for law in [Law::Coulomb, Law::Regularized] {
        let (ya, yb) = (BeamsCycle::new(&a, law, fa), BeamsCycle::new(&b, law, fb));
        // D grows from 0 at the onset of sliding F_s like (F - F_s) (Coulomb) or (F - F_1)^(3/2):
        // a round-off change of F (the scaled F and F_s are rounded independently) changes D by
        // 1.5 x 2 eps F / (F - F_s) relative, which the tolerance adds. At F_s itself, not compared.
        if !near(f, ya.onset()) {
            let conditioning = 1.5 * 4.0 * f64::EPSILON * f / (f - ya.onset()).abs();
            check(
                &format!("{law:?} D"),
                scales(
                    yb.dissipation(),
                    ya.dissipation(),
                    energy,
                    tol + conditioning,
                ),
            )?;
            check(
                &format!("{law:?} zeta"),
                scales(
                    yb.damping_ratio(),
                    ya.damping_ratio(),
                    1.0,
                    tol + conditioning,
                ),
            )?;
        }
        check(
            &format!("{law:?} secant stiffness"),
            scales(yb.secant_stiffness(), ya.secant_stiffness(), sigma * s, tol),
        )?;
    }
    Ok(())
}

fn check_plate_scaling(p: PlateParams, s: f64, sigma: f64) -> Result<(), String> {
    let q = PlateParams {
        half_length: p.half_length * s,
        thickness: p.thickness * s,
        youngs_modulus: p.youngs_modulus * sigma,
        pressure: p.pressure * sigma,
        tangential_stiffness: p.tangential_stiffness * sigma / s,
        ..p
    };
    let (a, b) = (
        SqueezedPlate::new(p).map_err(|e| e.to_string())?,
        SqueezedPlate::new(q).map_err(|e| format!("scaled: {e}"))?,
    );
    let tol = 1e-9;
    let check = |what: &str, ok: bool| {
        if ok {
            Ok(())
        } else {
            Err(format!("{what} (s = {s}, sigma = {sigma})"))
        }
    };
    let (ca, cb, ra, rb) = (a.coulomb(), b.coulomb(), a.regularized(), b.regularized());
    // X_s = L - l: where l is within round-off of L, the regime may differ and X_s, a difference
    // of nearly equal lengths, carries the relative error 2 eps L / X_s of the rounded l.
    let slide = p.poisson * p.thickness / (p.friction * (1.0 - p.poisson));
    if !near(slide, p.half_length) {
        check("Coulomb regime", ca.regime() == cb.regime())?;
    }
    check(
        "u_C(L)",
        scales(cb.end_displacement(), ca.end_displacement(), s, 1e-12),
    )?;
    let conditioning = 8.0 * f64::EPSILON * p.half_length / ca.stick_end().max(f64::MIN_POSITIVE);
    check(
        "X_s",
        scales(cb.stick_end(), ca.stick_end(), s, 1e-12 + conditioning),
    )?;
    check(
        "u_reg(L)",
        scales(rb.end_displacement(), ra.end_displacement(), s, tol),
    )?;
    check(
        "X_r",
        scales(rb.micro_zone_end(), ra.micro_zone_end(), s, tol),
    )?;
    let (pa, pb) = (a.contact_pressure(), b.contact_pressure());
    for t in [0.0, 0.37, 1.0] {
        check(
            "P_r/P",
            scales(
                pb.ratio(t * q.half_length),
                pa.ratio(t * p.half_length),
                1.0,
                1e-9,
            ),
        )?;
    }
    check(
        "mean deviation",
        scales(pb.mean_deviation(), pa.mean_deviation(), 1.0, 1e-6),
    )?;
    Ok(())
}

fn plate_units(p: &PlateParams, t_s: f64, t_sigma: f64) -> (f64, f64) {
    let within = |d: Domain, v: f64| (d.min() / v, d.max() / v);
    let pick = |(lo, hi): (f64, f64), t: f64| {
        if lo >= hi {
            1.0
        } else {
            lo * (hi / lo).powf(t)
        }
    };
    let (e_lo, e_hi) = within(Domain::MODULUS, p.youngs_modulus);
    let (p_lo, p_hi) = within(Domain::PRESSURE, p.pressure);
    let sigma = pick((e_lo.max(p_lo), e_hi.min(p_hi)), t_sigma);
    let (l_lo, l_hi) = within(Domain::LENGTH, p.half_length);
    let (t_lo, t_hi) = within(Domain::LENGTH, p.thickness);
    let (k_lo, k_hi) = within(Domain::STIFFNESS, p.tangential_stiffness);
    let s_range = (
        l_lo.max(t_lo).max(sigma / k_hi),
        l_hi.min(t_hi).min(sigma / k_lo),
    );
    if s_range.0 > s_range.1 {
        return (1.0, 1.0);
    }
    (pick(s_range, t_s), sigma)
}

proptest! {
    #![proptest_config(common::fixed_seed(CASES))]

    #[test]
    fn every_accepted_beam_gives_finite_consistent_numbers(
        params in beam_params(),
        pick in force_pick(),
    ) {
        let beams = TwinBeams::new(params).unwrap();
        let f = pick_force(&beams, pick);
        let result = check_beams(params, f);
        prop_assert!(result.is_ok(), "{params:?} F = {f}: {}", result.unwrap_err());
    }

    #[test]
    fn every_accepted_plate_gives_finite_consistent_numbers(params in plate_params()) {
        let result = check_plate(params);
        prop_assert!(result.is_ok(), "{params:?}: {}", result.unwrap_err());
    }

    #[test]
    fn beams_scale_exactly_with_the_units(
        params in beam_params(),
        pick in force_pick(),
        t_s in 0.0..=1.0_f64,
        t_sigma in 0.0..=1.0_f64,
    ) {
        let beams = TwinBeams::new(params).unwrap();
        let f = pick_force(&beams, pick);
        let (s, sigma) = beam_units(&params, f, t_s, t_sigma);
        let result = check_beam_scaling(params, f, s, sigma);
        prop_assert!(result.is_ok(), "{params:?} F = {f}: {}", result.unwrap_err());
    }

    #[test]
    fn plates_scale_exactly_with_the_units(
        params in plate_params(),
        t_s in 0.0..=1.0_f64,
        t_sigma in 0.0..=1.0_f64,
    ) {
        let (s, sigma) = plate_units(&params, t_s, t_sigma);
        let result = check_plate_scaling(params, s, sigma);
        prop_assert!(result.is_ok(), "{params:?}: {}", result.unwrap_err());
    }
}

/// Every corner of a box, as the 2^n choices of its lower or upper end.
fn corners<const N: usize>(bounds: [(f64, f64); N]) -> impl Iterator<Item = [f64; N]> {
    (0..1_u32 << N).map(move |mask| {
        let mut corner = [0.0; N];
        for (i, (lo, hi)) in bounds.iter().enumerate() {
            corner[i] = if mask & (1 << i) == 0 { *lo } else { *hi };
        }
        corner
    })
}

fn ends(domain: Domain) -> (f64, f64) {
    (domain.min(), domain.max())
}

#[test]
fn every_corner_of_the_beam_domain() {
    let forces = |b: &TwinBeams| {
        [
            0.0,
            Domain::FORCE.max(),
            b.threshold_force(),
            b.first_macroslip_force(),
            1.5 * b.threshold_force(),
            2.0 * b.first_macroslip_force(),
        ]
        .map(|f| Domain::FORCE.clamp(f))
    };
    let bounds = [
        BeamParam::Length,
        BeamParam::Width,
        BeamParam::HalfHeight,
        BeamParam::Modulus,
        BeamParam::Pressure,
        BeamParam::Friction,
        BeamParam::Stiffness,
    ]
    .map(|p| ends(p.spec().domain));
    for [length, width, half_height, e, p, mu, kt] in corners(bounds) {
        let params = TwinBeamsParams {
            length,
            width,
            half_height,
            youngs_modulus: e,
            pressure: p,
            friction: mu,
            tangential_stiffness: kt,
            ..TwinBeamsParams::PAPER
        };
        let beams = TwinBeams::new(params).unwrap();
        for f in forces(&beams) {
            if let Err(e) = check_beams(params, f) {
                panic!("{params:?} F = {f}: {e}");
            }
        }
    }
}

#[test]
fn every_corner_of_the_plate_domain() {
    let mut bounds = PlateParam::ALL.map(|p| ends(p.spec().domain));
    bounds[3] = (0.0, 0.5_f64.next_down());
    for [l, t, e, nu, mu, p, kt] in corners(bounds) {
        let params = PlateParams {
            half_length: l,
            thickness: t,
            youngs_modulus: e,
            poisson: nu,
            friction: mu,
            pressure: p,
            tangential_stiffness: kt,
        };
        if let Err(e) = check_plate(params) {
            panic!("{params:?}: {e}");
        }
    }
}

#[test]
fn corners_map_onto_corners_under_a_change_of_units() {
    // The smallest structure (every length 1e-6 mm, E and P at their minimum) and, by s = 1e12,
    // sigma = 1, the largest (every length 1e6 mm), with K_T going from 1e6 to its minimum 1e-6;
    // then the same structure by s = 1e6, sigma = 1e8 and by an irregular change. Each pair is
    // checked both ways, at forces on both sides of F_thre and F_1 that both systems accept.
    let small = TwinBeamsParams {
        length: 1e-6,
        width: 1e-6,
        half_height: 1e-6,
        youngs_modulus: 1e-4,
        pressure: 1e-6,
        friction: 0.3,
        tangential_stiffness: 1e6,
        ..TwinBeamsParams::PAPER
    };
    let mut checked = 0;
    for (s, sigma) in [(1e12, 1.0), (1e6, 1e8), (3.7e9, 17.0)] {
        let big = scaled_beams(&small, s, sigma);
        let b = TwinBeams::new(small).unwrap();
        for f in [
            0.5 * b.threshold_force(),
            1.5 * b.threshold_force(),
            0.5 * (b.threshold_force() + b.first_macroslip_force()),
            3.0 * b.first_macroslip_force(),
        ] {
            let f_big = f * sigma * s * s;
            if !Domain::FORCE.contains(f_big) {
                continue;
            }
            if let Err(e) = check_beam_scaling(small, f, s, sigma) {
                panic!("F = {f}: {e}");
            }
            if let Err(e) = check_beam_scaling(big, f_big, 1.0 / s, 1.0 / sigma) {
                panic!("back from F = {f_big}: {e}");
            }
            checked += 1;
        }
    }
    assert!(checked >= 8, "{checked}");
    let small = PlateParams {
        half_length: 1e-6,
        thickness: 1e-6,
        youngs_modulus: 1e-4,
        poisson: 0.3,
        friction: 0.3,
        pressure: 1e-6,
        tangential_stiffness: 1e6,
    };
    for (s, sigma) in [(1e12, 1.0), (1e6, 1e8), (2.5e7, 3.0)] {
        let big = PlateParams {
            half_length: 1e-6 * s,
            thickness: 1e-6 * s,
            youngs_modulus: 1e-4 * sigma,
            pressure: 1e-6 * sigma,
            tangential_stiffness: 1e6 * sigma / s,
            ..small
        };
        if let Err(e) = check_plate_scaling(small, s, sigma) {
            panic!("{e}");
        }
        if let Err(e) = check_plate_scaling(big, 1.0 / s, 1.0 / sigma) {
            panic!("back: {e}");
        }
    }
}
