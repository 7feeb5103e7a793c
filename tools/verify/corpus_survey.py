#!/usr/bin/python3
"""Every public deck (tests/data/public-decks) run for a few hundred cycles and sorted by outcome:
ran to normal termination, or rejected, by the first reason in the order below (issue 26, "the
corpus": decks read, run to termination, rejected by reason).

  tools/verify/corpus_survey.py [--mcdyna build/mcdyna] [--cycles 300] [--out DIR] [--list]
                                [--expect FILE] [--write-expect FILE]

--expect compares every deck's outcome and reason with FILE (lines "outcome<TAB>deck<TAB>reason",
as --write-expect writes them) and exits 1 on any difference: the corpus test
(tests/CMakeLists.txt). A deck that starts to run, or is rejected for another reason, is a
change to make on purpose: rewrite the file and say why in the commit.

Reasons, in the order they are decided (a deck is counted once, under the first that applies):
  fragment      a piece of a larger model: an *INCLUDE not in the corpus, entities defined in
                another file (parts, sections, materials, nodes, parameters), no elements or no
                *CONTROL_TERMINATION
  implicit/thermal/…  the deck asks for an analysis mcdyna does not do (implicit, thermal, ...)
  unsupported   an explicit model using keywords mcdyna does not have (listed)
  input error   the deck breaks its own card layouts (fields out of their columns, ...)
  run failed    read and accepted, but the run did not reach normal termination
"""
import argparse
import os
import re
import subprocess
import sys
from collections import Counter, defaultdict

ROOT = os.path.realpath(os.path.join(os.path.dirname(__file__), "..", ".."))
CORPUS = os.path.join(ROOT, "tests", "data", "public-decks")

# A piece of a larger model: what it needs lives in files the corpus does not have.
INCOMPLETE = [
    r'include file ".*" not found',
    r"defines no nodes and no elements",
    r"node\(s\) but no elements",
    r"has no \*CONTROL_TERMINATION",
    r"parameter &\w+ is not defined",
    r"card \d+ is missing \(the keyword ends before it\)",
]
# Entities used but defined nowhere: a fragment, unless an unsupported keyword defined them.
DANGLING = [
    r"which is not defined",
    r"\*PART card 1 field (SECID|MID): value 0",
]
# Analyses other than explicit mechanics, by the keyword that asks for them.
ANALYSIS = [
    ("implicit", re.compile(r"\*CONTROL_IMPLICIT_(GENERAL|SOLUTION|EIGENVALUE|DYNAMICS|AUTO)")),
    ("thermal", re.compile(r"\*CONTROL_(SOLUTION|THERMAL_\w+)\b")),
    ("user material", re.compile(r"\*MAT_USER_DEFINED\w*")),
]


def corpus_files():
    out = []
    for d, _, files in os.walk(CORPUS):
        out += [os.path.join(d, f) for f in files]
    return sorted(out)


def unsupported_keywords(text):
    return sorted(set(re.findall(r"^  UNSUPPORTED\s+(\*\S+)", text, re.M)))


def errors(text):
    return [m.group(1) for m in re.finditer(r"error: (.*)$", text, re.M)]


def classify(log):
    """(outcome, detail) of a deck that did not run, from its `mcdyna check` report."""
    errs = errors(log)
    incomplete = [e for e in errs if any(re.search(p, e) for p in INCOMPLETE)]
    if incomplete:
        return "fragment", incomplete[0]
    unsupported = unsupported_keywords(log)
    for name, pattern in ANALYSIS:
        hits = [k for k in unsupported if pattern.fullmatch(k)]
        if hits:
            return name, " ".join(hits)
    feature = [e for e in errs if "not supported" in e or "only 8-node" in e]
    if unsupported or feature:
        return "unsupported", " ".join(unsupported + feature[:1])
    dangling = [e for e in errs if any(re.search(p, e) for p in DANGLING)]
    if dangling:
        return "fragment", dangling[0]
    if errs:
        return "input error", errs[0]
    return "run failed", ""


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mcdyna", default=os.path.join(ROOT, "build", "mcdyna"))
    ap.add_argument("--cycles", type=int, default=300)
    ap.add_argument("--out", default=os.path.join(os.environ.get("TMPDIR", "/tmp"), "corpus_survey"))
    ap.add_argument("--list", action="store_true", help="one line per deck")
    ap.add_argument("--expect", help="the outcome expected of each deck; exit 1 on a difference")
    ap.add_argument("--write-expect", help="write each deck's outcome to this file")
    args = ap.parse_args()
    found = {}
    os.makedirs(args.out, exist_ok=True)
    outcomes = Counter()
    details = defaultdict(Counter)
    keywords = Counter()
    for i, deck in enumerate(corpus_files()):
        rel = os.path.relpath(deck, CORPUS)
        run = subprocess.run(
            [args.mcdyna, "run", deck, "--out", os.path.join(args.out, f"deck{i:02d}"), "-q",
             "--threads", "1", "--cycles", str(args.cycles), "--max-messages", "0"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
            text=True, errors="replace", timeout=1800, cwd=ROOT)
        check = subprocess.run([args.mcdyna, "check", deck, "--max-messages", "0"],
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               stdin=subprocess.DEVNULL, text=True, errors="replace", cwd=ROOT)
        if run.returncode == 0:
            outcome, detail = "ran", ""
        else:
            outcome, detail = classify(check.stdout)
            if outcome == "run failed":
                lines = run.stdout.strip().splitlines()
                detail = lines[-1] if lines else f"exit {run.returncode}"
        for k in unsupported_keywords(check.stdout):
            keywords[k] += 1
        outcomes[outcome] += 1
        # The reason as the expectation file keeps it: this checkout's path left out.
        found[rel] = (outcome, detail.replace(ROOT, "<root>")[:200])
        short = re.sub(r"\d+", "N", detail)[:110]
        details[outcome][short] += 1
        if args.list:
            print(f"{outcome:12s} {rel}  {detail[:150]}")
    total = sum(outcomes.values())
    print(f"{total} decks read; {outcomes['ran']} ran to normal termination "
          f"({args.cycles} cycles at most)")
    for outcome in ["fragment", "implicit", "thermal", "user material", "unsupported",
                    "input error", "run failed"]:
        if outcomes[outcome]:
            print(f"  rejected, {outcome}: {outcomes[outcome]}")
            for d, n in details[outcome].most_common():
                print(f"      {n:3d}  {d}")
    print("unsupported keywords (decks using each, from `mcdyna check`):")
    print("  " + "; ".join(f"{k} {n}" for k, n in keywords.most_common()))
    if args.write_expect:
        with open(args.write_expect, "w") as f:
            f.write("# Outcome of every public deck (tools/verify/corpus_survey.py --write-expect)\n")
            for rel in sorted(found):
                f.write(f"{found[rel][0]}\t{rel}\t{found[rel][1]}\n")
    if args.expect:
        expected = {}
        with open(args.expect) as f:
            for line in f:
                if line.strip() and not line.startswith("#"):
                    outcome, rel, reason = line.rstrip("\n").split("\t")
                    expected[rel] = (outcome, reason)
        wrong = [f"{rel}: expected {expected.get(rel, '(not listed)')}, got {found.get(rel, '(missing)')}"
                 for rel in sorted(set(expected) | set(found)) if expected.get(rel) != found.get(rel)]
        for w in wrong:
            print("MISMATCH " + w)
        print(f"{max(0, len(expected) - len(wrong))} of {len(expected)} decks as expected")
        return 1 if wrong else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
