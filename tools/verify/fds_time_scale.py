#!/usr/bin/python3
"""Time scale and mass scaling as knobs of the FDS scene (issue 47): a time-scaled run's axial
force and torque against the run at the paper's own speeds, per stage of the schedule, and the
study's speed-against-error view.

tools/study.py calls these for its "MC-SPG recipe" runs ("h H scale S", and "h H scale S
FACTOR" with one of the factors of the thread changed): the reference of a time-scale run is the
slowest finished run at the same h (scale 1, the paper's speeds, once it has run); that of a
factor run is the run at the same h and scale with the recipe's factors.

  stage_figures(mcdyna, mine, reference, stage1_end)
      per stage and column: RMS |A - B| over the reference's peak over the whole run, and the
      correlation, from `mcdyna compare --x plunge --from/--to` on the force_vs_plunge.csv files
  plot(rows, png)      force error per stage against core time, thread depth against time scale
  table(rows)          the markdown table for manual/verification.md

usage: fds_time_scale.py MCDYNA MINE_force.csv REFERENCE_force.csv STAGE1_END_S
       fds_time_scale.py MCDYNA --check   (the stage figures on curves with a known answer)
"""
import math
import os
import re
import subprocess
import sys
import tempfile

COLUMNS = ("axial_force", "torque")
STAGES = ("stage1", "stage2")


def parse_resolution(resolution):
    """("0.3", 20.0, "") from "h 0.3 scale 20", ("0.3", 20.0, "FS 0.8") from "h 0.3 scale 20
    FS 0.8", or None for a run that is not a time-scale run."""
    m = re.fullmatch(r"h ([0-9.]+) scale ([0-9.]+)( .+)?", resolution)
    return (m.group(1), float(m.group(2)), (m.group(3) or "").strip()) if m else None


def compare_rows(mcdyna, mine, reference, lo=None, hi=None, columns=COLUMNS):
    """{column: (RMS |A-B|, peak |B|, corr, max |A-B|)} of `mcdyna compare` aligned on plunge in
    [lo, hi]."""
    cmd = [mcdyna, "compare", mine, reference, "--x", "plunge"]
    for c in columns:
        cmd += ["-c", c]
    if lo is not None:
        cmd += ["--from", repr(lo)]
    if hi is not None:
        cmd += ["--to", repr(hi)]
    done = subprocess.run(cmd, capture_output=True, text=True, check=True)
    out = {}
    for line in done.stdout.splitlines():
        f = line.split()
        if f and f[0] in columns:
            # column max|A-B| at RMS max/peakB peakA at peakB at corr
            out[f[0]] = (float(f[3]), abs(float(f[7])), float(f[9]), float(f[1]))
    if set(out) != set(columns):
        raise RuntimeError(f"mcdyna compare gave no {columns} rows:\n{done.stdout}")
    return out


def plunge_at(force_csv, t):
    """The plunge (mm) at time t of a force_vs_plunge.csv (time,plunge,axial_force,torque)."""
    prev = None
    with open(force_csv) as f:
        next(f)
        for line in f:
            time, plunge = (float(v) for v in line.split(",")[:2])
            if time >= t:
                if prev is None or time == prev[0]:
                    return plunge
                w = (t - prev[0]) / (time - prev[0])
                return prev[1] + w * (plunge - prev[1])
            prev = (time, plunge)
    raise ValueError(f"{force_csv} ends before t = {t}")


def stage_figures(mcdyna, mine, reference, stage1_end):
    """{stage1_axial_rms, stage1_axial_corr, ..., stage2_torque_corr, stage_boundary}: each
    column's RMS difference over the reference's peak over the whole run (one yardstick for both
    stages: stage 2's own peak is a third of stage 1's), and its correlation in the stage."""
    boundary = plunge_at(reference, stage1_end)
    whole = compare_rows(mcdyna, mine, reference)
    out = {"stage_boundary": boundary}
    for stage, (lo, hi) in zip(STAGES, ((None, boundary), (boundary, None))):
        part = compare_rows(mcdyna, mine, reference, lo, hi)
        for c in COLUMNS:
            key = f"{stage}_{c.split('_')[0]}"
            rms, _, corr, _ = part[c]
            out[key + "_rms"] = rms / whole[c][1]
            out[key + "_corr"] = corr
    for c in COLUMNS:
        out[f"whole_{c.split('_')[0]}_rms"] = whole[c][0] / whole[c][1]
    return out


def plot(rows, png):
    """Left: each stage's force and torque error against the run's core time, one line per h
    (the speed-against-error view); right: thread depth against time scale with its noise."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    runs = [r for r in rows if "stage1_axial_rms" in r and not r.get("factor")]
    if not any(r["stage1_axial_rms"] > 0 for r in runs):
        return  # the reference alone: nothing to draw on the log axes
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.4))
    for h in sorted({r["h"] for r in runs}, reverse=True):
        mine = sorted((r for r in runs if r["h"] == h and r["stage1_axial_rms"] > 0),
                      key=lambda r: r["core_s"])
        for key, style, label in (("stage1_axial", "o-", "stage 1 force"),
                                  ("stage2_axial", "s-", "stage 2 force"),
                                  ("stage1_torque", "o--", "stage 1 torque"),
                                  ("stage2_torque", "s--", "stage 2 torque")):
            ax.plot([r["core_s"] for r in mine], [100 * r[key + "_rms"] for r in mine], style,
                    label=f"h {h}: {label}")
        for r in mine:
            dt2ms = f", DT2MS {r['dt2ms']:g}" if r.get("dt2ms") else ", no DT2MS"
            ax.annotate(f"×{r['time_scale']:g}{dt2ms}", (r["core_s"], 100 * r["stage1_axial_rms"]),
                        fontsize=7, textcoords="offset points", xytext=(3, 4))
        depth = sorted((r for r in runs if r["h"] == h and "thread_depth" in r),
                       key=lambda r: r["time_scale"])
        bx.errorbar([r["time_scale"] for r in depth], [r["thread_depth"] for r in depth],
                    yerr=[r.get("thread_noise_floor", 0) for r in depth], fmt="o-", capsize=3,
                    label=f"h {h}")
    ax.axhline(5.0, color="k", lw=0.8, ls=":", label="5 % of peak")
    for axis, x, y, title in ((ax, "core time (wall × threads), s",
                               "RMS difference from the paper-speed run, % of its peak",
                               "FDS: speed against error (time scale as the knob)"),
                              (bx, "time scale (1: the paper's speeds)",
                               "thread depth formed, mm (bar: noise floor)",
                               "thread depth (tools/verify/fds_unwrap.py)")):
        axis.set_xscale("log")
        axis.set_xlabel(x)
        axis.set_ylabel(y)
        axis.set_title(title, fontsize=10)
        axis.grid(alpha=0.3, which="both")
        axis.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def table(rows):
    """Markdown lines: one row per time-scale run, the reference's own row marked."""
    runs = sorted((r for r in rows if "stage1_axial_rms" in r and not r.get("factor")),
                  key=lambda r: (-float(r["h"]), -r["time_scale"]))
    if not runs:
        return []
    lines = ["| h | time scale | DT2MS s | force RMS / peak, stage 1 / 2 (corr) | torque RMS / "
             "peak, stage 1 / 2 (corr) | thread depth mm (noise) | plate KE/IE: after contact / "
             "stage 2 | added mass t | cycles | core s |",
             "|---" * 10 + "|"]
    for r in runs:
        if r["stage1_axial_rms"] == 0.0 and r["stage2_axial_corr"] == 1.0:
            force = torque = "the reference"
        else:
            force = (f"{100 * r['stage1_axial_rms']:.1f} / {100 * r['stage2_axial_rms']:.1f} % "
                     f"({r['stage1_axial_corr']:.3f} / {r['stage2_axial_corr']:.3f})")
            torque = (f"{100 * r['stage1_torque_rms']:.1f} / {100 * r['stage2_torque_rms']:.1f} % "
                      f"({r['stage1_torque_corr']:.3f} / {r['stage2_torque_corr']:.3f})")
        depth = (f"{r['thread_depth']:.3f} ({r.get('thread_noise_floor', 0):.3f})"
                 if "thread_depth" in r else "-")
        ke = f"{r.get('kinetic_over_internal') or 0:.3f} / {r.get('kinetic_over_internal_stage2') or 0:.1e}"
        lines.append(f"| {r['h']} | {r['time_scale']:g} | {r.get('dt2ms', 0):g} | {force} | "
                     f"{torque} | {depth} | {ke} | {r.get('added_mass', 0):.2g} | "
                     f"{r['cycles']:,} | {r['core_s']:,.0f} |")
    return lines


def factor_table(rows):
    """Markdown lines: one row per factor run against its recipe run (same h and time scale)."""
    runs = [r for r in rows if r.get("factor") and "stage1_axial_rms" in r]
    if not runs:
        return []
    lines = ["| h | time scale | factor changed | force RMS / peak against the recipe, stage 1 / "
             "2 (corr) | torque, stage 1 / 2 | thread depth mm (noise) | recipe's depth | "
             "peak thrust N | cycles | core s |", "|---" * 10 + "|"]
    for r in sorted(runs, key=lambda r: (-float(r["h"]), r["factor"])):
        base = next((b for b in rows if b.get("h") == r["h"] and not b.get("factor")
                     and b.get("time_scale") == r["time_scale"]), {})
        depth = (f"{r['thread_depth']:.3f} ({r.get('thread_noise_floor', 0):.3f})"
                 if "thread_depth" in r else "-")
        lines.append(
            f"| {r['h']} | {r['time_scale']:g} | {r['factor']} | "
            f"{100 * r['stage1_axial_rms']:.1f} / {100 * r['stage2_axial_rms']:.1f} % "
            f"({r['stage1_axial_corr']:.3f} / {r['stage2_axial_corr']:.3f}) | "
            f"{100 * r['stage1_torque_rms']:.1f} / {100 * r['stage2_torque_rms']:.1f} % | {depth} | "
            f"{base.get('thread_depth', float('nan')):.3f} | {r.get('peak_thrust', 0):,.0f} | "
            f"{r['cycles']:,} | {r['core_s']:,.0f} |")
    return lines


def check(mcdyna):
    """A reference whose force rises to 1000 N in stage 1 (plunge 0-4.5 mm, t 0-4.5 s) and
    falls to 300 N in stage 2 (to 9 mm, 9 s); the other run is the same in stage 1 and 30 N higher
    in stage 2, with the torque 10 % higher throughout. Want: stage 1 force 0, stage 2 force 30 /
    1000, torque RMS 10 % of each stage's RMS torque over the peak torque."""
    n = 901
    plunge = [9.0 * k / (n - 1) for k in range(n)]
    force = [1000.0 * math.sin(math.pi / 2 * min(x / 4.5, 1.0)) if x <= 4.5
             else 1000.0 - 700.0 * (x - 4.5) / 4.5 for x in plunge]
    torque = [100.0 + 10.0 * x for x in plunge]
    with tempfile.TemporaryDirectory() as d:
        paths = []
        for name, df, tf in (("ref", 0.0, 1.0), ("mine", 30.0, 1.1)):
            path = os.path.join(d, name + ".csv")
            with open(path, "w") as f:
                f.write("time,plunge,axial_force,torque\n")
                for x, fz, mz in zip(plunge, force, torque):
                    f.write(f"{x},{x},{fz + (df if x > 4.5 else 0.0)},{tf * mz}\n")
            paths.append(path)
        got = stage_figures(mcdyna, paths[1], paths[0], 4.5)
    # Torque 100 + 10 x: the RMS of 0.1 (100 + 10 x) over stage 1 (x 0-4.5) and stage 2 (4.5-9).
    rms = [math.sqrt(sum((10 + x) ** 2 for x in plunge if lo <= x <= hi)
                     / sum(1 for x in plunge if lo <= x <= hi)) / 190.0 for lo, hi in
           ((0, 4.5), (4.5, 9))]
    want = {"stage_boundary": 4.5, "stage1_axial_rms": 0.0, "stage2_axial_rms": 0.03,
            "stage1_torque_rms": rms[0], "stage2_torque_rms": rms[1]}
    ok = True
    for k, v in want.items():
        # Resampling onto the denser file's points moves a figure by a point's share at most.
        good = abs(got[k] - v) <= 2e-3 * max(abs(v), 1.0)
        ok &= good
        print(f"  {k:<20} {got[k]:.5f} (want {v:.5f}) {'ok' if good else 'WRONG'}")
    return ok


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[2] == "--check":
        sys.exit(0 if check(sys.argv[1]) else 1)
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    for k, v in stage_figures(sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])).items():
        print(f"{k:<22} {v:.4f}")
