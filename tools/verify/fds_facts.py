#!/usr/bin/python3
"""What an FDS run's speeds and added mass did to it (issue 47): the knobs of its deck and the
inertia of its plate, for the study's records and tables.

  time_scale             the deck's TIME SCALE (tools/decks/fds.py: every speed x it)
  dt2ms                  its DT2MS in s (0: no mass scaling)
  added_mass             mass added by DT2MS at the end, t, and its share of the plate's mass
  added_mass_by_part     the same per part (matsum), where it sits
  kinetic_over_internal  the plate's largest kinetic over internal energy after the first
                         contact, once the plate's internal energy has reached 10 % of its
                         largest, as `mcdyna run`'s summary takes it (the plate: every part but
                         the rigid screw). Below that the ratio follows where an output falls in
                         the transient of the first bite (h 0.3 with a 1 % floor: 0.100 / 0.046 /
                         0.111 at time scales 20 / 10 / 5)
  kinetic_over_internal_at  the time where it is largest, s
  kinetic_over_internal_stage2  the same in stage 2 alone, where the thread forms (the
                         largest after contact falls in stage 1, soon after the tip touches:
                         at h 0.3 its value is set by where the output falls in that transient)
  kinetic_over_internal_stage2_at  its time, s
  stage1_end             when stage 1 ends, s (the deck's header)
  added_mass_largest     the largest total added mass at any output, t (DT2MS can add mass and
                         take it back as the step recovers)

usage: fds_facts.py DECK RUN_DIR   (prints the facts as JSON)
       fds_facts.py --check        (the energy ratio on a synthetic matsum with a known answer)
"""
import csv
import json
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fds_section import SCREW_PART  # noqa: E402

IE_FLOOR = 0.1  # of the plate's largest internal energy (io/inertia.hpp kInternalFloor)


def deck_knobs(deck):
    """(time_scale, dt2ms, end of stage 1 in s or None) from the header tools/decks/fds.py
    writes."""
    scale, dt2ms, stage1_end = 1.0, 0.0, None
    with open(deck) as f:
        for line in f:
            if not line.startswith("$"):
                if line.startswith("*KEYWORD"):
                    break
                continue
            m = re.match(r"\$ TIME SCALE ([0-9.eE+-]+):", line)
            if m:
                scale = float(m.group(1))
            m = re.search(r"stage 1 ends at ([0-9.eE+-]+) s", line)
            if m:
                stage1_end = float(m.group(1))
            m = re.match(r"\$ MASS SCALING: DT2MS = ([0-9.eE+-]+) s", line)
            if m:
                dt2ms = float(m.group(1))
    return scale, dt2ms, stage1_end


def first_contact(run_dir):
    """The first time the screw's contact carries a force (rcforc.csv), or None."""
    with open(os.path.join(run_dir, "rcforc.csv")) as f:
        for row in csv.DictReader(f):
            if any(float(row[k]) != 0.0 for k in ("x_force", "y_force", "z_force")):
                return float(row["time"])
    return None


def plate_energies(run_dir):
    """{time: [IE, KE, added mass]} of the plate and {part: added mass at the end}."""
    plate, added = {}, {}
    with open(os.path.join(run_dir, "matsum.csv")) as f:
        for row in csv.DictReader(f):
            part = int(row["part"])
            if part == SCREW_PART:
                continue
            t = float(row["time"])
            e = plate.setdefault(t, [0.0, 0.0, 0.0])
            e[0] += float(row["internal_energy"])
            e[1] += float(row["kinetic_energy"])
            e[2] += float(row["added_mass"])
            added[part] = float(row["added_mass"])  # the last row is the end
    return plate, added


def kinetic_over_internal(plate, contact):
    """(largest KE / IE of the plate after `contact` once IE >= IE_FLOOR of its largest, time)."""
    after = {t: e for t, e in plate.items() if contact is not None and t >= contact}
    if not after:
        return None, None
    top = max(e[0] for e in after.values())
    best, at = None, None
    for t in sorted(after):
        ie, ke = after[t][0], after[t][1]
        if top > 0.0 and ie >= IE_FLOOR * top and (best is None or ke / ie > best):
            best, at = ke / ie, t
    return best, at


def facts(deck, run_dir, plate_mass=None):
    scale, dt2ms, stage1_end = deck_knobs(deck)
    plate, added = plate_energies(run_dir)
    ratio, at = kinetic_over_internal(plate, first_contact(run_dir))
    total = sum(added.values())
    out = dict(time_scale=scale, dt2ms=dt2ms, added_mass=total,
               added_mass_by_part={str(p): m for p, m in sorted(added.items())},
               added_mass_largest=max(e[2] for e in plate.values()),
               kinetic_over_internal=ratio, kinetic_over_internal_at=at)
    if stage1_end is not None:
        out["stage1_end"] = stage1_end
        # The IE floor stays the whole run's: stage 2 starts well above it.
        ratio2, at2 = kinetic_over_internal(plate, stage1_end)
        out.update(kinetic_over_internal_stage2=ratio2, kinetic_over_internal_stage2_at=at2)
    if plate_mass:
        out["added_mass_share"] = total / plate_mass
    return out


def check():
    """A plate whose KE/IE is 0.5 at its contact (IE below the floor there), then 0.2, 0.05."""
    rows = [(0.0, 0.0, 0.0), (1.0, 1e-6, 1e-6), (2.0, 1.0, 0.2), (3.0, 10.0, 0.5)]
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "matsum.csv"), "w") as f:
            f.write("time,part,internal_energy,kinetic_energy,eroded_internal_energy,"
                    "x_momentum,y_momentum,z_momentum,x_rigid_velocity,y_rigid_velocity,"
                    "z_rigid_velocity,hourglass_energy,added_mass\n")
            for t, ie, ke in rows:
                for part, share in ((1, 0.75), (2, 0.25)):
                    f.write(f"{t},{part},{ie * share},{ke * share},0,0,0,0,0,0,0,0,"
                            f"{1e-9 * part * t}\n")
                f.write(f"{t},{SCREW_PART},0,1e3,0,0,0,0,0,0,0,0,0\n")  # the screw: left out
        with open(os.path.join(d, "rcforc.csv"), "w") as f:
            f.write("time,contact,side,x_force,y_force,z_force\n0,1,slave,0,0,0\n"
                    "1,1,slave,0,0,-5\n2,1,slave,0,0,-7\n")
        plate, added = plate_energies(d)
        ratio, at = kinetic_over_internal(plate, first_contact(d))
        ok = abs(ratio - 0.2) < 1e-12 and at == 2.0 and abs(added[2] - 6e-9) < 1e-21
        print(f"KE/IE after contact {ratio} at {at} (want 0.2 at 2.0; the 1.0 at t = 1 is below "
              f"the IE floor), added mass of part 2 {added[2]:.3g} (want 6e-09): "
              f"{'ok' if ok else 'WRONG'}")
        # Stage 2 from t = 2.5: only the last output, 0.05.
        ratio2, at2 = kinetic_over_internal(plate, 2.5)
        ok2 = abs(ratio2 - 0.05) < 1e-12 and at2 == 3.0
        print(f"KE/IE in stage 2 (from 2.5) {ratio2} at {at2} (want 0.05 at 3.0): "
              f"{'ok' if ok2 else 'WRONG'}")
        return ok and ok2


if __name__ == "__main__":
    if sys.argv[1:] == ["--check"]:
        sys.exit(0 if check() else 1)
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    print(json.dumps(facts(sys.argv[1], sys.argv[2]), indent=1))
