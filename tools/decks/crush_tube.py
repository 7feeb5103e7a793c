#!/usr/bin/python3
"""Writes the axial crush of a thin-walled square aluminium tube (shell verification, issue 26).

Square tube of side C = 50 mm (mid-surface), wall t = 1.5 mm, length 150 mm; elastic-perfectly
plastic aluminium (E 70 GPa, nu 0.3, rho 2.7e-9 t/mm^3, sigma0 100 MPa: the rigid-perfectly
plastic flow stress of the crushing theories). Both ends are clamped (as welded to end plates);
the top end's nodes are driven down at 10 m/s (ramped over 0.5 ms).
Automatic single-surface contact between the folds. Units t, mm, s, N, MPa.
A trigger (--trigger, mm) starts the symmetric folding mode the theory assumes: over the top two
fold half-wavelengths H = 0.99 t^1/3 C^2/3 (Wierzbicki and Abramowicz 1983) two opposite faces
are dented in and the other two out, sin(pi s / C) across each face; without it the clamped,
driven end starts an all-outward (extensional) first lobe.

Abramowicz and Jones (1984, Int. J. Impact Engng 2: 179-208), symmetric mode with the effective
crushing distance: P_m = 13.06 sigma0 t^(5/3) C^(1/3) = 9.46 kN here (C/t = 33). The crushing
force is the reaction of the driven nodes (bndout); tools/verify/crush_force.py integrates it.

usage: crush_tube.py N OUT.k [--elform 2|16] [--nip 5] [--crush 70] [--speed 10000]
                             [--trigger 0.15]
  N: elements along each side (the length takes the same element size)
"""
import argparse
import math


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("n", type=int, help="elements per side")
    ap.add_argument("out")
    ap.add_argument("--elform", type=int, default=2)
    ap.add_argument("--nip", type=int, default=5)
    ap.add_argument("--crush", type=float, default=70.0, help="crush distance, mm")
    ap.add_argument("--speed", type=float, default=10000.0, help="mm/s")
    ap.add_argument("--ihq", type=int, default=0, help="0: the default hourglass control")
    ap.add_argument("--trigger", type=float, default=0.15, help="dent amplitude, mm (0: none)")
    a = ap.parse_args()
    side, thick, length = 50.0, 1.5, 150.0
    h = side / a.n
    nz = round(length / h)
    around = 4 * a.n
    ramp = 5e-4
    end = (a.crush + 0.5 * a.speed * ramp) / a.speed

    wave = 0.99 * thick ** (1 / 3) * side ** (2 / 3)  # fold half-wavelength H

    def point(k, z):
        """Mid-surface point k of the cross-section at height z, counter-clockwise from
        (-C/2, -C/2), moved out of its face by the trigger's dent."""
        s, r = divmod(k, a.n)
        f = r / a.n * side - side / 2
        x, y = [(f, -side / 2), (side / 2, f), (-f, side / 2), (-side / 2, -f)][s]
        below_top = length - z
        if below_top < 2 * wave:
            dent = a.trigger * (1 if s % 2 == 0 else -1) * math.sin(math.pi * r / a.n)
            dent *= math.sin(math.pi * below_top / wave)
            nx, ny = [(0, -1), (1, 0), (0, 1), (-1, 0)][s]
            x, y = x + dent * nx, y + dent * ny
        return x, y

    nid = lambda k, j: 1 + (k % around) + around * j
    out = []
    w = out.append
    w("$ " + "-" * 94)
    w(f"$ crush_tube n = {a.n} (element {h:g} mm), ELFORM {a.elform}, NIP {a.nip}, trigger"
      f" {a.trigger:g} mm"
      " - written by tools/decks/crush_tube.py")
    w("$ What it shows: a 50 x 50 x 1.5 mm aluminium square tube, 150 mm long, crushed axially at")
    w(f"$   {a.speed / 1000:g} m/s by {a.crush:g} mm; folds form from the driven end.")
    w("$ Expected:     mean crushing force near Abramowicz-Jones 13.06 sigma0 t^5/3 C^1/3 = 9.46 kN")
    w("$   (bndout.csv, the driven nodes' reaction); tools/verify/crush_force.py.")
    w("$ Units:        t, mm, s, N, MPa.")
    w("$ " + "-" * 94)
    w("*KEYWORD")
    w("*TITLE")
    w(f"square tube crush n {a.n} ELFORM {a.elform}")
    w("*CONTROL_TERMINATION")
    w(f"{end:10.4e}")
    w("*CONTROL_TIMESTEP")
    w("       0.0       0.9")
    w("*CONTROL_SHELL")
    w("      20.0         0        -1         1         2         2         1")
    w("*DATABASE_BINARY_D3PLOT")
    w(f"{end / 20:10.3e}")
    w("*DATABASE_GLSTAT")
    w(f"{end / 500:10.3e}")
    w("*DATABASE_BNDOUT")
    w(f"{end / 1000:10.3e}")
    w("*PART")
    w("tube")
    w(f"         1         1         1         0{1 if a.ihq else 0:10d}")
    w("*SECTION_SHELL")
    w(f"         1{a.elform:10d}{0.8333333:10.7f}{a.nip:10d}")
    w(f"{thick:10.4g}{thick:10.4g}{thick:10.4g}{thick:10.4g}")
    w("*MAT_PIECEWISE_LINEAR_PLASTICITY")
    w(f"         1{2.7e-9:10.3e}{70000.0:10.1f}{0.3:10.2f}{100.0:10.1f}{0.0:10.1f}")
    if a.ihq:
        w("*HOURGLASS")
        w(f"         1{a.ihq:10d}       0.1")
    w("*NODE")
    for j in range(nz + 1):
        for k in range(around):
            x, y = point(k, j * h)
            w(f"{nid(k, j):8d}{x:16.8e}{y:16.8e}{j * h:16.8e}")
    w("*ELEMENT_SHELL")
    e = 0
    for j in range(nz):
        for k in range(around):
            e += 1
            w(f"{e:8d}{1:8d}{nid(k, j):8d}{nid(k + 1, j):8d}{nid(k + 1, j + 1):8d}{nid(k, j + 1):8d}")
    w("*SET_NODE_LIST_GENERATE")
    w("         1")
    w(f"{nid(0, 0):10d}{nid(around - 1, 0):10d}")
    w("*SET_NODE_LIST_GENERATE")
    w("         2")
    w(f"{nid(0, nz):10d}{nid(around - 1, nz):10d}")
    w("*BOUNDARY_SPC_SET")
    w("         1         0         1         1         1         1         1         1")
    w("         2         0         1         1         0         1         1         1")
    w("*BOUNDARY_PRESCRIBED_MOTION_SET")
    w("         2         3         0         1      -1.0")
    w("*DEFINE_CURVE")
    w("         1")
    w(f"{0.0:20.6e}{0.0:20.6e}")
    w(f"{ramp:20.6e}{a.speed:20.6e}")
    w(f"{1.0:20.6e}{a.speed:20.6e}")
    w("*CONTACT_AUTOMATIC_SINGLE_SURFACE")
    w("         1         0         3")
    w("       0.2       0.2")
    w("*END")
    with open(a.out, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
