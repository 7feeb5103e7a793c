#!/usr/bin/env bash
# Speed of the flow-drill-screw scene (issues 5 and 23): particle-steps per second of the FDS deck
# (h 0.15 mm: 19,547 MC-SPG particles, 11,520 FE hexahedra, 9,672 rigid screw shells, automatic
# nodes-to-surface contact with friction) on 1 and 2 threads, per core, and the split of the wall
# time over the phases. The run starts at t = 0 (the tip touching the plate) and goes CYCLES
# cycles into the plunge, so contact is active throughout.
#
# Usage: tools/bench/fds_speed.sh [H] [CYCLES] [TIME_SCALE]   (default 0.15 3000 20)
#   BINARY=build/mcdyna  THREADS="1 2"  SPG_STEP=eigen|nn (--spg-step, default eigen)
#   OSU=1 (*CONTROL_ACCURACY OSU of the generated deck, default 1)
#   RUN=DIR: also the cycles per plunge-mm of a finished FDS run in DIR, per stage (from its
#     d3hsp cycle count and force_vs_plunge.csv / glstat.csv)
#   INSTRUCTIONS=1: also count each phase's instructions per particle-step with callgrind
#     (tools/bench/instructions.py, cycles 41-100 of the same deck, about 5 minutes) and give the
#     roofline its instruction columns
#   ROOFLINE=0: skip the roofline (by default the machine's ceilings are measured once with
#     tools/bench/bandwidth.cpp and each run's phases are set against them, tools/bench/roofline.py)
# Figures print; nothing is asserted (wall-clock time is never a test).
set -euo pipefail
cd "$(dirname "$0")/../.."
h=${1:-0.15}
cycles=${2:-3000}
scale=${3:-20}
binary=${BINARY:-build/mcdyna}
step=${SPG_STEP:-eigen}
osu=${OSU:-1}
work=${TMPDIR:-/tmp}/mcdyna_fds_bench
mkdir -p "$work"
# The bench deck, ending after CYCLES cycles: fds_deck OUT CYCLES.
fds_deck() {
  /usr/bin/python3 tools/decks/fds.py "$h" "$1" --time-scale "$scale" --cycles "$2" \
    --states 1 --osu "$osu" >/dev/null
}
deck=$work/fds_h${h}_${cycles}_osu${osu}.k
fds_deck "$deck" "$cycles"

roofline=${ROOFLINE:-1}
ceilings=$work/ceilings.txt
if [[ "$roofline" == 1 ]]; then
  # The ceilings with the solver's own compiler flags (CMake's Release: -O3, no -march).
  g++ -O3 -fopenmp tools/bench/bandwidth.cpp -o "$work/bandwidth"
  echo "ceilings of this machine (tools/bench/bandwidth.cpp):"
  "$work/bandwidth" ${THREADS:-1 2} | tee "$ceilings" | sed 's/^/  /'
fi

counts=""
if [[ "$roofline" == 1 && "${INSTRUCTIONS:-0}" == 1 ]]; then
  for n in 40 100; do
    fds_deck "$work/fds_h${h}_$n.k" "$n"
  done
  counts=$work/instructions.txt
  /usr/bin/python3 tools/bench/instructions.py "$binary" "$work/fds_h${h}_40.k" \
    "$work/fds_h${h}_100.k" --spg-step "$step" | tee "$counts" | sed 's/^/  /'
fi

echo "deck: FDS h = $h mm, time scale $scale, $cycles cycles from the first touch, OSU $osu," \
  "--spg-step $step, $binary"
for threads in ${THREADS:-1 2}; do
  out=$work/out_$threads
  "$binary" run "$deck" --threads "$threads" --spg-step "$step" --out "$out" -q >/dev/null 2>&1
  wall=$(awk '/^  total  /{print $2}' "$out/d3hsp")
  rate=$(grep -o '[0-9.]* million particle-steps/s' "$out/d3hsp" | awk '{print $1}')
  particles=$(grep -o 'SPG part 1: [0-9]* particles' "$out/d3hsp" | head -1 | awk '{print $4}')
  per_core=$(awk -v r="$rate" -v t="$threads" 'BEGIN{printf "%.3f", r / t}')
  echo "threads $threads: wall $wall s, $rate million particle-steps/s ($per_core per core," \
    "$particles particles)"
  # The phase split of the timing summary: "  name   seconds s   share %".
  awk '/^Timing per phase/{on=1; next} on && /^  total/{exit}
       on && / s +[0-9.]+ %$/{n=NF; name=$1; for(i=2;i<=n-4;i++) name=name" "$i;
                               printf "    %-22s %9s s %6s %%\n", name, $(n-3), $(n-1)}' \
    "$out/d3hsp"
  if [[ "$roofline" == 1 ]]; then
    /usr/bin/python3 tools/bench/roofline.py "$out/d3hsp" "$ceilings" $counts | sed 's/^/    /'
  fi
done

if [[ -n "${RUN:-}" ]]; then
  /usr/bin/python3 - "$RUN" <<'EOF'
import csv, re, sys
run = sys.argv[1]
text = open(f"{run}/d3hsp").read()
total = int(re.findall(r"at t = [0-9.e+-]+, cycle (\d+)", text)[-1])
steps = [(float(r["time"]), float(r["time_step"])) for r in csv.DictReader(open(f"{run}/glstat.csv"))]
plunge = [(float(r["time"]), float(r["plunge"])) for r in csv.DictReader(open(f"{run}/force_vs_plunge.csv"))]
def plunge_at(t):
    for (t0, p0), (t1, p1) in zip(plunge, plunge[1:]):
        if t0 <= t <= t1:
            return p0 + (p1 - p0) * (t - t0) / (t1 - t0) if t1 > t0 else p1
    return plunge[-1][1]
# Cycles between glstat rows from their steps (the mean of the steps at both ends).
rows = []
for (t0, d0), (t1, d1) in zip(steps, steps[1:]):
    mean = 0.5 * (d0 + d1) if d0 > 0 else d1
    rows.append((t0, t1, (t1 - t0) / mean if mean > 0 else 0.0))
est = sum(r[2] for r in rows)
scale = total / est if est > 0 else 1.0  # the glstat rows estimate; scaled to the real count
by_stage = {}
for t0, t1, n in rows:
    p0, p1 = plunge_at(t0), plunge_at(t1)
    stage = 1 if p1 <= 4.55 + 1e-6 else 2  # the schedule's first 4.55 mm (tools/decks/fds.py)
    c, mm = by_stage.get(stage, (0.0, 0.0))
    by_stage[stage] = (c + n * scale, mm + (p1 - p0))
print(f"run {run}: {total} cycles, plunge {plunge[-1][1]:.3f} mm")
for stage, (c, mm) in sorted(by_stage.items()):
    if mm > 0:
        print(f"  stage {stage}: {c:.0f} cycles over {mm:.3f} mm: {c / mm:.0f} cycles per plunge-mm")
EOF
fi
