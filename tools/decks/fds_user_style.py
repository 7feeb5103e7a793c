#!/usr/bin/python3
"""A small flow-drill-screw deck written the way engineers write theirs (issue 23 item 5), to
show that such decks check and run unchanged: a main file with *PARAMETER / *PARAMETER_EXPRESSION
for the schedule, *CONTROL_ACCURACY (OSU 1, INN 4), *CONTROL_MPP_DECOMPOSITION_PARTS_DISTRIBUTE
over the SPG part, and *INCLUDE files for the meshes:

  sheets.k  two stacked sheets: the top one MC-SPG (part 1), the bottom one FE hexahedra
            (part 2), with a contact between them (separate nodes on the interface)
  screw.k   a rigid screw meshed with hexahedra (part 3): a square-section pin with a pointed
            tip, spinning and plunging
  ring.k    a rigid hold-down ring of shells (part 4) on the top sheet, held fixed

It is coarse (a few hundred particles): a test deck for reading and running, not a physics
result. usage: fds_user_style.py OUT_DIR
"""
import os
import sys

H = 0.5          # mm, the sheets' spacing
N = 8            # elements per side of a sheet (4 x 4 mm)
LAYERS = 2       # per sheet
SCREW_H = 0.25   # mm
PIN = 4          # screw elements per side (1 x 1 mm)
PIN_LAYERS = 6


def nodes_and_hexes(nx, ny, nz, h, origin, first_node, first_element, part, taper=None):
    """Box mesh lines (*NODE rows and *ELEMENT_SOLID rows); `taper(k)` scales the x-y size of
    node layer k about the box's axis (the screw's point)."""
    x0, y0, z0 = origin
    node_lines, element_lines = [], []
    nid = lambda i, j, k: first_node + i + (nx + 1) * (j + (ny + 1) * k)
    cx, cy = x0 + 0.5 * nx * h, y0 + 0.5 * ny * h
    for k in range(nz + 1):
        s = taper(k) if taper else 1.0
        for j in range(ny + 1):
            for i in range(nx + 1):
                x = cx + s * (x0 + i * h - cx)
                y = cy + s * (y0 + j * h - cy)
                node_lines.append(f"{nid(i, j, k):8d}{x:16.6f}{y:16.6f}{z0 + k * h:16.6f}")
    e = first_element
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                c = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                     nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                     nid(i, j + 1, k + 1)]
                element_lines.append(f"{e:8d}{part:8d}" + "".join(f"{n:8d}" for n in c))
                e += 1
    return node_lines, element_lines


def write(path, lines):
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    side = N * H
    # Sheets: bottom FE (z -1 .. 0), top SPG (z 0 .. 1), separate nodes at z = 0.
    bn, be = nodes_and_hexes(N, N, LAYERS, H, (0.0, 0.0, -LAYERS * H), 1, 1, 2)
    tn, te = nodes_and_hexes(N, N, LAYERS, H, (0.0, 0.0, 0.0), 10001, 10001, 1)
    perimeter = [1 + i + (N + 1) * (j + (N + 1) * k) for k in range(LAYERS + 1)
                 for j in range(N + 1) for i in range(N + 1) if i in (0, N) or j in (0, N)]
    lines = ["$ two stacked sheets: part 1 MC-SPG on top, part 2 FE hexahedra below", "*NODE"]
    lines += bn + tn + ["*ELEMENT_SOLID"] + be + te
    lines += ["*SET_NODE_LIST", "         1"]
    lines += ["".join(f"{n:10d}" for n in perimeter[i:i + 8]) for i in range(0, len(perimeter), 8)]
    write(os.path.join(out, "sheets.k"), lines)
    # Screw: a 1 x 1 mm pin from z 1.05 up, its lowest node layer drawn to a point.
    x0 = 0.5 * side - 0.5 * PIN * SCREW_H
    sn, se = nodes_and_hexes(PIN, PIN, PIN_LAYERS, SCREW_H, (x0, x0, LAYERS * H + 0.05), 20001,
                             20001, 3, taper=lambda k: 0.2 if k == 0 else 1.0)
    write(os.path.join(out, "screw.k"),
          ["$ rigid screw of hexahedra (part 3)", "*NODE"] + sn + ["*ELEMENT_SOLID"] + se)
    # Ring: shells on the top face, a square annulus between 1 mm and 2 mm from the centre.
    ring_nodes, ring_shells = [], []
    c = 0.5 * side
    grid = [c - 2.0, c - 1.0, c, c + 1.0, c + 2.0]
    nid = {}
    for j, y in enumerate(grid):
        for i, x in enumerate(grid):
            nid[(i, j)] = 30001 + i + 5 * j
            ring_nodes.append(f"{nid[(i, j)]:8d}{x:16.6f}{y:16.6f}{LAYERS * H + 0.02:16.6f}")
    e = 30001
    for j in range(4):
        for i in range(4):
            if 1 <= i <= 2 and 1 <= j <= 2:
                continue  # the hole
            ring_shells.append(f"{e:8d}{4:8d}{nid[(i, j)]:8d}{nid[(i + 1, j)]:8d}"
                               f"{nid[(i + 1, j + 1)]:8d}{nid[(i, j + 1)]:8d}")
            e += 1
    write(os.path.join(out, "ring.k"),
          ["$ rigid hold-down ring of shells (part 4)", "*NODE"] + ring_nodes +
          ["*ELEMENT_SHELL"] + ring_shells)

    main = f"""$ FDS joint, user style: parameters, includes, OSU, MPP decomposition
*KEYWORD
*TITLE
FDS user-style deck (two sheets, hex screw, shell ring)
*PARAMETER
$ PRMR1      VAL1     PRMR2      VAL2
R rpm         5000.0R vplunge     2000.0
R tscale        20.0R plunge         0.6
*PARAMETER_EXPRESSION
R omega     -&rpm*&tscale*2.0*pi/60.0
R vz        -&vplunge*&tscale
R tend      &plunge/(&vplunge*&tscale)
R tramp     0.05*&tend
*CONTROL_TERMINATION
&tend
*CONTROL_TIMESTEP
       0.0       0.9         0       0.0    -2e-08
*CONTROL_ACCURACY
$      OSU       INN    PIDOSU      IACC
         1         4         0         1
*CONTROL_CONTACT
       0.1
*CONTROL_MPP_DECOMPOSITION_PARTS_DISTRIBUTE
         1
*SET_PART_LIST
         1
         1
*DATABASE_GLSTAT
&tramp
*DATABASE_RCFORC
&tramp
*DATABASE_BNDOUT
&tramp
*DATABASE_BINARY_D3PLOT
&tend
*INCLUDE
sheets.k
*INCLUDE
screw.k
*INCLUDE
ring.k
*PART
top sheet (MC-SPG)
         1         1         1         1
*PART
bottom sheet
         2         2         1         1
*PART
screw
         3         2         2
*PART
hold-down ring
         4         3         3
*SECTION_SOLID_SPG
         1        47
       1.5       1.5       1.5         0         0                  15       0.0
         1       0.4      1.15         3       1.0         0         0    -0.001
*SECTION_SOLID
         2         1
*SECTION_SHELL
         3         2
       0.1       0.1       0.1       0.1
*MAT_JOHNSON_COOK_TITLE
AA6061-T6 JC-1
         1    2.7E-9   26000.0
     324.0     114.0      0.42     0.002      1.34     925.0     293.0       1.0
    8.96E8       0.0       2.0
*EOS_GRUNEISEN
         1 5386000.0     1.339       0.0       0.0      1.99       0.0
*MAT_RIGID_TITLE
steel screw
         2   7.85E-9  210000.0       0.3
       1.0         4         4
*MAT_RIGID_TITLE
steel ring, held
         3   7.85E-9  210000.0       0.3
       1.0         7         7
*BOUNDARY_SPC_SET
         1         0         1         1         1         0         0         0
*BOUNDARY_PRESCRIBED_MOTION_RIGID
         3         3         0         1       1.0
         3         7         0         2       1.0
*DEFINE_CURVE
         1
$                 A1                  O1
                 0.0                 0.0
{'&tramp':>20}{'&vz':>20}
{'&tend':>20}{'&vz':>20}
*DEFINE_CURVE
         2
                 0.0                 0.0
{'&tramp':>20}{'&omega':>20}
{'&tend':>20}{'&omega':>20}
*SET_PART_LIST
         2
         1         2
*CONTACT_AUTOMATIC_NODES_TO_SURFACE_ID
         1screw on sheets
         2         3         2         3
       0.3       0.3
*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_ID
         2sheet on sheet
         1         2         3         3
       0.2       0.2
*CONTACT_AUTOMATIC_NODES_TO_SURFACE_ID
         3ring on top sheet
         1         4         3         3
       0.3       0.3
*END
"""
    with open(os.path.join(out, "main.k"), "w") as f:
        f.write(main)


if __name__ == "__main__":
    main()
