"""Worked example: read a CalculiX run of the paper's twin beams, compare it with the closed
forms, and plot w(L) against F for three K_T from vectorized sweeps, the FE points on top.

    pip install ./python matplotlib
    python python/examples/calculix_beams.py [RESULT.dat] [OUT.png]

RESULT.dat defaults to the run kept in tests/data/calculix (its deck, paper-beams.inp, beside it
gives the parameters); OUT.png to python/examples/out/w-vs-F.png. Units: mm, N, MPa, K_T in MPa/mm.

What the figure shows: below F_thre = 80 N the CalculiX points sit about 2 % above the red
(Euler-Bernoulli) curve, the shear deflection the beam theory neglects; compare's verdict judges
them against the shear-corrected closed form (within 0.4 %) and says so. Past F_1 every K_T
tends to Coulomb: the whole interface slides at mu P.
"""

from __future__ import annotations

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt
import numpy as np

import microslip

HERE = Path(__file__).resolve().parent
RESULT = HERE.parents[1] / "tests" / "data" / "calculix" / "paper-beams.dat"


def main(result: Path, out: Path) -> None:
    # 1. The FE run against the closed forms: the verdict, and the points it compared.
    report = microslip.compare(result, "beam")
    print(report.verdict.summary)
    implied = report.implied
    print(f"implied by the FE run: mu = {implied.mu:.4f}, K_T = {implied.KT_MPa_per_mm:.1f} MPa/mm")
    fe_force = np.array([row.F_N for row in report.rows])
    fe_w = np.array([row.w_fe_mm for row in report.rows])

    # 2. The closed forms over the force, one vectorized sweep per K_T (the deck's and a factor
    #    of 5 either side, as the paper's Fig. 7).
    beams = microslip.preset("paper-beams").replace(KT=report.KT_MPa_per_mm)
    forces = np.linspace(0.0, 3.0 * beams.regime_scale, 2001)  # up to 3 F_thre
    fig, (ax, below) = plt.subplots(
        2, 1, figsize=(7.5, 7.0), dpi=120, sharex=True, gridspec_kw={"height_ratios": [3, 2]}
    )
    coulomb = beams.sweep(F=forces)["w_coulomb"]
    ax.plot(forces, coulomb, color="black", lw=1.2, ls="--", label="plain Coulomb")
    for kt, colour in [(beams.KT / 5, "tab:blue"), (beams.KT, "tab:red"), (beams.KT * 5, "tab:green")]:
        swept = beams.replace(KT=kt).sweep(F=forces, quantities=["ratio"])
        ax.plot(forces, swept["w_regularized"], color=colour, lw=1.6, label=f"regularized, K_T = {kt:g} MPa/mm")
        below.plot(forces, swept["ratio"], color=colour, lw=1.6)
    ax.plot(fe_force, fe_w, "o", color="tab:red", mfc="white", ms=7, mew=1.6,
            label=f"CalculiX, K_T = {beams.KT:g} MPa/mm")
    ax.axvline(beams.regime_scale, color="grey", lw=0.8, ls=":")
    ax.annotate("F_thre", (beams.regime_scale, 0.0), xytext=(4, 6), textcoords="offset points", color="grey")
    below.plot(fe_force, fe_w / beams.sweep(F=fe_force)["w_coulomb"], "o", color="tab:red", mfc="white", ms=7, mew=1.6)
    below.axhline(1.0, color="black", lw=1.2, ls="--")
    below.axvline(beams.regime_scale, color="grey", lw=0.8, ls=":")
    below.set_xlabel("tip force F (N)")
    below.set_ylabel("w(L) / w(L) Coulomb")
    below.grid(alpha=0.3)
    ax.set_ylabel("tip deflection w(L) (mm)")
    ax.set_title("Paper twin beams: w(L) vs F, closed forms and CalculiX")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", fontsize=9)
    ax.set_xlim(0.0, forces[-1])
    ax.set_ylim(bottom=0.0)
    fig.tight_layout()
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out)
    print(f"wrote {out}")


if __name__ == "__main__":
    result = Path(sys.argv[1]) if len(sys.argv) > 1 else RESULT
    out = Path(sys.argv[2]) if len(sys.argv) > 2 else HERE / "out" / "w-vs-F.png"
    main(result, out)
