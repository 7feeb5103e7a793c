#!/usr/bin/python3
"""Writes the flow-drill-screw (FDS) thread-forming deck of the MC-SPG paper (§4.3): a rigid M5
screw (drilling cone and forming cylinder at the thread's minor radius, then the 0.7 mm pitch
right-hand thread; spun clockwise seen from its head) plunging through a 1.5 mm 6061-T6 plate of
20 mm diameter whose central Ø7 mm region is MC-SPG (ITB 3, bond failure FS 0.4, STRETCH 1.15),
joined by common nodes to an outer FE ring clamped at its perimeter; JC-1 with a Grüneisen EOS;
penalty contact with friction 0.3. Units t, mm, s, N, MPa. Deterministic: same arguments, same
bytes.

The paper's two-stage schedule: 5000 rpm at 2.0 m/s while the tip penetrates, then 20,000 rpm at
0.2 m/s (0.6 mm per turn against the 0.7 mm pitch: the plate extrudes up along the thread).
--time-scale S runs it S times faster (all speeds x S, times / S) so a coarse run finishes on a
workstation; --mass-scaling DT adds mass where the step is below DT (DT2MS). Both are stated in
the deck header. --fe-erosion makes the whole plate FE hexahedra with erosion at an effective
plastic strain of 0.4, the paper's comparison.

usage: fds.py H OUT.k [--time-scale 10] [--mass-scaling 0] [--msc 0] [--stage2 4.4] [--feed 0.6]
                      [--fe-erosion] [--states 100] [--cycles N] [--restart-cycles 20000]
"""
import argparse
import math

from spg_section import field
from taylor_bar import jc1_cards, layered_hexahedra, layered_nodes, node_line, section

PLATE_RADIUS, SPG_RADIUS, THICKNESS = 10.0, 3.5, 1.5
MAJOR, PITCH = 2.5, 0.7  # thread major radius, pitch
DEPTH = 0.433            # ISO M5 thread depth (major - minor) / 2
MINOR = MAJOR - DEPTH
# The forming zone below the thread, as on a flow-drill screw: a cone from TIP_RADIUS at the
# point to the minor radius, then a cylinder at the minor radius as long as the plate is thick,
# so the tip drills and the cylinder forms the hole and bushing at the minor radius during stage
# 1, and the thread forms into that wall in stage 2. (A cone straight to the major radius made
# the hole at the crests: the thread passed through it and formed nothing.)
TIP_LENGTH, TIP_RADIUS = 3.0, 0.3
FORMING_LENGTH = TIP_LENGTH + THICKNESS
LEAD_IN = PITCH          # the thread grows from the minor radius to its full depth over a turn
THREADED = 7 * PITCH     # threaded length above the forming zone
CLEARANCE = 0.05         # tip above the plate at t = 0
STAGE1 = (5000.0, 2000.0)   # rpm, mm/s
STAGE2 = (20000.0, 200.0)


def thread_radius(z, theta):
    """Radius of the threaded surface at height z (from the tip point) and angle theta: ISO-like
    triangular profile, root flat P/4, crest flat P/8, right-handed."""
    phase = ((z - PITCH * theta / (2.0 * math.pi)) / PITCH) % 1.0
    root, crest = 0.25, 0.125
    flank = (1.0 - root - crest) / 2.0
    if phase < root:
        f = 0.0
    elif phase < root + flank:
        f = (phase - root) / flank
    elif phase < root + flank + crest:
        f = 1.0
    else:
        f = 1.0 - (phase - root - flank - crest) / flank
    return MAJOR - DEPTH + DEPTH * f


def screw_radius(z, theta):
    """The forming zone (cone, then cylinder at the minor radius) up to FORMING_LENGTH, the
    thread above it, its depth growing over LEAD_IN and falling again over the last LEAD_IN."""
    if z < TIP_LENGTH:
        return TIP_RADIUS + (MINOR - TIP_RADIUS) * z / TIP_LENGTH
    if z < FORMING_LENGTH:
        return MINOR
    # Lead-in at the bottom and the same lead-out at the top: the two linear ramps over whole
    # turns add up to a full turn of thread at every angle, so the centre of mass stays on the
    # spin axis (a thread cut off square at the top put it 0.03 mm off).
    u = z - FORMING_LENGTH
    depth = min(1.0, u / LEAD_IN, (THREADED - u) / LEAD_IN)
    return MINOR + (thread_radius(u, theta) - MINOR) * max(0.0, depth)


def screw_surface(h, z0):
    """Quadrilateral shells of the screw surface on a (theta, z) grid, closed by triangle fans at
    the tip and the top; normals outward. Returns nodes [(x, y, z)] and shells [(n1..n4)]."""
    n_theta = 8 * max(12, round(2.0 * math.pi * MAJOR / h / 8.0))
    per_pitch = max(8, math.ceil(PITCH / h))
    dz = PITCH / per_pitch
    # Rows: the forming zone at about dz, then the thread at exactly dz for whole turns, which
    # keeps the screw's centre of mass on the axis it is spun about.
    n_forming = math.ceil(FORMING_LENGTH / dz)
    heights = ([FORMING_LENGTH * k / n_forming for k in range(n_forming)] +
               [FORMING_LENGTH + dz * k for k in range(round(THREADED / dz) + 1)])
    n_z = len(heights) - 1
    length = heights[-1]
    nodes, shells = [], []
    for z in heights:
        for j in range(n_theta):
            t = 2.0 * math.pi * j / n_theta
            r = screw_radius(z, t)
            nodes.append((r * math.cos(t), r * math.sin(t), z0 + z))
    ring = lambda k, j: k * n_theta + (j % n_theta)
    for k in range(n_z):
        for j in range(n_theta):
            # Counter-clockwise seen from outside: theta then z.
            shells.append((ring(k, j), ring(k, j + 1), ring(k + 1, j + 1), ring(k + 1, j)))
    tip = len(nodes)
    nodes.append((0.0, 0.0, z0))
    top = len(nodes)
    nodes.append((0.0, 0.0, z0 + length))
    for j in range(n_theta):
        shells.append((tip, ring(0, j + 1), ring(0, j), ring(0, j)))
        shells.append((top, ring(n_z, j), ring(n_z, j + 1), ring(n_z, j + 1)))
    return nodes, shells, n_theta, n_z


def plate_section(h):
    """In-plane mesh of the plate: the butterfly disc of radius SPG_RADIUS (inner square of half
    width R/2 with spacing about h, radial spacing h on the axes, 1.5 h along the rim) and an FE
    ring out to PLATE_RADIUS on the same rim nodes, its radial spacing growing from h by 20 % a
    ring. Returns points, quads of the disc, quads of the ring, the perimeter points."""
    n = max(2, round(2.0 * math.pi * SPG_RADIUS / (1.5 * h) / 8.0))
    nr = max(2, round((SPG_RADIUS - 0.5 * SPG_RADIUS) / h))
    pts, quads = section(n, nr, SPG_RADIUS)
    # The rim nodes of the butterfly, by angle.
    rim = sorted((i for i, (x, y) in enumerate(pts)
                  if abs(math.hypot(x, y) - SPG_RADIUS) < 1e-9),
                 key=lambda i: math.atan2(pts[i][1], pts[i][0]))
    radii, r, step = [SPG_RADIUS], SPG_RADIUS, h
    while r < PLATE_RADIUS - 1e-9:
        step *= 1.2
        r = min(PLATE_RADIUS, r + step)
        if PLATE_RADIUS - r < 0.5 * step:
            r = PLATE_RADIUS
        radii.append(r)
    ring_quads, prev = [], rim
    for r in radii[1:]:
        cur = []
        for i in rim:
            a = math.atan2(pts[i][1], pts[i][0])
            cur.append(len(pts))
            pts.append((r * math.cos(a), r * math.sin(a)))
        m = len(rim)
        for j in range(m):
            ring_quads.append([prev[j], cur[j], cur[(j + 1) % m], prev[(j + 1) % m]])
        prev = cur
    return pts, quads, ring_quads, prev


def orient(pts, quads):
    for q in quads:
        area = sum(pts[q[k]][0] * pts[q[(k + 1) % 4]][1] - pts[q[(k + 1) % 4]][0] * pts[q[k]][1]
                   for k in range(4))
        if area < 0:
            q.reverse()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("h", type=float, help="nodal distance in the MC-SPG region, mm")
    ap.add_argument("out")
    ap.add_argument("--time-scale", type=float, default=10.0)
    ap.add_argument("--mass-scaling", type=float, default=0.0, help="DT2MS (s, > 0)")
    ap.add_argument("--msc", type=int, default=0)
    ap.add_argument("--kernel", type=int, default=0, help="KERNEL: 0 updated Lagrangian, 1 Eulerian")
    # Stage 2 runs "until the end of screw driving" (paper §4.3); with no screw head here, until
    # the threaded length spans the plate and the bushing: at 4.4 mm the thread's first turn is
    # 4.4 mm below the plate's top face (the bushing reaches ~2.7 mm) and its last still above it.
    # With 2.1 mm the thread only reached the top of the hole (manual/verification.md).
    ap.add_argument("--stage2", type=float, default=4.4, help="plunge in stage 2, mm")
    ap.add_argument("--fe-erosion", action="store_true")
    ap.add_argument("--states", type=int, default=100)
    ap.add_argument("--penalty-scale", type=float, default=10.0,
                    help="SFSA = SFSB: contact penalty x this (the screw skin is 0.02 mm thin)")
    ap.add_argument("--cycles", type=int, default=0, help="ENDCYC: stop after N cycles (benchmarks)")
    ap.add_argument("--restart-cycles", type=int, default=20000,
                    help="*DATABASE_BINARY_RUNRSF: running restart file every N cycles (0: none)")
    ap.add_argument("--osu", type=int, default=0, choices=(0, 1),
                    help="*CONTROL_ACCURACY OSU: 1 second-order objective stress update")
    # What sets the formed thread (issue 47): the paper's values by default, one at a time.
    ap.add_argument("--fs", type=float, default=0.4,
                    help="*SECTION_SOLID_SPG FS: bonds fail past this plastic strain")
    ap.add_argument("--stretch", type=float, default=1.15,
                    help="*SECTION_SOLID_SPG STRETCH: bonds fail past this stretch")
    ap.add_argument("--dx", type=float, default=1.5,
                    help="*SECTION_SOLID_SPG DX = DY = DZ: support over the nodal distance")
    ap.add_argument("--friction", type=float, default=0.3, help="contact FS = FD")
    ap.add_argument("--skin", type=float, default=0.02, help="screw shell thickness, mm")
    ap.add_argument("--feed", type=float, default=None,
                    help="stage-2 plunge per turn, mm (the paper's: 0.6 at 20,000 rpm and 0.2 m/s;"
                         " 0.7 follows the thread's lead)")
    a = ap.parse_args()
    h, scale = a.h, a.time_scale
    layers = max(2, round(THICKNESS / h))
    pts, disc, ring, perimeter = plate_section(h)
    orient(pts, disc)
    orient(pts, ring)
    npl = len(pts)

    # Schedule: stage 1 until the tip is through and the thread reaches the plate.
    plunge1 = CLEARANCE + FORMING_LENGTH
    speed2 = STAGE2[1] if a.feed is None else a.feed * STAGE2[0] / 60.0
    v1, v2 = STAGE1[1] * scale, speed2 * scale
    w1, w2 = STAGE1[0] * scale * 2 * math.pi / 60, STAGE2[0] * scale * 2 * math.pi / 60
    t1 = plunge1 / v1
    t_end = t1 + a.stage2 / v2
    ramp = 0.02 * t1

    screw_nodes, screw_shells, n_theta, n_z = screw_surface(h, THICKNESS + CLEARANCE)
    first_screw = 1_000_001
    out = []
    w = out.append
    method = "FE hexahedra with erosion at plastic strain 0.4" if a.fe_erosion else "MC-SPG centre"
    w("$ " + "-" * 94)
    w(f"$ fds h = {h} mm ({method}) - written by tools/decks/fds.py")
    w("$ What it shows: a rigid M5 flow-drill screw (tip cone and forming cylinder at the minor")
    w("$   radius, 0.7 mm pitch right-hand thread) spinning clockwise (seen from its head) and")
    w("$   plunging through a 1.5 mm 6061-T6 plate (JC-1 + Gruneisen), MC-SPG paper section 4.3.")
    schedule = ("the paper's speeds" if a.feed is None
                else f"the paper's, stage 2 fed {a.feed:g} mm per turn")
    w(f"$ Schedule ({schedule}): {STAGE1[0]:.0f} rpm at {STAGE1[1] / 1000:.1f} m/s for the "
      f"first {plunge1:.2f} mm")
    w(f"$   (until the thread reaches the plate), then {STAGE2[0]:.0f} rpm at "
      f"{speed2 / 1000:.{1 if a.feed is None else 4}f} m/s for {a.stage2:.2f} mm.")
    w(f"$ TIME SCALE {scale:g}: every speed x {scale:g} and every time / {scale:g} "
      f"(stage 1 ends at {t1:.4e} s, end {t_end:.4e} s).")
    w(f"$ MASS SCALING: {'DT2MS = %g s' % a.mass_scaling if a.mass_scaling > 0 else 'none'}.")
    w(f"$ CONTACT: penalty x {a.penalty_scale:g} (SFSA = SFSB), SOFT 1, friction {a.friction:g}.")
    paper = (0.4, 1.15, 1.5, 0.02)
    if (a.fs, a.stretch, a.dx, a.skin) != paper:
        w(f"$ FACTORS: FS {a.fs:g}, STRETCH {a.stretch:g}, DX {a.dx:g}, screw skin {a.skin:g} mm "
          f"(the paper's: FS 0.4, STRETCH 1.15, DX 1.5, skin 0.02).")
    if a.osu:
        w("$ ACCURACY: OSU 1, the second-order objective stress update (mid-step strain rates,")
        w("$   Hughes-Winget rotation) in the plate's particles and elements.")
    w(f"$ Plate: {layers} layers through 1.5 mm; Ø7 mm centre "
      f"{'FE' if a.fe_erosion else 'MC-SPG'}, FE ring to Ø20 mm, perimeter clamped.")
    # The eigenvalue step: the nearest-neighbour one collapses on pairs squeezed under the screw,
    # and how long it stays down is chaotic (issue 46, h 0.3: TSSFAC 0.899 instead of 0.9 took
    # 210,610 cycles to 0.68 ms where 0.9 took 60,871; manual/verification.md).
    w(f"$ How to run: mcdyna run {a.out} --spg-step eigen --out results/fds; "
      "tools/verify/fds_force.py results/fds")
    w("$ " + "-" * 94)
    w("*KEYWORD")
    w("*TITLE")
    w(f"FDS thread forming h {h} mm" + (" FE erosion" if a.fe_erosion else " MC-SPG"))
    w("*CONTROL_TERMINATION")
    w(f"{t_end:10.4E}" + (f"{a.cycles:10d}" if a.cycles else ""))
    w("*CONTROL_TIMESTEP")
    w(f"       0.0       0.9         0       0.0{field(-a.mass_scaling) if a.mass_scaling else '       0.0'}")
    w("*CONTROL_CONTACT")
    w("       0.1")
    if a.osu:
        w("*CONTROL_ACCURACY")
        w("         1         1")
    if a.restart_cycles > 0:
        # A running restart file, so a long run that is stopped (or killed) can be continued
        # with `mcdyna run DECK --restart runrsf`.
        w("*DATABASE_BINARY_RUNRSF")
        w(f"{a.restart_cycles:10d}")
    w("*DATABASE_BINARY_D3PLOT")
    w(f"{t_end / a.states:10.4E}")
    # Histories every 1/72 of stage 1 (0.063 mm of plunge in stage 1, 0.0063 mm in stage 2),
    # whatever the length of stage 2.
    for name in ("GLSTAT", "MATSUM", "RCFORC", "BNDOUT", "NODOUT"):
        w(f"*DATABASE_{name}")
        w(f"{t1 / 72:10.4E}")
    w("*DATABASE_HISTORY_NODE")
    w(f"{first_screw + len(screw_nodes) - 2:10d}")  # the screw's tip point
    # Parts: 1 centre (SPG or FE), 2 FE ring, 3 screw.
    w("*PART")
    w("plate centre")
    w(f"         1         {2 if a.fe_erosion else 1}         1         1         1")
    w("*PART")
    w("plate ring")
    w("         2         2         1         1         1")
    w("*PART")
    w("screw")
    w("         3         3         2")
    if not a.fe_erosion:
        w("*SECTION_SOLID_SPG")
        w("$    SECID    ELFORM")
        w("         1        47")
        w("$       DX        DY        DZ   ISPLINE    KERNEL    LSCALE    SMSTEP       MSC")
        smstep = 5 if a.kernel == 1 else 15
        w(f"{field(a.dx) * 3}         0{a.kernel:10d}          {smstep:10d}{float(a.msc):10.1f}")
        w("$     IDAM        FS   STRETCH       ITB     MSFAC       ISC     BOXID     PDAMP")
        w(f"         1{field(a.fs)}{field(a.stretch)}         3       1.0         0         0"
          "    -0.001")
    w("*SECTION_SOLID")
    w("         2         1")
    w("*SECTION_SHELL")
    w("         3         2")
    w(field(a.skin) * 4)
    w("*HOURGLASS")
    w("         1         4       0.1")
    out.extend(jc1_cards())
    if a.fe_erosion:
        w("*MAT_ADD_EROSION")
        w("         1       0.0       0.0       0.0       0.4")
    w("*MAT_RIGID_TITLE")
    w("screw steel")
    w("         2   7.85E-9  210000.0       0.3")
    w("       1.0         4         4")
    # Plate nodes, layer by layer from the bottom (z = 0) to the top (z = 1.5).
    w("*NODE")
    out.extend(layered_nodes(pts, [THICKNESS * k / layers for k in range(layers + 1)]))
    out.extend(node_line(first_screw + i, x, y, z) for i, (x, y, z) in enumerate(screw_nodes))
    w("*ELEMENT_SOLID")
    out.extend(layered_hexahedra(disc, npl, layers, 1))
    out.extend(layered_hexahedra(ring, npl, layers, 2, 1 + len(disc) * layers))
    w("*ELEMENT_SHELL")
    for i, s in enumerate(screw_shells):
        w(f"{1_000_001 + i:8d}{3:8d}" + "".join(f"{first_screw + v:8d}" for v in s))
    # Clamped perimeter.
    w("*SET_NODE_LIST")
    w("         1")
    ids = [1 + v + npl * k for k in range(layers + 1) for v in perimeter]
    for i in range(0, len(ids), 8):
        w("".join(f"{v:10d}" for v in ids[i:i + 8]))
    w("*BOUNDARY_SPC_SET")
    w("         1         0         1         1         1         1         1         1")
    # Screw motion: plunge along -z (DOF 3, velocity), spin about z (DOF 7, angular velocity)
    # clockwise seen from the head (omega_z < 0), the sense that drives a right-hand thread in.
    # (Spun the other way it unscrews from the thread it forms: at h 0.3 the thrust at the end
    # was 1,350 N against 800 N; stage 1, axisymmetric forming, is the same either way.)
    w("*BOUNDARY_PRESCRIBED_MOTION_RIGID")
    w("         3         3         0         1      -1.0")
    w("         3         7         0         2      -1.0")
    for lcid, (s1, s2) in ((1, (v1, v2)), (2, (w1, w2))):
        w("*DEFINE_CURVE")
        w(f"{lcid:10d}")
        for t, v in ((0.0, 0.0), (ramp, s1), (t1, s1), (t1 + ramp, s2), (2.0 * t_end, s2)):
            w(f"{t:20.10E}{v:20.10E}")
    w("*SET_PART_LIST")
    w("         1")
    w("         1         2")
    # Soft constraint (SOFT 1): the aluminium particles against the steel screw get the larger of
    # the standard penalty and one matched to their mass and the step (keywords.md §2.15).
    w("*CONTACT_AUTOMATIC_NODES_TO_SURFACE_ID")
    w("         1screw on plate")
    w("         1         3         2         3")
    w(field(a.friction) * 2)
    w("$     SFSA      SFSB")
    w(f"{a.penalty_scale:10.1f}{a.penalty_scale:10.1f}")
    w("         1       0.1")
    w("*END")
    with open(a.out, "w") as f:
        f.write("\n".join(out) + "\n")
    print(f"{a.out}: {npl * (layers + 1)} plate nodes ({len(disc) * layers} centre, "
          f"{len(ring) * layers} ring elements), screw {len(screw_nodes)} nodes / "
          f"{len(screw_shells)} shells ({n_theta} x {n_z}), end {t_end:.4e} s")


if __name__ == "__main__":
    main()
