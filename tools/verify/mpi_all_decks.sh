#!/bin/bash
# Every shipped deck (decks/) and every public deck that runs on one process
# (tests/data/public-decks), run for a few cycles on 1 process and under mpirun on 2 and 3
# processes (one thread each): every history and d3plot state byte for byte the same (issue 25,
# "mpirun runs every shipped deck"). Prints one line per deck.
#
#   [MCDYNA=binary] tools/verify/mpi_all_decks.sh [OUT_DIR] [CYCLES]   (default build/mcdyna, with MPI)
set -u
cd "$(dirname "$0")/../.."
source tests/mpi/compare_outputs.sh
out=$(realpath -m "${1:-${TMPDIR:-/tmp}/mcdyna_mpi_all}")
cycles=${2:-200}
bin=$(realpath "${MCDYNA:-build/mcdyna}")  # MCDYNA: a copy, safe from rebuilds
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
rm -rf "$out"
mkdir -p "$out"
status=0
same=0 ran=0 skipped=0
while IFS= read -r deck; do
  name=$(echo "$deck" | tr '/' '_')
  d="$out/$name"
  if ! "$bin" run "$deck" --out "$d/np1" -q --threads 1 --cycles "$cycles" >"$d.np1.log" 2>&1 </dev/null; then
    skipped=$((skipped + 1))  # not a complete explicit model (or not supported): not compared
    continue
  fi
  ran=$((ran + 1))
  line="$deck:"
  for n in 2 3; do
    if ! mpirun -np "$n" --oversubscribe "$bin" run "$deck" --out "$d/np$n" -q --threads 1 \
      --cycles "$cycles" >"$d.np$n.log" 2>&1 </dev/null; then
      if grep -q "each process needs at least one" "$d.np$n.log"; then
        line="$line $n: too few elements;"
        continue
      fi
      line="$line $n: RUN FAILED;"
      status=1
      continue
    fi
    differing_outputs "$d/np1" "$d/np$n"
    differ=$DIFFERING
    if [ -z "$differ" ]; then line="$line $n: same;"; else
      line="$line $n: DIFFERENT$differ;"
      status=1
    fi
  done
  echo "$line"
  [[ "$line" == *DIFFERENT* || "$line" == *FAILED* ]] || same=$((same + 1))
done < <(
  ls decks/*/*.k
  find tests/data/public-decks -type f \( -name '*.k' -o -name '*.key' -o -name '*.dyn' \) | sort
)
echo "$ran decks ran on one process ($skipped did not: not complete explicit models or unsupported); $same of them the same on 2 and 3 processes"
exit $status
