#!/usr/bin/python3
"""Final length and footprint diameter of a Taylor-bar run from its last d3plot state.

usage: taylor_bar.py RESULTS_DIR [RESULTS_DIR ...] [--png shape.png]
Prints: final length Lf (max z - min z), footprint diameter Df (2 x largest radius of the nodes
that started on the impact face), and Lf against the references of benchmarks.md §1.1. --png
draws each run's final outline (the outermost node of each initial layer) over Wilkins &
Guinan's digitized profile.
"""
import argparse

import numpy as np
from vtk.util.numpy_support import vtk_to_numpy

from d3plot import read_state, states

REFERENCES = {"OpenRadioss/DynELA (this model)": 15.95, "Wilkins & Guinan 1973 (test)": 16.51}
# Wilkins & Guinan's final outline, digitized (r, z from the impact face), mm.
PROFILE = [(8.35, 0), (7.14, 0.79), (6.22, 1.47), (5.21, 2.30), (4.68, 2.73), (4.38, 3.37),
           (4.29, 4.10), (4.05, 4.98), (3.90, 6.10), (3.76, 11.34), (3.81, 16.51)]


def state(results, which):
    t, name = states(results)[which]
    return t, read_state(results, name)


def final_points(results):
    """(time, final positions, initial positions) of the last state."""
    t, grid = state(results, -1)
    x = vtk_to_numpy(grid.GetPoints().GetData())
    x_initial = vtk_to_numpy(state(results, 0)[1].GetPoints().GetData())
    return t, x, x_initial


def final_shape(results):
    """(final length, footprint diameter) in mm."""
    _, x, x_initial = final_points(results)
    # The impact face: the nodes at the lowest z of the first state (same point order).
    face = x[x_initial[:, 2] <= x_initial[:, 2].min() + 1e-9]
    return x[:, 2].max() - x[:, 2].min(), 2.0 * np.hypot(face[:, 0], face[:, 1]).max()


def outline(results):
    """The final silhouette: per node layer of the undeformed bar (both the FE and the SPG decks
    are built in layers), the node of largest radius: (its z from the lowest point, its r), mm.
    The curve compared with Wilkins & Guinan's outline; one row per layer, so a study record can
    keep it."""
    _, x, x_initial = final_points(results)
    z = x[:, 2] - x[:, 2].min()
    r = np.hypot(x[:, 0], x[:, 1])
    _, layer = np.unique(np.round(x_initial[:, 2], 6), return_inverse=True)
    order = np.lexsort((r, layer))  # by layer, then radius: each layer's last is its outermost
    outer = order[np.r_[layer[order][1:] != layer[order][:-1], True]]
    return z[outer], r[outer]


def plot_profiles(runs, png):
    """Final outlines [(label, z, r)] (from outline()) in the (r, z) plane over the experiment's."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    plt.figure(figsize=(4.5, 6))
    for label, z, r in runs:
        plt.plot(r, z, "-", lw=1, label=label)
    plt.plot(*zip(*PROFILE), "k-", lw=1.5, label="Wilkins & Guinan (digitized)")
    plt.xlabel("r (mm)")
    plt.ylabel("z (mm)")
    plt.axis("equal")
    plt.legend(fontsize=7)
    plt.tight_layout()
    plt.savefig(png, dpi=120)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("results", nargs="+")
    ap.add_argument("--png")
    a = ap.parse_args()
    for results in a.results:
        t = states(results)[-1][0]
        length, diameter = final_shape(results)
        print(f"{results}: state t = {t:.4e} s: final length {length:.3f} mm, "
              f"footprint diameter {diameter:.3f} mm")
        for name, ref in REFERENCES.items():
            print(f"  vs {name}: Lf {ref:.2f} mm, difference {100 * (length / ref - 1):+.2f} %")
    if a.png:
        plot_profiles([(r, *outline(r)) for r in a.results], a.png)


if __name__ == "__main__":
    main()
