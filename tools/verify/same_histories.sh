#!/bin/bash
# Two solver binaries on the shipped decks, outputs compared byte for byte: what a change that
# only restructures the code (issue 25 item 1) must leave alone. Every history (ASCII and CSV)
# and every d3plot state must be identical; glstat's "time per zone cycle" line and d3hsp
# (timings) are left out.
#
#   tools/verify/same_histories.sh OLD_BINARY NEW_BINARY OUT_DIR
#   NEW_LAUNCH="mpirun -np 3 --oversubscribe" tools/verify/same_histories.sh BIN BIN OUT_DIR
#
# NEW_LAUNCH runs the new binary under a launcher: one binary on one process against the same
# binary over several (issue 25, the same bits for any process count).
#
# About 3.5 minutes on 2 threads. Prints one line per deck, "same" or the files that differ;
# exits 1 if any differs.
set -u
OLD=$(realpath "$1")
NEW=$(realpath "$2")
OUT=$(realpath -m "$3")
cd "$(dirname "$0")/../.."
mkdir -p "$OUT"
status=0
compare() { # name deck [options...]
  local name=$1 deck=$2
  shift 2
  for b in old new; do
    local bin=$OLD launch=""
    [ $b = new ] && bin=$NEW && launch=${NEW_LAUNCH:-}
    rm -rf "$OUT/$name.$b"
    $launch "$bin" run "$deck" --out "$OUT/$name.$b" -q "$@" >"$OUT/$name.$b.log" 2>&1
  done
  local same=1
  for f in $(cd "$OUT/$name.old" && ls | grep -v "d3hsp\|lock\|runrsf\|d3dump"); do
    if [ "$f" = glstat ]; then
      diff -q <(grep -v "time per zone" "$OUT/$name.old/$f") \
        <(grep -v "time per zone" "$OUT/$name.new/$f") >/dev/null || {
        echo "  $name: $f differs"
        same=0
      }
    else
      cmp -s "$OUT/$name.old/$f" "$OUT/$name.new/$f" || {
        echo "  $name: $f differs"
        same=0
      }
    fi
  done
  [ $same = 1 ] || status=1
  echo "$name: $([ $same = 1 ] && echo same || echo DIFFERENT) ($(ls "$OUT/$name.old" | wc -l) files)"
}
# FE with a rigid wall, FE / MC-SPG / ITB 1 Taylor bars, nodal motion and bond failure, an
# elastic SPG rod with SPC output, FDS (rigid prescribed motion, contact, SPC) both ways.
compare cube decks/cube/cube_drop.k
compare taylor_fe decks/taylor_bar/taylor_coarse.k --cycles 3000
compare taylor_spg decks/taylor_bar/taylor_spg_coarse.k --cycles 1500
compare taylor_itb1 decks/taylor_bar/taylor_spg_coarse.k --cycles 800 --spg-stabilization spg
compare tension decks/fracture/tension_spg_h1.k --cycles 3000
compare rod decks/elastic_wave/rod_spg_h0.2.k
compare fds03 decks/fds/fds_h0.3.k --cycles 4000
compare fds03_itb1 decks/fds/fds_h0.3.k --cycles 2000 --spg-stabilization spg
exit $status
