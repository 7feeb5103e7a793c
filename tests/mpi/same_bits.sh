#!/bin/bash
# One deck on 1 process and under mpirun on 2, 3 and 4: every history (ASCII and CSV) and every
# d3plot state must be byte for byte the same (issue 25: the same bits for any process count).
# glstat's "time per zone cycle" line is a timing and is left out, as are d3hsp and the dumps;
# d3hsp's timing table must give each phase's range over the processes.
#
#   [PROCESSES="2 3"] tests/mpi/same_bits.sh MCDYNA MPIEXEC OUT_DIR DECK [run options...]
#
# PROCESSES: the counts compared with 1 process (default 2, 3 and 4).
# Prints one line per process count and exits 1 when any file differs or a run fails.
set -u
source "$(dirname "$0")/compare_outputs.sh"
bin=$1 mpiexec=$2 out=$3 deck=$4
shift 4
rm -rf "$out"
mkdir -p "$out"
"$bin" run "$deck" --out "$out/np1" -q "$@" >"$out/np1.log" 2>&1 || {
  echo "1 process: the run failed"
  cat "$out/np1.log"
  exit 1
}
status=0
for n in ${PROCESSES:-2 3 4}; do
  # One thread per process: CI machines may have fewer cores than processes, and the answer
  # does not depend on the thread count either.
  "$mpiexec" -np "$n" --oversubscribe --allow-run-as-root "$bin" run "$deck" --out "$out/np$n" \
    -q --threads 1 "$@" >"$out/np$n.log" 2>&1 || {
    echo "$n processes: the run failed"
    cat "$out/np$n.log"
    status=1
    continue
  }
  # d3hsp's timing rows end with the least and the most any process took: process 0's seconds
  # lie between them ("  name  p0 s  share %  least - most s").
  if ! awk '/^Timing per phase/{on=1; next} on && /^  total/{exit}
            on && / - [0-9.]+ s$/{rows++; if (!($(NF-3)+0 <= $(NF-7)+0 && $(NF-7)+0 <= $(NF-1)+0)) bad=1}
            END{exit !(rows > 0 && !bad)}' "$out/np$n/d3hsp"; then
    echo "$n processes: d3hsp's timing table has no range over the processes, or a wrong one"
    status=1
  fi
  differing_outputs "$out/np1" "$out/np$n"
  differ=$DIFFERING
  if [ -z "$differ" ]; then
    echo "$n processes: $OUTPUT_FILES files byte-identical to 1 process"
  else
    echo "$n processes: DIFFERENT:$differ"
    status=1
  fi
done
exit $status
