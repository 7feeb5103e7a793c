#!/usr/bin/python3
"""Elastic-wave rod runs against the analytic solution (benchmarks.md §3).

usage: elastic_wave.py RESULTS_DIR [RESULTS_DIR ...] [--png histories.png]
For each run directory (made by `mcdyna run decks/elastic_wave/rod_hH.k --out DIR`) prints:
  - the relative L2 error of the free-end displacement u(L, t) over 0 <= t <= 80, from nodout.csv
    (the free-end node is the one starting at x = 10);
  - the mid-length stress sigma_xx(L/2, t) from the d3plot states (mean of the two element layers
    that meet at x = 5): mean absolute error divided by rho c |v0| = 1, over the states at least
    1 time unit away from the jumps at t = 5, 15, 25, ..., and the largest overshoot beyond 1;
  - the number of elements, cycles and the wall time from d3hsp.
"""
import argparse
import re

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

from d3plot import read_state, states

V0, L, C, RHO = -0.01, 10.0, 1.0, 100.0
T_END = 80.0


def u_free_end(t):
    """Triangle wave of amplitude |v0| L / c and period 4 L / c."""
    p = np.mod(t, 4 * L / C)
    g = np.where(p <= L, p, np.where(p <= 3 * L, 2 * L - p, p - 4 * L))
    return V0 * g


def sigma_mid(t, x=L / 2):
    """Piecewise-constant stress at x: +rho c v0 for x/c < t' < (2L - x)/c, -rho c v0 for
    (2L + x)/c < t' < (4L - x)/c, else 0 (t' = t mod 4L/c)."""
    p = np.mod(t, 4 * L / C)
    s = np.zeros_like(p)
    s[(p > x / C) & (p < (2 * L - x) / C)] = RHO * C * V0
    s[(p > (2 * L + x) / C) & (p < (4 * L - x) / C)] = -RHO * C * V0
    return s


def read_nodout(results):
    data = np.genfromtxt(f"{results}/nodout.csv", delimiter=",", names=True)
    tip = data[np.isclose(data["x_coor"] - data["x_disp"], L)]
    return tip["time"], tip["x_disp"]


def mid_stress(results):
    times, stress = [], []
    layers = None
    for t, name in states(results):
        grid = read_state(results, name)
        if layers is None:
            # Cells touching the plane x = 5 in the initial configuration: take the cell centres
            # of the first state (t = 0, undeformed) and keep the two layers nearest to x = 5.
            centres = vtk.vtkCellCenters()
            centres.SetInputData(grid)
            centres.Update()
            cx = vtk_to_numpy(centres.GetOutput().GetPoints().GetData())[:, 0]
            dist = np.round(np.abs(cx - L / 2), 9)
            layers = dist == dist.min()
        s = vtk_to_numpy(grid.GetCellData().GetArray("stress"))[:, 0]
        times.append(t)
        stress.append(s[layers].mean())
    return np.array(times), np.array(stress), int(layers.size)


def run_facts(results):
    text = open(f"{results}/d3hsp").read()
    m = re.search(r"at t = \S+, cycle (\d+)", text)
    wall = re.search(r"^  total\s+([0-9.]+) s", text, re.M)
    return (int(m.group(1)) if m else -1), (float(wall.group(1)) if wall else float("nan"))


def analyse(results):
    t, u = read_nodout(results)
    keep = t <= T_END + 1e-9
    t, u = t[keep], u[keep]
    ua = u_free_end(t)
    l2 = np.sqrt(np.trapz((u - ua) ** 2, t) / np.trapz(ua**2, t))
    ts, s, cells = mid_stress(results)
    jumps = np.arange(5.0, T_END + 1, 10.0)
    away = np.min(np.abs(ts[:, None] - jumps[None, :]), axis=1) >= 1.0
    scale = RHO * C * abs(V0)
    stress_err = np.mean(np.abs(s[away] - sigma_mid(ts[away]))) / scale
    overshoot = max(0.0, np.abs(s).max() / scale - 1.0)
    cycles, wall = run_facts(results)
    return dict(dir=results, cells=cells, l2=l2, stress=stress_err, overshoot=overshoot,
                cycles=cycles, wall=wall, t=t, u=u, ts=ts, s=s)


def plot_histories(series, png):
    """u(L, t) and sigma_xx(L/2, t) of [(label, t, u, ts, s)] over the analytic solution."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    tt = np.linspace(0, T_END, 2001)
    ax1.plot(tt, u_free_end(tt), "k-", lw=2, label="analytic")
    ax2.plot(tt, sigma_mid(tt), "k-", lw=2, label="analytic")
    for label, t, u, ts, s in series:
        ax1.plot(t, u, lw=1, label=label)
        ax2.plot(ts, s, ".-", lw=0.8, ms=3, label=label)
    ax1.set_ylabel("u(L, t)")
    ax2.set_ylabel("sigma_xx(L/2, t)")
    ax2.set_xlabel("t")
    ax1.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("results", nargs="+")
    ap.add_argument("--png")
    a = ap.parse_args()
    rows = [analyse(r) for r in a.results]
    print(f"{'run':<28} {'elements':>9} {'cycles':>7} {'wall s':>8} {'u(L) L2':>9} "
          f"{'sigma(L/2)':>11} {'overshoot':>9}")
    for r in rows:
        print(f"{r['dir']:<28} {r['cells']:>9d} {r['cycles']:>7d} {r['wall']:>8.2f} "
              f"{r['l2']:>9.4f} {r['stress']:>11.4f} {100 * r['overshoot']:>8.1f}%")
    for a_, b_ in zip(rows, rows[1:]):
        if a_["l2"] > 0 and b_["l2"] > 0:
            print(f"observed order {a_['dir']} -> {b_['dir']}: u {np.log2(a_['l2'] / b_['l2']):.2f}, "
                  f"sigma {np.log2(a_['stress'] / b_['stress']):.2f} (per halving of h)")
    if a.png:
        plot_histories([(r["dir"], r["t"], r["u"], r["ts"], r["s"]) for r in rows], a.png)


if __name__ == "__main__":
    main()
