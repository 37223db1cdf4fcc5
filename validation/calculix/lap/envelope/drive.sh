#!/bin/bash
# usage: drive.sh NAME[:variant] ...   runs each case in turn (ONE ccx at a time), skipping done ones.
# variant: c (coarse, default), f (every element size halved), i (force increments halved)
cd "$(dirname "$0")"
for spec in "$@"; do
  name=${spec%%:*}; var=${spec#*:}; [ "$var" = "$spec" ] && var=c
  run=${name}_${var}
  if [ -s runs/$run/post.json ]; then echo "skip $run"; continue; fi
  echo "$(date +%T) start $run"
  ./run.sh $run $(python3 grid.py args $name $var) > runs_$run.txt 2>&1 || echo "FAILED $run"
  echo "$(date +%T) end $run: $(grep wall runs/$run/gen.txt)"
done
