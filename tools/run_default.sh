#!/usr/bin/env bash
# Sets up a fresh Debian machine, builds mcdyna (Release) and runs the default deck.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)"
build/mcdyna run decks/cube/cube_drop.k --out results/cube
