#!/bin/bash
# A run stopped the LS-DYNA way in mid-run and continued from the restart dumps it left must
# write the same histories and d3plot states as the run that went through (issue 48, item 7):
#   HOW sw1   the sense switch: "sw1" written to OUT/parts/d3kil (every process stops at the
#             same cycle after a d3dump01, one file per process; exit code 5)
#   HOW TERM  SIGTERM to the launcher (mpirun forwards it to every process before it kills
#             them) or, on one process, to mcdyna (runrsf, one file per process)
# The stop lands wherever the run is once the first 5 % line is in d3hsp: any cycle must do.
#
#   tests/mpi/stop_and_continue.sh MCDYNA MPIEXEC N OUT_DIR DECK HOW END_TIME
#
# MPIEXEC "none" runs one process without a launcher (N must be 1).
set -u
source "$(dirname "$0")/compare_outputs.sh"
bin=$1 mpiexec=$2 n=$3 out=$4 deck=$5 how=$6 end=$7
rm -rf "$out"
mkdir -p "$out"
launch=("$bin")
[ "$mpiexec" != none ] && launch=("$mpiexec" -np "$n" --oversubscribe --allow-run-as-root "$bin")
run=("${launch[@]}" run "$deck" -q --threads 1 --end-time "$end")
"${run[@]}" --out "$out/through" >"$out/through.log" 2>&1 || {
  echo "the uninterrupted run failed"
  cat "$out/through.log"
  exit 1
}
"${run[@]}" --out "$out/parts" >"$out/first.log" 2>&1 &
pid=$!
for _ in $(seq 1 600); do  # until the run has written its first 5 % line (at most 60 s)
  grep -q "^cycle" "$out/parts/d3hsp" 2>/dev/null && break
  sleep 0.1
done
if [ "$how" = sw1 ]; then
  echo sw1 >"$out/parts/d3kil"
else
  kill -TERM "$pid"
fi
wait "$pid"
code=$?
grep -E "stopped by sense switch|interrupted by signal" "$out/first.log" >/dev/null || {
  echo "the first part did not stop on $how (exit code $code):"
  tail -5 "$out/first.log"
  exit 1
}
# mcdyna exits 5; mpirun signalled itself reports its own status (Open MPI: 1).
if [ "$how" = sw1 ] || [ "$mpiexec" = none ]; then
  [ "$code" = 5 ] || {
    echo "exit code $code after $how, expected 5"
    exit 1
  }
fi
dump=d3dump01
[ "$how" = TERM ] && dump=runrsf
files=$(ls "$out/parts" | grep -c "^$dump")
[ "$files" = "$n" ] || {
  echo "expected $n restart file(s) $dump, found $files: $(ls "$out/parts")"
  exit 1
}
rm -f "$out/parts/.mcdyna.lock"
"${run[@]}" --out "$out/parts" --restart "$out/parts/$dump" >"$out/second.log" 2>&1 || {
  echo "the restart failed"
  cat "$out/second.log"
  exit 1
}
differing_outputs "$out/through" "$out/parts"
if [ -n "$DIFFERING" ]; then
  echo "$n process(es), stopped by $how and continued: DIFFERENT:$DIFFERING"
  exit 1
fi
stop=$(grep -oE "(sense switch sw1 \(d3kil\)|interrupted by signal) at t = [0-9.e+-]+, cycle [0-9]+" "$out/first.log")
echo "$n process(es), $stop, exit code $code, continued: $OUTPUT_FILES files byte-identical to the run that went through"
