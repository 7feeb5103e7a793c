#!/usr/bin/python3
"""mcdyna's LS-DYNA d3plot read by an independent reader, VTK's vtkLSDynaReader, against the VTK
series of the same run (d3plot.pvd) and its nodout (issue 49).

    tools/verify/d3plot_lsdyna.py RESULTS [RESULTS ...]

Per run: the states and their times, the node count and user IDs, the parts, and per state the
nodes' deflected coordinates, velocities and accelerations and each element's stress and
effective plastic strain (solids; shells: mid-surface, inner and outer layers) by user ID, and
the eroded elements (deletion flags) against the cells the VTK series leaves out. Both files
hold single-precision fields written from the same state, so they must agree exactly once the
series' double coordinates are rounded to single. nodout (its CSV, full precision) must agree
with the d3plot's coordinates and velocities at the states' times to single precision (the
d3plot's velocity is the mean of v^{n-1/2} and v^{n+1/2}, nodout's too).

Prints one line per run with the largest differences; exits 1 if any run disagrees.
"""
import csv
import os
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import d3plot as series  # noqa: E402  (the VTK series reader beside this script)

# vtkLSDynaReader's cell type numbers (vtkLSDynaReader.h, LSDynaMetaData::LSDYNA_TYPES).
BEAM, SHELL, SOLID = 2, 3, 5
SINGLE = np.finfo(np.float32).eps


def nodout_rows(results):
    """nodout.csv as {time: {node: {column: value}}} (empty without nodout). Its numbers have ten
    digits, the states' times in d3plot.pvd too: the same time prints the same."""
    path = os.path.join(results, "nodout.csv")
    if not os.path.exists(path):
        return {}
    rows = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            t = float(row.pop("time"))
            node = int(row.pop("node"))
            rows.setdefault(t, {})[node] = {k: float(v) for k, v in row.items()}
    return rows


def reader_of(results):
    r = vtk.vtkLSDynaReader()
    r.SetDatabaseDirectory(results)
    r.UpdateInformation()
    if not r.IsDatabaseValid():
        raise SystemExit(f"{results}: vtkLSDynaReader finds no valid d3plot")
    for t in (SOLID, SHELL, BEAM):
        for a in range(r.GetNumberOfCellArrays(t)):
            r.SetCellArrayStatus(t, a, 1)
    for a in range(r.GetNumberOfPointArrays()):
        r.SetPointArrayStatus(a, 1)
    r.SetDeletedCellsAsGhostArray(1)  # deleted cells kept, flagged in vtkGhostType
    return r


def blocks(output):
    """Every unstructured grid of the reader's output (one per part)."""
    it = output.NewIterator()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        yield it.GetCurrentDataObject()
        it.GoToNextItem()


# VTK 9.1's reader garbles the user IDs of a 4-byte file (it reads them as 8-byte words), so
# nodes and cells are matched by geometry: a node by its deflected coordinates in single
# precision (the bits both files hold), a cell by the set of its nodes' keys.
def key(x):
    return np.asarray(x, dtype=np.float32).tobytes()


def cell_key(g, c, point_keys):
    ids = g.GetCell(c).GetPointIds()
    return tuple(sorted({point_keys[ids.GetId(k)] for k in range(ids.GetNumberOfIds())}))


# Components of the series' own fields: a run without deformable shells (a rigid tool's) has no
# shell fields in its series, and the d3plot holds zeros there.
SERIES_COMPONENTS = {"stress_middle": 6, "stress_bottom": 6, "stress_top": 6,
                     "layer_plastic_strain": 3, "thickness": 1, "internal_energy_density": 1,
                     "beam_resultants": 6}


def values(cd, c, names):
    """The cell's values of `names` (arrays of the reader or of the series), one flat vector."""
    out = []
    for n in names:
        a = cd.GetArray(n)
        out.extend(a.GetTuple(c) if a is not None else [0.0] * SERIES_COMPONENTS[n])
    return np.array(out, dtype=np.float32)


# What each element class carries in both files: the reader's arrays, the series' arrays.
FIELDS = {
    "solid": (["Stress", "EffPlastStrn"], ["stress", "effective_plastic_strain"]),
    "shell": (["Stress", "StressInnerSurf", "StressOuterSurf", "EffPlastStrn",
               "EffPlastStrnInnerSurf", "EffPlastStrnOuterSurf", "Thickness", "InternalEnergy"],
              ["stress_middle", "stress_bottom", "stress_top", "layer_plastic_strain",
               "thickness", "internal_energy_density"]),
    "beam": (["AxialForce", "ShearResultant", "BendingResultant", "TorsionResultant"],
             ["beam_resultants"]),
}


def shell_series(v):
    # stress_middle, _bottom, _top (18), plastic strain bottom, middle, top, thickness, energy
    return np.concatenate([v[0:18], [v[19], v[18], v[20]], v[21:23]]).astype(np.float32)


def beam_series(v):
    # beam_resultants N Vs Vt T Ms Mt -> the reader's N, (Vs Vt), (Ms Mt), T
    return np.array([v[0], v[1], v[2], v[4], v[5], v[3]], dtype=np.float32)


def kind_of(cell_type):
    return {vtk.VTK_HEXAHEDRON: "solid", vtk.VTK_QUAD: "shell", vtk.VTK_TRIANGLE: "shell",
            vtk.VTK_LINE: "beam"}.get(cell_type)


def d3plot_state(r, k):
    """{node key: (v, a)} and {cell key: (kind, values, deleted)} from vtkLSDynaReader."""
    r.SetTimeStep(k)
    r.Update()
    nodes, cells = {}, {}
    for g in blocks(r.GetOutput()):
        pd, cd = g.GetPointData(), g.GetCellData()
        x = vtk_to_numpy(g.GetPoints().GetData())
        v = vtk_to_numpy(pd.GetArray("Velocity"))
        a = vtk_to_numpy(pd.GetArray("Acceleration"))
        keys = [key(p) for p in x]
        for n, kk in enumerate(keys):
            nodes.setdefault(kk, []).append((v[n], a[n]))
        ghost = cd.GetArray("vtkGhostType")
        for c in range(g.GetNumberOfCells()):
            kind = kind_of(g.GetCellType(c))
            if kind is None:
                continue
            deleted = ghost is not None and ghost.GetValue(c) != 0
            cells[cell_key(g, c, keys)] = (kind, values(cd, c, FIELDS[kind][0]), deleted)
    return nodes, cells


def vtu_state(results, name):
    g = series.read_state(results, name)
    pd, cd = g.GetPointData(), g.GetCellData()
    x = vtk_to_numpy(g.GetPoints().GetData())
    v = vtk_to_numpy(pd.GetArray("velocity"))
    a = vtk_to_numpy(pd.GetArray("acceleration"))
    keys = [key(p) for p in x]
    nodes = {}
    for n, kk in enumerate(keys):
        nodes.setdefault(kk, []).append((v[n], a[n]))
    cells = {}
    for c in range(g.GetNumberOfCells()):
        kind = kind_of(g.GetCellType(c))
        if kind is None:  # SPG particles (vertices): not in the d3plot yet
            continue
        vals = values(cd, c, FIELDS[kind][1])
        if kind == "shell":
            vals = shell_series(vals)
        elif kind == "beam":
            vals = beam_series(vals)
        cells[cell_key(g, c, keys)] = (kind, vals)
    return nodes, cells, {kk: x[n] for n, kk in enumerate(keys)}


def check(results):
    r = reader_of(results)
    states = series.states(results)
    worst = {"v": 0.0, "a": 0.0, "elements": 0.0, "nodout": 0.0}
    compared = {"nodes": 0, "elements": 0, "nodout": 0}
    problems = []
    if r.GetNumberOfTimeSteps() != len(states):
        problems.append(f"{r.GetNumberOfTimeSteps()} d3plot states, {len(states)} VTK states")
    nodout = nodout_rows(results)
    for k, (t, name) in enumerate(states[: r.GetNumberOfTimeSteps()]):
        # d3plot.pvd prints ten digits: within a single-precision step of the d3plot's time.
        if abs(r.GetTimeValue(k) - t) > SINGLE * abs(t):
            problems.append(f"state {k}: time {r.GetTimeValue(k)} against {t}")
        dn, dc = d3plot_state(r, k)
        vn, vc, where = vtu_state(results, name)
        # Every node of the d3plot's parts is a node of the series at the same coordinates
        # (single precision), with the same velocity and acceleration.
        for kk, got in dn.items():
            if kk not in vn:
                problems.append(f"state {k}: a d3plot node at {np.frombuffer(kk, np.float32)} "
                                "is no node of the series")
                break
            v, a = got[0]
            best = min(vn[kk], key=lambda q: float(np.max(np.abs(q[0] - v)) +
                                                    np.max(np.abs(q[1] - a))))
            worst["v"] = max(worst["v"], float(np.max(np.abs(best[0] - v))))
            worst["a"] = max(worst["a"], float(np.max(np.abs(best[1] - a))))
            compared["nodes"] += 1
        # The intact d3plot elements are the series' cells, with the same values; the deleted
        # ones are cells the series left out.
        alive = {kk for kk, c in dc.items() if not c[2]}
        if alive != set(vc):
            problems.append(f"state {k}: {len(alive)} intact d3plot elements, {len(vc)} series "
                            f"cells, {len(alive ^ set(vc))} unmatched")
        for kk, (kind, vals) in vc.items():
            if kk in dc:
                worst["elements"] = max(worst["elements"],
                                        float(np.max(np.abs(dc[kk][1] - vals))))
                compared["elements"] += 1
        # nodout at this state's time: each listed node is the d3plot node nearest its printed
        # coordinates, with coordinates and velocity equal to single precision.
        points = [(np.frombuffer(kk, np.float32).astype(np.float64), kk) for kk in dn]
        # (Ten digits each: the same time may differ in the last, 1e-9 relative.)
        near = [tn for tn in nodout if abs(tn - t) <= 1e-9 * max(abs(t), 1e-300)]
        for node, q in (nodout[near[0]] if near else {}).items():
            ref_x = np.array([q["x_coor"], q["y_coor"], q["z_coor"]])
            ref_v = np.array([q["x_vel"], q["y_vel"], q["z_vel"]])
            x, kk = min(points, key=lambda p: float(np.max(np.abs(p[0] - ref_x))))
            v = dn[kk][0][0].astype(np.float64)
            worst["nodout"] = max(
                worst["nodout"],
                float(np.max(np.abs(x - ref_x))) / max(float(np.max(np.abs(ref_x))), 1e-30),
                float(np.max(np.abs(v - ref_v))) / max(float(np.max(np.abs(ref_v))), 1e-30))
            compared["nodout"] += 1
    if any(worst[k] != 0.0 for k in ("v", "a", "elements")):
        problems.append("values differ: " + ", ".join(f"{k} {worst[k]:.3g}" for k in worst))
    if worst["nodout"] > 4 * SINGLE:
        problems.append(f"nodout velocity differs by {worst['nodout']:.3g} (relative)")
    print(f"{results}: {r.GetNumberOfTimeSteps()} states, {r.GetNumberOfNodes()} nodes, "
          f"{r.GetNumberOfSolidCells()} solids, {r.GetNumberOfShellCells()} shells, "
          f"{r.GetNumberOfBeamCells()} beams, {r.GetNumberOfPartArrays()} parts; largest "
          f"differences to the series: velocity {worst['v']:.3g}, acceleration {worst['a']:.3g}, "
          f"element values {worst['elements']:.3g}; to nodout {worst['nodout']:.3g} relative "
          f"({compared['nodes']} node, {compared['elements']} element and {compared['nodout']} "
          f"nodout values compared)"
          + ("" if not problems else "\n  " + "\n  ".join(problems[:5])))
    return not problems


def main():
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    ok = [check(results) for results in sys.argv[1:]]
    return 0 if all(ok) else 1


if __name__ == "__main__":
    sys.exit(main())
