#!/bin/bash
# The shipped decks' LS-DYNA d3plot read by VTK's independent reader (vtkLSDynaReader) and held
# against the VTK series and nodout of the same run (tools/verify/d3plot_lsdyna.py; issue 49):
# FE hexahedra with a rigid wall, the FE Taylor bar, Belytschko-Tsay shells with contact, fully
# integrated shells, beams, a spot weld, erosion, and FDS h 0.3 (its hexahedra, the screw's rigid
# shells and every node; VTK 9.1 reads only part of the SPG particles' section, which
# tests/unit/io/d3plot_test.cpp checks word by word instead).
#
#   tools/verify/d3plot_decks.sh MCDYNA OUT_DIR
#
# About a minute on 2 threads. Prints one line per deck; exits 1 if any disagrees.
set -u
BIN=$(realpath "$1")
OUT=$(realpath -m "$2")
cd "$(dirname "$0")/../.."
mkdir -p "$OUT"
status=0
runs=()
run() { # name deck [options...]
  local name=$1 deck=$2
  shift 2
  rm -rf "${OUT:?}/$name"
  if ! "$BIN" run "$deck" --out "$OUT/$name" -q "$@" >"$OUT/$name.log" 2>&1; then
    echo "$name: the run failed (see $OUT/$name.log)"
    status=1
    return 0
  fi
  runs+=("$OUT/$name")
}
run cube decks/cube/cube_drop.k
run taylor_fe decks/taylor_bar/taylor_coarse.k --cycles 3000
/usr/bin/python3 tools/decks/crush_tube.py 8 "$OUT/crush_tube.k" >/dev/null
run crush_tube "$OUT/crush_tube.k" --cycles 3000
/usr/bin/python3 tools/decks/shell_cantilever.py 10 "$OUT/cantilever16.k" --elform 16 >/dev/null
run cantilever16 "$OUT/cantilever16.k"
run beams tests/regression/beam_tip_load/beam_tip_load.k
run spot_weld tests/regression/spot_weld_lap/spot_weld_lap.k
run fds03 decks/fds/fds_h0.3.k --cycles 2000
cat >"$OUT/eroding_bar.k" <<'EOF'
*KEYWORD
*CONTROL_TERMINATION
0.2
*DATABASE_BINARY_D3PLOT
0.02
*PART
bar
1,1,1
*SECTION_SOLID
1,1
*MAT_PLASTIC_KINEMATIC
1,1.0,100.0,0.3,0.5,1.0,1.0
0,0,0.05
EOF
/usr/bin/python3 - "$OUT/eroding_bar.k" <<'EOF'
# A 6 x 1 x 1 bar of edge 0.5 (as tests/unit/solver_support.hpp's eroding_bar), one end held,
# the other pulled at 5 length/time until it necks and its elements erode.
import sys
nodes, solids = [], []
for k in range(2):
    for j in range(2):
        for i in range(7):
            nodes.append((len(nodes) + 1, 0.5 * i, 0.5 * j, 0.5 * k))
def n(i, j, k):
    return 1 + i + 7 * j + 14 * k
for i in range(6):
    solids.append((i + 1, [n(i, 0, 0), n(i + 1, 0, 0), n(i + 1, 1, 0), n(i, 1, 0),
                           n(i, 0, 1), n(i + 1, 0, 1), n(i + 1, 1, 1), n(i, 1, 1)]))
with open(sys.argv[1], "a") as f:
    f.write("*NODE\n" + "".join(f"{a},{x},{y},{z}\n" for a, x, y, z in nodes))
    f.write("*ELEMENT_SOLID\n" + "".join(f"{e},1," + ",".join(map(str, c)) + "\n"
                                         for e, c in solids))
    f.write("*SET_NODE_LIST\n1\n1,8,15,22\n*SET_NODE_LIST\n2\n7,14,21,28\n"
            "*BOUNDARY_SPC_SET\n1,0,1,1,1,0,0,0\n*BOUNDARY_PRESCRIBED_MOTION_SET\n2,1,0,3,1.0\n"
            "*DEFINE_CURVE\n3\n0,5\n1,5\n*END\n")
EOF
run eroding_bar "$OUT/eroding_bar.k"
[ ${#runs[@]} -gt 0 ] && { /usr/bin/python3 tools/verify/d3plot_lsdyna.py "${runs[@]}" || status=1; }
exit $status
