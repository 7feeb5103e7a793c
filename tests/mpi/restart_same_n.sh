#!/bin/bash
# A run over N processes stopped after a restart dump and continued from it (each process
# reads its own d3dumpNN.000r) must write the same histories and d3plot states as the run
# that went through (issue 25: one dump per process, a restart on the same N).
#
#   tests/mpi/restart_same_n.sh MCDYNA MPIEXEC N OUT_DIR DECK DUMP_CYCLES STOP_CYCLES [END_TIME]
#
# END_TIME (optional) ends the run that goes through and the continued one there instead of at
# the deck's termination time. RUN_OPTIONS (environment, optional): more `mcdyna run` options
# for all three runs.
set -u
source "$(dirname "$0")/compare_outputs.sh"
bin=$1 mpiexec=$2 n=$3 out=$4 deck=$5 every=$6 stop=$7
end=()
[ $# -ge 8 ] && end=(--end-time "$8")
rm -rf "$out"
mkdir -p "$out"
# The deck with a d3dump every DUMP_CYCLES cycles.
sed "0,/^\*KEYWORD/s//*KEYWORD\n*DATABASE_BINARY_D3DUMP\n$every/" "$deck" >"$out/deck.k"
read -r -a options <<<"${RUN_OPTIONS:-}"
launch=("$mpiexec" -np "$n" --oversubscribe --allow-run-as-root "$bin" run "$out/deck.k" -q
  "${options[@]}")
"${launch[@]}" --out "$out/through" "${end[@]}" >"$out/through.log" 2>&1 || {
  echo "the uninterrupted run failed"
  cat "$out/through.log"
  exit 1
}
"${launch[@]}" --out "$out/parts" --cycles "$stop" >"$out/first.log" 2>&1 || {
  echo "the first part failed"
  cat "$out/first.log"
  exit 1
}
dumps=$(ls "$out/parts" | grep -c "^d3dump01\.")
[ "$dumps" = "$n" ] || {
  echo "expected $n files d3dump01.0000 ..., found $dumps: $(ls "$out/parts")"
  exit 1
}
"${launch[@]}" --out "$out/parts" --restart "$out/parts/d3dump01" "${end[@]}" >"$out/second.log" 2>&1 || {
  echo "the restart failed"
  cat "$out/second.log"
  exit 1
}
differing_outputs "$out/through" "$out/parts"
differ=$DIFFERING
if [ -n "$differ" ]; then
  echo "$n processes, restarted from $n dumps: DIFFERENT:$differ"
  exit 1
fi
echo "$n processes, restarted from $n dumps: $OUTPUT_FILES files byte-identical to the run that went through"
