#!/usr/bin/env bash
# Element-cycles per second of the shell pass (issue 26): the cantilever strip of
# tools/decks/shell_cantilever.py meshed 200 x 100 (20,000 shells), elastic, on 1 and 2 threads,
# for Belytschko-Tsay (ELFORM 2) and the fully integrated shell (ELFORM 16), NIP 2 and 5.
# The hexahedra's figure for comparison is tools/bench/solver_speed.sh (Taylor bar, ELFORM 1).
# OpenRadioss is not on this machine, so its QEPH shell is not run on the same deck.
# Usage: tools/bench/shell_speed.sh [CYCLES]   (default 500; needs build/mcdyna)
set -euo pipefail
cd "$(dirname "$0")/../.."
cycles=${1:-500}
work=${TMPDIR:-/tmp}/mcdyna_shell_bench
mkdir -p "$work"
for elform in 2 16; do
  for nip in 2 5; do
    deck=$work/strip_${elform}_${nip}.k
    /usr/bin/python3 tools/decks/shell_cantilever.py 200 "$deck" --ny 100 --elform "$elform" \
      --nip "$nip" --end 1.0
    for threads in 1 2; do
      build/mcdyna run "$deck" --threads "$threads" --cycles "$cycles" --out "$work/out" -q >/dev/null
      rate=$(grep -o '[0-9.]* million element-cycles/s' "$work/out/d3hsp")
      wall=$(awk '/^  total  /{print $2}' "$work/out/d3hsp")
      echo "ELFORM $elform NIP $nip, 20000 shells, $cycles cycles, threads $threads: wall $wall s, $rate"
    done
  done
done
