#!/usr/bin/python3
"""Speed against error for the verified scenes (issue 6): runs each scene at several resolutions
and methods with build/mcdyna, measures every run's error against its reference and its cost,
and writes a table and plots.

usage: tools/study.py [--quick] [--out results/study] [--threads N] [--only FAMILY ...]
                      [--cases NAME ...] [--reuse] [--records DIR] [--no-run]

Families, methods and references (benchmarks.md, paper §4):
  elastic_wave  FE hex, MC-SPG, plain DNI (--spg-stabilization none), SPG ITB 1
                (--spg-stabilization spg); h 0.2 / 0.1 (quick) + 0.05
                error: relative L2 of the free-end displacement against the analytic solution
                (also the mid-length stress error)
  taylor_bar    FE hex, MC-SPG with MSC 1; coarse (quick) + medium, fine; MC-SPG MSC 0 coarse;
                SPG ITB 1 (MSC 0, its own stabilisation) coarse and medium
                error: final length against Wilkins & Guinan's 16.51 mm (also the footprint
                diameter against their 16.7 mm, and the length against the FE codes' 15.95 mm)
  fds           MC-SPG and FE with erosion; h 0.3 (quick) + 0.15; MC-SPG h 0.125 and 0.10
                error: RMS difference of the axial force on the screw against the reference run,
                aligned on plunge, over the reference's peak (`mcdyna compare`); the reference
                is the finest MC-SPG run of the study, or decks/fds/reference_force_h0.15.csv
                when the study has no finer run than h 0.3 (decks/fds/fds_h0.15.k run through the
                whole schedule, stage 2 of 4.4 mm, plunge 0 to 8.95 mm, 2026-11-27;
                manual/verification.md)
                The paper's comparison (Fig. 11, Table 2): SPG ITB 1 beside MC-SPG with the same
                (eigenvalue) step estimate on the same deck, at h 0.3 (the shipped deck),
                h 0.2 (8 layers, no mass scaling; ITB 1 takes about 3 hours on this 2-core
                machine) and h 0.15 with the fast recipe (DT2MS 1e-8 s, OSU 1); the table then
                gives the cost ratio SPG : MC-SPG of each pair (paper: 2.39 at h 0.125)
                Time scale as a knob (issue 47): "MC-SPG recipe" (DT2MS 1e-8 s, OSU 1, eigen
                step) at h 0.3 through the whole schedule at 20, 10, 5, 2 and 1 times the
                paper's speeds ("h 0.3 scale S"), at h 0.2 at 20 and 5; what sets the thread:
                one fds.py setting changed off the recipe at h 0.3 and time scale 20 ("h 0.3
                scale 20 FACTOR", THREAD_FACTORS). Every FDS record's facts name its time_scale,
                dt2ms, added_mass (and by part), the plate's kinetic_over_internal after first
                contact (tools/verify/fds_facts.py), the thread_depth of its last state and
                what a full thread measures at its particle spacing, thread_full_depth
                (tools/verify/fds_unwrap.py, whose unrolled wall is NAME_wall.png); records
                older than these facts get them from tools/verify/fds_backfill.py

Writes OUT/study.csv (one row per run, one header row), the same as a Markdown table
(OUT/study.md, for manual/verification.md), OUT/error_vs_time.png (log-log, one
line per method, one panel per family) and the history plots OUT/elastic_wave.png,
OUT/taylor_bar.png, OUT/fds_force.png. Every finished run leaves a record in RECORDS (default
OUT/records): NAME.json with its facts and error figures, and the histories the plots draw, a few
hundred kB in all, so the full study's records are committed (manual/data/study_full) and a
study is assembled from runs made over several sessions or machines. --reuse keeps runs whose
d3hsp reports a normal termination or, when the run directory is gone, whose record exists, and
continues stopped runs from their running restart file (OUT/runs/NAME/runrsf); a record, once
written, stands for its run under --reuse. --no-run starts no run and makes the table and plots
from what has finished, naming the runs still missing.
The quick study takes about 8 minutes on 2 cores; the full one several hours.
"""
import argparse
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass, field

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools", "verify"))

import elastic_wave  # noqa: E402  (tools/verify)
from columns import read_columns, write_columns  # noqa: E402
import fds_facts  # noqa: E402
import fds_force  # noqa: E402
import fds_time_scale  # noqa: E402
import taylor_bar  # noqa: E402

# MCDYNA=path runs another binary (a copy, so a long study survives rebuilds of build/).
MCDYNA = os.environ.get("MCDYNA", os.path.join(ROOT, "build", "mcdyna"))
FDS_REFERENCE = os.path.join(ROOT, "decks", "fds", "reference_force_h0.15.csv")
TAYLOR_EXPERIMENT_LENGTH, TAYLOR_EXPERIMENT_DIAMETER, TAYLOR_FE_LENGTH = 16.51, 16.7, 15.95
QUICK_STAGE2 = 2.1  # mm of stage 2 in the quick study's FDS runs
ITB1 = ["--spg-stabilization", "spg"]  # the original SPG stabilisation (eigenvalue step)
TIME_SCALES = ("20", "10", "5", "2", "1")  # issue 47: the FDS schedule's speeds x these
# Issue 47: what sets the formed thread, one factor off the recipe at a time (tools/decks/fds.py's
# flags; a later flag overrides the recipe's --mass-scaling).
THREAD_FACTORS = (("FS 0.8", ["--fs", "0.8"]), ("STRETCH 1.3", ["--stretch", "1.3"]),
                  ("friction 0.1", ["--friction", "0.1"]), ("penalty x30", ["--penalty-scale", "30"]),
                  ("skin 0.1", ["--skin", "0.1"]), ("KERNEL 1", ["--kernel", "1"]),
                  ("DX 1.2", ["--dx", "1.2"]), ("DX 1.6", ["--dx", "1.6"]),
                  ("DT2MS 3e-8", ["--mass-scaling", "3e-8"]),
                  ("feed 0.7", ["--feed", "0.7"]), ("feed 0.5", ["--feed", "0.5"]))
# What an FDS run's speeds and added mass did (tools/verify/fds_facts.py) and the thread it formed.
FDS_KNOBS = ("time_scale", "dt2ms", "added_mass", "added_mass_largest", "kinetic_over_internal",
             "kinetic_over_internal_stage2", "thread_depth", "thread_noise_floor",
             "thread_full_depth", "stage1_end")


@dataclass
class Case:
    family: str
    method: str
    resolution: str
    deck: str                      # path relative to ROOT; "{out}" stands for --out
    quick: bool
    flags: list = field(default_factory=list)
    generate: list = field(default_factory=list)  # generator argv writing `deck`

    @property
    def name(self):
        return f"{self.family}_{self.method}_{self.resolution}".replace(" ", "_").replace("+", "")


def cases():
    out = []
    for h, quick in (("0.2", True), ("0.1", True), ("0.05", False)):
        out.append(Case("elastic_wave", "FE hex", f"h {h}", f"decks/elastic_wave/rod_h{h}.k", quick))
        out.append(Case("elastic_wave", "MC-SPG", f"h {h}", f"decks/elastic_wave/rod_spg_h{h}.k",
                        quick))
        out.append(Case("elastic_wave", "plain DNI", f"h {h}",
                        f"decks/elastic_wave/rod_spg_h{h}.k", quick,
                        flags=["--spg-stabilization", "none"]))
        # ITB 1 at h 0.1 costs 70 s of one core (3.3 x MC-SPG): the full study only.
        out.append(Case("elastic_wave", "SPG ITB 1", f"h {h}",
                        f"decks/elastic_wave/rod_spg_h{h}.k", h == "0.2", flags=ITB1))
    # MC-SPG Taylor bars: MSC 1 (low-energy-mode control) at every resolution; the paper's MSC 0
    # alone at coarse only, in the full study: the medium bar with MSC 0 pairs its axis layers
    # and its step falls to 4e-10 s at 38 us (manual/verification.md).
    for r, quick in (("coarse", True), ("medium", False), ("fine", False)):
        out.append(Case("taylor_bar", "FE hex", r, f"decks/taylor_bar/taylor_{r}.k", quick))
        out.append(Case("taylor_bar", "MC-SPG MSC 1", r, f"decks/taylor_bar/taylor_spg_{r}.k",
                        quick, flags=["--spg-mode-control", "0.5"]))
    out.append(Case("taylor_bar", "MC-SPG MSC 0", "coarse", "decks/taylor_bar/taylor_spg_coarse.k",
                    False))
    for r in ("coarse", "medium"):
        out.append(Case("taylor_bar", "SPG ITB 1", r, f"decks/taylor_bar/taylor_spg_{r}.k", False,
                        flags=ITB1))
    # FDS: h 0.15 carries DT2MS 2e-9 s, h 0.125 and 0.10 the fast recipe (DT2MS 1e-8 s, OSU 1,
    # the eigen step; decks/generate.sh); the finest finished one is the full study's reference.
    # The quick study's FDS runs stop 2.1 mm into stage 2 (plunge 6.65 mm, a quarter of the cost
    # of the whole 4.4 mm; peak, break-through and the start of the thread forming) and are
    # compared with the reference over that range.
    for h in ("0.3", "0.15"):
        out.append(Case("fds", "MC-SPG", f"h {h}", f"decks/fds/fds_h{h}.k", False))
    for h in ("0.125", "0.1"):
        out.append(Case("fds", "MC-SPG", f"h {h}", f"decks/fds/fds_h{h}.k", False,
                        flags=["--spg-step", "eigen"]))
    for h in ("0.3", "0.15"):
        out.append(Case("fds", "FE + erosion", f"h {h}", f"{{out}}/decks/fds_fe_h{h}.k", False,
                        generate=["tools/decks/fds.py", h, "{deck}", "--time-scale", "20",
                                  "--fe-erosion"]))
    # The paper's pairs: ITB 1 and MC-SPG, both with the eigenvalue step, on the same deck.
    fast = ["--time-scale", "20", "--mass-scaling", "1e-8", "--osu", "1"]
    for method, flags in (("SPG ITB 1", ITB1), ("MC-SPG eigen", ["--spg-step", "eigen"])):
        out.append(Case("fds", method, "h 0.3", "decks/fds/fds_h0.3.k", False, flags=flags))
        out.append(Case("fds", method, "h 0.2", "{out}/decks/fds_h0.2.k", False, flags=flags,
                        generate=["tools/decks/fds.py", "0.2", "{deck}", "--time-scale", "20"]))
        out.append(Case("fds", method, "h 0.15 DT2MS 1e-8", "{out}/decks/fds_h0.15_fast.k", False,
                        flags=flags, generate=["tools/decks/fds.py", "0.15", "{deck}"] + fast))
    # Issue 47: time scale as a knob. Today's recipe (DT2MS 1e-8 s, OSU 1, eigen step) at h 0.3
    # through the whole schedule, from 20 times the paper's speeds down to the paper's own.
    # At h 0.2 the scale the h 0.3 runs point to (20: force and thread) and one four times slower
    # (5: the torque too), where DT2MS 1e-8 s starts to add mass.
    for h, scales in (("0.3", TIME_SCALES), ("0.2", ("20", "5"))):
        for scale in scales:
            out.append(Case("fds", "MC-SPG recipe", f"h {h} scale {scale}",
                            f"{{out}}/decks/fds_h{h}_scale{scale}.k", False,
                            flags=["--spg-step", "eigen"],
                            generate=["tools/decks/fds.py", h, "{deck}", "--time-scale", scale,
                                      "--mass-scaling", "1e-8", "--osu", "1"]))
    # What sets the thread: one factor at a time off the recipe at h 0.3, time scale 20.
    for label, flags in THREAD_FACTORS:
        out.append(Case("fds", "MC-SPG recipe", f"h 0.3 scale 20 {label}",
                        f"{{out}}/decks/fds_h0.3_scale20_{label.replace(' ', '_')}.k", False,
                        flags=["--spg-step", "eigen"],
                        generate=["tools/decks/fds.py", "0.3", "{deck}", "--time-scale", "20",
                                  "--mass-scaling", "1e-8", "--osu", "1"] + flags))
    quick_stage2 = ["--time-scale", "20", "--stage2", str(QUICK_STAGE2)]
    out.append(Case("fds", "MC-SPG", "h 0.3", "{out}/decks/fds_h0.3_quick.k", True,
                    generate=["tools/decks/fds.py", "0.3", "{deck}"] + quick_stage2))
    out.append(Case("fds", "FE + erosion", "h 0.3", "{out}/decks/fds_fe_h0.3_quick.k", True,
                    generate=["tools/decks/fds.py", "0.3", "{deck}", "--fe-erosion"] +
                    quick_stage2))
    return out


def run_facts(run_dir):
    """Cycles, wall time, particles, elements and rates from d3hsp; None if it did not finish."""
    path = os.path.join(run_dir, "d3hsp")
    if not os.path.exists(path):
        return None
    text = open(path).read()
    if "normal termination" not in text:
        return None

    def number(pattern, cast=float, default=0):
        # The last match: a run continued from a restart dump appends to d3hsp, and its summary
        # (with the wall time of all the run's parts) comes last.
        m = re.findall(pattern, text, re.M)
        return cast(m[-1]) if m else default

    # FE hexahedra: the parts whose section is a solid element (an SPG part's hexahedra become
    # particles).
    solids = sum(int(m.group(1)) for m in
                 re.finditer(r"^\s+\d+\s+(\d+)\s+\d+ solid ELFORM", text, re.M))
    wall, threads = number(r"^  total\s+([0-9.]+) s"), number(r"^threads: (\d+)", int)
    return dict(
        cycles=number(r"normal termination .* cycle (\d+)", int),
        wall=wall,
        threads=threads,
        # A run continued from a restart dump may have run its parts on other thread counts:
        # d3hsp then gives its core time (wall x threads over the parts).
        core=number(r"^  core time\s+([0-9.]+) s", default=wall * threads),
        particles=number(r"^  SPG particles\s+(\d+)", int),
        solids=solids,
    )


def run_case(case, out_dir, threads, reuse):
    run_dir = os.path.join(out_dir, "runs", case.name)
    deck = case.deck.format(out=out_dir)
    if case.generate:
        os.makedirs(os.path.dirname(deck), exist_ok=True)
        argv = [a.format(deck=deck) for a in case.generate]
        subprocess.run(["/usr/bin/python3", os.path.join(ROOT, argv[0])] + argv[1:], check=True,
                       cwd=ROOT, stdout=subprocess.DEVNULL)
    elif not os.path.exists(os.path.join(ROOT, deck)):
        sys.exit(f"study: {deck} is missing: decks/generate.sh writes the large decks")
    cmd = [MCDYNA, "run", os.path.join(ROOT, deck), "--out", run_dir, "-q"] + case.flags
    if threads:
        cmd += ["--threads", str(threads)]
    # A run that was stopped (signal, or killed after a *DATABASE_BINARY_RUNRSF dump) continues
    # from its running restart file, bit for bit.
    resume = os.path.join(run_dir, "runrsf")
    if reuse and os.path.exists(resume):
        cmd += ["--restart", resume]
    start = time.time()
    print(f"  {case.family:<13} {case.method:<13} {case.resolution:<7}"
          + (" (continued)" if "--restart" in cmd else ""), end="", flush=True)
    done = subprocess.run(cmd, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                          text=True)
    print(f" {time.time() - start:8.1f} s" + ("" if done.returncode == 0 else
                                               f"  exit {done.returncode}"), flush=True)
    if done.returncode != 0:
        print(done.stderr.strip()[-2000:], file=sys.stderr)


def record_base(records, case):
    return os.path.join(records, case.name)


def write_record(records, case, run_dir, facts):
    """Keeps what the table and the plots need of a finished run, small enough to commit:
    RECORDS/NAME.json (the run's facts and, for the analytic and experimental references, its
    error figures) and the histories the plots draw (NAME_u.csv and NAME_sigma.csv,
    NAME_outline.csv or NAME_force.csv). A study assembled over several sessions or machines
    takes finished runs from their records (--reuse) when their run directories are gone."""
    os.makedirs(records, exist_ok=True)
    base = record_base(records, case)
    rec = dict(family=case.family, method=case.method, resolution=case.resolution,
               deck=case.deck, flags=case.flags, facts=facts,
               recorded=time.strftime("%Y-%m-%d"), checkout=checkout_commit(),
               solver=os.path.relpath(MCDYNA, ROOT))
    if case.family == "elastic_wave":
        r = elastic_wave.analyse(run_dir)
        rec["figures"] = {"u_l2": r["l2"], "sigma_error": r["stress"],
                          "sigma_overshoot": r["overshoot"]}
        write_columns(base + "_u.csv", ("time", "u"), (r["t"], r["u"]))
        write_columns(base + "_sigma.csv", ("time", "sigma"), (r["ts"], r["s"]))
    elif case.family == "taylor_bar":
        length, diameter = taylor_bar.final_shape(run_dir)
        err = abs(length / TAYLOR_EXPERIMENT_LENGTH - 1.0)
        rec["figures"] = {"final_length": length, "footprint_diameter": diameter,
                          "length_error_vs_experiment": err,
                          "diameter_error_vs_experiment":
                              abs(diameter / TAYLOR_EXPERIMENT_DIAMETER - 1),
                          "length_error_vs_fe_codes": abs(length / TAYLOR_FE_LENGTH - 1.0)}
        write_columns(base + "_outline.csv", ("z", "r"), taylor_bar.outline(run_dir))
    else:
        # The FDS error depends on the study's reference: measured when the table is made.
        fds_force.write_force_csv(run_dir)
        shutil.copyfile(os.path.join(run_dir, "force_vs_plunge.csv"), base + "_force.csv")
        # What the speeds and the added mass did (issue 47), and the thread formed.
        deck = os.path.join(ROOT, case.deck.format(out=os.path.dirname(os.path.dirname(run_dir))))
        rec["facts"].update(fds_facts.facts(deck, run_dir))
        rec["facts"].update(thread_facts(run_dir, base + "_wall.png"))
    with open(base + ".json", "w") as f:
        json.dump(rec, f, indent=1)
        f.write("\n")
    return rec


def thread_facts(run_dir, png):
    """The thread depth of the run's last state (tools/verify/fds_unwrap.py, which also draws
    the unrolled hole wall into `png`), the measurement's noise floor and what it gives on a full
    thread at the run's particle spacing, mm."""
    unwrap = os.path.join(ROOT, "tools", "verify", "fds_unwrap.py")
    done = subprocess.run(["/usr/bin/python3", unwrap, run_dir, png], capture_output=True,
                          text=True)
    m = re.search(r"thread depth formed: ([0-9.]+) mm.*\(noise floor\): ([0-9.]+) mm",
                  done.stdout)
    if done.returncode != 0 or not m:
        print(f"study: no thread depth for {run_dir}:\n{done.stdout}{done.stderr}", file=sys.stderr)
        return {}
    full = re.search(r"a full thread on the screw's profile measures ([0-9.]+) mm", done.stdout)
    return {"thread_depth": float(m.group(1)), "thread_noise_floor": float(m.group(2)),
            "thread_full_depth": float(full.group(1))}


def read_record(records, case):
    path = record_base(records, case) + ".json"
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def checkout_commit():
    """The commit of the checkout the study ran from (the solver may be a copy built earlier:
    `solver` names it)."""
    done = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                          capture_output=True, text=True)
    return done.stdout.strip() or "unknown"


def compare_force(mine, reference_csv):
    """Axial force on the screw (a force_vs_plunge.csv) against the reference, aligned on
    plunge, by `mcdyna compare`: (RMS |A - B| / peak B, max |A - B| / peak B, corr)."""
    if os.path.abspath(mine) == os.path.abspath(reference_csv):
        return 0.0, 0.0, 1.0
    rms, peak_b, corr, worst = fds_time_scale.compare_rows(MCDYNA, mine, reference_csv,
                                                           columns=("axial_force",))["axial_force"]
    return rms / peak_b, worst / peak_b, corr


def measure(case, rec, records, fds_reference):
    """Error figures of one finished run from its record: (error for the plot, all figures)."""
    if case.family == "elastic_wave":
        return rec["figures"]["u_l2"], rec["figures"]
    if case.family == "taylor_bar":
        return rec["figures"]["length_error_vs_experiment"], rec["figures"]
    rms, worst, corr = compare_force(record_base(records, case) + "_force.csv", fds_reference)
    return rms, {"force_rms_over_peak": rms, "force_max_over_peak": worst,
                 "force_correlation": corr}


def time_scale_figures(rows, cases, records):
    """Each time-scale run ("MC-SPG recipe", "h H scale S") against the slowest finished run at
    its h, and each factor run ("h H scale S FACTOR") against the recipe run at its h and scale,
    per stage (tools/verify/fds_time_scale.py): adds h, factor and the stage figures to its row."""
    runs = []
    for row, case in zip(rows, cases):
        parsed = fds_time_scale.parse_resolution(case.resolution) if case.family == "fds" else None
        if parsed and "stage1_end" in row:
            row["h"], _, row["factor"] = parsed
            runs.append((row, case))
    for row, case in runs:
        recipe = [(r, c) for r, c in runs if r["h"] == row["h"] and not r["factor"]]
        if row["factor"]:
            recipe = [(r, c) for r, c in recipe if r["time_scale"] == row["time_scale"]]
        if not recipe:
            continue
        ref_row, ref_case = min(recipe, key=lambda rc: rc[0]["time_scale"])
        row["time_scale_reference"] = ref_case.resolution
        mine = record_base(records, case) + "_force.csv"
        row["peak_thrust"] = max(fds_force.read_force_csv(mine)[1])
        row.update(fds_time_scale.stage_figures(
            MCDYNA, mine, record_base(records, ref_case) + "_force.csv", ref_row["stage1_end"]))


def resolution_key(case):
    m = re.search(r"[0-9.]+", case.resolution)
    order = {"coarse": 0, "medium": 1, "fine": 2}
    return -float(m.group(0)) if m else order.get(case.resolution, 0)


# Panels of error_vs_time.png: (family, figure, axis label).
PANELS = [("elastic_wave", "u_l2", "elastic wave: u(L) relative L2 error"),
          ("elastic_wave", "sigma_error", "elastic wave: σ(L/2) mean error / ρc|v0|"),
          ("taylor_bar", "length_error_vs_experiment", "Taylor bar: |Lf / 16.51 mm − 1|"),
          ("fds", "force_rms_over_peak", "FDS: axial force RMS diff / reference peak")]


def plot_error_vs_time(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    panels = [p for p in PANELS if any(r["family"] == p[0] and r.get(p[1], 0) > 0 for r in rows)]
    if not panels:
        return
    fig, axes = plt.subplots(1, len(panels), figsize=(4.6 * len(panels), 4.2), squeeze=False)
    for ax, (fam, key, label) in zip(axes[0], panels):
        for method in dict.fromkeys(r["method"] for r in rows if r["family"] == fam):
            pts = [r for r in rows if r["family"] == fam and r["method"] == method
                   and r.get(key, 0) > 0]
            if not pts:
                continue
            ax.loglog([p["core_s"] for p in pts], [p[key] for p in pts], "o-", label=method)
            for p in pts:
                ax.annotate(p["resolution"], (p["core_s"], p[key]), fontsize=7,
                            textcoords="offset points", xytext=(3, 3))
        # The cost axis is core time (wall x threads): a long run continued from its restart
        # dump on another thread count, or runs on 1 and 2 threads, stay comparable.
        ax.set_xlabel("core time (wall × threads), s")
        ax.set_ylabel(label, fontsize=9)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def history_plots(out_dir, records, finished):
    """OUT/elastic_wave.png, taylor_bar.png and fds_force.png from the records of the finished
    runs [(case, record)]."""
    def label(case):
        return f"{case.method} {case.resolution}"
    elastic = [c for c, _ in finished if c.family == "elastic_wave" and c.method != "plain DNI"]
    if elastic:
        series = [(label(c), *read_columns(record_base(records, c) + "_u.csv"),
                   *read_columns(record_base(records, c) + "_sigma.csv")) for c in elastic]
        elastic_wave.plot_histories(series, os.path.join(out_dir, "elastic_wave.png"))
    taylor = [c for c, _ in finished if c.family == "taylor_bar"]
    if taylor:
        taylor_bar.plot_profiles([(label(c), *read_columns(record_base(records, c) +
                                                           "_outline.csv")) for c in taylor],
                                 os.path.join(out_dir, "taylor_bar.png"))
    fds = [c for c, _ in finished if c.family == "fds"]
    if fds:
        fds_force.plot_curves([(label(c), *fds_force.read_force_csv(record_base(records, c) +
                                                                    "_force.csv")) for c in fds],
                              os.path.join(out_dir, "fds_force.png"))


# The figures beside the plotted error in study.md, per family: (key, heading, format).
OTHER_FIGURES = {
    "elastic_wave": [("sigma_error", "σ(L/2) error", "{:.4f}")],
    "taylor_bar": [("final_length", "Lf mm", "{:.3f}"), ("footprint_diameter", "Df mm", "{:.2f}"),
                   ("length_error_vs_fe_codes", "Lf vs FE codes", "{:.4f}")],
    "fds": [("force_max_over_peak", "max/peak", "{:.3f}"), ("force_correlation", "corr",
                                                             "{:.3f}")],
}


def write_markdown(rows, path, ratios=()):
    """The table for manual/verification.md: one row per run; the cost per core second so runs
    made on 1 and 2 threads (or continued on another count) compare; then the cost ratios."""
    with open(path, "w") as f:
        f.write("| family | method | resolution | particles | elements | cycles | wall s "
                "(threads) | core s | (p+e)-steps per core-s | error | other figures |\n")
        f.write("|---" * 11 + "|\n")
        for r in rows:
            work = (r["particles"] + r["elements"]) * r["cycles"]
            # A run continued on another thread count: its core time is not wall x threads.
            mixed = abs(r["core_s"] - r["wall_s"] * r["threads"]) > 0.01 * r["core_s"]
            threads = "mixed" if mixed else r["threads"]
            other = ", ".join(f"{head} {fmt.format(r[key])}"
                              for key, head, fmt in OTHER_FIGURES[r["family"]] if key in r)
            if r["family"] == "fds" and r["force_correlation"] == 1.0 and r["error"] == 0.0:
                other = "the reference"
            f.write(f"| {r['family'].replace('_', ' ')} | {r['method']} | {r['resolution']} | "
                    f"{r['particles']:,} | {r['elements']:,} | {r['cycles']:,} | "
                    f"{r['wall_s']:,.1f} ({threads}) | {r['core_s']:,.1f} | "
                    f"{work / r['core_s'] / 1e6:.2f} M | {r['error']:.4f} | {other} |\n")
        if ratios:
            f.write("\n" + "".join(f"- {line}\n" for line in ratios))
        scales = fds_time_scale.table(rows)
        if scales:
            f.write("\nFDS time scale against the slowest run at the same h (per stage, "
                    "tools/verify/fds_time_scale.py):\n\n" + "".join(f"{line}\n" for line in scales))
        factors = fds_time_scale.factor_table(rows)
        if factors:
            f.write("\nFDS: what sets the thread, one factor at a time against the recipe run at "
                    "the same h and time scale:\n\n" + "".join(f"{line}\n" for line in factors))


# The MC-SPG run an ITB 1 run is paired with for the cost ratio, in order of preference: the same
# step estimate (eigen) first, then the scheme alone (MSC 0), then the family's MC-SPG run (the
# Taylor bar's is MSC 1: its medium bar with MSC 0 does not finish).
PARTNERS = ("MC-SPG eigen", "MC-SPG MSC 0", "MC-SPG", "MC-SPG MSC 1")


def cost_ratios(rows):
    """The paper's Table 2 figure for every ITB 1 run with an MC-SPG partner at the same
    resolution: core time and cycles of SPG : MC-SPG. Lines of text."""
    lines = []
    for r in rows:
        if r["method"] != "SPG ITB 1":
            continue
        for partner in PARTNERS:
            b = next((q for q in rows if q["family"] == r["family"] and q["method"] == partner
                      and q["resolution"] == r["resolution"]), None)
            if b:
                lines.append(f"cost ratio SPG ITB 1 : {partner}, {r['family'].replace('_', ' ')} "
                             f"{r['resolution']}: core time {r['core_s'] / b['core_s']:.2f} "
                             f"({r['core_s']:,.1f} / {b['core_s']:,.1f} s), cycles "
                             f"{r['cycles'] / b['cycles']:.2f} ({r['cycles']:,} / {b['cycles']:,})")
                break
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="the CI-length subset (~8 min)")
    ap.add_argument("--out", default=os.path.join(ROOT, "results", "study"))
    ap.add_argument("--threads", type=int, default=0, help="OpenMP threads (default: all)")
    ap.add_argument("--only", nargs="+", choices=["elastic_wave", "taylor_bar", "fds"])
    ap.add_argument("--cases", nargs="+", metavar="NAME",
                    help="only the runs whose names (OUT/runs/NAME) contain one of these, e.g. "
                         "taylor_bar_MC-SPG_MSC_1_fine: to share a study between processes")
    ap.add_argument("--reuse", action="store_true",
                    help="keep runs that finished before (their run directories or records)")
    ap.add_argument("--records", help="where the runs' records go (default OUT/records)")
    ap.add_argument("--no-run", action="store_true",
                    help="start no run: the table and plots from finished runs and records only")
    a = ap.parse_args()
    if not os.path.exists(MCDYNA):
        sys.exit("study: build/mcdyna is missing (cmake --build build)")
    # The quick study runs the cases marked quick; the full study the others (the quick FDS
    # variants are shortened versions of full-study runs).
    selected = [c for c in cases()
                if c.quick == a.quick or (not a.quick and c.family != "fds")]
    selected = [c for c in selected if not a.only or c.family in a.only]
    selected = [c for c in selected if not a.cases or any(k in c.name for k in a.cases)]
    os.makedirs(a.out, exist_ok=True)
    print(f"study ({'quick' if a.quick else 'full'}): {len(selected)} runs into {a.out}")
    records = a.records or os.path.join(a.out, "records")
    finished = []  # (case, record)
    missing = []  # runs with neither a record nor a finished run directory
    for case in selected:
        run_dir = os.path.join(a.out, "runs", case.name)
        # Under --reuse a record, once written, stands for its run (delete it to measure again).
        rec = read_record(records, case) if a.reuse else None
        if rec:
            print(f"  {case.family:<13} {case.method:<13} {case.resolution:<7} (from its record, "
                  f"{rec['recorded']})", flush=True)
        else:
            facts = run_facts(run_dir) if a.reuse else None
            if not facts and not a.no_run:
                run_case(case, a.out, a.threads, a.reuse)
                facts = run_facts(run_dir)
            if facts:
                rec = write_record(records, case, run_dir, facts)
            else:
                missing.append(case.name)
        if rec:
            finished.append((case, rec))
    # The FDS reference: the finest MC-SPG run of the study, unless that is only h 0.3.
    spg_fds = sorted((c for c, _ in finished if c.family == "fds" and c.method == "MC-SPG"),
                     key=resolution_key)
    fds_reference = FDS_REFERENCE
    if spg_fds and spg_fds[-1].resolution != "h 0.3":
        fds_reference = record_base(records, spg_fds[-1]) + "_force.csv"
    rows = []
    for case, rec in finished:
        facts = rec["facts"]
        error, figures = measure(case, rec, records, fds_reference)
        work = facts["particles"] + facts["solids"]
        rows.append(dict(family=case.family, method=case.method, resolution=case.resolution,
                         particles=facts["particles"], elements=facts["solids"],
                         cycles=facts["cycles"], threads=facts["threads"],
                         wall_s=facts["wall"], core_s=facts["core"],
                         steps_per_s=work * facts["cycles"] / facts["wall"] if facts["wall"] else 0,
                         error=error, **figures,
                         **{k: facts[k] for k in FDS_KNOBS if k in facts}))
    time_scale_figures(rows, [c for c, _ in finished], records)
    columns = []
    for r in rows:
        columns += [k for k in r if k not in columns]
    with open(os.path.join(a.out, "study.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns)
        w.writeheader()
        w.writerows(rows)
    print(f"\n{'family':<13} {'method':<13} {'res':<7} {'particles':>9} {'elements':>8} "
          f"{'cycles':>7} {'wall s':>8} {'core s':>8} {'(p+e)-steps/s':>13} {'error':>9}")
    for r in rows:
        print(f"{r['family']:<13} {r['method']:<13} {r['resolution']:<7} {r['particles']:>9} "
              f"{r['elements']:>8} {r['cycles']:>7} {r['wall_s']:>8.1f} {r['core_s']:>8.1f} "
              f"{r['steps_per_s'] / 1e6:>12.3f}M {r['error']:>9.4f}")
    if any(c.family == "fds" for c, _ in finished):
        print(f"fds reference: {os.path.relpath(fds_reference, ROOT)}")
    ratios = cost_ratios(rows)
    for line in ratios:
        print(line)
    write_markdown(rows, os.path.join(a.out, "study.md"), ratios)
    plot_error_vs_time(rows, os.path.join(a.out, "error_vs_time.png"))
    fds_time_scale.plot(rows, os.path.join(a.out, "fds_time_scale.png"))
    history_plots(a.out, records, finished)
    print(f"wrote {os.path.join(a.out, 'study.csv')}, error_vs_time.png and the history plots")
    if missing:
        sys.exit(f"study: {len(missing)} run(s) without a result: {' '.join(missing)}")


if __name__ == "__main__":
    main()
