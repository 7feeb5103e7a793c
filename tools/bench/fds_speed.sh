#!/usr/bin/env bash
# Speed of the flow-drill-screw scene (issue 5): particle-steps per second of the h = 0.15 mm deck
# (19,547 MC-SPG particles, 11,520 FE hexahedra, 9,672 rigid screw shells, automatic
# nodes-to-surface contact with friction) on 1 and 2 threads, and the share of the contact phase
# in the wall time. The run starts at t = 0 (the tip touching the plate) and goes CYCLES cycles
# into the plunge, so contact is active throughout.
# Usage: tools/bench/fds_speed.sh [H] [CYCLES] [TIME_SCALE]   (default 0.15 3000 20; needs build/mcdyna)
set -euo pipefail
cd "$(dirname "$0")/../.."
h=${1:-0.15}
cycles=${2:-3000}
scale=${3:-20}
work=${TMPDIR:-/tmp}/mcdyna_fds_bench
mkdir -p "$work"
deck=$work/fds_h${h}_${cycles}.k
/usr/bin/python3 tools/decks/fds.py "$h" "$deck" --time-scale "$scale" --cycles "$cycles" \
  --states 1 >/dev/null

echo "deck: FDS h = $h mm, time scale $scale, $cycles cycles from the first touch"
for threads in 1 2; do
  out=$work/out_$threads
  build/mcdyna run "$deck" --threads "$threads" --out "$out" -q >/dev/null 2>&1
  wall=$(awk '/^  total  /{print $2}' "$out/d3hsp")
  contact=$(awk '/^  contact  /{print $(NF - 1)}' "$out/d3hsp")
  rate=$(grep -o '[0-9.]* million particle-steps/s' "$out/d3hsp")
  particles=$(grep -o 'SPG part 1: [0-9]* particles' "$out/d3hsp" | awk '{print $4}')
  echo "threads $threads: wall $wall s, $rate ($particles particles), contact $contact % of the wall time"
done
