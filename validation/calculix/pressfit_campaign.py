#!/usr/bin/env python3
"""The press fit's CalculiX campaign (docs/theory.md section 18, "CalculiX"): CalculiX issue #98's fit.

Runs the bundled deck (`microslip deck ccx pressfit --preset pressfit-ccx98`: axisymmetric CAX4,
the interference resolved frictionless in step 1, F = 0.3 and 0.8 F_gross, then the capacity step)
on both meshes and at two force steps (F_gross/40, the deck's default, and F_gross/80), then the
same deck with the contact pair of the issue's node slave (`TYPE=NODE TO SURFACE`, slave the node
surface NSHAFT) and with a node-to-surface pair of element-face slaves, and prints what
`microslip compare pressfit` says of each: Delta at both loads against the shear lag, the contact
pressure against Lamé's, the push-out capacity against F_gross, the verdict. Convergence: how far
the fine mesh and the halved step move Delta and the capacity.

    python3 validation/calculix/pressfit_campaign.py [--microslip PATH] [--keep DIR] [--quick]

`--quick` runs the coarse mesh only (the surface-to-surface deck and the node slave): about 40 s
of ccx on one thread. Needs `ccx` (2.20) on PATH; each run uses one thread (OMP_NUM_THREADS=1).
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

PRESET = ["--preset", "pressfit-ccx98"]
SURFACE_PAIR = "*CONTACT PAIR, INTERACTION=JENKINS, TYPE=SURFACE TO SURFACE\nSSHAFT, SHUB"
PAIRS = {
    "surface-to-surface": SURFACE_PAIR,
    "node slave": "*CONTACT PAIR, INTERACTION=JENKINS, TYPE=NODE TO SURFACE\nNSHAFT, SHUB",
    "node-to-surface, face slave":
        "*CONTACT PAIR, INTERACTION=JENKINS, TYPE=NODE TO SURFACE\nSSHAFT, SHUB",
}


def find_microslip(given):
    if given:
        return given
    for candidate in [shutil.which("microslip"), "target/release/microslip", "target/debug/microslip"]:
        if candidate and Path(candidate).exists():
            return candidate
    sys.exit("microslip not found: build it (cargo build --release) or pass --microslip")


def gross(microslip, workdir):
    """F_gross (N) as the deck's expected lines state it."""
    deck = workdir / "expected.inp"
    if deck.exists():
        deck.unlink()
    subprocess.run([microslip, "deck", "ccx", "pressfit", *PRESET, "-o", str(deck)], check=True)
    found = re.search(r"F_gross = mu p 2 pi r L = (\S+) N", deck.read_text())
    if not found:
        sys.exit(f"{deck}: no F_gross in its expected lines")
    return float(found.group(1))


def run(microslip, workdir, job, args, pair):
    inp = workdir / f"{job}.inp"
    if inp.exists():
        inp.unlink()
    subprocess.run([microslip, "deck", "ccx", "pressfit", *PRESET, *args, "-o", str(inp)],
                   check=True)
    text = inp.read_text()
    if SURFACE_PAIR not in text:
        sys.exit(f"{inp}: the deck's contact pair is not the expected surface-to-surface one")
    inp.write_text(text.replace(SURFACE_PAIR, pair))
    env = dict(os.environ, OMP_NUM_THREADS="1")
    start = time.time()
    with open(workdir / f"{job}.log", "w") as log:
        subprocess.run(["nice", "-n", "10", "ccx", "-i", job], cwd=workdir, env=env, check=True,
                       stdout=log, stderr=subprocess.STDOUT)
    wall = time.time() - start
    out = subprocess.run([microslip, "compare", "pressfit", str(workdir / f"{job}.dat"),
                          "--format", "json"], capture_output=True, text=True)
    if out.returncode not in (0, 1):
        sys.exit(f"compare {job}: exit {out.returncode}: {out.stderr}")
    return json.loads(out.stdout), wall


def pct(x):
    return "-" if x is None else f"{100 * x:+.2f} %"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--microslip")
    parser.add_argument("--keep", help="keep decks and results in this directory")
    parser.add_argument("--quick", action="store_true", help="the coarse mesh only")
    options = parser.parse_args()
    if shutil.which("ccx") is None:
        sys.exit("ccx not found: apt-get install calculix-ccx")
    microslip = find_microslip(options.microslip)
    workdir = Path(options.keep or tempfile.mkdtemp(prefix="microslip-pressfit-"))
    workdir.mkdir(parents=True, exist_ok=True)
    f_gross = gross(microslip, workdir)
    half_step = ["--increment", f"{f_gross / 80:.6g}"]
    cases = [("coarse, F_gross/40", "pfc", [], "surface-to-surface"),
             ("coarse, node slave", "pfcn", [], "node slave")]
    if not options.quick:
        cases += [("coarse, F_gross/80", "pfch", half_step, "surface-to-surface"),
                  ("fine, F_gross/40", "pff", ["--mesh", "fine"], "surface-to-surface"),
                  ("fine, F_gross/80", "pffh", ["--mesh", "fine", *half_step],
                   "surface-to-surface"),
                  ("fine, node slave", "pffn", ["--mesh", "fine"], "node slave"),
                  ("coarse, node-to-surface, face slave", "pfcf", [],
                   "node-to-surface, face slave")]
    print(f"CalculiX issue #98's fit (F_gross = {f_gross:.6g} N), decks of `microslip deck ccx "
          f"pressfit --preset pressfit-ccx98`, in {workdir}\n")
    print("| run | contact | F (N) | Delta ccx (mm) | vs continuum | Delta shear lag (mm) | vs "
          "shear lag | p ccx after step 1 (MPa) | dp | capacity ccx (N) | vs F_gross | verdict | "
          "ccx wall (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    results = {}
    for label, job, args, contact in cases:
        data, wall = run(microslip, workdir, job, args, PAIRS[contact])
        results[label] = data
        capacity = next(r for r in data["rows"] if r["kind"] == "capacity")
        for row in data["rows"]:
            if row["kind"] != "load":
                continue
            print(f"| {label} | {contact} | {row['F_N']:.5g} | {row['Delta_fe_mm']:.5g} | "
                  f"{pct(row['continuum_diff'])} | {row['Delta_mm']:.5g} | {pct(row['delta_diff'])} | "
                  f"{row['p_assembled_fe_MPa']:.5g} | {pct(row['pressure_diff'])} | "
                  f"{capacity['F_N']:.5g} | {pct(capacity['capacity_diff'])} | "
                  f"{'agrees' if data['verdict']['agrees'] else 'does not agree'} | {wall:.0f} |")
    print()
    for label, data in results.items():
        print(f"{label}: {data['verdict']['summary']}")
    if not options.quick:
        print()
        for what, a, b in [("halving the force step, coarse", "coarse, F_gross/40",
                            "coarse, F_gross/80"),
                           ("halving the force step, fine", "fine, F_gross/40", "fine, F_gross/80"),
                           ("halving every element", "coarse, F_gross/40", "fine, F_gross/40")]:
            moves = []
            for ra, rb in zip(results[a]["rows"], results[b]["rows"]):
                if ra["kind"] == "load":
                    moves.append(f"Delta at {ra['F_N']:.5g} N {pct(rb['Delta_fe_mm'] / ra['Delta_fe_mm'] - 1)}")
                else:
                    moves.append(f"capacity {pct(rb['F_N'] / ra['F_N'] - 1)}")
            print(f"{what}: " + ", ".join(moves))
    if not options.keep:
        shutil.rmtree(workdir, ignore_errors=True)


if __name__ == "__main__":
    main()
