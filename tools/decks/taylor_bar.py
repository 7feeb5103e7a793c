#!/usr/bin/python3
"""Writes the Taylor-bar deck (benchmarks.md §1): 6061-T6 cylinder D = 7.82 mm, L = 23.46 mm at
373 m/s onto a rigid wall, Johnson-Cook set JC-1 with a Gruneisen EOS, hexahedra (butterfly mesh
of the circular section). Units t, mm, s, N, MPa. Deterministic: same arguments, same bytes.

With --spg the bar is one MC-SPG part (ELFORM 47, ITB 3, cubic box kernel, DX = 1.5, updated-
Lagrangian kernel renewed every 15 steps) at the paper's three nodal distances (§4.2): 0.49,
0.33 and 0.25 mm, 11,809 / 38,380 / 86,500 particles (paper: 11,809 / 38,325 / 86,621).

usage: taylor_bar.py {coarse|medium|fine} OUT.k [--elform 1|2] [--spg] [--end 8.0e-5]
                      [--restart-cycles 20000]
"""
import argparse
import math

from spg_section import spg_section

RESOLUTIONS = {  # cells across the half inner square, radial cells, axial cells
    "coarse": (3, 3, 35),
    "medium": (4, 4, 47),
    "fine": (6, 6, 70),
}
SPG_RESOLUTIONS = {  # nodes per section x layers: 241 x 49, 505 x 76, 865 x 100
    "coarse": (4, 5, 48),
    "medium": (6, 7, 75),
    "fine": (8, 9, 99),
}


def section(n, nr, radius):
    """Butterfly mesh of a disc: inner square (2n x 2n) + four blocks of 2n x nr cells."""
    s = 0.45 * radius
    pts, index = [], {}

    def node(key, xy):
        if key not in index:
            index[key] = len(pts)
            pts.append(xy)
        return index[key]

    # Inner square grid nodes keyed ("s", i, j), i, j in [-n, n].
    for j in range(-n, n + 1):
        for i in range(-n, n + 1):
            node(("s", i, j), (s * i / n, s * j / n))
    quads = []
    for j in range(-n, n):
        for i in range(-n, n):
            quads.append([index[("s", i, j)], index[("s", i + 1, j)], index[("s", i + 1, j + 1)],
                          index[("s", i, j + 1)]])
    # Outer blocks: side edge point t in [-n, n] mapped from the square edge to the arc.
    sides = [  # (square edge point, arc angle) for t in [-n, n]
        lambda t: ((s, s * t / n), math.pi / 4 * t / n),
        lambda t: ((-s * t / n, s), math.pi / 2 + math.pi / 4 * t / n),
        lambda t: ((-s, -s * t / n), math.pi + math.pi / 4 * t / n),
        lambda t: ((s * t / n, -s), 1.5 * math.pi + math.pi / 4 * t / n),
    ]
    square_key = [lambda t: ("s", n, t), lambda t: ("s", -t, n), lambda t: ("s", -n, -t),
                  lambda t: ("s", t, -n)]
    for b, side in enumerate(sides):
        def key(t, r, b=b):
            if r == 0:
                return square_key[b](t)
            corner = abs(t) == n
            # Corner rays are shared between neighbouring blocks: key them by angle.
            return ("ray", round(side(t)[1] / (math.pi / 4)) % 8, r) if corner else ("o", b, t, r)
        for t in range(-n, n + 1):
            (x0, y0), th = side(t)
            for r in range(1, nr + 1):
                f = r / nr
                xy = ((1 - f) * x0 + f * radius * math.cos(th), (1 - f) * y0 + f * radius * math.sin(th))
                node(key(t, r), xy)
        for t in range(-n, n):
            for r in range(nr):
                quads.append([index[key(t, r)], index[key(t, r + 1)], index[key(t + 1, r + 1)],
                              index[key(t + 1, r)]])
    return pts, quads


def jc1_cards():
    """AA6061-T6 with JC-1 and its Gruneisen EOS (benchmarks.md §1), material and EOS 1: the
    Taylor bar's material and the FDS plate's."""
    return [
        "*MAT_JOHNSON_COOK_TITLE",
        "AA6061-T6 JC-1",
        "         1    2.7E-9   26000.0",
        "     324.0     114.0      0.42     0.002      1.34     925.0     293.0       1.0",
        "    8.96E8       0.0       2.0",
        "*EOS_GRUNEISEN",
        "         1 5386000.0     1.339       0.0       0.0      1.99       0.0",
    ]


def node_line(nid, x, y, z):
    return f"{nid:8d}{x:16.9f}{y:16.9f}{z:16.9f}{0:8d}{0:8d}"


def layered_nodes(pts, heights):
    """*NODE lines (without the keyword) of the in-plane points at each height: node
    1 + p + len(pts) k for point p on layer k."""
    return [node_line(1 + p + len(pts) * k, x, y, z)
            for k, z in enumerate(heights) for p, (x, y) in enumerate(pts)]


def layered_hexahedra(quads, npl, layers, part, first=1):
    """*ELEMENT_SOLID lines (without the keyword) extruding the quads through the layers of
    layered_nodes; element IDs from `first`."""
    out, e = [], first - 1
    for k in range(layers):
        for q in quads:
            e += 1
            ids = [1 + v + npl * k for v in q] + [1 + v + npl * (k + 1) for v in q]
            out.append(f"{e:8d}{part:8d}" + "".join(f"{v:8d}" for v in ids))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("resolution", choices=RESOLUTIONS)
    ap.add_argument("out")
    ap.add_argument("--elform", type=int, default=1)
    ap.add_argument("--spg", action="store_true", help="MC-SPG particles instead of hexahedra")
    ap.add_argument("--end", type=float, default=8.0e-5)
    ap.add_argument("--cycles", type=int, default=0,
                    help="ENDCYC: stop after this many cycles (benchmarks; 0: at ENDTIM)")
    ap.add_argument("--restart-cycles", type=int, default=20000,
                    help="*DATABASE_BINARY_RUNRSF: running restart file every N cycles (0: none)")
    a = ap.parse_args()
    n, nr, nz = (SPG_RESOLUTIONS if a.spg else RESOLUTIONS)[a.resolution]
    name = f"taylor_spg_{a.resolution}" if a.spg else f"taylor_{a.resolution}"
    method = "MC-SPG, ELFORM 47" if a.spg else f"ELFORM {a.elform}"
    radius, length = 3.91, 23.46
    pts, quads = section(n, nr, radius)
    # Orient every quad counter-clockwise so the hexahedra have positive volume.
    for q in quads:
        area = sum(pts[q[k]][0] * pts[q[(k + 1) % 4]][1] - pts[q[(k + 1) % 4]][0] * pts[q[k]][1]
                   for k in range(4))
        if area < 0:
            q.reverse()
    npl = len(pts)
    out = []
    w = out.append
    w("$ " + "-" * 94)
    w(f"$ taylor_bar {a.resolution} ({method}) - written by tools/decks/taylor_bar.py")
    w("$ What it shows: Taylor impact of a 6061-T6 bar, D = 7.82 mm, L = 23.46 mm, 373 m/s onto a")
    w("$   frictionless rigid wall; JC-1 (324/114/0.42/0.002/1.34, TM 925, TR 293, CP 896) with")
    w("$   Gruneisen EOS (C 5386 m/s, S1 1.339, GAMMA0 1.99), adiabatic heating. Units t-mm-s.")
    w(f"$ How to run:   mcdyna run decks/taylor_bar/{name}.k --out results/{name}")
    w("$ Expected:     final length about 15.95 mm (OpenRadioss 15.91, DynELA 15.98 for this")
    w("$   model); Wilkins & Guinan measured 16.51 mm (D0 = 7.62 mm). tools/verify/taylor_bar.py")
    w("$   prints length and footprint diameter from the last d3plot state.")
    w("$ " + "-" * 94)
    w("*KEYWORD")
    w("*TITLE")
    w(f"Taylor bar 6061-T6 373 m/s {a.resolution}" + (" MC-SPG" if a.spg else ""))
    w("*CONTROL_TERMINATION")
    w(f"{a.end:10.3E}" + (f"{a.cycles:10d}" if a.cycles else ""))
    w("*CONTROL_TIMESTEP")
    w("       0.0       0.9")
    if a.restart_cycles > 0:
        # The fine bars run for hours: a stopped run continues from runrsf (--restart).
        w("*DATABASE_BINARY_RUNRSF")
        w(f"{a.restart_cycles:10d}")
    w("*DATABASE_BINARY_D3PLOT")
    w(f"{a.end / 20:10.3E}")
    w("*DATABASE_GLSTAT")
    w(f"{a.end / 200:10.3E}")
    w("*DATABASE_MATSUM")
    w(f"{a.end / 200:10.3E}")
    w("*DATABASE_RWFORC")
    w(f"{a.end / 200:10.3E}")
    w("*PART")
    w("bar")
    w("         1         1         1         1")
    if a.spg:
        out.extend(spg_section())
    else:
        w("*SECTION_SOLID")
        w(f"         1{a.elform:10d}")
    out.extend(jc1_cards())
    w("*NODE")
    out.extend(layered_nodes(pts, [length * k / nz for k in range(nz + 1)]))
    w("*ELEMENT_SOLID")
    out.extend(layered_hexahedra(quads, npl, nz, 1))
    w("*INITIAL_VELOCITY")
    w("         0")
    w("       0.0       0.0 -373000.0")
    w("*RIGIDWALL_PLANAR_ID")
    w("         1impact wall")
    w("         0")
    w("       0.0       0.0       0.0       0.0       0.0       1.0")
    w("*END")
    with open(a.out, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
