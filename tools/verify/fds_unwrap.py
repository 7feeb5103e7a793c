#!/usr/bin/python3
"""Has the screw formed a thread in the plate? Unrolls the hole wall of an FDS run's state
(tools/decks/fds.py) and measures the thread depth it carries, whether the wall touches the
screw, and the deepest thread the measurement can show at the run's particle spacing.

The hole wall is the plate material nearest the axis: per cell of a (θ, z) grid (10° × 0.05 mm)
the smallest radius of a plate point (particles and live FE nodes). A formed thread shows as
stripes inclined at the lead (0.7 mm per turn) in the unrolled map, and as a wall radius that
varies with the thread phase: at the screw's crests the wall is pushed out towards the major
radius (2.5 mm), between them material fills the groove down towards the minor radius (2.07 mm).
The phase of every wall cell is measured from the screw's own crests in the same state (the
screw's points beyond CREST_RADIUS; the sense of the helix is the one along which the crests
line up). The thread depth formed is the peak-to-trough height of the wall radius's first
harmonic in that phase, 2a for r = r0 + a cos(2π(phase − offset)/PITCH) fitted over all wall
cells, with offset 0 for a wall out at the crests. The same fit along the opposite-handed
helix, which no thread follows, gives the noise floor of the measurement (an unthreaded, ragged
wall gives about that much along either helix).

Two figures say what the depth means at a given particle spacing (issue 47):
- Contact: the gap between the wall and the screw, per phase from the crest: per cell of
  10° × one particle spacing, the plate point with the smallest radial gap to the screw's own
  profile (the screw's outermost points by phase, in the same state). Cells as tall as the
  spacing hold a wall particle where the wall is there; 0.05 mm cells mostly do not at h 0.3,
  so the wall radius by phase above stands 0.1-0.2 mm off the screw where the particles touch it.
- Full-thread depth: the same depth measurement on a plate that fills the screw's groove
  completely, sampled by a jittered lattice at the run's particle spacing (its plate particles'
  median nearest-neighbour distance in the first state; jitter JITTER of the spacing, as flow
  leaves the particles): the deepest thread this measurement can show at that spacing. The
  screw's own profile has a first harmonic of about 0.46 mm (the crest and root flats make it
  more than the 0.433 mm between major and minor radius); a full thread measures that with
  particles far finer than the pitch, and less where few cells hold a wall particle.

usage: fds_unwrap.py RUN_DIR OUT.png [--state N (default: last)] [--z-range -3.0 1.5]
                     [--title TEXT]
       fds_unwrap.py --check   (the fit on synthetic walls with known answers; tools/test.sh)
"""
import argparse
import sys

import numpy as np
from fds_section import SCREW_PART, load_state

PITCH = 0.7  # mm, the M5 thread of tools/decks/fds.py (its lead: single start)
MINOR, MAJOR = 2.067, 2.5  # mm
CREST_RADIUS = 2.45  # mm: screw points beyond this lie on the thread's crest
WALL_SEARCH = 3.0  # mm: plate points beyond this radius are not the hole wall
PHASE_BINS = 7
CELL_DEGREES, CELL_DZ = 10.0, 0.05  # the wall grid
CONTACT = 0.1  # mm: a wall point this close to the screw's profile touches it (the contact's
#                penetration and skin are a few hundredths)
PROFILE_BINS = 56  # phase bins of the screw's profile (0.0125 mm)
JITTER = 0.2  # of the spacing: the full-thread lattice's disorder (0.15-0.3 move the h 0.3
#               figure by ±0.03 mm, the h 0.10 one by 0.01)
FULL_SEEDS = 4


def phase(theta, z, sense):
    """Position along the pitch, 0 … PITCH, of a point at angle theta (rad) and height z, for a
    helix advancing `sense` × PITCH per turn."""
    return np.mod(z - sense * PITCH * theta / (2.0 * np.pi), PITCH)


def from_crest(theta, z, sense, crest_phase):
    """Phase measured from the screw's crest, −PITCH/2 … PITCH/2."""
    return np.mod(phase(theta, z, sense) - crest_phase + PITCH / 2, PITCH) - PITCH / 2


def mean_phasor(p):
    """Mean of exp(2πi p / PITCH): its length is 1 when all phases agree, ~0 when they are
    uniform; its angle is their circular mean."""
    return np.mean(np.exp(2j * np.pi * p / PITCH))


def harmonic(r, p):
    """(peak-to-trough 2a, offset) of the first harmonic of r over the phase p (one pitch)."""
    c = np.mean((r - r.mean()) * np.exp(-2j * np.pi * p / PITCH))
    return 4.0 * abs(c), np.mod(-np.angle(c) * PITCH / (2 * np.pi) + PITCH / 2, PITCH) - PITCH / 2


def polar(x):
    return np.hypot(x[:, 0], x[:, 1]), np.mod(np.arctan2(x[:, 1], x[:, 0]), 2.0 * np.pi), x[:, 2]


def wall_grid(r, theta, z, z_range):
    """The unrolled wall: per (z, θ) cell the smallest radius of the points in it (NaN where
    none), and the cells' centres."""
    z0, z1 = z_range
    nt, nz = int(round(360.0 / CELL_DEGREES)), int(round((z1 - z0) / CELL_DZ))
    it = np.minimum((theta / (2 * np.pi) * nt).astype(int), nt - 1)
    iz = np.minimum(((z - z0) / (z1 - z0) * nz).astype(int), nz - 1)
    wall = np.full((nz, nt), np.inf)
    np.minimum.at(wall, (iz, it), r)
    wall[np.isinf(wall)] = np.nan
    tc = (np.arange(nt) + 0.5) * 2 * np.pi / nt
    zc = z0 + (np.arange(nz) + 0.5) * (z1 - z0) / nz
    return wall, tc, zc


def thread_fit(wall, tc, zc, sense, crest_phase):
    """(depth, offset from the crest, noise floor along the opposite helix, mean wall radius per
    phase bin, the bins' centres) of an unrolled wall."""
    T, Z = np.meshgrid(tc, zc)
    have = ~np.isnan(wall)
    rel = from_crest(T[have], Z[have], sense, crest_phase)
    bins = np.minimum(((rel + PITCH / 2) / PITCH * PHASE_BINS).astype(int), PHASE_BINS - 1)
    means = np.array([wall[have][bins == b].mean() if (bins == b).any() else np.nan
                      for b in range(PHASE_BINS)])
    centres = (np.arange(PHASE_BINS) + 0.5) * PITCH / PHASE_BINS - PITCH / 2
    depth, offset = harmonic(wall[have], rel)
    control, _ = harmonic(wall[have], phase(T[have], Z[have], -sense))
    return depth, offset, control, means, centres


def screw_profile(r, theta, z, sense, crest_phase, z_window=(-1.5, 1.5)):
    """The screw's radius by phase from its crest: its outermost points per PROFILE_BINS bin
    (over z_window: at the end the threaded length sits in −1.5 … 1.5 mm). Returns a function
    of the phase from the crest."""
    keep = (z > z_window[0]) & (z < z_window[1]) & (r > 1.5)
    rel = from_crest(theta[keep], z[keep], sense, crest_phase)
    edges = np.linspace(-PITCH / 2, PITCH / 2, PROFILE_BINS + 1)
    b = np.clip(np.digitize(rel, edges) - 1, 0, PROFILE_BINS - 1)
    radius = np.array([r[keep][b == k].max() if (b == k).any() else np.nan
                       for k in range(PROFILE_BINS)])
    centres = 0.5 * (edges[:-1] + edges[1:])
    ok = ~np.isnan(radius)
    return lambda p: np.interp(p, centres[ok], radius[ok], period=PITCH)


def contact_by_phase(r, theta, z, profile, sense, crest_phase, spacing, z_range):
    """Per phase bin from the crest: (median gap, share of cells within CONTACT) of the plate
    point nearest the screw's profile in each 10° × `spacing` cell, and how many cells."""
    rel = from_crest(theta, z, sense, crest_phase)
    gap = r - profile(rel)
    nt = int(round(360.0 / CELL_DEGREES))  # the wall grid's sectors, cells `spacing` tall
    key = (np.minimum((theta / (2 * np.pi) * nt).astype(int), nt - 1)
           + nt * ((z - z_range[0]) / spacing).astype(int))
    order = np.lexsort((gap, key))
    first = np.r_[True, key[order][1:] != key[order][:-1]]
    g, p = gap[order][first], rel[order][first]
    bins = np.minimum(((p + PITCH / 2) / PITCH * PHASE_BINS).astype(int), PHASE_BINS - 1)
    return [(np.median(g[bins == b]), np.mean(g[bins == b] < CONTACT)) if (bins == b).any()
            else (np.nan, np.nan) for b in range(PHASE_BINS)], len(g)


def particle_spacing(x):
    """The median nearest-neighbour distance of points (a sample of up to 2,000 against all)."""
    rng = np.random.default_rng(0)
    sample = x[rng.choice(len(x), min(len(x), 2000), replace=False)]
    near = np.empty(len(sample))
    for i in range(0, len(sample), 200):
        d = np.linalg.norm(sample[i:i + 200, None, :] - x[None, :, :], axis=2)
        d[d == 0.0] = np.inf
        near[i:i + 200] = d.min(axis=1)
    return float(np.median(near))


def full_thread_depth(profile, spacing, z_range, seed):
    """The depth this measurement gives on a plate that fills the screw's groove (phase from the
    crest = phase, crest at 0, right-handed), sampled by a lattice of `spacing` jittered by
    JITTER of it."""
    rng = np.random.default_rng(seed)
    z0, z1 = z_range
    g = np.arange(-WALL_SEARCH - spacing, WALL_SEARCH + spacing, spacing)
    X, Y, Z = np.meshgrid(g + rng.uniform(0, spacing), g + rng.uniform(0, spacing),
                          np.arange(z0, z1, spacing) + rng.uniform(0, spacing), indexing="ij")
    x = np.c_[X.ravel(), Y.ravel(), Z.ravel()] + rng.normal(0, JITTER * spacing, (X.size, 3))
    r, theta, z = polar(x)
    keep = (r < WALL_SEARCH) & (z > z0) & (z < z1)
    keep &= r > profile(from_crest(theta, z, 1.0, 0.0))
    wall, tc, zc = wall_grid(r[keep], theta[keep], z[keep], z_range)
    return thread_fit(wall, tc, zc, 1.0, 0.0)[0]


def check():
    """The fit recovers known walls: a thread of depth 0.3 mm bulging 0.1 mm after the crest, on
    the cell grid the measurement uses, with ±0.02 mm of noise; and a ragged unthreaded wall.
    The full-thread depth of a cosine profile 0.3 mm deep is 0.3 mm with particles far finer
    than the pitch and falls as they coarsen; the contact gaps of that plate are ~0."""
    rng = np.random.default_rng(1)
    theta, z = np.meshgrid((np.arange(36) + 0.5) * np.pi / 18, np.linspace(-3, 1, 80))
    theta, z = theta.ravel(), z.ravel()
    p = phase(theta, z, +1.0)
    noise = rng.uniform(-0.02, 0.02, p.size)
    depth, offset = harmonic(2.3 + 0.15 * np.cos(2 * np.pi * (p - 0.1) / PITCH) + noise, p)
    flat, _ = harmonic(2.3 + noise, p)
    wrong, _ = harmonic(2.3 + 0.15 * np.cos(2 * np.pi * p / PITCH), phase(theta, z, -1.0))
    print(f"threaded 0.300 mm at +0.100: {depth:.4f} mm at {offset:+.4f}; unthreaded: {flat:.4f};"
          f" threaded, along the opposite helix: {wrong:.4f}")
    # Noise of ±0.02 mm over 2,880 cells moves the fitted harmonic by ~0.002 mm.
    ok = abs(depth - 0.3) < 0.005 and abs(offset - 0.1) < 0.005 and flat < 0.005 and wrong < 0.02
    cosine = lambda q: 2.35 + 0.15 * np.cos(2 * np.pi * q / PITCH)  # noqa: E731
    fine = full_thread_depth(cosine, 0.03, (-0.5, 0.5), 0)
    coarse = full_thread_depth(cosine, 0.3, (-1.5, 1.5), 0)
    # A full thread sampled at 0.03 mm: cells of 0.05 mm hold wall points within ~0.01 mm of
    # the profile (2 % of the depth); at 0.3 mm most cells hold a point of the second row.
    print(f"full 0.300 mm cosine thread sampled at 0.03 mm: {fine:.4f} mm; at 0.3 mm: {coarse:.4f}")
    ok &= abs(fine - 0.3) < 0.01 and coarse < 0.8 * fine
    # Random plates (~0.1 mm apart) filling the groove, and standing 0.15 mm off it.
    g = rng.uniform(-1.0, 1.0, (40000, 3)) * [3.0, 3.0, 0.5]
    r, th, zz = polar(g)
    shares = []
    for off in (0.0, 0.15):
        out = r > cosine(from_crest(th, zz, 1.0, 0.0)) + off
        gaps, cells = contact_by_phase(r[out], th[out], zz[out], cosine, 1.0, 0.0, 0.3,
                                       (-0.5, 0.5))
        shares.append((min(s for _, s in gaps), max(s for _, s in gaps)))
    print(f"contact, random plate filling the groove: every phase bin within {CONTACT} mm in "
          f"{shares[0][0]:.2f} of its {cells} cells or more; standing 0.15 mm off: at most "
          f"{shares[1][1]:.2f}")
    # (The top row of cells is 0.1 mm tall: a few of its 36 cells hold no point that close.)
    ok &= shares[0][0] > 0.9 and shares[1][1] == 0.0
    raise SystemExit(0 if ok else "fds_unwrap.py --check: the fit missed a known wall")


def crest_helix(r, theta, z, z_range):
    """(sense, crest phase) of the screw's points: the sense along which the crests (points
    beyond CREST_RADIUS) line up, the longest mean phasor, and their circular mean phase."""
    crest = (r > CREST_RADIUS) & (z > z_range[0]) & (z < z_range[1])
    if crest.sum() < 10:
        raise SystemExit(f"only {crest.sum()} screw crest points in z "
                         f"{z_range[0]} … {z_range[1]}")
    sense = max((+1.0, -1.0), key=lambda s: abs(mean_phasor(phase(theta[crest], z[crest], s))))
    at = np.mod(np.angle(mean_phasor(phase(theta[crest], z[crest], sense))) * PITCH / (2 * np.pi),
                PITCH)
    return sense, at


def full_thread(run):
    """(particle spacing, full-thread depths by seed) from a run's first state: its plate's
    spacing and the screw's profile over its whole length."""
    _, _, x, part, _ = load_state(run, 0)
    r, theta, z = polar(x)
    plate = (part != SCREW_PART) & (part != 0) & (r < 3.5)
    spacing = particle_spacing(x[plate])
    screw = part == SCREW_PART
    sense, crest_phase = crest_helix(r[screw], theta[screw], z[screw], (-np.inf, np.inf))
    profile = screw_profile(r[screw], theta[screw], z[screw], sense, crest_phase,
                            (-np.inf, np.inf))
    # Built right-handed: the measurement does not see the hand (a mirror image).
    return spacing, [full_thread_depth(profile, spacing, (-1.5, 1.5), seed)
                     for seed in range(FULL_SEEDS)]


def main():
    if "--check" in sys.argv[1:]:
        check()
    if sys.argv[1:2] == ["--full-thread"]:
        spacing, full = full_thread(sys.argv[2])
        print(f"{sys.argv[2]}: a full thread on the screw's profile measures {np.mean(full):.3f} mm"
              f" (± {np.std(full):.3f}) at this particle spacing ({spacing:.3f} mm)")
        return
    ap = argparse.ArgumentParser()
    ap.add_argument("run")
    ap.add_argument("png")
    ap.add_argument("--state", type=int, default=-1)
    ap.add_argument("--z-range", type=float, nargs=2, default=(-3.0, 1.5))
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    time, name, x, part, _ = load_state(a.run, a.state)
    r, theta, z = polar(x)
    z0, z1 = a.z_range

    screw = part == SCREW_PART
    sense, crest_phase = crest_helix(r[screw], theta[screw], z[screw], a.z_range)

    plate = (part != SCREW_PART) & (part != 0) & (r < WALL_SEARCH) & (z > z0) & (z < z1)
    wall, tc, zc = wall_grid(r[plate], theta[plate], z[plate], a.z_range)
    depth, offset, control, means, centres = thread_fit(wall, tc, zc, sense, crest_phase)
    have = ~np.isnan(wall)
    print(f"state {name} at t = {time:.4e} s: {have.sum()} wall cells of {wall.shape[1]} x "
          f"{wall.shape[0]} in z {z0} … {z1} mm; screw crest helix sense {sense:+.0f}")
    print("  mean wall radius by phase from the screw's crest (mm): " +
          "  ".join(f"{c:+.2f}: {m:.3f}" for c, m in zip(centres, means)))

    spacing, full = full_thread(a.run)
    profile = screw_profile(r[screw], theta[screw], z[screw], sense, crest_phase)
    gaps, cells = contact_by_phase(r[plate], theta[plate], z[plate], profile, sense, crest_phase,
                                   spacing, a.z_range)
    print(f"  gap to the screw's profile by phase (median over {cells} cells of 10° x "
          f"{spacing:.3f} mm, share within {CONTACT} mm): " +
          "  ".join(f"{c:+.2f}: {g:.3f} ({s:.2f})" for c, (g, s) in zip(centres, gaps)))
    print(f"  a full thread on the screw's profile measures {np.mean(full):.3f} mm "
          f"(± {np.std(full):.3f}) at this particle spacing ({spacing:.3f} mm)")
    print(f"  thread depth formed: {depth:.3f} mm, wall out at {offset:+.3f} mm from the crest "
          f"(a full M5 thread: {MAJOR - MINOR:.3f} mm at 0); along the opposite-handed helix "
          f"(noise floor): {control:.3f} mm")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.8),
                                  gridspec_kw={"width_ratios": [3, 1.2]})
    m = ax.pcolormesh(np.degrees(tc), zc, wall, cmap="viridis", vmin=MINOR - 0.1,
                      vmax=MAJOR + 0.2, shading="nearest")
    fig.colorbar(m, ax=ax, label="hole wall radius, mm")
    crest = screw & (r > CREST_RADIUS)
    ax.scatter(np.degrees(theta[crest]), z[crest], s=0.5, c="r", alpha=0.6,
               label="screw thread crest")
    ax.set_xlabel("angle about the screw axis, degrees")
    ax.set_ylabel("z, mm")
    ax.set_xlim(0, 360)
    ax.set_ylim(z0, z1)
    ax.legend(loc="upper right", fontsize=8)
    ax.set_title(a.title or f"t = {time * 1e3:.3f} ms", fontsize=10)
    ax2.plot(centres, means, "o-", label="wall (mean per 10° x 0.05 mm)")
    ax2.plot(centres, profile(centres) + np.array([g for g, _ in gaps]), "s-", ms=4,
             label=f"wall (median per 10° x {spacing:.2f} mm)")
    fine_phase = np.linspace(-PITCH / 2, PITCH / 2, 141)
    ax2.plot(fine_phase, profile(fine_phase), "-", color="0.4", lw=1, label="screw")
    ax2.axhline(MINOR, color="0.5", ls="--", lw=0.8)
    ax2.axhline(MAJOR, color="0.5", ls="--", lw=0.8)
    ax2.set_xlabel("phase from the screw's crest, mm")
    ax2.set_ylabel("mean wall radius, mm")
    ax2.legend(fontsize=8)
    ax2.set_title(f"thread depth formed {depth:.2f} mm (full at this\nspacing {np.mean(full):.2f};"
                  f" opposite helix {control:.2f})", fontsize=10)
    ax2.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)
    print(f"wrote {a.png}")


if __name__ == "__main__":
    main()
