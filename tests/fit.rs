//! Identification of mu and K_T from synthetic measurements: known parameters plus noise must be
//! recovered within the uncertainty the fit reports, and data that cannot show a parameter must say so.

use microslip::fit::{Evidence, Measurement, Status, fit_twin_beams};
use microslip::{TipForce, TwinBeams, TwinBeamsParams};

/// Deterministic Gaussian noise (xorshift64 + Box-Muller), so the test is reproducible.
struct Noise(u64);

impl Noise {
    fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    fn gaussian(&mut self) -> f64 {
        let (u1, u2) = (self.uniform().max(1e-300), self.uniform());
        (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
    }
}

fn measure(mu: f64, kt: f64, forces: &[f64], sigma: f64, seed: u64) -> Vec<Measurement> {
    let beams = TwinBeams::new(TwinBeamsParams {
        friction: mu,
        tangential_stiffness: kt,
        ..TwinBeamsParams::PAPER
    })
    .unwrap();
    let mut noise = Noise(seed);
    forces
        .iter()
        .map(|&f| Measurement {
            force: f,
            deflection: beams
                .regularized(TipForce::new(f).unwrap())
                .tip_deflection()
                + sigma * noise.gaussian(),
        })
        .collect()
}

fn linspace(from: f64, to: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| from + (to - from) * i as f64 / (n - 1) as f64)
        .collect()
}

#[test]
fn noisy_data_recover_the_true_parameters_within_the_reported_uncertainty() {
    // (mu, K_T, force range): deep macroslip, just past F_1, soft interface, a stiffer one.
    let cases = [
        (0.3, 600.0, 300.0),
        (0.3, 120.0, 160.0),
        (0.5, 60.0, 400.0),
        (0.2, 1000.0, 200.0),
    ];
    let mut total = 0;
    let mut outside_two_sigma = 0;
    for (case, &(mu, kt, f_max)) in cases.iter().enumerate() {
        for seed in 1..=5u64 {
            let forces = linspace(f_max / 40.0, f_max, 40);
            // Noise: 0.5 % of the largest deflection, a realistic dial-gauge scatter.
            let clean = measure(mu, kt, &forces, 0.0, seed);
            let sigma = 0.005 * clean.last().unwrap().deflection;
            let data = measure(mu, kt, &forces, sigma, seed * 7919 + case as u64);
            let fit = fit_twin_beams(TwinBeamsParams::PAPER, &data, None, None).unwrap();
            assert!(
                fit.rms < 2.0 * sigma && fit.rms > 0.5 * sigma,
                "case {case} seed {seed}: rms {} vs sigma {sigma}",
                fit.rms
            );
            for (estimate, truth, name) in [(&fit.mu, mu, "mu"), (&fit.kt, kt, "K_T")] {
                assert_ne!(
                    estimate.status,
                    Status::NotIdentifiable,
                    "case {case} seed {seed}: {name} {estimate:?}"
                );
                let se = estimate.std_error.expect("standard error");
                let z = (estimate.value - truth).abs() / se;
                assert!(
                    z < 4.0,
                    "case {case} seed {seed}: {name} = {} +- {se}, truth {truth}",
                    estimate.value
                );
                total += 1;
                outside_two_sigma += usize::from(z > 2.0);
            }
        }
    }
    // Honest error bars: about 95 % of estimates within 2 standard errors (allow some slack).
    assert!(
        outside_two_sigma * 100 <= total * 15,
        "{outside_two_sigma} of {total} estimates beyond 2 sigma"
    );
}

#[test]
fn data_below_the_threshold_cannot_show_mu() {
    let forces = linspace(5.0, 70.0, 20); // F_thre = 80 N
    let data = measure(0.3, 600.0, &forces, 1e-5, 42);
    let fit = fit_twin_beams(TwinBeamsParams::PAPER, &data, None, None).unwrap();
    assert_eq!(fit.mu.status, Status::NotIdentifiable, "{fit:?}");
    assert!(
        matches!(fit.mu.evidence, Evidence::NoDataAboveFirstMacroslip { .. }),
        "{:?}",
        fit.mu.evidence
    );
    let note = microslip::report::text::evidence(&fit.mu.evidence);
    assert!(note.contains("no measurement above F_1"), "{note}");
    assert_eq!(fit.beyond_first_macroslip, 0);
    // K_T still shows in the microslip stiffness.
    assert_ne!(fit.kt.status, Status::NotIdentifiable, "{:?}", fit.kt);
    assert!((fit.kt.value / 600.0 - 1.0).abs() < 4.0 * fit.kt.std_error.unwrap() / 600.0);
}

#[test]
fn a_stiff_interface_leaves_k_t_undetermined() {
    // K_T = 1e7: indistinguishable from plain Coulomb at 0.5 % noise.
    let forces = linspace(10.0, 300.0, 30);
    let clean = measure(0.3, 1e7, &forces, 0.0, 1);
    let sigma = 0.005 * clean.last().unwrap().deflection;
    let data = measure(0.3, 1e7, &forces, sigma, 3);
    let fit = fit_twin_beams(TwinBeamsParams::PAPER, &data, None, None).unwrap();
    assert_ne!(fit.kt.status, Status::Identified, "{:?}", fit.kt);
    assert_eq!(fit.mu.status, Status::Identified, "{:?}", fit.mu);
}

/// The spread of repeated fits next to the errors they state.
#[derive(Debug)]
struct Coverage {
    /// Per parameter (mu, K_T): sample standard deviation of the estimates.
    scatter: [f64; 2],
    /// Per parameter: mean stated standard error.
    stated: [f64; 2],
    /// Per parameter: fraction of fits with the truth within +-1 stated standard error.
    within: [f64; 2],
}

/// Issue 25 (5): `sweep beam --from 0 --to 300 --points 61 --set mu=0.22 --set KT=300`, each w
/// multiplied by 1 + `relative` N(0,1) and shifted by `absolute` N(0,1) mm, fitted `repeats` times.
fn coverage(relative: f64, absolute: f64, repeats: u64) -> Coverage {
    let (mu, kt) = (0.22, 300.0);
    let clean = measure(mu, kt, &linspace(0.0, 300.0, 61), 0.0, 1);
    let mut noise = Noise(0x9e37_79b9_7f4a_7c15);
    let fits: Vec<_> = (0..repeats)
        .map(|_| {
            let data: Vec<Measurement> = clean
                .iter()
                .map(|m| Measurement {
                    force: m.force,
                    deflection: m.deflection * (1.0 + relative * noise.gaussian())
                        + absolute * noise.gaussian(),
                })
                .collect();
            fit_twin_beams(TwinBeamsParams::PAPER, &data, None, None).unwrap()
        })
        .collect();
    let n = fits.len() as f64;
    let per = |pick: &dyn Fn(&microslip::fit::FitResult) -> &microslip::fit::Estimate, truth: f64| {
        let values: Vec<f64> = fits.iter().map(|f| pick(f).value).collect();
        let mean = values.iter().sum::<f64>() / n;
        let scatter = (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
        let errors: Vec<f64> = fits.iter().map(|f| pick(f).std_error.unwrap()).collect();
        let stated = errors.iter().sum::<f64>() / n;
        let within = values
            .iter()
            .zip(&errors)
            .filter(|(v, e)| (*v - truth).abs() <= **e)
            .count() as f64
            / n;
        (scatter, stated, within)
    };
    let (m, k) = (per(&|f| &f.mu, mu), per(&|f| &f.kt, kt));
    Coverage {
        scatter: [m.0, k.0],
        stated: [m.1, k.1],
        within: [m.2, k.2],
    }
}

#[test]
fn issue_measurement() {
    eprintln!("relative 1 %: {:?}", coverage(0.01, 0.0, 40));
    eprintln!("absolute 1e-3 mm: {:?}", coverage(0.0, 1e-3, 40));
}
