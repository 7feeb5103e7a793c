#!/bin/bash
# The build without MPI (-DMCDYNA_MPI=OFF) against the MPI build on one process: the same decks
# must write the same bytes (only core::Communicator and the launcher check differ between the
# two), and a no-MPI binary started by mpirun over several processes must stop with one clear
# error (exit code 2) and write nothing. tools/test.sh runs it; the whole suite runs on the MPI
# build, in Release and under the sanitizers.
#
#   tests/nompi_same_bytes.sh NOMPI_MCDYNA MPI_MCDYNA OUT_DIR
set -u
source "$(dirname "$0")/mpi/compare_outputs.sh"
nompi=$1 mpi=$2 out=$3
root=$(cd "$(dirname "$0")/.." && pwd)
rm -rf "$out"
mkdir -p "$out"
status=0
check() { # name deck [run options...]
  local name=$1 deck=$2
  shift 2
  for build in nompi mpi; do
    local bin=$nompi
    [ $build = mpi ] && bin=$mpi
    "$bin" run "$root/$deck" --out "$out/$name/$build" -q "$@" >"$out/$name/$build.log" 2>&1 || {
      echo "$name: the $build run failed"
      cat "$out/$name/$build.log"
      status=1
      return
    }
  done
  differing_outputs "$out/$name/mpi" "$out/$name/nompi"
  if [ -n "$DIFFERING" ]; then
    echo "$name: DIFFERENT:$DIFFERING"
    status=1
  else
    echo "$name: $OUTPUT_FILES files byte-identical to the MPI build's"
  fi
}
mkdir -p "$out"/{cube,rod,taylor_fe,taylor_spg,fracture,fds}
check cube decks/cube/cube_drop.k
check rod decks/elastic_wave/rod_spg_h0.2.k
check taylor_fe decks/taylor_bar/taylor_coarse.k --cycles 300
check taylor_spg decks/taylor_bar/taylor_spg_coarse.k --cycles 100
check fracture decks/fracture/tension_spg_h1.k --cycles 300
check fds decks/fds/fds_h0.3.k --cycles 100 --spg-step eigen

# Started as 2 processes without MPI built in: process 0 says so, process 1 stays silent.
message=$(OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=0 "$nompi" run "$root/decks/cube/cube_drop.k" \
  --out "$out/launcher" 2>&1)
code=$?
if [ $code -ne 2 ] || [[ $message != *"started as 2 processes (mpirun -np 2), but this build has no MPI"* ]] ||
  [ -e "$out/launcher/d3hsp" ]; then
  echo "mpirun -np 2 without MPI built in: exit code $code, expected 2 and one clear error:"
  echo "$message"
  status=1
else
  echo "mpirun -np 2 without MPI built in: exit code 2, one clear error, nothing written"
fi
exit $status
