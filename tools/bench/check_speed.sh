#!/usr/bin/env bash
# Speed of `mcdyna check` on a generated deck with 1,000,000 hexahedra (100^3) and 1,030,301
# nodes. Prints wall time, peak resident memory and deck size. Target (issue 2): < 3 s, < 1 GiB.
# Usage: tools/bench/check_speed.sh [N]   (default N = 100; needs build/mcdyna)
set -euo pipefail
cd "$(dirname "$0")/../.."
n=${1:-100}
deck=${TMPDIR:-/tmp}/mcdyna_bench_${n}.k
[ -f "$deck" ] || /usr/bin/python3 tools/bench/generate_mesh_deck.py "$n" "$deck"
echo "deck: $deck ($(du -m "$deck" | cut -f1) MB, $((n*n*n)) elements, $(((n+1)*(n+1)*(n+1))) nodes)"
for run in 1 2 3; do
  /usr/bin/time -f "run $run: wall %e s, peak RSS %M KiB" build/mcdyna check -q "$deck" >/dev/null
done
