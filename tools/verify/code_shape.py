#!/usr/bin/python3
"""The figures that measure the code's shape (design.md §7, issue 48), printed before and after a
restructuring:

  - the files that include solver/state.hpp (directly);
  - the functions that take the whole solver State (a parameter of type State& / const State&);
  - the longest functions in cli/ and solver/ (lines, from Universal Ctags' start and end);
  - the files a commit touches, by folder (--commit REV), to measure "a new formulation touches
    its folder, its .kw files, its tests and at most two lines elsewhere";
  - cycles among solver/'s folders (one folder includes another's header, directly or through
    others, and back; the root counts as a folder): --layers prints the folders' includes and
    exits 1 on a cycle (a CTest entry, "solver folders: no include cycles").

    tools/verify/code_shape.py [--rev REV] [--top N] [--commit REV] [--layers]

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


INCLUDE = re.compile(r'^\s*#\s*include\s+"(solver/[^"]+)"', re.M)


def solver_folder(rel):
    """The folder of a path under src/solver/ ("." for the root)."""
    parts = rel.split("/")
    return parts[0] if len(parts) > 1 else "."


def folder_includes(root):
    """{folder: {included folder: [file -> header, ...]}} among src/solver/'s folders."""
    solver = os.path.join(root, "src", "solver")
    edges = {}
    for dirpath, _, files in os.walk(solver):
        for f in files:
            path = os.path.join(dirpath, f)
            here = solver_folder(os.path.relpath(path, solver))
            with open(path, encoding="utf-8") as fh:
                for header in INCLUDE.findall(fh.read()):
                    there = solver_folder(header[len("solver/"):])
                    edges.setdefault(here, {})
                    if there != here:
                        edges[here].setdefault(there, []).append(
                            f"{os.path.relpath(path, solver)} -> {header}")
    return edges


def folder_cycles(edges):
    """The strongly connected sets of more than one folder (Tarjan), each sorted."""
    index, low, stack, on, found = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in edges.get(v, {}):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            scc = []
            while True:
                w = stack.pop()
                on.discard(w)
                scc.append(w)
                if w == v:
                    break
            if len(scc) > 1:
                found.append(sorted(scc))

    for v in sorted(edges):
        if v not in index:
            visit(v)
    return found


def layers(root):
    """Prints each folder's includes of other folders and any cycle; 1 on a cycle."""
    edges = folder_includes(root)
    for here in sorted(edges):
        there = ", ".join(f"{t} ({len(v)})" for t, v in sorted(edges[here].items()))
        print(f"  {here:10s} -> {there or '(nothing of the solver)'}")
    cycles = folder_cycles(edges)
    for c in cycles:
        print("folder cycle: " + " <-> ".join(c))
        for a in c:
            for b in c:
                for e in edges.get(a, {}).get(b, []):
                    print(f"    {e}")
    print(f"folder cycles in src/solver/: {len(cycles)}")
    return 1 if cycles else 0


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
    print(f"folder cycles in src/solver/: {len(folder_cycles(folder_includes(root)))}")


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
    ap.add_argument("--layers", action="store_true",
                    help="print solver/'s folder includes; exit 1 on a cycle")
    a = ap.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    if a.commit:
        touched(root, a.commit)
        return 0
    measure = (lambda r: layers(r)) if a.layers else (lambda r: shape(r, a.top) or 0)
    if a.rev:
        with tempfile.TemporaryDirectory() as tmp:
            subprocess.run(["git", "worktree", "add", "--detach", tmp, a.rev], cwd=root,
                           check=True, capture_output=True)
            try:
                print(f"at {a.rev}")
                return measure(tmp)
            finally:
                subprocess.run(["git", "worktree", "remove", "--force", tmp], cwd=root,
                               check=True, capture_output=True)
    return measure(root)


if __name__ == "__main__":
    sys.exit(main())
