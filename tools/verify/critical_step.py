#!/usr/bin/python3
"""The true critical step of a state, by bisection (issue 23).

From a restart dump, run CYCLES cycles at a fixed step (mcdyna run --fixed-step, no mass
scaling) and call the step unstable when the run stops on a non-finite value, an inverted
particle or element, or when the energy balance (total energy minus external work) moves by
more than --energy-tol (1 %) of the state's total energy (or of the work put in over the probe,
at the start of a run): an unstable mode grows geometrically, so over a few hundred cycles it
passes that bound from round-off within a few per cent of the critical step. Bisects between a step known to be stable (the code's own step at
the dump unless --low is given) and one that is not (doubling from it) to --rel.

Usage: critical_step.py DECK DUMP [--outputs RUN_DIR] [--cycles 300] [--threads 1] [--rel 0.03] [--low DT]
Prints one line per probe and the result: critical step, the code's step at the dump and the
ratio.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def glstat_rows(out):
    with open(os.path.join(out, "glstat.csv")) as f:
        return list(csv.DictReader(f))


def probe_dir(args):
    """A fresh output directory holding the histories the dump continues (cut back by mcdyna)."""
    out = tempfile.mkdtemp(prefix="probe_", dir=args.work)
    src = os.path.dirname(os.path.abspath(args.dump)) if not args.outputs else args.outputs
    for name in os.listdir(src):
        path = os.path.join(src, name)
        if os.path.isfile(path) and not name.startswith(("d3dump", "runrsf", "d3plot_")) \
                and not name.endswith((".dump", ".csv.tmp")):
            shutil.copy(path, out)
    return out


def probe(args, dt, work):
    out = probe_dir(args)
    cmd = [args.binary, "run", args.deck, "--restart", args.dump, "--fixed-step", repr(dt),
           "--cycles", str(args.cycles), "--threads", str(args.threads), "--out", out, "-q"]
    rc = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode
    rows = glstat_rows(out)
    # The last row written before the dump's time, and the probe's final row.
    before = [r for r in rows if float(r["time"]) <= args.start_time]
    first, last = (before[-1] if before else rows[0]), rows[-1]
    total0, total1 = float(first["total_energy"]), float(last["total_energy"])
    work0, work1 = float(first["external_work"]), float(last["external_work"])
    ke0, ke1 = float(first["kinetic_energy"]), float(last["kinetic_energy"])
    # Energy balance (total minus external work) and kinetic growth, against the state's total
    # energy or, at the start of a run where it is ~0, the work put in over the probe.
    scale = max(abs(total0), abs(work1 - work0), 1e-30)
    drift = abs((total1 - work1) - (total0 - work0)) / scale
    growth = (ke1 - ke0) / max(ke0, abs(work1 - work0), 1e-30)
    stable = rc == 0 and drift <= args.energy_tol and growth <= args.kinetic_tol
    print(f"  dt {dt:.4e}: exit {rc}, energy drift {drift:.2e}, kinetic {growth:+.3f} over "
          f"{float(last['time']) - float(first['time']):.3e} s -> {'stable' if stable else 'UNSTABLE'}",
          flush=True)
    subprocess.run(["rm", "-rf", out])
    return stable, first


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("deck")
    ap.add_argument("dump")
    ap.add_argument("--cycles", type=int, default=300)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--rel", type=float, default=0.03)
    ap.add_argument("--low", type=float, default=0.0, help="a step known to be stable")
    ap.add_argument("--energy-tol", type=float, default=0.01)
    ap.add_argument("--kinetic-tol", type=float, default=float("inf"),
                    help="also unstable when the kinetic energy grows by more than this share (off)")
    ap.add_argument("--outputs", default="",
                    help="the run's output directory (default: the dump's directory)")
    ap.add_argument("--binary", default=os.path.join(ROOT, "build", "mcdyna"))
    ap.add_argument("--work", default=tempfile.gettempdir())
    args = ap.parse_args()

    # The code's own step at the dump: the first glstat row of a one-cycle run from it.
    out = probe_dir(args)
    subprocess.run([args.binary, "run", args.deck, "--restart", args.dump, "--cycles", "1",
                    "--threads", str(args.threads), "--out", out, "-q"],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    row = glstat_rows(out)[-1]
    subprocess.run(["rm", "-rf", out])
    own = float(row["time_step"])
    args.start_time = float(row["time"]) - 0.5 * own
    print(f"state t = {float(row['time']):.4e} s: code's step {own:.4e} s "
          f"(added mass {float(row['added_mass']):.3e} t)", flush=True)
    low = args.low if args.low > 0 else own
    ok, _ = probe(args, low, args.work)
    if not ok:
        print("the low step is not stable by this test: give a smaller --low")
        sys.exit(1)
    high = 2.0 * low
    while probe(args, high, args.work)[0]:
        low, high = high, 2.0 * high
        if high > 1e3 * own:
            sys.exit("no unstable step found below 1000 x the code's step")
    while high / low - 1.0 > args.rel:
        mid = (low * high) ** 0.5
        if probe(args, mid, args.work)[0]:
            low = mid
        else:
            high = mid
    print(f"critical step between {low:.4e} and {high:.4e} s; code's step {own:.4e} s; "
          f"ratio {low / own:.2f}")


if __name__ == "__main__":
    main()
