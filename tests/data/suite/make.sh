#!/bin/sh
# Remakes the CalculiX results that tests/suite.rs's stand-in solver hands back: real ccx 2.20
# runs of the decks `microslip suite` writes for the bundled preset plate-bench, at each mesh
# rung, and the same decks with the stick slope on their *FRICTION card 10 % above the deck's
# K_T (the header keeps K_T: a solver that used another stick slope than it was given). Each
# .frd is cut to its step and CONTACT lines, all that the stick slope is read from, without the
# nodes whose six values are all 0 (the reader skips them). Then
# far-coarse.dat: the coarse rung's results with u(L) (the set UEND's x displacements) 25 % larger,
# a stand-in for a mesh far too coarse for the case (a ladder that is not converged).
# Run from the repository's root: sh tests/data/suite/make.sh (needs ccx on the PATH).
set -eu
out=$(pwd)/tests/data/suite
bin=${MICROSLIP:-target/debug/microslip}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cut_frd() {
    awk '/^ *1PSTEP/ || /^ *100C/ { print; next }
         /^ *-4 / { inside = ($2 == "CONTACT") }
         inside && /^ -1/ { values = substr($0, 14); gsub(/-?0\.00000E[+-]00/, "", values)
                            if (values ~ /^ *$/) next }
         inside { print }
         /^ *-3/ { inside = 0 }' "$1"
}
for mesh in coarse fine finest; do
    for variant in plain off; do
        # The stick slope 10 % off is tested on the quick ladder (coarse, fine) only.
        [ "$variant-$mesh" = off-finest ] && continue
        dir=$work/$variant-$mesh
        mkdir -p "$dir"
        "$bin" deck ccx plate --preset plate-bench --mesh "$mesh" -o "$dir/job.inp"
        if [ "$variant" = off ]; then
            sed -i '/^\*FRICTION/{n;s/, 10000\.0$/, 11000.0/}' "$dir/job.inp"
            grep -q ', 11000.0$' "$dir/job.inp"
        fi
        (cd "$dir" && OMP_NUM_THREADS=1 nice -n 10 ccx -i job > job.log 2>&1)
        cp "$dir/job.dat" "$out/$variant-$mesh.dat"
        cut_frd "$dir/job.frd" > "$out/$variant-$mesh.frd"
    done
done
awk '/displacements .* for set / { inside = ($0 ~ /set UEND /) }
     inside && NF == 4 && $1 ~ /^[0-9]+$/ { printf "%10d  %.6E %s %s\n", $1, 1.25 * $2, $3, $4; next }
     { print }' "$out/plain-coarse.dat" > "$out/far-coarse.dat"
