#!/usr/bin/env bash
# Issue 48 (docs/theory.md (V2L)): the twin beams in linear geometry just above first slip, and
# the same decks with NLGEOM beside them. For each case: `microslip deck ccx beam` writes the
# NLGEOM deck, `sed` removes NLGEOM from every *STEP for the linear one, CalculiX runs both (one
# thread), and `microslip compare beam` and `microslip beam --format json` give each load's
# w(L) / Timoshenko - 1 against the (V2) and (V2L) bounds. Prints one table row per load.
#
#   validation/calculix/linear_geometry.sh [MICROSLIP] [WORKDIR]
#
# About 40 minutes on one core (the fine-mesh runs are the longest). Needs ccx and python3.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=$(realpath "${1:-$root/target/debug/microslip}")
work=${2:-$(mktemp -d)}
mkdir -p "$work"
cd "$work"
# name | parameters | loads (N): 0.8-0.9, 1.02, 1.05, 1.1 F_1 | extra deck flags
cases=(
  "issue|L=250 h=8 mu=0.45 P=3.5 KT=2500|268.8,341.04,349.44|"
  "G1|L=220 h=9 mu=0.35 P=3 KT=1500|226.8,257.0,264.6,277.2|"
  "G2|L=160 h=6 b=15 E=70000 nu=0.33 mu=0.3 P=1.5 KT=400|48.6,55.09,56.71,59.41|"
  "G3|L=300 h=10 mu=0.5 P=2.5 KT=800|300.0,340.0,350.0,366.67|"
  "G4|L=200 h=6 mu=0.4 P=2 KT=60|131.8,149.4,153.8,161.1|"
  "G1-fine|L=220 h=9 mu=0.35 P=3 KT=1500|226.8,257.0,264.6,277.2|--mesh fine"
  "G1-half-step|L=220 h=9 mu=0.35 P=3 KT=1500|226.8,257.0,264.6,277.2|--increment 3.15"
  "G4-half-step|L=200 h=6 mu=0.4 P=2 KT=60|131.8,149.4,153.8,161.1|--increment 1.83"
)
for case in "${cases[@]}"; do
  IFS='|' read -r name sets loads extra <<<"$case"
  mkdir -p "$name"
  args=()
  for kv in $sets; do args+=(--set "$kv"); done
  # shellcheck disable=SC2086
  "$bin" deck ccx beam "${args[@]}" --beam-theory timoshenko --loads "$loads" $extra -o "$name/nl.inp"
  sed 's/^\*STEP, NLGEOM,/*STEP,/' "$name/nl.inp" >"$name/lin.inp"
  for job in lin nl; do
    [ -f "$name/$job.dat" ] || (cd "$name" && OMP_NUM_THREADS=1 ccx -i "$job" >"$job.log" 2>&1)
  done
  python3 - "$bin" "$name" "$sets" <<'PY'
import json, subprocess, sys
bin, name, sets = sys.argv[1:4]
args = [a for kv in sets.split() for a in ("--set", kv)]
for job, words in (("lin", "linear"), ("nl", "NLGEOM")):
    out = subprocess.run([bin, "compare", "beam", f"{name}/{job}.dat", "--format", "json"],
                         capture_output=True, text=True).stdout
    for row in json.loads(out)["rows"]:
        force, w = row["F_N"], row["w_fe_mm"]
        beam = json.loads(subprocess.run(
            [bin, "beam", "--beam-theory", "timoshenko", *args, "--set", f"F={force}",
             "--format", "json"], capture_output=True, text=True).stdout)
        error = w / row["w_shear_corrected_mm"] - 1
        theory = beam["beam_theory"]
        v2 = theory["vs_continuum_nlgeom_within_fraction"]
        v2l = theory["vs_continuum_linear_within_fraction"]
        print(f"| {name} | {words} | {force / beam['F_1_N']:.3f} F_1 | {100 * error:+.3f} % | "
              f"{100 * v2:.2f} % | {100 * v2l:.2f} % | {abs(error) / v2l:.2f} |")
PY
done
