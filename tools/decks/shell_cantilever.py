#!/usr/bin/python3
"""Writes the elastic cantilever plate of the shell verification (issue 26).

A steel strip L = 100 mm long, b = 10 mm wide, t = 1 mm thick (SI units: m, s, kg, Pa),
clamped at x = 0 (all six degrees of freedom), free at x = L, released from rest in its first
bending mode shape with velocity: v_z = v0 phi(x / L), the rotations w_y = -v0 phi'(x), v0 the
tip velocity. Euler-Bernoulli beam theory gives the first-mode frequency

    f1 = (beta1 L)^2 / (2 pi L^2) sqrt(E I / (rho A)),  beta1 L = 1.875104,  I = b t^3 / 12,

83.6 Hz (period 11.96 ms) for E = 210 GPa, rho = 7850 kg/m^3. The tip displacement
(nodout.csv) crosses zero every half period; tools/verify/shell_modes.py measures it.

usage: shell_cantilever.py NX OUT.k [--elform 2|16] [--ny 2] [--end 0.05] [--nip 2] [--v0 0.1]
"""
import argparse
import math

BETA_L = 1.8751040687119611
SIGMA = (math.cosh(BETA_L) + math.cos(BETA_L)) / (math.sinh(BETA_L) + math.sin(BETA_L))


def mode(s):
    """First cantilever mode at s = x / L, 2 at the tip."""
    b = BETA_L * s
    return math.cosh(b) - math.cos(b) - SIGMA * (math.sinh(b) - math.sin(b))


def mode_slope(s):
    """d phi / ds."""
    b = BETA_L * s
    return BETA_L * (math.sinh(b) + math.sin(b) - SIGMA * (math.cosh(b) - math.cos(b)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("nx", type=int, help="elements along the length")
    ap.add_argument("out")
    ap.add_argument("--ny", type=int, default=2)
    ap.add_argument("--elform", type=int, default=2)
    ap.add_argument("--nip", type=int, default=2)
    ap.add_argument("--end", type=float, default=0.05)
    ap.add_argument("--v0", type=float, default=0.1, help="tip velocity, m/s")
    a = ap.parse_args()
    length, width, thick = 0.1, 0.01, 0.001
    e_mod, nu, rho = 210e9, 0.3, 7850.0
    tip = mode(1.0)
    nid = lambda i, j: 1 + i + (a.nx + 1) * j
    out = []
    w = out.append
    w("$ " + "-" * 94)
    w(f"$ shell cantilever nx = {a.nx}, ny = {a.ny}, ELFORM {a.elform}, NIP {a.nip}"
      " - written by tools/decks/shell_cantilever.py")
    w("$ What it shows: a clamped steel strip 100 x 10 x 1 mm vibrating in its first bending mode")
    w("$   (released with the mode's velocity field, tip velocity v0).")
    w("$ Expected:     tip displacement (nodout) periodic with the beam-theory period 11.96 ms;")
    w("$   tools/verify/shell_modes.py measures it. Energy kept (glstat).")
    w("$ Units:        m, s, kg, N, Pa.")
    w("$ " + "-" * 94)
    w("*KEYWORD")
    w("*TITLE")
    w(f"shell cantilever nx {a.nx} ELFORM {a.elform}")
    w("*CONTROL_TERMINATION")
    w(f"{a.end:10.4f}")
    w("*CONTROL_TIMESTEP")
    w("       0.0       0.9")
    w("*DATABASE_BINARY_D3PLOT")
    w(f"{a.end / 20:10.3e}")
    w("*DATABASE_GLSTAT")
    w(f"{1e-4:10.3e}")
    w("*DATABASE_NODOUT")
    w(f"{2e-5:10.3e}")
    w("*DATABASE_HISTORY_NODE")
    w(f"{nid(a.nx, a.ny // 2):10d}")
    w("*PART")
    w("strip")
    w("         1         1         1")
    w("*SECTION_SHELL")
    w(f"         1{a.elform:10d}{0.8333333:10.7f}{a.nip:10d}")
    w(f"{thick:10.4g}{thick:10.4g}{thick:10.4g}{thick:10.4g}")
    w("*MAT_ELASTIC")
    w(f"         1{rho:10.4g}{e_mod:10.4g}{nu:10.4g}")
    w("*NODE")
    for j in range(a.ny + 1):
        for i in range(a.nx + 1):
            x, y = length * i / a.nx, width * (j / a.ny - 0.5)
            w(f"{nid(i, j):8d}{x:16.8e}{y:16.8e}{0.0:16.8e}")
    w("*ELEMENT_SHELL")
    eid = 0
    for j in range(a.ny):
        for i in range(a.nx):
            eid += 1
            w(f"{eid:8d}{1:8d}{nid(i, j):8d}{nid(i + 1, j):8d}{nid(i + 1, j + 1):8d}"
              f"{nid(i, j + 1):8d}")
    w("*SET_NODE_LIST")
    w("         1")
    clamped = [nid(0, j) for j in range(a.ny + 1)]
    for k in range(0, len(clamped), 8):
        w("".join(f"{n:10d}" for n in clamped[k:k + 8]))
    w("*BOUNDARY_SPC_SET")
    w("         1         0         1         1         1         1         1         1")
    w("*INITIAL_VELOCITY_NODE")
    for j in range(a.ny + 1):
        for i in range(1, a.nx + 1):
            s = i / a.nx
            vz = a.v0 * mode(s) / tip
            wy = -a.v0 * mode_slope(s) / tip / length
            w(f"{nid(i, j):10d}{0.0:10.3g}{0.0:10.3g}{vz:10.4e}{0.0:10.3g}{wy:10.4e}{0.0:10.3g}")
    w("*END")
    with open(a.out, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
