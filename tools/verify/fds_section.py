#!/usr/bin/python3
"""Section through the screw axis of an FDS run's state (MC-SPG paper Fig. 12): the plate's
particles and FE nodes within a slab |y| < HALF_WIDTH around the plane y = 0, coloured by
effective plastic strain, and the screw's nodes in the same slab in grey. Threads formed in the
hole show as a saw-tooth on the hole wall at the thread pitch. Prints how many plate points are
in the slab and the hole's wall radius range over the plate thickness.

usage: fds_section.py RUN_DIR OUT.png [--state N (default: last)] [--half-width 0.1]
                      [--title TEXT]
"""
import argparse

import numpy as np
from vtk.util.numpy_support import vtk_to_numpy

from d3plot import read_state, run_title, states

SCREW_PART = 3  # tools/decks/fds.py: plate parts 1 (SPG) and 2 (FE ring), screw 3


def point_fields(grid):
    """Per point: part id and effective plastic strain, from the cell fields of the cells that use
    the point (vertex cells of the particles, hexahedra, shells)."""
    n = grid.GetNumberOfPoints()
    part = np.zeros(n, dtype=int)
    strain = np.zeros(n)
    cells = grid.GetCellData()
    part_of_cell = vtk_to_numpy(cells.GetArray("part_id"))
    eps_of_cell = vtk_to_numpy(cells.GetArray("effective_plastic_strain"))
    alive = cells.GetArray("erosion_state")
    alive = vtk_to_numpy(alive) if alive is not None else np.zeros(len(part_of_cell))
    ids = grid.GetCells()
    conn = vtk_to_numpy(ids.GetConnectivityArray())
    offsets = vtk_to_numpy(ids.GetOffsetsArray())
    for c in range(grid.GetNumberOfCells()):
        if alive[c] != 0:
            continue  # eroded element: its nodes stay, the material is gone
        pts = conn[offsets[c]:offsets[c + 1]]
        part[pts] = part_of_cell[c]
        strain[pts] = np.maximum(strain[pts], eps_of_cell[c])
    return part, strain


def load_state(run, state):
    """(time, file name, point coordinates, part id and plastic strain per point) of a run's state
    (index into d3plot.pvd, -1 the last)."""
    time, name = states(run)[state]
    grid = read_state(run, name)
    x = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    part, strain = point_fields(grid)
    return time, name, x, part, strain


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run")
    ap.add_argument("png")
    ap.add_argument("--state", type=int, default=-1)
    ap.add_argument("--half-width", type=float, default=0.1)
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    time, name, x, part, strain = load_state(a.run, a.state)
    slab = np.abs(x[:, 1]) < a.half_width
    plate = slab & (part != SCREW_PART) & (part != 0)
    screw = slab & (part == SCREW_PART)
    r = np.abs(x[plate, 0])
    z = x[plate, 2]
    print(f"state {name} at t = {time:.4e} s: {plate.sum()} plate points and {screw.sum()} screw "
          f"points within |y| < {a.half_width} mm")
    inner = r < 3.5
    if inner.any():
        for z0, z1 in ((-0.5, 0.0), (0.0, 0.5), (0.5, 1.0), (1.0, 1.5)):
            band = inner & (z >= z0) & (z < z1)
            if band.any():
                print(f"  z {z0:+.1f} … {z1:+.1f} mm: hole wall at r = {r[band].min():.3f} mm")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(9, 5))
    ax.scatter(x[screw, 0], x[screw, 2], s=2, c="0.6", label="screw (rigid shells)")
    sc = ax.scatter(x[plate, 0], x[plate, 2], s=6, c=strain[plate], cmap="viridis",
                    vmin=0.0, vmax=max(1.0, float(np.percentile(strain[plate], 99))))
    fig.colorbar(sc, ax=ax, label="effective plastic strain")
    ax.set_xlim(-5.0, 5.0)
    ax.set_ylim(-3.5, 3.0)
    ax.set_aspect("equal")
    ax.set_xlabel("x, mm (section y = 0 through the screw axis)")
    ax.set_ylabel("z, mm")
    ax.set_title(a.title or f"{run_title(a.run)}: t = {time * 1e3:.3f} ms")
    ax.legend(loc="lower right", fontsize=8)
    fig.tight_layout()
    fig.savefig(a.png, dpi=130)
    print(f"wrote {a.png}")


if __name__ == "__main__":
    main()
