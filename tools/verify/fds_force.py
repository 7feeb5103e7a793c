#!/usr/bin/python3
"""Force on the flow-drill screw against plunge distance (MC-SPG paper Fig. 11) from an FDS run
(decks/fds/, tools/decks/fds.py): the axial contact force on the screw from rcforc.csv (master
side, +z = the plate pushing the screw back: compressive thrust), the torque about the screw
axis (the master moment about z; the axis is x = y = 0), and the plunge from the screw tip's
z displacement in nodout.csv. Writes force_vs_plunge.csv (one header row) and, with --png, the
plot; prints the peak thrust and where it occurs, the break-through (the thrust falling below
half its peak after it) and the first sign reversal (tension) after the peak.

usage: fds_force.py RUN_DIR [--png out.png] [--label TEXT] [RUN_DIR2 | force_vs_plunge.csv ...]
"""
import argparse
import csv
import os

import numpy as np

from columns import read_columns, write_columns


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return rows


def history(run):
    rc = [r for r in read_csv(os.path.join(run, "rcforc.csv")) if r["side"] == "master"]
    t = np.array([float(r["time"]) for r in rc])
    fz = np.array([float(r["z_force"]) for r in rc])
    mz = np.array([float(r["z_moment"]) for r in rc])
    nod = read_csv(os.path.join(run, "nodout.csv"))
    tn = np.array([float(r["time"]) for r in nod])
    zd = np.array([float(r["z_disp"]) for r in nod])
    plunge = np.interp(t, tn, -zd)
    return t, plunge, fz, mz


def write_force_csv(run):
    """RUN/force_vs_plunge.csv (time, plunge, axial_force, torque); returns the columns."""
    t, plunge, fz, mz = history(run)
    write_columns(os.path.join(run, "force_vs_plunge.csv"),
                  ("time", "plunge", "axial_force", "torque"), (t, plunge, fz, mz))
    return t, plunge, fz, mz


def summary(plunge, fz):
    k = int(np.argmax(fz))
    out = {"peak_thrust": fz[k], "plunge_at_peak": plunge[k]}
    after = np.nonzero(fz[k:] < 0.5 * fz[k])[0]
    out["break_through"] = plunge[k + after[0]] if after.size else float("nan")
    reversal = np.nonzero(fz[k:] < 0.0)[0]
    out["sign_reversal"] = plunge[k + reversal[0]] if reversal.size else float("nan")
    out["largest_tension"] = -fz.min() if fz.min() < 0.0 else 0.0
    return out


def read_force_csv(path):
    """(plunge, axial_force, torque) of a force_vs_plunge.csv (write_force_csv's layout)."""
    _, plunge, fz, mz = read_columns(path)
    return plunge, fz, mz


def plot_curves(curves, png):
    """Axial force and torque against plunge of [(label, plunge, fz, mz)]."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
    for label, plunge, fz, mz in curves:
        ax.plot(plunge, fz, label=label)
        bx.plot(plunge, mz, label=label)
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_ylabel("axial force on the screw, N (+ thrust)")
    bx.set_ylabel("torque about the axis, N mm")
    bx.set_xlabel("plunge distance, mm")
    ax.legend()
    ax.grid(alpha=0.3)
    bx.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--png")
    ap.add_argument("--label", action="append")
    a = ap.parse_args()
    curves = []
    for i, run in enumerate(a.runs):
        if run.endswith(".csv"):  # a force_vs_plunge.csv already written (decks/fds/reference_*)
            plunge, fz, mz = read_force_csv(run)
        else:
            t, plunge, fz, mz = write_force_csv(run)
        s = summary(plunge, fz)
        label = a.label[i] if a.label and i < len(a.label) else run
        def at(x):
            return "never" if np.isnan(x) else f"from {x:.3f} mm"
        print(f"{label}: peak thrust {s['peak_thrust']:.1f} N at plunge {s['plunge_at_peak']:.3f} mm; "
              f"thrust below half the peak {at(s['break_through'])}; tension (force < 0) "
              f"{at(s['sign_reversal'])}, largest {s['largest_tension']:.1f} N; "
              f"largest torque {np.abs(mz).max():.2f} N mm")
        curves.append((label, plunge, fz, mz))
    if a.png:
        plot_curves(curves, a.png)
        print(f"wrote {a.png}")

if __name__ == "__main__":
    main()
