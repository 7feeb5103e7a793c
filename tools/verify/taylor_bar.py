#!/usr/bin/python3
"""Final length and footprint diameter of a Taylor-bar run from its last d3plot state.

usage: taylor_bar.py RESULTS_DIR [--png shape.png]
Prints: final length Lf (max z - min z), footprint diameter Df (2 x largest radius of the nodes
that started on the impact face), and Lf against the references of benchmarks.md §1.1.
"""
import argparse

import numpy as np
from vtk.util.numpy_support import vtk_to_numpy

from d3plot import read_state, states

REFERENCES = {"OpenRadioss/DynELA (this model)": 15.95, "Wilkins & Guinan 1973 (test)": 16.51}


def state(results, which):
    t, name = states(results)[which]
    return t, read_state(results, name)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("results")
    ap.add_argument("--png")
    a = ap.parse_args()
    t, grid = state(a.results, -1)
    x = vtk_to_numpy(grid.GetPoints().GetData())
    z0, z1 = x[:, 2].min(), x[:, 2].max()
    # The impact face: the nodes at the lowest z of the first state (same point order).
    x_initial = vtk_to_numpy(state(a.results, 0)[1].GetPoints().GetData())
    face = x[x_initial[:, 2] <= x_initial[:, 2].min() + 1e-9]
    diameter = 2.0 * np.hypot(face[:, 0], face[:, 1]).max()
    print(f"state t = {t:.4e} s: final length {z1 - z0:.3f} mm, footprint diameter {diameter:.3f} mm")
    for name, ref in REFERENCES.items():
        print(f"  vs {name}: Lf {ref:.2f} mm, difference {100 * ((z1 - z0) / ref - 1):+.2f} %")
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        r = np.hypot(x[:, 0], x[:, 1])
        plt.figure(figsize=(4, 6))
        plt.plot(r, x[:, 2] - z0, ".", ms=1)  # the bar rebounds: measure from its lowest point
        prof = [(8.35, 0), (7.14, 0.79), (6.22, 1.47), (5.21, 2.30), (4.68, 2.73), (4.38, 3.37),
                (4.29, 4.10), (4.05, 4.98), (3.90, 6.10), (3.76, 11.34), (3.81, 16.51)]
        plt.plot(*zip(*prof), "r-", label="Wilkins & Guinan (digitized)")
        plt.xlabel("r (mm)")
        plt.ylabel("z (mm)")
        plt.axis("equal")
        plt.legend(fontsize=7)
        plt.tight_layout()
        plt.savefig(a.png, dpi=120)


if __name__ == "__main__":
    main()
