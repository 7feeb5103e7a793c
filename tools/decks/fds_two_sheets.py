#!/usr/bin/python3
"""A flow-drill-screw joint deck as engineers write one (issue 46 item 3), for speed figures on
more than tools/decks/fds.py's single plate: two stacked square sheets, each an MC-SPG centre
joined by common nodes to an FE hexahedral surround clamped at its edge, with separate nodes
where they touch; a rigid screw meshed with hexahedra (a square pin drawn to a point), spinning
and plunging; contact screw-on-sheets (nodes to surface) and sheet-on-sheet (surface to
surface), with force transducers on the screw and between the sheets. JC-1 with a Grüneisen
EOS and the paper's bond failure, as fds_user_style.py. At the default h 0.2 it has 30,118 particles (two 7.2 mm centres, 2 mm thick) and 24,080 hexahedra.
Units t, mm, s, N, MPa. Deterministic: same arguments, same bytes.

usage: fds_two_sheets.py OUT.k [--h 0.2] [--side 10] [--centre 7.2] [--thickness 2]
                                [--screw-element 0.25] [--time-scale 20]
"""
import argparse

from fds_user_style import nodes_and_hexes

PARTS = {"top SPG": 1, "top FE": 2, "bottom SPG": 3, "bottom FE": 4, "screw": 5}
PIN_SIDE, PIN_LENGTH = 2.0, 4.0  # mm
TIP = {0: 0.15, 1: 0.5, 2: 0.8}  # x-y scale of the lowest node layers: the pointed tip


def sheet(n, layers, h, z0, centre, first_node, first_element, parts):
    """One sheet of n x n x layers hexahedra from z0 up: the elements within the centre square
    go to the SPG part, the others to the FE part (common nodes at the border). Returns node
    lines, element lines and the perimeter node IDs (the clamp)."""
    nid = lambda i, j, k: first_node + i + (n + 1) * (j + (n + 1) * k)
    side = n * h
    lo, hi = 0.5 * (side - centre), 0.5 * (side + centre)
    nodes = [f"{nid(i, j, k):8d}{i * h:16.6f}{j * h:16.6f}{z0 + k * h:16.6f}"
             for k in range(layers + 1) for j in range(n + 1) for i in range(n + 1)]
    elements, e = [], first_element
    for k in range(layers):
        for j in range(n):
            for i in range(n):
                x, y = (i + 0.5) * h, (j + 0.5) * h
                spg = lo < x < hi and lo < y < hi
                c = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                     nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                     nid(i, j + 1, k + 1)]
                part = parts[0] if spg else parts[1]
                elements.append(f"{e:8d}{part:8d}" + "".join(f"{m:8d}" for m in c))
                e += 1
    perimeter = [nid(i, j, k) for k in range(layers + 1) for j in range(n + 1)
                 for i in range(n + 1) if i in (0, n) or j in (0, n)]
    return nodes, elements, perimeter


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out")
    ap.add_argument("--h", type=float, default=0.2, help="sheet element size, mm")
    ap.add_argument("--side", type=float, default=10.0, help="sheet side, mm")
    ap.add_argument("--centre", type=float, default=7.2, help="side of each SPG centre, mm")
    ap.add_argument("--thickness", type=float, default=2.0, help="of each sheet, mm")
    ap.add_argument("--screw-element", type=float, default=0.25, help="screw element size, mm")
    ap.add_argument("--time-scale", type=float, default=20.0)
    a = ap.parse_args()
    n, layers = round(a.side / a.h), round(a.thickness / a.h)
    per_sheet = (n + 1) ** 2 * (layers + 1)
    top = sheet(n, layers, a.h, 0.0, a.centre, 1, 1, (PARTS["top SPG"], PARTS["top FE"]))
    bottom = sheet(n, layers, a.h, -a.thickness, a.centre, per_sheet + 1, n * n * layers + 1,
                   (PARTS["bottom SPG"], PARTS["bottom FE"]))
    pin, pin_layers = round(PIN_SIDE / a.screw_element), round(PIN_LENGTH / a.screw_element)
    x0 = 0.5 * (n * a.h - pin * a.screw_element)
    first = 2 * per_sheet + 1
    screw_nodes, screw_elements = nodes_and_hexes(
        pin, pin, pin_layers, a.screw_element, (x0, x0, a.thickness + 0.05), first,
        2 * n * n * layers + 1, PARTS["screw"], taper=lambda k: TIP.get(k, 1.0))
    clamp = top[2] + bottom[2]
    s = a.time_scale
    omega, vz, plunge = -5000.0 * s * 2.0 * 3.141592653589793 / 60.0, -2000.0 * s, 1.0
    end = plunge / (2000.0 * s)
    ramp = 0.05 * end
    f = lambda v: f"{v:20.8g}"
    lines = [
        "*KEYWORD",
        "*TITLE",
        f"FDS joint: two sheets with SPG centres, hexahedral screw, h {a.h} mm",
        f"$ fds_two_sheets.py {a.out} --h {a.h} --side {a.side} --centre {a.centre} "
        f"--thickness {a.thickness} --screw-element {a.screw_element} --time-scale {s}",
        "*CONTROL_TERMINATION", f"{end:10.4g}",
        "*CONTROL_TIMESTEP", "       0.0       0.9         0       0.0     -1e-8",
        "*CONTROL_ACCURACY", "         1         4         0         1",
        "*CONTROL_CONTACT", "       0.1",
        "*DATABASE_GLSTAT", f"{ramp:10.4g}",
        "*DATABASE_RCFORC", f"{ramp:10.4g}",
        "*DATABASE_BINARY_D3PLOT", f"{end / 10:10.4g}",
        "*PART", "top sheet centre (MC-SPG)", "         1         1         1         1",
        "*PART", "top sheet surround", "         2         2         1         1",
        "*PART", "bottom sheet centre (MC-SPG)", "         3         1         1         1",
        "*PART", "bottom sheet surround", "         4         2         1         1",
        "*PART", "screw", "         5         2         2",
        "*SECTION_SOLID_SPG", "         1        47",
        "       1.5       1.5       1.5         0         0                  15       0.0",
        "         1       0.4      1.15         3       1.0         0         0    -0.001",
        "*SECTION_SOLID", "         2         1",
        "*MAT_JOHNSON_COOK_TITLE", "AA6061-T6 JC-1",
        "         1    2.7E-9   26000.0",
        "     324.0     114.0      0.42     0.002      1.34     925.0     293.0       1.0",
        "    8.96E8       0.0       2.0",
        "*EOS_GRUNEISEN", "         1 5386000.0     1.339       0.0       0.0      1.99       0.0",
        "*MAT_RIGID_TITLE", "steel screw", "         2   7.85E-9  210000.0       0.3",
        "       1.0         4         4",
        "*NODE", *top[0], *bottom[0], *screw_nodes,
        "*ELEMENT_SOLID", *top[1], *bottom[1], *screw_elements,
        "*SET_NODE_LIST", "         1",
        *["".join(f"{m:10d}" for m in clamp[i:i + 8]) for i in range(0, len(clamp), 8)],
        "*BOUNDARY_SPC_SET", "         1         0         1         1         1         0"
        "         0         0",
        "*BOUNDARY_PRESCRIBED_MOTION_RIGID",
        "         5         3         0         1       1.0",
        "         5         7         0         2       1.0",
        "*DEFINE_CURVE", "         1", f(0.0) + f(0.0), f(ramp) + f(vz), f(end) + f(vz),
        "*DEFINE_CURVE", "         2", f(0.0) + f(0.0), f(ramp) + f(omega), f(end) + f(omega),
        "*SET_PART_LIST", "         1", "         1         3",
        "*SET_PART_LIST", "         2", "         1         2",
        "*SET_PART_LIST", "         3", "         3         4",
        "*CONTACT_AUTOMATIC_NODES_TO_SURFACE_ID", "         1screw on sheets",
        "         1         5         2         3", "       0.3       0.3",
        "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_ID", "         2sheet on sheet",
        "         2         3         2         2", "       0.2       0.2",
        # The screw's force from every contact on it, and the force between the sheets.
        "*CONTACT_FORCE_TRANSDUCER_PENALTY_ID", "         3screw force",
        "         5         0         3", "", "",
        "*CONTACT_FORCE_TRANSDUCER_PENALTY_ID", "         4top sheet on bottom sheet",
        "         2         3         2         2", "", "",
        "*END",
    ]
    with open(a.out, "w") as out:
        out.write("\n".join(lines) + "\n")
    spg = sum(1 for line in top[1] + bottom[1] if int(line[8:16]) in (1, 3))
    print(f"{a.out}: {2 * per_sheet + len(screw_nodes)} nodes, {spg} SPG elements, "
          f"{len(top[1]) + len(bottom[1]) - spg} FE hexahedra, {len(screw_elements)} screw "
          f"hexahedra")


if __name__ == "__main__":
    main()
