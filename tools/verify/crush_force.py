#!/usr/bin/python3
"""Crushing force of the square tube (tools/decks/crush_tube.py) from bndout.csv: the force the
driven end's prescribed motion applies, summed over its nodes, against the crush distance, and
its mean over the crush against Abramowicz and Jones (1984), P_m = 13.06 sigma0 t^(5/3) C^(1/3).

  tools/verify/crush_force.py RUN_DIR [--speed 10000] [--ramp 5e-4] [--png OUT.png]
"""
import argparse
import csv
import os
import sys
from collections import defaultdict

SIGMA0, THICK, SIDE = 100.0, 1.5, 50.0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run")
    ap.add_argument("--speed", type=float, default=10000.0)
    ap.add_argument("--ramp", type=float, default=5e-4)
    ap.add_argument("--png")
    a = ap.parse_args()
    force = defaultdict(float)
    with open(os.path.join(a.run, "bndout.csv")) as f:
        for r in csv.DictReader(f):
            force[float(r["time"])] -= float(r["z_force"])
    times = sorted(force)

    def crush(t):  # the driven end's travel under the ramped velocity
        if t <= a.ramp:
            return 0.5 * a.speed * t * t / a.ramp
        return a.speed * (t - 0.5 * a.ramp)

    d = [crush(t) for t in times]
    p = [force[t] for t in times]
    work = sum(0.5 * (p[k] + p[k - 1]) * (d[k] - d[k - 1]) for k in range(1, len(d)))
    mean = work / d[-1]
    reference = 13.06 * SIGMA0 * THICK ** (5 / 3) * SIDE ** (1 / 3)
    print(f"crush {d[-1]:.1f} mm: peak {max(p) / 1e3:.2f} kN, mean {mean / 1e3:.3f} kN, "
          f"absorbed {work / 1e3:.1f} J")
    print(f"Abramowicz-Jones {reference / 1e3:.3f} kN: mean force {100 * (mean / reference - 1):+.1f} %")
    for lo, hi in [(0, 20), (20, 40), (40, 60), (60, 80)]:
        sel = [k for k in range(1, len(d)) if lo <= d[k] < hi]
        if len(sel) > 2:
            w = sum(0.5 * (p[k] + p[k - 1]) * (d[k] - d[k - 1]) for k in sel)
            print(f"  {lo:2d}-{hi:2d} mm: mean {w / (d[sel[-1]] - d[sel[0] - 1]) / 1e3:.2f} kN")
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        plt.figure(figsize=(8, 4.5))
        plt.plot(d, [x / 1e3 for x in p], lw=0.8, label="mcdyna")
        plt.axhline(reference / 1e3, color="k", ls="--", label="Abramowicz-Jones mean")
        plt.axhline(mean / 1e3, color="C1", ls=":", label="mcdyna mean")
        plt.xlabel("crush (mm)")
        plt.ylabel("force (kN)")
        plt.legend()
        plt.tight_layout()
        plt.savefig(a.png, dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main())
