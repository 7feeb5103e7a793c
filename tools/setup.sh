#!/usr/bin/env bash
# Installs the Debian packages mcdyna needs, and only those that are missing.
# Idempotent and silent when everything is present; prints what it installs otherwise.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config clang-format
  libeigen3-dev libfmt-dev libcli11-dev libvtk9-dev doctest-dev libomp-dev
  python3-numpy python3-matplotlib python3-vtk9 time
  xvfb xauth  # tools/verify/render_state.py renders states offscreen under xvfb-run
  openmpi-bin libopenmpi-dev  # runs over many processes (issue 25); MCDYNA_MPI=OFF builds without
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
