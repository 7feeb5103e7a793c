#!/usr/bin/env bash
# Sets up a fresh Debian machine, builds (Release), checks formatting, runs the whole test suite
# but the "verification" cases (the three longest MPI decks, minutes each: `ctest -L
# verification` before landing a change to the SPG parts, contact or the processes' code)
# and the elastic-wave family of the quick study (tools/study.py end to end, ~25 s, then its table
# again from the runs' records alone), links mcdyna without MPI (the one-process communicator with
# the same solver objects) and checks that it writes the same bytes as the MPI build on one
# process (tests/nompi_same_bytes.sh), then builds the unit tests with AddressSanitizer +
# UndefinedBehaviorSanitizer (the solver -O2 with line tables for the reports, the set-up code
# and the tests -O0 as unity builds) and runs them (without the physics-length cases and the
# long decks; the MPI decks on 1 and 2 processes). Goal: under 30 minutes on a 2-core machine
# (1,510 s at a081681, manual/verification.md "CI time").
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
jobs=$(nproc)

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$jobs"

echo "== clang-format check"
git ls-files 'src/*.cpp' 'src/*.hpp' 'tests/*.cpp' 'tests/*.hpp' | xargs clang-format --dry-run --Werror

# ctest runs $jobs cases at once: each on one OpenMP thread they fill the cores without
# oversubscription (measured on the Release cases without MPI: 75.7 s -> 62.4 s of wall time); the
# cases that compare thread counts set theirs (omp_set_num_threads, --threads), the MPI decks run
# one thread per process.
export OMP_NUM_THREADS=1

echo "== tests (Release; the \"verification\" cases, minutes each, run before landing: ctest -L verification)"
ctest --test-dir build --output-on-failure -j "$jobs" -LE verification

echo "== study smoke: tools/study.py --quick --only elastic_wave (the seven quick elastic-wave runs, ITB 1 at h 0.2 among them)"
rm -rf build/study_smoke
/usr/bin/python3 tools/study.py --quick --only elastic_wave --threads "$jobs" --out build/study_smoke
# The same table again from the runs' records alone (run directories gone), as a study assembled
# over several sessions is.
cp build/study_smoke/study.csv build/study_smoke/study_from_runs.csv
rm -rf build/study_smoke/runs
/usr/bin/python3 tools/study.py --quick --only elastic_wave --reuse --out build/study_smoke >/dev/null
cmp build/study_smoke/study.csv build/study_smoke/study_from_runs.csv

echo "== FDS thread measure on synthetic walls: tools/verify/fds_unwrap.py --check"
/usr/bin/python3 tools/verify/fds_unwrap.py --check
echo "== FDS run facts on a synthetic matsum: tools/verify/fds_facts.py --check"
/usr/bin/python3 tools/verify/fds_facts.py --check
echo "== FDS time-scale figures per stage on curves with a known answer: tools/verify/fds_time_scale.py --check"
/usr/bin/python3 tools/verify/fds_time_scale.py build/mcdyna --check

echo "== mcdyna without MPI: the same bytes as the MPI build on one process"
# The one-process communicator linked with the same solver objects (CMakeLists.txt: only
# core/communicator.cpp differs between the builds), so no second build of the solver.
cmake --build build -j "$jobs" --target mcdyna_one_process
tests/nompi_same_bytes.sh build/mcdyna_one_process build/mcdyna build/nompi_same_bytes

echo "== tests (AddressSanitizer + UndefinedBehaviorSanitizer; physics-length cases left out)"
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMCDYNA_SANITIZE=ON \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" >/dev/null
cmake --build build-asan -j "$jobs"
# Physics-length cases the Release pass runs are left out here, each 30-370 s under the
# sanitizers, where shorter cases run the same code under them (the one case of a code path
# stays: ELFORM 16, bond failure, the angular budget): the MC-SPG Taylor bar's 10 us, the elastic
# waves (FE convergence, ITB 1, MC-SPG), the shells' 1-and-2-thread identity, the C0 triangles'
# period, the bouncing shell plates, MSC 1 beside a neck, ITB 1's ringing block, the FDS restart,
# particles crossing over 3 processes, the beam's first-mode period; the corpus (the reader fuzz
# reads the same decks under them); the longest MPI decks (the FE and SPG rods' split runs in
# the eroding bar, the cube, the two-sheet decks and the restarts). The "long" label: the long
# MPI decks.
physics_length=(
  "MC-SPG Taylor bar, first 10 us"
  "elastic wave rod: free-end displacement converges"
  "ITB 1 keeps the elastic wave smooth"
  "MC-SPG keeps the elastic wave smooth"
  "shells: results are bitwise identical for 1 and 2 threads"
  "ELFORM 4\\): the cantilever"
  "shell contact: plates touch at their half thicknesses"
  "MSC 1: low-energy-mode control keeps the layers"
  "ITB 1: linear momentum to round-off and the energy of a ringing"
  "restart: the FDS scene continued from a d3dump"
  "SPG particles cross to another process on 3 processes"
  "a beam cantilever's first-mode period converges"
  "corpus: every public deck runs"
  "MPI: SPG elastic rod h 0.2: 1-2 processes"
  "MPI: FE Taylor bar \\(rigid wall\\), 1500 cycles: 1-2 processes"
  # Thread-count identities (the sanitizers look for memory errors and undefined behaviour, which
  # the other cases of the same code find); the 3-process restart of the two sheets in contact
  # (its eigenvalue-step twin runs the same deck's contact dump); physics-length cases whose code
  # shorter ones run: ITB 1's critical step (two other ITB 1 cases), the MC-SPG free body's
  # momentum (the angular-momentum case), OSU 1's spinning block (the OSU 1 mass-scaling case),
  # the clamped strip's modal solution (the other shell cases).
  "bitwise identical (for|on) 1 and 2 threads"
  "MPI: 3 processes restart two SPG sheets in contact from"
  "ITB 1 critical step"
  "MC-SPG free body: linear momentum"
  "OSU 1: a spinning free block"
  "an impulsively loaded clamped strip"
  # 20-26 s each under them, their code run by shorter cases there: the SIGINT stop and
  # continue (the d3kil stop and the refused dumps run the restart path), the FDS run summary
  # (the FDS decks over processes run the scene), particles crossing on 2 processes (the
  # 3-process sheet restart re-owns particles at its renewals), the power iteration's patch
  # products (the eigenvalue-step sheets and the eigen mass-scaling case run them).
  "restart: an interrupted run leaves runrsf"
  "run summary: the driven screw's speed"
  "SPG particles cross to another process on 2 processes"
  "Power-iteration products on a renewal's patch"
)
exclude=$(IFS='|'; echo "${physics_length[*]}")
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-asan --output-on-failure -j "$jobs" -LE long -E "$exclude"
