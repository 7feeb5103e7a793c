#!/bin/bash
# Two solver binaries on the shipped decks, outputs compared byte for byte: what a change that
# only restructures the code (issue 25 item 1) must leave alone. Every history (ASCII and CSV)
# and every d3plot state must be identical; glstat's "time per zone cycle" line and d3hsp
# (timings) are left out.
#
#   tools/verify/same_histories.sh OLD_BINARY NEW_BINARY OUT_DIR
#   NEW_LAUNCH="mpirun -np 3 --oversubscribe" tools/verify/same_histories.sh BIN BIN OUT_DIR
#
# ONLY="beams spot_weld" runs those cases only. NEW_LAUNCH runs the new binary under a launcher: one binary on one process against the same
# binary over several (issue 25, the same bits for any process count).
#
# About 5 minutes on 2 threads. Prints one line per deck, "same" or the files that differ;
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
  [[ -z ${ONLY:-} || " $ONLY " == *" $name "* ]] || return 0
  for b in old new; do
    local bin=$OLD launch=""
    [ $b = new ] && bin=$NEW && launch=${NEW_LAUNCH:-}
    rm -rf "$OUT/$name.$b"
    $launch "$bin" run "$deck" --out "$OUT/$name.$b" -q "$@" >"$OUT/$name.$b.log" 2>&1
    eval "local rc_$b=$?"
  done
  # Both runs must end as they did (the same exit code) and write the same set of files.
  if [ "$rc_old" != "$rc_new" ] || [ ! -d "$OUT/$name.old" ] || [ ! -d "$OUT/$name.new" ]; then
    echo "$name: DIFFERENT (exit $rc_old with the old binary, $rc_new with the new; see $OUT/$name.*.log)"
    status=1
    return 0
  fi
  if [ "$(cd "$OUT/$name.old" && find . -type f | sort)" != "$(cd "$OUT/$name.new" && find . -type f | sort)" ]; then
    echo "  $name: the two runs wrote different sets of files"
    status=1
  fi
  local same=1
  # Every file, also in the case folders of a deck with *CASE.
  for f in $(cd "$OUT/$name.old" && find . -type f | grep -v "d3hsp\|lock\|runrsf\|d3dump"); do
    if [ "$(basename "$f")" = glstat ]; then
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
  echo "$name: $([ $same = 1 ] && echo same || echo DIFFERENT) ($(find "$OUT/$name.old" -type f | wc -l) files)"
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
# Shells (Belytschko-Tsay with contact, fully integrated), beams of both formulations, a spot
# weld that fails, joints, an SPG lap joint with two contacts, erosion over a border.
/usr/bin/python3 tools/decks/crush_tube.py 8 "$OUT/crush_tube.k" >/dev/null
compare crush_tube "$OUT/crush_tube.k" --cycles 3000
/usr/bin/python3 tools/decks/shell_cantilever.py 10 "$OUT/cantilever16.k" --elform 16 >/dev/null
compare cantilever16 "$OUT/cantilever16.k"
compare beams tests/regression/beam_tip_load/beam_tip_load.k
compare spot_weld tests/regression/spot_weld_lap/spot_weld_lap.k
compare spring_damper tests/regression/spring_damper/spring_damper.k
compare sliding_block tests/regression/sliding_block/sliding_block.k
compare sensor_release tests/regression/sensor_release/sensor_release.k
compare revolute tests/data/public-decks/WillemJR/dynakw/test/full_files/joint_revolute.k --cycles 3000
compare translational tests/data/public-decks/WillemJR/dynakw/test/full_files/joint_translational.k --cycles 3000
compare projectile tests/data/public-decks/ansys/pydyna/tests/testfiles/run/case-keywords/projectile.k --cycles 3000
compare two_sheets tests/data/mpi/two_sheets.k
compare eroding_bar tests/data/mpi/eroding_bar.k
exit $status
