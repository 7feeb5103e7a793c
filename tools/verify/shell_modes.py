#!/usr/bin/python3
"""First-mode period of the shell cantilever (tools/decks/shell_cantilever.py) from its tip
displacement, against Euler-Bernoulli beam theory, and the energy balance of the run.

  tools/verify/shell_modes.py RUN_DIR [--node ID]

Prints the period from the zero crossings of the tip z displacement (linear interpolation
between history samples; the mean over all full periods), the beam-theory period, the error,
and the largest drift of glstat's total energy from its start.
"""
import argparse
import csv
import math
import os
import sys

E, NU, RHO = 210e9, 0.3, 7850.0
LENGTH, THICK = 0.1, 0.001
BETA_L = 1.8751040687119611


def beam_period():
    """Euler-Bernoulli first-mode period of the strip (I / A = t^2 / 12)."""
    f1 = BETA_L**2 / (2 * math.pi * LENGTH**2) * math.sqrt(E * THICK**2 / (12 * RHO))
    return 1.0 / f1


def columns(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run")
    ap.add_argument("--node", type=int, default=None)
    a = ap.parse_args()
    rows = columns(os.path.join(a.run, "nodout.csv"))
    node = a.node if a.node is not None else int(rows[0]["node"])
    t = [float(r["time"]) for r in rows if int(r["node"]) == node]
    z = [float(r["z_disp"]) for r in rows if int(r["node"]) == node]
    # z starts at 0 going up: the crossings after the start are half periods apart.
    crossings = []
    for k in range(1, len(z)):
        if t[k - 1] > 0 and z[k - 1] * z[k] < 0:
            crossings.append(t[k - 1] - z[k - 1] * (t[k] - t[k - 1]) / (z[k] - z[k - 1]))
    if len(crossings) < 2:
        print("fewer than two zero crossings: run longer")
        return 1
    periods = len(crossings) - 1
    period = 2.0 * (crossings[-1] - crossings[0]) / periods
    ref = beam_period()
    amp = max(abs(v) for v in z)
    g = columns(os.path.join(a.run, "glstat.csv"))
    total = [float(r["total_energy"]) for r in g]
    hourglass = float(g[-1]["hourglass_energy"])
    drift = max(abs(x - total[0]) for x in total) / total[0]
    print(f"tip node {node}: period {period * 1e3:.4f} ms from {periods} half periods, "
          f"amplitude {amp * 1e3:.4f} mm")
    print(f"beam theory {ref * 1e3:.4f} ms: error {100 * (period / ref - 1):+.2f} %")
    print(f"energy: total drift {100 * drift:.2e} % of the start, hourglass {100 * hourglass / total[0]:.2f} %")
    return 0


if __name__ == "__main__":
    sys.exit(main())
