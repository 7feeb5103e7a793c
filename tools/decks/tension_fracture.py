#!/usr/bin/python3
"""Writes a notched bar pulled apart until it breaks in two: MC-SPG bond failure (paper §3.2,
Eqs. 35-36).

Square bar 4 x 4 x 20 mm (units t-mm-s), hexahedra of edge H generating MC-SPG particles
(*SECTION_SOLID_SPG, ITB 3, IDAM 1 with FS = 0.3 and STRETCH = 1.1, MSC 1: control of
low-energy modes, without which the layers beside the neck pair up under slow plastic tension
at h = 0.5 and the bar breaks away from the notch; see src/solver/spg/mode_control.cpp).
A notch one element deep
and two elements high runs round the bar at mid-length, so the net section yields first and the
strain localises there. MAT_003, 6061-T6-like: E = 69 GPa, nu = 0.33, yield 276 MPa, tangent
modulus 600 MPa. Both end faces are pulled apart at 5 m/s each (ramped over 10 us) by
*BOUNDARY_PRESCRIBED_MOTION_SET along z; they are free laterally.

Expected: the notch necks, bonds break there (bond_damage in the d3plot states), and the run
summary reports two separate pieces; the total mass stays that of the bar (particles are never
deleted).

usage: tension_fracture.py H OUT.k [--end 4.0E-4]
"""
import argparse

from spg_section import spg_section

WIDTH, LENGTH = 4.0, 20.0
SPEED = 5000.0  # mm/s at each end
RAMP = 1.0e-5


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("h", type=float, help="nodal distance in mm (1.0, 0.5)")
    ap.add_argument("out")
    ap.add_argument("--end", type=float, default=4.0e-4)
    a = ap.parse_args()
    n, m = round(WIDTH / a.h), round(LENGTH / a.h)
    mid = m // 2

    def notched(i, j, k):  # element (i, j, k) cut away by the notch
        ring = i == 0 or j == 0 or i == n - 1 or j == n - 1
        return ring and mid - 1 <= k <= mid

    elements = [(i, j, k) for k in range(m) for j in range(n) for i in range(n)
                if not notched(i, j, k)]
    nid = lambda i, j, k: 1 + i + (n + 1) * (j + (n + 1) * k)
    corners = lambda i, j, k: [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k),
                               nid(i, j + 1, k), nid(i, j, k + 1), nid(i + 1, j, k + 1),
                               nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)]
    used = sorted({c for e in elements for c in corners(*e)})
    name = f"tension_spg_h{a.h:g}"
    out = []
    w = out.append
    w("$ " + "-" * 94)
    w(f"$ tension_fracture h = {a.h:g} mm (MC-SPG, bond failure) - written by "
      "tools/decks/tension_fracture.py")
    w("$ What it shows: a notched 4 x 4 x 20 mm bar (MAT_003, 6061-T6-like) pulled apart at")
    w("$   5 m/s per end; MC-SPG bonds (IDAM 1, FS 0.3, STRETCH 1.1) break at the notch;")
    w("$   MSC 1 (control of low-energy modes) keeps the layers beside the neck from pairing up.")
    w(f"$ How to run:   mcdyna run decks/fracture/{name}.k --out results/{name}")
    w("$ Expected:     bonds broken at the notch, two separate pieces in the run summary,")
    w("$   total mass unchanged (glstat/matsum); bond_damage in the d3plot states.")
    w("$ " + "-" * 94)
    w("*KEYWORD")
    w("*TITLE")
    w(f"notched bar pulled to fracture h = {a.h:g} mm MC-SPG")
    w("*CONTROL_TERMINATION")
    w(f"{a.end:10.3E}")
    w("*CONTROL_TIMESTEP")
    w("       0.0       0.9")
    w("*DATABASE_BINARY_D3PLOT")
    w(f"{a.end / 15:10.3E}")
    w("*DATABASE_GLSTAT")
    w(f"{a.end / 150:10.3E}")
    w("*DATABASE_MATSUM")
    w(f"{a.end / 150:10.3E}")
    w("*DATABASE_BNDOUT")
    w(f"{a.end / 150:10.3E}")
    w("*PART")
    w("bar")
    w("         1         1         1")
    out.extend(spg_section(1, fs=0.3, stretch=1.1, msc=1))
    w("*MAT_PLASTIC_KINEMATIC")
    w("$      MID        RO         E        PR      SIGY      ETAN      BETA")
    w("         1    2.7E-9   69000.0      0.33     276.0     600.0       1.0")
    w("$      SRC       SRP        FS        VP")
    w("       0.0       0.0       0.0       0.0")
    w("*DEFINE_CURVE")
    w("         1")
    w(f"{0.0:20.6E}{0.0:20.6E}")
    w(f"{RAMP:20.6E}{1.0:20.6E}")
    w(f"{1.0:20.6E}{1.0:20.6E}")
    for sid, k in ((1, 0), (2, m)):
        w("*SET_NODE_LIST")
        w(f"{sid:10d}")
        ids = [nid(i, j, k) for j in range(n + 1) for i in range(n + 1)]
        for c in range(0, len(ids), 8):
            w("".join(f"{x:10d}" for x in ids[c:c + 8]))
    w("*BOUNDARY_PRESCRIBED_MOTION_SET")
    w("$     NSID       DOF       VAD      LCID        SF")
    w(f"         1         3         0         1{-SPEED:10.1f}")
    w(f"         2         3         0         1{SPEED:10.1f}")
    w("*NODE")
    for node in used:
        q = node - 1
        i, j, k = q % (n + 1), (q // (n + 1)) % (n + 1), q // ((n + 1) * (n + 1))
        w(f"{node:8d}{i * a.h:16.8f}{j * a.h:16.8f}{k * a.h:16.8f}       0       0")
    w("*ELEMENT_SOLID")
    for eid, e in enumerate(elements, 1):
        w(f"{eid:8d}       1")
        w("".join(f"{c:8d}" for c in corners(*e)))
    w("*END")
    with open(a.out, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
