#!/bin/bash
# Shell cantilever mesh study (issue 26): the first-mode period of the clamped steel strip of
# tools/decks/shell_cantilever.py at 5, 10, 20 and 40 elements along its length (2 across)
# against Euler-Bernoulli beam theory, with the energy drift, the hourglass share and the cost.
#
#   [MCDYNA=binary] [ELFORM=2|16] tools/verify/shell_cantilever_study.sh [OUT_DIR]   (about 10 s)
set -eu
cd "$(dirname "$0")/../.."
out=$(realpath -m "${1:-${TMPDIR:-/tmp}/shell_cantilever_study}")
bin=$(realpath "${MCDYNA:-build/mcdyna}")
mkdir -p "$out"
elform=${ELFORM:-2}
for nx in 5 10 20 40; do
  /usr/bin/python3 tools/decks/shell_cantilever.py "$nx" "$out/cantilever_$nx.k" --elform "$elform"
  "$bin" run "$out/cantilever_$nx.k" --out "$out/nx$nx" --threads 1 >"$out/nx$nx.log" 2>&1
  echo "== nx $nx ($((2 * nx)) shells): $(grep -E 'element-cycles/s' "$out/nx$nx.log" | xargs)," \
    "$(grep -E '^  total' "$out/nx$nx.log" | xargs)"
  /usr/bin/python3 tools/verify/shell_modes.py "$out/nx$nx"
done
