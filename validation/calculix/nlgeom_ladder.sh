#!/usr/bin/env bash
# Issue 45, item 5 (docs/theory.md (BC4a), "on converged ladders"): the twin beams' NLGEOM
# allowance re-measured on converged CalculiX. For each stick case: `microslip deck ccx beam` writes
# the NLGEOM deck at --mesh coarse, fine and finest (h, h/2, h/4), `sed` removes NLGEOM from every
# *STEP for the linear one (as linear_geometry.sh does), CalculiX runs both (one thread, one run at
# a time), `microslip compare beam` reads w(L), and the summary Richardson-extrapolates each w(L)
# and the ratio NLGEOM / linear - 1 with the observed order (the rules of src/fe/ladder.rs: order
# in [0.5, 4] and shrinking differences, else "not asymptotic" with the rungs' spread; uncertainty
# 1.25 x the correction), divided by (P/E)(L/h)^2, against the envelope 0.06 + tanh(kL)/kL.
# Then the increment check: the soft case's stick load (and the pressure) in 4 fixed increments
# instead of one, coarse and fine. A run whose contact `microslip compare` finds locked (its
# pressure beyond 5 P: the finest deck's clamp corner) is left out of its ladder and shown.
#
#   validation/calculix/nlgeom_ladder.sh [MICROSLIP] [WORKDIR]
#
# Roles are fixed here BEFORE the runs: "cal" cases draw the envelope, "hold" cases (the stick rows
# of the hold-outs H1-H4 of (BC4a)) are judged by it and never used to draw it.
# Wall time (2026-11-29, CalculiX 2.20, one core of a 2-core machine shared with two other ccx
# campaigns, nice 10): the campaign of docs/theory.md, C3 to C3-inc4 (H4, C7, H3, C8, H1 not run then),
# took about 90 minutes, 5317 s of ccx (the summary's last line); LIMIT=900 (H2's finest NLGEOM run
# stopped there). A finest NLGEOM run takes 35 s (C5) to 1053 s (C1); the whole list would take
# about 2.5 hours. The hold-outs (2026-11-30, LIMIT=600, one core of the shared machine, nice
# 10, CASES=H4, then H3, then H1): H4 630 s of ccx (finest NLGEOM 407 s), H3 348 s (finest
# NLGEOM 228 s), H1 927 s (its finest NLGEOM run stopped at 600 s; run alone without a limit it
# took 1436 s and locked); 1905 s of ccx, about 37 minutes of wall clock. C7 and C8 are still
# not run. CASES=C1,C2 runs (or summarizes) those only.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=$(realpath "${1:-$root/target/debug/microslip}")
work=${2:-$(mktemp -d)}
mkdir -p "$work"
cd "$work"
# name | role | parameters (b 20, E 210000, nu 0.3, mu 0.3 where not set) | stick load F (N) | ccx deck
# edit | meshes (default all three)
cases=(
  "C3|cal|L=200 h=5 P=2 KT=50|20|"
  "C3-F45.8|load|L=200 h=5 P=2 KT=50|45.8||coarse fine"
  "C1|cal|L=200 h=5 P=2 KT=5|20|"
  "C2|cal|L=200 h=10 P=2 KT=50|20|"
  "C6|cal|L=200 h=10 P=1 KT=600|40|"
  "C5|cal|L=150 h=15 mu=0.6 P=2 KT=1000|470.1|"
  "H2|hold|L=120 h=4 P=3 mu=0.2 KT=20|88.4|"
  "C3-inc4|inc|L=200 h=5 P=2 KT=50|20|inc4|coarse fine"
  "H4|hold|L=180 h=7 b=25 E=200000 P=2.5 mu=0.35 KT=150|150.1|"
  "C7|cal|L=250 h=8 mu=0.45 P=3.5 KT=2500|268.8|"
  "H3|hold|L=200 h=12 E=110000 nu=0.34 P=5 mu=0.5 KT=3000|720|"
  "C8|cal|L=200 h=5 P=2 KT=5000|20|"
  "H1|hold|L=300 h=6 b=15 E=70000 nu=0.33 P=1.5 mu=0.4 KT=200|36|"
)
only=${CASES:-}
for case in "${cases[@]}"; do
  IFS='|' read -r name role sets load edit meshes <<<"$case"
  [ -z "$only" ] || [[ ",$only," == *",$name,"* ]] || continue
  mkdir -p "$name"
  args=()
  for kv in $sets; do args+=(--set "$kv"); done
  for mesh in ${meshes:-coarse fine finest}; do
    nl="$name/nl-$mesh.inp"
    [ -f "$nl" ] || "$bin" deck ccx beam "${args[@]}" --loads "$load" --mesh "$mesh" -o "$nl"
    if [ "$edit" = inc4 ]; then
      # Every step (the pressure, then the stick load) in 4 fixed increments instead of 1.
      sed -i '/^\*STATIC$/{s/$/, DIRECT/;n;s/^1\., 1\.$/0.25, 1./}' "$nl"
    fi
    sed 's/^\*STEP, NLGEOM,/*STEP,/' "$nl" >"$name/lin-$mesh.inp"
    for job in nl lin; do
      [ -s "$name/$job-$mesh.dat" ] && [ -f "$name/$job-$mesh.time" ] && continue
      start=$(date +%s)
      # A run longer than LIMIT seconds (default: none) is stopped and left out (its .time says so).
      if ! (cd "$name" && OMP_NUM_THREADS=1 nice -n 10 timeout "${LIMIT:-0}" ccx -i "$job-$mesh" \
        >"$job-$mesh.log" 2>&1); then
        echo "stopped after ${LIMIT:-0} s" >"$name/$job-$mesh.time"
        echo "$name $job $mesh: stopped after ${LIMIT:-0} s" >&2
        continue
      fi
      echo "$(($(date +%s) - start))" >"$name/$job-$mesh.time"
      echo "$name $job $mesh: $(cat "$name/$job-$mesh.time") s" >&2
    done
  done
done
python3 - "$bin" "${cases[@]}" <<'PY'
import functools, json, math, os, subprocess, sys
bin, cases = sys.argv[1], sys.argv[2:]
SAFETY, ORDER = 1.25, (0.5, 4.0)  # src/fe/ladder.rs: SAFETY_FACTOR, SANE_ORDER

@functools.lru_cache(maxsize=None)
def compared(path):
    """`microslip compare beam PATH --format json`, once per run."""
    out = subprocess.run([bin, "compare", "beam", path, "--format", "json"],
                         capture_output=True, text=True).stdout
    return json.loads(out)

def w_of(path):
    row = compared(path)["rows"][0]
    return row["w_fe_mm"], row["continuum"]["response_mm"]

def locked(path):
    """Whether compare found the run's contact locked (its largest CPRESS beyond the beams' 5 P,
    `Deck::LOCKED_PRESSURE`), and that pressure (MPa); a run without output is neither."""
    if not os.path.exists(path):
        return False, 0.0
    run = compared(path)["stick_slope"]["runs"][0]
    return run["contact_locked"] is not None, run["peak_pressure_MPa"] or 0.0

def richardson(f1, f2, f3):
    e21, e32 = f1 - f2, f2 - f3
    if e21 == 0 and e32 == 0:
        return f3, 0.0, None, "converged"
    if e21 * e32 > 0 and abs(e32) < abs(e21):
        p = math.log(e21 / e32) / math.log(2)
        if ORDER[0] <= p <= ORDER[1]:
            c = e32 / (2 ** p - 1)
            return f3 - c, SAFETY * abs(c), p, "asymptotic"
        return f3, max(f1, f2, f3) - min(f1, f2, f3), p, "not asymptotic"
    return f3, max(f1, f2, f3) - min(f1, f2, f3), None, "not asymptotic"

print("| case | role | kL | group (P/E)(L/h)^2 | NLGEOM/lin - 1 over group: coarse, fine, finest |"
      " converged +- u | order | envelope | w lin coarse, fine, finest (mm) | w lin converged (order) |"
      " continuum / w lin converged - 1 |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
total = 0
for case in cases:
    name, role, sets, load, edit, *meshes = case.split("|")
    meshes = (meshes[0] if meshes else "").split() or ["coarse", "fine", "finest"]
    if not os.path.isdir(name):
        continue
    p = {"L": 200, "h": 10, "E": 210000, "P": 1, "KT": 600}
    p.update({k: float(v) for k, v in (kv.split("=") for kv in sets.split())})
    kl = 2 * math.sqrt(p["KT"] / (p["E"] * p["h"])) * p["L"]
    group = p["P"] / p["E"] * (p["L"] / p["h"]) ** 2
    env = 0.06 + math.tanh(kl) / kl
    def stopped(job):
        path = f"{name}/{job}.time"
        return os.path.exists(path) and open(path).read().startswith("stopped")
    # A linear run stopped, or on a spurious contact state (below), drops its rung; an NLGEOM
    # run stopped drops it from the ratio only.
    shown_lin = {m: "" for m in meshes}
    for m in meshes:
        if stopped(f"lin-{m}"):
            shown_lin[m] = " (stopped)"
        elif locked(f"{name}/lin-{m}.dat")[0]:
            peak = locked(f"{name}/lin-{m}.dat")[1] / p["P"]
            shown_lin[m] = f" (linear run spurious: peak {peak:.0f} P)"
    meshes = [m for m in meshes if not shown_lin[m]]
    dropped = "".join(f"; {m}{why}" for m, why in shown_lin.items() if why)
    try:
        nl = {m: w_of(f"{name}/nl-{m}.dat")[0] for m in meshes if not stopped(f"nl-{m}")}
        lin, continuum = zip(*(w_of(f"{name}/lin-{m}.dat") for m in meshes))
    except (json.JSONDecodeError, KeyError, IndexError, FileNotFoundError):
        print(f"| {name} | {role} | {kl:.2f} | incomplete |")
        continue
    for f in os.listdir(name):
        if f.endswith(".time"):
            t = open(f"{name}/{f}").read().split()
            total += int(t[-2] if t[0] == "stopped" else t[0])
    # An NLGEOM run whose contact `compare` finds locked (beyond 5 P somewhere) has settled on a
    # spurious contact state (the clamp's corner locked, slips there above the tip's): its rung
    # is left out of the NLGEOM ladder (shown as "x").
    sound = {m: not locked(f"{name}/nl-{m}.dat")[0] for m in nl}
    peaks = {m: locked(f"{name}/nl-{m}.dat")[1] / p["P"] for m in nl}
    ratios = {m: (nl[m] / b - 1) / group for m, b in zip(meshes, lin) if m in nl}
    good = [ratios[m] for m in meshes if m in nl and sound[m]]
    shown = ", ".join("x (stopped)" if m not in nl else f"{ratios[m]:.4f}" if sound[m]
                      else f"x ({ratios[m]:.4f}: peak {peaks[m]:.0f} P)" for m in meshes)
    if len(good) == 3:
        r, u, order, words = richardson(*good)
    else:  # fewer rungs: the finest answer, the rungs' spread as uncertainty
        r, u, order, words = good[-1], max(good) - min(good), None, f"{len(good)} rungs"
    if len(lin) == 3:
        wl, ul, pl, wordsl = richardson(*lin)
    else:
        wl, ul, pl, wordsl = lin[-1], abs(lin[-1] - lin[0]), None, f"{len(lin)} rungs"
    o = "n/a" if order is None else f"{order:.2f}"
    ol = "n/a" if pl is None else f"{pl:.2f}"
    print(f"| {name} | {role} | {kl:.2f} | {100 * group:.4f} % | {shown}{dropped}"
          + f" | {r:.4f} +- {u:.4f} ({words}) | {o} | {env:.4f} | "
          + ", ".join(f"{x:.7g}" for x in lin)
          + f" | {wl:.7g} +- {ul:.2g} ({wordsl}, {ol}) | {100 * (continuum[-1] / wl - 1):+.3f} % |")
print(f"\nccx wall time of the runs present: {total} s")
PY
