//! The cylinder's closed forms and semi-analytic solution against its independent discretized
//! solver (`discretized.rs`, which never sees them): Mindlin's shift and Mindlin-Deresiewicz's
//! dissipation per cycle under plain Coulomb (HC8)-(HC9), followed with the history of every node.

#[cfg(test)]
mod tests {
    use crate::kernel::regime::Law;
    use crate::problems::cylinder::cycle::{MasingCycle, MindlinCycle};
    use crate::problems::cylinder::discretized::{CylinderContact, FeLoop};

    /// The discretized loop under plain Coulomb, increment by increment with history, against
    /// Mindlin-Deresiewicz (HC9) and Mindlin's shift (HC8) at two amplitudes: D within 1.5e-3
    /// (measured 2.3e-4 at 0.9 mu P, 5.6e-4 at 0.5 mu P on 160 cells), delta_a within 1e-4.
    /// Planted faults caught: (HC9) with u ln u instead of 2 u ln u; the solver's kernel factor
    /// 2 / pi written 1 / pi (both off by tens of percent).
    #[test]
    fn the_coulomb_loop_is_mindlin_deresiewicz() {
        let contact = CylinderContact::STEEL;
        let gross = contact.gross_slip_load();
        for (phi, cells) in [(0.5, 160), (0.9, 80)] {
            let amplitude = phi * gross;
            let fe = FeLoop::run(contact, Law::Coulomb, cells, amplitude, 2).unwrap();
            let exact = MindlinCycle::new(gross, contact.contact_modulus(), amplitude);
            let d = exact.dissipation();
            assert!(
                ((fe.friction_work - d) / d).abs() < 1.5e-3,
                "{phi}: {} vs {d}",
                fe.friction_work
            );
            let peak = fe.virgin[fe.virgin.len() - 1].1;
            let expected = exact.peak_response();
            assert!(
                ((peak - expected) / expected).abs() < 1e-4,
                "{phi}: {peak} vs {expected}"
            );
            // Every point of the discretized unloading branch on Masing's closed-form branch (within
            // 2.2e-4 of delta_a: delta_v at Q_a / 2, where the slip zones are narrower, is less
            // resolved than at Q_a).
            for &(q, delta) in &fe.unloading {
                assert!(
                    (delta - exact.unloading(q)).abs() < 5e-4 * expected,
                    "{phi} {q}: {delta} vs {}",
                    exact.unloading(q)
                );
            }
        }
    }
}
