#!/usr/bin/python3
"""Where DT2MS mass scaling put its mass: per part of an mcdyna run's last d3plot state (or the
state at --time), the physical and added mass, how many nodes took more than 1 % of their own
mass, the share the heaviest 100 hold, the median factor (m + added) / m of those that took
any, and the added mass by distance from the z axis (the FDS screw axis).

usage: tools/verify/added_mass.py RUN [--time T] [--part ID] [--rings R1 R2 ...]
"""
import argparse
import os
import sys

import numpy as np
from vtk.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from d3plot import read_state, states  # noqa: E402


def node_arrays(grid):
    """Per node: position, mass (physical + added, as written), added mass, and the part of
    the first cell that uses it."""
    pd = grid.GetPointData()
    x = vtk_to_numpy(grid.GetPoints().GetData())
    mass = vtk_to_numpy(pd.GetArray("mass"))
    added = vtk_to_numpy(pd.GetArray("added_mass"))
    part = np.full(len(x), -1, dtype=np.int64)
    cell_part = vtk_to_numpy(grid.GetCellData().GetArray("part_id"))
    conn = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    offsets = vtk_to_numpy(grid.GetCells().GetOffsetsArray())
    for c in range(len(offsets) - 1):
        ids = conn[offsets[c]:offsets[c + 1]]
        sel = ids[part[ids] < 0]
        part[sel] = cell_part[c]
    return x, mass, added, part


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run")
    ap.add_argument("--time", type=float, help="the state nearest this time (default: the last)")
    ap.add_argument("--part", type=int, action="append", help="only these parts")
    ap.add_argument("--rings", type=float, nargs="+", default=[1.0, 2.0, 3.0, 3.5, 10.0],
                    help="outer radii (mm) of the rings the added mass is summed over")
    a = ap.parse_args()
    all_states = states(a.run)
    t, name = (min(all_states, key=lambda s: abs(s[0] - a.time)) if a.time is not None
               else all_states[-1])
    x, mass, added, part = node_arrays(read_state(a.run, name))
    print(f"{a.run}: state {name}, t = {t:.4e} s; added mass {added.sum():.3e} of a model of "
          f"{(mass - added).sum():.3e} (physical)")
    for p in sorted(set(part[part >= 0])):
        if a.part and p not in a.part:
            continue
        sel = part == p
        m, dm = mass[sel] - added[sel], added[sel]
        if dm.sum() <= 0.0:
            print(f"  part {p}: {sel.sum()} nodes, mass {m.sum():.3e}, nothing added")
            continue
        took = dm > 0.01 * m
        heaviest = np.sort(dm)[::-1][:100].sum() / dm.sum()
        factor = np.median((m[dm > 0] + dm[dm > 0]) / m[dm > 0])
        print(f"  part {p}: {sel.sum()} nodes, mass {m.sum():.3e}, added {dm.sum():.3e} "
              f"({dm.sum() / m.sum():.2f} x); {took.sum()} nodes took > 1 % of their mass; "
              f"the heaviest 100 hold {heaviest:.1%}; median factor {factor:.2f}")
        r = np.hypot(x[sel, 0], x[sel, 1])
        inner = 0.0
        for outer in a.rings:
            ring = (r >= inner) & (r < outer)
            print(f"    r {inner:4.1f}-{outer:4.1f} mm: {ring.sum():6d} nodes, added "
                  f"{dm[ring].sum():.3e} ({dm[ring].sum() / dm.sum():6.1%} of it, "
                  f"{dm[ring].sum() / max(m[ring].sum(), 1e-300):.2f} x their mass)")
            inner = outer


if __name__ == "__main__":
    main()
