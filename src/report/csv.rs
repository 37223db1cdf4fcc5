//! CSV rows for the sweeps. Headers are a contract with users' scripts: do not rename columns.
//! Floats are written in their shortest round-trip form (parsing a value back gives the same f64) by
//! `zmij`, already in the tree through serde_json: float formatting was 55 % of a million-row sweep
//! with `core::fmt` (measured with callgrind), and zmij is several times faster.

use std::io::{self, Write};

use crate::curves::{BeamPoint, PlatePoint};

/// Header of `microslip sweep beam --format csv`.
pub const BEAM_HEADER: &str =
    "F_N,w_coulomb_mm,w_regularized_mm,X_mm,regime_coulomb,regime_regularized";

/// Header of `microslip sweep plate --format csv`.
pub const PLATE_HEADER: &str =
    "KT_MPa_per_mm,u_coulomb_mm,u_regularized_mm,Xs_mm,Xr_mm,regime_coulomb,regime_regularized";

/// Header of `microslip sweep cycle --format csv`.
pub const CYCLE_HEADER: &str = "Fa_N,D_coulomb_Nmm,D_regularized_Nmm,zeta_coulomb,zeta_regularized";

/// Header of `microslip cycle --format csv` (the loop, both laws).
pub const LOOP_HEADER: &str = "branch,F_N,w_coulomb_mm,w_regularized_mm";

/// Writes one cycle-sweep row.
pub fn write_cycle_row(out: &mut impl Write, p: &crate::curves::CyclePoint) -> io::Result<()> {
    write_row(
        out,
        &[
            p.amplitude,
            p.d_coulomb,
            p.d_regularized,
            p.zeta_coulomb,
            p.zeta_regularized,
        ],
        &[],
    )
}

/// Writes one loop point: branch label first.
pub fn write_loop_row(
    out: &mut impl Write,
    branch: &str,
    force: f64,
    coulomb: f64,
    regularized: f64,
) -> io::Result<()> {
    out.write_all(branch.as_bytes())?;
    out.write_all(b",")?;
    write_row(out, &[force, coulomb, regularized], &[])
}

/// Writes numbers then labels as one CSV line.
fn write_row(out: &mut impl Write, numbers: &[f64], labels: &[&str]) -> io::Result<()> {
    let mut buffer = zmij::Buffer::new();
    for (i, &x) in numbers.iter().enumerate() {
        if i > 0 {
            out.write_all(b",")?;
        }
        out.write_all(buffer.format(x).as_bytes())?;
    }
    for label in labels {
        out.write_all(b",")?;
        out.write_all(label.as_bytes())?;
    }
    out.write_all(b"\n")
}

/// Writes one beam row.
pub fn write_beam_row(out: &mut impl Write, p: &BeamPoint) -> io::Result<()> {
    write_row(
        out,
        &[p.force, p.w_coulomb, p.w_regularized, p.micro_end],
        &[p.regime_coulomb.label(), p.regime_regularized.label()],
    )
}

/// Writes one plate row.
pub fn write_plate_row(out: &mut impl Write, p: &PlatePoint) -> io::Result<()> {
    write_row(
        out,
        &[p.kt, p.u_coulomb, p.u_regularized, p.stick_end, p.micro_end],
        &[p.regime_coulomb.label(), p.regime_regularized.label()],
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Regime;

    #[test]
    fn rows_round_trip_their_numbers() {
        let p = BeamPoint {
            force: 0.1 + 0.2,
            w_coulomb: 1e-7 / 3.0,
            w_regularized: 123_456_789.123,
            micro_end: 200.0,
            regime_coulomb: Regime::Stick,
            regime_regularized: Regime::MicroslipMacroslip,
        };
        let mut out = Vec::new();
        write_beam_row(&mut out, &p).unwrap();
        let line = String::from_utf8(out).unwrap();
        let fields: Vec<&str> = line.trim_end().split(',').collect();
        assert_eq!(fields[0].parse::<f64>().unwrap(), 0.1 + 0.2);
        assert_eq!(fields[1].parse::<f64>().unwrap(), 1e-7 / 3.0);
        assert_eq!(fields[2].parse::<f64>().unwrap(), 123_456_789.123);
        assert_eq!(&fields[4..], ["stick", "microslip+macroslip"]);
        for x in [0.0, 1.0, 5e-324, 1e300, 1.0 / 3.0, -2.5e-8] {
            let mut out = Vec::new();
            write_row(&mut out, &[x], &[]).unwrap();
            let text = String::from_utf8(out).unwrap();
            assert_eq!(text.trim_end().parse::<f64>().unwrap(), x, "{text}");
        }
    }
}
