#!/usr/bin/env bash
# Sets up a fresh Debian machine, builds mcdyna (Release) and runs the default deck: the
# flow-drill-screw scene at h = 0.3 mm (2,742 MC-SPG particles, FE ring, rigid screw, contact,
# time scale 20, the eigenvalue step; about 5 minutes on 2 cores), then prints the force on the
# screw against plunge and the depth of the thread it formed.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)"
build/mcdyna run decks/fds/fds_h0.3.k --spg-step eigen --out results/fds_h0.3
/usr/bin/python3 tools/verify/fds_force.py results/fds_h0.3 --png results/fds_h0.3/force_vs_plunge.png
/usr/bin/python3 tools/verify/fds_section.py results/fds_h0.3 results/fds_h0.3/section.png \
  --half-width 0.2
# The hole wall unrolled and the thread depth the screw formed in the plate (fds_unwrap.py).
/usr/bin/python3 tools/verify/fds_unwrap.py results/fds_h0.3 results/fds_h0.3/thread.png \
  --z-range -3 1.5
