#!/usr/bin/python3
"""Writes the elastic-wave rod deck of the MC-SPG paper (benchmarks.md §3).

Rod 0 <= x <= 10 with a 1.2 x 1.2 cross-section, E = 100, nu = 0, rho = 100, initial velocity
v0 = -0.01 along x, end x = 0 fixed, end x = 10 free. Hexahedra of edge h (the nodal distance).
The deck is a pure function of its arguments, so regenerating it gives the same bytes.

With --spg the rod is one MC-SPG part (*SECTION_SOLID_SPG, ELFORM 47, ITB 3, cubic box kernel,
DX = 1.5, updated-Lagrangian kernel): its hexahedra only generate the particles.

usage: elastic_wave.py H OUT.k [--elform 1|2] [--spg] [--end 80]
"""
import argparse

from spg_section import spg_section


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("h", type=float, help="nodal distance (0.2, 0.1, 0.05)")
    ap.add_argument("out")
    ap.add_argument("--elform", type=int, default=1)
    ap.add_argument("--spg", action="store_true", help="MC-SPG particles instead of hexahedra")
    ap.add_argument("--end", type=float, default=80.0)
    a = ap.parse_args()
    length, width = 10.0, 1.2
    nx, ny = round(length / a.h), round(width / a.h)
    nid = lambda i, j, k: 1 + i + (nx + 1) * (j + (ny + 1) * k)
    out = []
    w = out.append
    w("$ " + "-" * 94)
    method = "MC-SPG, ELFORM 47" if a.spg else f"ELFORM {a.elform}"
    name = f"rod_spg_h{a.h:g}" if a.spg else f"rod_h{a.h:g}"
    w(f"$ elastic_wave h = {a.h:g} ({method}) - written by tools/decks/elastic_wave.py")
    w("$ What it shows: the 1-D elastic wave in a rod fixed at x = 0 and free at x = 10 (MC-SPG")
    w("$   paper Sec. 4.1): E = 100, nu = 0, rho = 100, c = 1, v0 = -0.01, hexahedra of edge h.")
    w(f"$ How to run:   mcdyna run decks/elastic_wave/{name}.k --out results/{name}")
    w("$ Expected:     free-end displacement a triangle wave of amplitude 0.1 and period 40")
    w("$   (nodout.csv, node at the free-end centre); stress at x = 5 steps between 0 and -/+1.")
    w("$   tools/verify/elastic_wave.py compares both with the analytic solution.")
    w("$ " + "-" * 94)
    w("*KEYWORD")
    w("*TITLE")
    w(f"elastic wave rod h = {a.h:g}" + (" MC-SPG" if a.spg else ""))
    w("*CONTROL_TERMINATION")
    w(f"{a.end:10.4f}")
    w("*CONTROL_TIMESTEP")
    w("       0.0       0.9")
    w("*DATABASE_BINARY_D3PLOT")
    w("       1.0")
    w("*DATABASE_GLSTAT")
    w("      0.25")
    w("*DATABASE_NODOUT")
    w("      0.25")
    w("*DATABASE_SPCFORC")
    w("       1.0")
    w("*DATABASE_HISTORY_NODE")
    w(f"{nid(nx, ny // 2, ny // 2):10d}{nid(nx // 2, ny // 2, ny // 2):10d}")
    w("*PART")
    w("rod")
    w("         1         1         1")
    if a.spg:
        out.extend(spg_section())
    else:
        w("*SECTION_SOLID")
        w(f"         1{a.elform:10d}")
    w("*MAT_ELASTIC")
    w("         1     100.0     100.0       0.0")
    w("*NODE")
    for k in range(ny + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                tc = 7 if i == 0 else 0
                w(f"{nid(i, j, k):8d}{i * a.h:16.8f}{j * a.h:16.8f}{k * a.h:16.8f}{tc:8d}{0:8d}")
    w("*ELEMENT_SOLID")
    e = 0
    for k in range(ny):
        for j in range(ny):
            for i in range(nx):
                e += 1
                n = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                     nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                     nid(i, j + 1, k + 1)]
                w(f"{e:8d}{1:8d}" + "".join(f"{v:8d}" for v in n))
    w("*INITIAL_VELOCITY")
    w("         0")
    w("     -0.01       0.0       0.0")
    w("*END")
    with open(a.out, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
