#!/usr/bin/python3
"""Names the speeds and inertia in the facts of FDS study records written before issue 47
(time_scale, dt2ms, added_mass, kinetic_over_internal: tools/verify/fds_facts.py), in place;
records that have kinetic_over_internal are left alone, so it runs again as re-runs finish.

- time_scale and dt2ms: from the deck the record ran, its header as tools/decks/fds.py writes
  it: a generated deck is written again with the case's arguments (tools/study.py), a shipped
  deck is read at the record's own checkout (git show), a deck decks/generate.sh writes as it
  is in the tree.
- The inertia facts need the run's matsum and rcforc, gone with its run directory. With --rerun
  DIR, a record of the same case in DIR (the case run again, today's solver) gives them, and
  the record says so: facts.inertia_rerun names the re-run's checkout and cycles and how far its
  force is from the record's own (`mcdyna compare` over the whole plunge, RMS over the
  record's peak), so a reader knows whether the re-run is the same run.
- Without one, --documented NAME=ADDED_MASS:SOURCE takes the end's added mass from where the run
  was reported (the manual's line), and kinetic_over_internal stays null with a note naming what
  a re-run would cost.

usage: fds_backfill.py RECORDS [--rerun DIR] [--documented NAME=MASS:SOURCE ...]
                       [--mcdyna build/mcdyna]
"""
import argparse
import glob
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tools"))
sys.path.insert(0, HERE)
import fds_facts  # noqa: E402
import fds_time_scale  # noqa: E402
import study  # noqa: E402

INERTIA = ("added_mass", "added_mass_by_part", "added_mass_largest", "kinetic_over_internal",
           "kinetic_over_internal_at", "stage1_end", "kinetic_over_internal_stage2",
           "kinetic_over_internal_stage2_at", "thread_full_depth")


def deck_knobs(rec, case, tmp):
    """(time_scale, dt2ms, stage 1 end) of the deck the record ran."""
    deck = os.path.join(tmp, "deck.k")
    if case is not None and case.generate:
        argv = [a.format(deck=deck) for a in case.generate]
        subprocess.run(["/usr/bin/python3", os.path.join(ROOT, argv[0])] + argv[1:], check=True,
                       cwd=ROOT, stdout=subprocess.DEVNULL)
    else:
        shown = subprocess.run(["git", "-C", ROOT, "show", f"{rec['checkout']}:{rec['deck']}"],
                               capture_output=True, text=True)
        if shown.returncode != 0:
            # Not committed (decks/generate.sh writes the large decks): as it writes them today.
            return fds_facts.deck_knobs(os.path.join(ROOT, rec["deck"]))
        with open(deck, "w") as f:
            f.write(shown.stdout)
    return fds_facts.deck_knobs(deck)


def rerun_facts(name, records, rerun, mcdyna):
    """The inertia facts of the case's re-run and where it came from."""
    with open(os.path.join(rerun, name + ".json")) as f:
        again = json.load(f)
    facts = {k: again["facts"][k] for k in INERTIA if k in again["facts"]}
    diff = fds_time_scale.compare_rows(mcdyna, os.path.join(rerun, name + "_force.csv"),
                                        os.path.join(records, name + "_force.csv"))
    facts["inertia_rerun"] = {
        "checkout": again["checkout"], "cycles": again["facts"]["cycles"],
        "axial_rms_over_peak": diff["axial_force"][0] / diff["axial_force"][1],
        "torque_rms_over_peak": diff["torque"][0] / diff["torque"][1],
        "note": "added mass and kinetic/internal energy from this re-run of the case; the "
                "record's force and cost are its own run's"}
    return facts


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("records")
    ap.add_argument("--rerun")
    ap.add_argument("--documented", nargs="*", default=[], metavar="NAME=MASS:SOURCE")
    ap.add_argument("--mcdyna", default=os.path.join(ROOT, "build", "mcdyna"))
    a = ap.parse_args()
    documented = {}
    for item in a.documented:
        name, rest = item.split("=", 1)
        mass, source = rest.split(":", 1)
        documented[name] = (float(mass), source)
    cases = {c.name: c for c in study.cases()}
    for path in sorted(glob.glob(os.path.join(a.records, "fds_*.json"))):
        name = os.path.basename(path)[:-len(".json")]
        with open(path) as f:
            rec = json.load(f)
        facts = rec["facts"]
        if facts.get("kinetic_over_internal") is not None:
            continue  # complete (its own run's facts, or a re-run's)
        with tempfile.TemporaryDirectory() as tmp:
            scale, dt2ms, stage1_end = deck_knobs(rec, cases.get(name), tmp)
        facts.update(time_scale=scale, dt2ms=dt2ms)
        if stage1_end is not None:
            facts["stage1_end"] = stage1_end
        if a.rerun and os.path.exists(os.path.join(a.rerun, name + ".json")):
            facts.pop("inertia_note", None)
            facts.update(rerun_facts(name, a.records, a.rerun, a.mcdyna))
        elif name in documented:
            mass, source = documented[name]
            facts.update(added_mass=mass, kinetic_over_internal=None,
                         inertia_note=f"added mass at the end as reported in {source}; the "
                                      f"plate's kinetic/internal energy was not kept and a "
                                      f"re-run costs {facts['core']:,.0f} core-s")
        elif "as reported in" in facts.get("inertia_note", ""):
            pass  # documented by an earlier pass: kept (a later pass without --documented)
        elif dt2ms == 0.0:
            # No mass scaling: nothing is added. The energies went with the run directory.
            facts.update(added_mass=0.0, kinetic_over_internal=None,
                         inertia_note=f"no mass scaling (DT2MS 0); the plate's kinetic/internal "
                                      f"energy was not kept and a re-run costs "
                                      f"{facts['core']:,.0f} core-s")
        else:
            facts.update(added_mass=None, kinetic_over_internal=None,
                         inertia_note=f"not kept with the record; a re-run costs "
                                      f"{facts['core']:,.0f} core-s")
        with open(path, "w") as f:
            json.dump(rec, f, indent=1)
            f.write("\n")
        shown = {k: facts.get(k) for k in ("time_scale", "dt2ms", "added_mass",
                                           "kinetic_over_internal")}
        print(f"{name}: {shown}")


if __name__ == "__main__":
    main()
