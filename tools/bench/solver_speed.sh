#!/usr/bin/env bash
# Element-cycles per second of the explicit solver on the Taylor bar (ELFORM 1, Johnson-Cook +
# Gruneisen EOS, rigid wall), on 1 and 2 threads. Each run does CYCLES cycles of the fine deck
# (30,240 hexahedra) from the impact, so the plastic return mapping and the wall are active.
# Target (issue 3): >= 1.8 million on 1 thread and >= 3.4 million on 2.
# Usage: tools/bench/solver_speed.sh [RESOLUTION] [CYCLES]   (default fine 1500; needs build/mcdyna)
set -euo pipefail
cd "$(dirname "$0")/../.."
res=${1:-fine}
cycles=${2:-1500}
work=${TMPDIR:-/tmp}/mcdyna_solver_bench
mkdir -p "$work"
deck=$work/taylor_${res}_${cycles}.k
/usr/bin/python3 tools/decks/taylor_bar.py "$res" "$deck" --cycles "$cycles"
elements=$(awk '/^\*ELEMENT_SOLID/{f=1;next} /^\*/{f=0} f' "$deck" | wc -l)
echo "deck: Taylor bar $res, $elements hexahedra, $cycles cycles"
for threads in 1 2; do
  for run in 1 2 3; do
    out=$(build/mcdyna run "$deck" --threads "$threads" --out "$work/out_$threads" -q)
    rate=$(grep -o '[0-9.]* million element-cycles/s' "$work/out_$threads/d3hsp")
    wall=$(awk '/^  total  /{print $2}' "$work/out_$threads/d3hsp")
    echo "threads $threads run $run: wall $wall s, $rate"
  done
done
