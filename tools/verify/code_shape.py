#!/usr/bin/python3
"""The figures that measure the code's shape (design.md §7, issue 48), printed before and after a
restructuring:

  - the files that include solver/state.hpp (directly);
  - the functions that take the whole solver State (a parameter of type State& / const State&);
  - the longest functions in cli/ and solver/ (lines, from Universal Ctags' start and end);
  - the files a commit touches, by folder (--commit REV), to measure "a new formulation touches
    its folder, its .kw files, its tests and at most two lines elsewhere".

    tools/verify/code_shape.py [--rev REV] [--top N] [--commit REV]

--rev measures another revision (checked out into a temporary work tree).
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

STATE_PARAM = re.compile(r"(?<![\w:])(?:const\s+)?(?:solver::)?State\s*&")


def functions(root, folder):
    """Every function definition under ROOT/FOLDER with its lines and signature (Universal Ctags)."""
    try:
        out = subprocess.run(
            ["ctags", "-R", "--languages=C++", "--c++-kinds=f", "--fields=+neS",
             "--output-format=json", "-o", "-", folder],
            cwd=root, check=True, capture_output=True, text=True).stdout
    except FileNotFoundError:
        sys.exit("code_shape.py needs Universal Ctags: apt-get install universal-ctags")
    for line in out.splitlines():
        tag = json.loads(line)
        if tag.get("kind") != "function" or "end" not in tag:
            continue
        yield tag


def shape(root, top):
    src = os.path.join(root, "src")
    includers = []
    for dirpath, _, files in os.walk(src):
        for f in files:
            path = os.path.join(dirpath, f)
            with open(path, encoding="utf-8") as fh:
                if '#include "solver/state.hpp"' in fh.read():
                    includers.append(os.path.relpath(path, root))
    print(f"files including solver/state.hpp: {len(includers)}")

    whole_state = []
    lengths = {"src/cli": [], "src/solver": []}
    total = solver_fns = 0
    for tag in functions(root, "src"):
        total += 1
        solver_fns += tag["path"].startswith("src/solver/")
        if STATE_PARAM.search(tag.get("signature", "")):
            whole_state.append(tag)
        for folder, rows in lengths.items():
            if tag["path"].startswith(folder + "/"):
                name = tag["name"]
                if name.startswith("__anon"):
                    name = "lambda in " + tag.get("scope", "?").split("::")[-1]
                rows.append((tag["end"] - tag["line"] + 1, f"{tag['path']}:{tag['line']} {name}"))
    solver_state = sum(1 for t in whole_state if t["path"].startswith("src/solver/"))
    print(f"functions taking the whole State: {len(whole_state)} of {total} in src/ "
          f"({solver_state} of the solver's {solver_fns})")
    for folder, rows in lengths.items():
        rows.sort(reverse=True)
        over = sum(1 for n, _ in rows if n > 80)
        print(f"longest functions in {folder}/ ({over} over 80 lines):")
        for n, where in rows[:top]:
            print(f"  {n:5d}  {where}")


def touched(root, rev):
    """Files a commit touches, grouped by top folder, with added+removed lines."""
    out = subprocess.run(["git", "show", "--numstat", "--format=", rev], cwd=root, check=True,
                         capture_output=True, text=True).stdout
    rows = [line.split("\t") for line in out.splitlines() if line.strip()]
    print(f"{rev}: {len(rows)} files")
    for added, removed, path in rows:
        print(f"  +{added:>5} -{removed:>5}  {path}")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rev", help="measure this revision instead of the work tree")
    ap.add_argument("--top", type=int, default=5)
    ap.add_argument("--commit", help="list the files this commit touches")
    a = ap.parse_args()
    root = subprocess.run(["git", "rev-parse", "--show-toplevel"], check=True,
                          capture_output=True, text=True).stdout.strip()
    if a.commit:
        touched(root, a.commit)
        return 0
    if a.rev:
        with tempfile.TemporaryDirectory() as tmp:
            subprocess.run(["git", "worktree", "add", "--detach", tmp, a.rev], cwd=root,
                           check=True, capture_output=True)
            try:
                print(f"at {a.rev}")
                shape(tmp, a.top)
            finally:
                subprocess.run(["git", "worktree", "remove", "--force", tmp], cwd=root,
                               check=True, capture_output=True)
    else:
        shape(root, a.top)
    return 0


if __name__ == "__main__":
    sys.exit(main())
