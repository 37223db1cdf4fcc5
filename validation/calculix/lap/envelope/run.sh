#!/bin/bash
# usage: run.sh NAME key=value ...   (gen.py deck, ccx, post.py; all in runs/NAME/)
set -e
cd "$(dirname "$0")"
name=$1; shift
mkdir -p runs/$name; cd runs/$name
python3 ../../gen.py $name "$@" > gen.txt
start=$(date +%s)
OMP_NUM_THREADS=1 nice ccx -i $name > $name.log 2>&1
end=$(date +%s)
echo "wall $((end-start)) s" >> gen.txt
python3 ../../post.py $name > post.txt
python3 ../../post.py $name --json > post.json
rm -f spooles.out
cat gen.txt post.txt
