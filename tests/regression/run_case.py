#!/usr/bin/python3
"""Runs one regression case and checks its outputs against its reference.

    tests/regression/run_case.py MCDYNA CASE_DIR OUT_DIR

CASE_DIR/case.json names the deck, the run's options and the checks:
  {"deck": "spring_damper.k", "options": ["--threads", "1"],
   "checks": [
     {"what": "...", "history": "nodout.csv", "reference": "reference.csv",
      "column": "x_disp", "tolerance": 3e-3, "why": "where the tolerance comes from"},
     {"what": "...", "history": "nodout.csv", "where": {"node": 11}, "column": "z_disp",
      "at": "last", "expected": -1.90496e-4, "tolerance": 3e-3, "why": "..."}]}
A check with a "reference" compares the whole curve with `mcdyna compare --tol` (max|A - B| /
peak|B|; "points": resample on that many points, e.g. the history's own rows, so that the
comparison does not interpolate between its outputs); one with "expected" compares a value (the last row, or the row at time "at") as
|A - expected| / |expected|. Prints one line per check and exits 1 if any fails.
"""
import csv
import json
import pathlib
import subprocess
import sys


def value_at(path, check):
    rows = list(csv.DictReader(open(path)))
    where = check.get("where", {})
    rows = [r for r in rows if all(float(r[k]) == float(v) for k, v in where.items())]
    if not rows:
        raise SystemExit(f"{path}: no row matches {where}")
    at = check.get("at", "last")
    row = rows[-1] if at == "last" else min(rows, key=lambda r: abs(float(r["time"]) - at))
    return float(row[check["column"]])


def main():
    mcdyna, case, out = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    spec = json.load(open(case / "case.json"))
    run = subprocess.run([mcdyna, "run", str(case / spec["deck"]), "--out", str(out), "-q",
                          *spec.get("options", [])], capture_output=True, text=True)
    if run.returncode != 0:
        print(f"{case.name}: the run ended with exit {run.returncode}\n{run.stdout}{run.stderr}")
        return 1
    failed = 0
    for check in spec["checks"]:
        history = out / check["history"]
        if "reference" in check:
            r = subprocess.run([mcdyna, "compare", str(history), str(case / check["reference"]),
                                "-c", check["column"], "--tol", str(check["tolerance"]),
                                *(["--points", str(check["points"])] if "points" in check else [])],
                               capture_output=True, text=True)
            ok = r.returncode == 0
            # The compared column's row: max|A-B|, at, RMS, max/peakB, ...
            name = check["column"].split(":")[0]
            rows = [l.split() for l in r.stdout.splitlines() if l.startswith(name + " ")]
            numbers = [f for f in rows[0] if f[0].isdigit()] if rows else []
            detail = (f"max|A-B| / peak|B| {numbers[3]}" if len(numbers) > 3
                      else (r.stdout + r.stderr).strip().splitlines()[-1])
        else:
            got = value_at(history, check)
            error = abs(got - check["expected"]) / abs(check["expected"])
            ok = error <= check["tolerance"]
            detail = f"{got:.6e} against {check['expected']:.6e}: {error:.2e}"
        failed += not ok
        print(f"{case.name}: {'ok  ' if ok else 'FAIL'} {check['what']} ({detail}; "
              f"tolerance {check['tolerance']:g}: {check['why']})")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
