#!/usr/bin/env bash
# Particle-steps per second of the MC-SPG solver on the Taylor bar (ELFORM 47, ITB 3, DX 1.5
# box support, Johnson-Cook + Gruneisen EOS, rigid wall), on 1 and 2 threads, with the cost split
# over the SPG phases, and the cost ratio of plain nodal integration (--spg-stabilization none)
# to MC-SPG on the same deck. Each run does CYCLES cycles from the impact.
# Target (issue 4): >= 7e5 particle-steps/s on 1 thread and >= 1.4e6 on 2 (twice LAMMPS
# MACHDYN's 3.5e5 per core at ~29 neighbours on this machine).
# Usage: tools/bench/spg_speed.sh [RESOLUTION] [CYCLES]   (default coarse 1000; needs build/mcdyna)
set -euo pipefail
cd "$(dirname "$0")/../.."
res=${1:-coarse}
cycles=${2:-1000}
work=${TMPDIR:-/tmp}/mcdyna_spg_bench
mkdir -p "$work"
deck=$work/taylor_spg_${res}_${cycles}.k
/usr/bin/python3 tools/decks/taylor_bar.py "$res" --spg "$deck" --cycles "$cycles" >/dev/null

# One run; prints its rate and phase split, leaves the wall time in $wall.
run() {
  local threads=$1 mode=$2 label=$3 out=$work/out_${threads}_$2
  build/mcdyna run "$deck" --threads "$threads" --spg-stabilization "$mode" --out "$out" -q \
    >/dev/null 2>&1
  wall=$(awk '/^  total  /{print $2}' "$out/d3hsp")
  local rate split summary
  rate=$(grep -o '[0-9.]* million particle-steps/s' "$out/d3hsp")
  split=$(awk '/^  SPG (neighbour search|shape functions|smoothing|stress|forces) /{
      name = $2; if ($3 !~ /^[0-9]/) name = name " " $3;
      printf "%s%s %s %%", sep, name, $(NF - 1); sep = ", " }' "$out/d3hsp")
  summary=$(grep -o '[0-9.]* neighbours per particle, [0-9]* kernel renewals' "$out/d3hsp")
  echo "$label threads $threads: wall $wall s, $rate; $summary"
  echo "    split: $split"
}

echo "deck: Taylor bar $res MC-SPG, $cycles cycles from the impact"
for threads in 1 2; do
  for rep in 1 2; do
    run "$threads" mc "mc  run $rep"
  done
done
run 2 mc "mc  (ratio)"
mc=$wall
run 2 none "none (ratio)"
none=$wall
awk -v a="$none" -v b="$mc" 'BEGIN { printf "cost ratio none : mc = %.2f : 1 (2 threads)\n", a / b }'
