#!/usr/bin/env bash
# Issue 43 item 1: the move of the older problems' FE points, comparisons, compare reports and
# report rows into their face folders changes no output. Runs a broad command set with two
# binaries (OLD, NEW) from the repository root and compares stdout, stderr and the exit code of
# each command byte for byte; `deck` is compared through the deck file it writes to stdout.
#
#   validation/same_outputs.sh OLD_BINARY NEW_BINARY
#
# Prints one line per differing command and the counts; exits 1 if any differ. It takes about
# 15 minutes with debug binaries (a compare judges each row against the continuum).
set -u
old=$1
new=$2
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Both binaries run under the same name, so that help and usage lines match.
mkdir -p "$work/old" "$work/new"
cp "$old" "$work/old/microslip"
cp "$new" "$work/new/microslip"
# Inputs the fixtures lack: a cylinder curve, a lap curve, an interface profile.
printf 'Q_N_per_mm,sa_mm\n0,0\n100,0.0011\n250,0.004\n' >"$work/cyl.csv"
printf 'F_N,Delta_mm\n1000,0.0047\n3000,0.0143\n' >"$work/lap.csv"
printf 'F_N,Delta_mm\n1000,0.0047\n7000,0.0143\n' >"$work/lap-beyond.csv"
printf 'x_mm,slip_mm,shear_MPa\n0,1e-5,6.6e-3\n10,2e-5,1.32e-2\n20,4e-5,2.64e-2\n30,1e-4,6.6e-2\n40,2e-4,1.32e-1\n50,8e-4,0.3\n60,1.6e-3,0.3\n' >"$work/interface.csv"
printf 'F_N,w_mm\n0,0\n40,0.0114\n' >"$work/beam-zero.csv"
printf 'KT_MPa_per_mm,u_mm\n0,1\n' >"$work/plate-bad.csv"

cmds=()
add() { cmds+=("$*"); }
C=tests/data/calculix
R=tests/data/reports/inputs
S=tests/data/stick_slope
for f in text json; do
  add beam --format $f
  add beam --set F=120 --format $f
  add beam --beam-theory timoshenko --format $f
  add beam --preset paper-beams-soft --format $f
  add plate --format $f
  add plate --set KT=1e4 --format $f
  add plate --set nu=0 --format $f
  add plate --preset plate-bench --format $f
  add lap --format $f
  add lap --set F=5000 --format $f
  add cylinder --format $f
  add cylinder --set Q=100 --format $f
  add cycle --amplitude 150 --format $f
  add cycle --preset paper-beams-soft --amplitude 80 --format $f
  add cycle --preset lap-aluminium --amplitude 4000 --format $f
  add cycle --preset cylinder-steel-pad --amplitude 200 --format $f
  add kt --format $f
  add kt --preset paper-plate --kn 1e6 --format $f
  add kt --preset lap-aluminium --format $f
  add kt --preset cylinder-steel-pad --format $f
  add kt --element-size 1 --kn 1000 --format $f
  add kt --tolerance 1% --from 0 --to 300 --format $f
  add kt --tolerance 1% --preset paper-plate --format $f
  add solve beam --vary KT --target ratio=1.01 --format $f
  add solve plate --vary KT --target ratio=1.01 --format $f
  add fit beam $R/fit-beam.csv --format $f
  add fit cylinder $R/fit-cylinder.csv --format $f
done
add cycle --amplitude 150 --format csv
add cycle --preset lap-aluminium --amplitude 4000 --format csv
add cycle --preset cylinder-steel-pad --amplitude 200 --format csv
for f in csv json; do
  add sweep beam --from 10 --to 300 --points 7 --format $f
  add sweep beam --beam-theory timoshenko --from 10 --to 300 --points 5 --format $f
  add sweep plate --from 1e2 --to 1e8 --points 7 --format $f
  add sweep lap --from 0 --to 6000 --points 7 --format $f
  add sweep cycle --from 10 --to 300 --points 5 --format $f
  add sweep cycle --preset lap-aluminium --from 500 --to 5000 --points 5 --format $f
  add sweep cycle --preset cylinder-steel-pad --from 50 --to 500 --points 5 --format $f
  add sweep --model cylinder --from 25 --to 450 --points 6 --format $f
  add sweep --model beam --vary KT --from 100 --to 1000 --points 4 --format $f
  add sweep --model lap --vary mu --from 0.3 --to 0.6 --points 4 --format $f
  add sweep --model plate --vary P --from 1 --to 20 --points 4 --format $f
done
add report
add presets
for m in beam plate lap cylinder; do
  add deck ccx $m
  add deck ccx $m --mesh fine
  add deck ccx $m --near-coulomb
done
add deck ccx beam --loads 40,80,120 --increment 2
add deck ccx lap --loads 1000,3000
add deck ccx plate --preset plate-bench
add deck ccx cylinder --loads 100,200
add deck ccx lap --loads 3000,1000
add deck ccx plate --loads 1
for f in text csv json; do
  add compare beam $C/paper-beams.dat --format $f
  add compare beam $R/compare-beam.csv --format $f
  add compare beam $R/compare-beam-two.csv --set KT=120 --format $f
  add compare beam $work/beam-zero.csv --format $f
  add compare beam $R/compare-beam.csv --interface $work/interface.csv --kinematics linear --format $f
  add compare beam $R/compare-beam.csv --kinematics nlgeom --format $f
  add compare plate $C/plate-kt1e4.dat $C/paper-plate.dat --format $f
  add compare plate $C/paper-plate.dat --format $f
  add compare plate $R/compare-plate.csv --format $f
  add compare plate $R/compare-plate.csv --kinematics nlgeom --format $f
  add compare plate $S/plate-kt1e4.dat --deck $C/plate-kt1e4.inp --format $f
  add compare plate $S/plate-kt1e4-plus10.dat --deck $C/plate-kt1e4.inp --format $f
  add compare plate $S/plate-kt1e4-minus10.dat --deck $C/plate-kt1e4.inp --format $f
  add compare lap $C/lap-aluminium.dat --format $f
  add compare lap $work/lap.csv --format $f
  add compare lap $work/lap.csv $work/lap.csv --format $f
  add compare cylinder $work/cyl.csv --format $f
  add compare cylinder $work/cyl.csv --set KT=30000 --format $f
done
# Slow in a debug build (a continuum solve per row): one format each. The slender and stubby
# beams' fixtures take minutes per run in a debug build and are left out.
add compare beam $C/paper-beams.dat --set KT=120 --format json
add compare beam $C/paper-beams.dat --beam-theory timoshenko --format text
# Refusals: their messages are output too.
add compare lap $work/lap-beyond.csv
add compare plate $work/plate-bad.csv
add compare beam $C/paper-plate.dat
add compare plate $C/paper-beams.dat
add compare lap $C/paper-beams.dat
add compare beam $C/paper-beams.dat --interface $work/interface.csv
add compare beam $C/paper-beams.dat $C/slender-beams.dat
add compare cylinder $C/lap-aluminium.dat
for c in "" beam plate lap cylinder sweep cycle compare deck kt fit solve; do
  add $c --help
done

# SAME_OUTPUTS_LIST=1: print the commands only.
if [ -n "${SAME_OUTPUTS_LIST:-}" ]; then
  printf '%s\n' "${cmds[@]}"
  exit 0
fi
differ=0
n=0
failed=0
for c in "${cmds[@]}"; do
  n=$((n + 1))
  # shellcheck disable=SC2086
  (cd "$PWD" && "$work/old/microslip" $c >"$work/o.out" 2>"$work/o.err"; echo $? >"$work/o.rc")
  # shellcheck disable=SC2086
  (cd "$PWD" && "$work/new/microslip" $c >"$work/n.out" 2>"$work/n.err"; echo $? >"$work/n.rc")
  [ "$(cat "$work/o.rc")" = 0 ] || failed=$((failed + 1))
  if ! cmp -s "$work/o.out" "$work/n.out" || ! cmp -s "$work/o.err" "$work/n.err" ||
    ! cmp -s "$work/o.rc" "$work/n.rc"; then
    differ=$((differ + 1))
    echo "DIFFERS: microslip $c"
    diff "$work/o.out" "$work/n.out" | head -5
    diff "$work/o.err" "$work/n.err" | head -5
  fi
done
echo "$n commands, $differ differ ($failed of them exit non-zero in both: refusals, and compare's verdict 'does not agree')"
[ "$differ" -eq 0 ]
