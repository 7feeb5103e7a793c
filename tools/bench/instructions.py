#!/usr/bin/env python3
"""Instructions per particle-step of each SPG phase, counted by callgrind (valgrind): the
roofline's third ceiling (tools/bench/roofline.py), since this VM exposes no hardware counters
and the SPG phases turn out bound by the instructions they issue. Deterministic: the same count
for the same binary and deck whatever else the machine does.

Usage: instructions.py MCDYNA DECK_SHORT DECK_LONG [--flags ...]
  Runs both decks (the same deck with two ENDCYC values) under callgrind on one thread and
  prints, per phase, (inclusive instructions of LONG - those of SHORT) / (extra cycles x
  particles): the set-up and the first renewal cancel. Writes `phase instructions` lines.
"""
import os
import re
import subprocess
import sys
import tempfile

# Phase -> inclusive functions (callgrind_annotate names), summed. OpenMP clones (the parallel
# loops inside a function, "[clone ._omp_fn.N]") are left out, as their parent counts them,
# except where a pattern names the clone: the force gather, and the hexahedra, whose element
# loop is a parallel region whole.
PHASES = {
    "SPG smoothing": [r"\bspg::advance_velocities\(mcdyna::solver::State&", r"\bspg::absorb_constraints\("],
    "SPG stress": [r"::particle_update<"],
    "SPG forces": [r"spg::particle_pass\(mcdyna::solver::State&, mcdyna::solver::spg::Domain&, double, Eigen::Matrix<double, 3, -1, 0, 3, -1>&\) \[clone \._omp_fn\.0\]"],
    "SPG step estimate": [r"\bspg::recalibrate_stiffness_length\("],
    "SPG renewal": [r"\bspg::renew_kernel\(mcdyna::solver::State&, mcdyna::solver::spg::Domain&, std::vector",
                    r"\bspg::rows_to_renew\(", r"\bspg::break_bonds\("],
    "elements": [r"fe::element_loop<.*_omp_fn"],
    "contact": [r"contact::interface_pass\("],
}


def run(mcdyna, deck, flags, work):
    out = os.path.join(work, os.path.basename(deck) + ".cg")
    env = dict(os.environ, OMP_WAIT_POLICY="PASSIVE")  # mcdyna would re-execute itself to set it
    subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", mcdyna, "run",
                    deck, "--threads", "1", "--out", os.path.join(work, "out"), "-q", *flags],
                   check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    text = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", out],
                          check=True, capture_output=True, text=True).stdout
    d3hsp = open(os.path.join(work, "out", "d3hsp")).read()
    cycles = int(re.findall(r"cycle (\d+)", d3hsp)[-1])
    particles = int(re.search(r"SPG particles\s+(\d+)", d3hsp).group(1))
    counts = {}
    for phase, patterns in PHASES.items():
        total = 0
        for line in text.splitlines():
            m = re.match(r"\s*([0-9,]+) \([ 0-9.]+%\)\s+(.*)$", line)
            if not m:
                continue
            name = m.group(2)
            if "[clone" in name and not any("_omp_fn" in p for p in patterns):
                continue
            if any(re.search(p, name) for p in patterns):
                total += int(m.group(1).replace(",", ""))
        counts[phase] = total
    return cycles, particles, counts


def main():
    mcdyna, short, long_ = sys.argv[1:4]
    flags = sys.argv[4:]
    with tempfile.TemporaryDirectory() as work:
        c1, n, a = run(mcdyna, short, flags, work)
        c2, _, b = run(mcdyna, long_, flags, work)
    steps = (c2 - c1) * n
    print(f"instructions per particle-step (callgrind, cycles {c1 + 1}-{c2}, {n} particles):")
    for phase in PHASES:
        print(f"{phase} {(b[phase] - a[phase]) / steps:.0f}")


if __name__ == "__main__":
    main()
