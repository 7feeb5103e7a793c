#!/usr/bin/env python3
"""Roofline of an MC-SPG cycle: per phase, the bytes moved and flops done per particle-step by the
solver's data structures, the time those take at this machine's ceilings (tools/bench/bandwidth.cpp),
and the share of that bound the measured phase reaches.

Usage: roofline.py D3HSP CEILINGS [INSTRUCTIONS]   (fds_speed.sh runs it after each run)
  D3HSP         a finished run's d3hsp (its timing per phase, particles, neighbours per particle)
  CEILINGS      what tools/bench/bandwidth prints
  INSTRUCTIONS  what tools/bench/instructions.py prints for the same deck and binary: adds the
                instructions per particle-step, the instructions per cycle they ran at and the
                time they take at the core's issue ceiling (the bound that holds here)

The model counts compulsory traffic: every array a pass streams, at its element size, once per
pass (a pair array once per pair, a per-particle array once per particle). Columns read through
an index (x, v, u-hat, a, w sigma F^-T of a neighbour) are counted once per particle, as if the
neighbours' columns stayed in cache while the rows that share them are visited; the "gather"
ceiling measures what such indexed reads cost when they do not. Flops count additions,
multiplications and divisions of the per-pair arithmetic as written (a division as one flop,
though it costs 4-8 times a multiply); per-particle material work is an estimate (named below).

Layouts (src/solver/spg/domain.hpp, neighbours.hpp, shape_functions.hpp): Index int32 (4 B),
reals double (8 B), a 3-vector 24 B, a 3 x 3 tensor 72 B, a flag 1 B.
"""
import re
import sys

# Per phase: bytes per pair, bytes per particle, flops per pair, flops per particle, indexed
# column reads per pair (`gathers`: the passes over the pairs that read a neighbour's column
# through an index, PDAMP's two ends counted), and what each counts. n pairs per particle (the row length, which the transpose's length equals on average).
PHASES = {
    # advance_velocities + absorb_constraints (smoothing.cpp), MC-SPG with PDAMP (the FDS decks):
    # scatter over the row: neighbours 4 + phi 8; PDAMP's other ends over the transpose: rows 4;
    # the Eq. 13 gather: psi 8 + rows 4.
    # Per particle: u-hat r/w 48 + previous u-hat w 24, node force r 24, node index 4, m_J 8,
    # pinned 1, a w 24, node acceleration w 24, PDAMP share w 8 r 8, removed energy w 8,
    # offsets 2 x 4, smoothed w 24, node velocity w 24; constraints: node velocity r 24,
    # smoothed r/w 48, change w 24.
    # Flops per pair: scatter 6; PDAMP impulse at both ends 2 x 25 (r 3, r.r 5, dv 3, dv.r 5,
    # products and the division 6, times r 3) plus 2 x 3 to accumulate; gather 6.
    "SPG smoothing": dict(pair_bytes=28, particle_bytes=386, pair_flops=68, particle_flops=40,
                          gathers=4),
    # particle_update (particle_pass.cpp): F-hat and L over the row: neighbours 4 + node 4 +
    # grad phi 24 (the node index is a second indirection per pair); DT2MS reads the row's
    # mass factors again (neighbours 4).
    # Per particle: F-hat w 72, w sigma F^-T w 72, deviator r/w 96, plastic strain, damage,
    # pressure, EOS energy, temperature, viscosity, internal energy, volume r/w 16 each (128),
    # length, renewal volume, mobility, mass, initial volume, surface, step, mode stiffness
    # (60), flags 4, x and v of its node 48.
    # Flops per pair: F-hat and L, 2 x (3 subtractions + 9 multiply-adds) = 42.
    # Per particle (estimate): two 3 x 3 inverses and determinants 2 x 40, the eigenvalues of
    # F^T F 60, the Hughes-Winget rotation and mid-step gradient 120, Johnson-Cook radial
    # return with its powers and logarithm about 150, EOS and bulk viscosity 40, w sigma F^-T 60.
    "SPG stress": dict(pair_bytes=36, particle_bytes=480, pair_flops=42, particle_flops=510,
                       gathers=2),
    # The internal-force gather over the transpose (particle_pass.cpp): rows 4 + grad phi 24; per
    # particle: offsets 4, node 4, node force r/w 48. Flops per pair: 3 x 3 times 3-vector, 18.
    "SPG forces": dict(pair_bytes=28, particle_bytes=56, pair_flops=18, particle_flops=3,
                       gathers=1),
    # One power iteration every second cycle (frequency.cpp apply, halved per cycle): strain over
    # the rows (neighbours 4 + grad phi 24), forces over the transpose (rows 4 + grad phi 24),
    # u-hat over the rows (neighbours 4, phi 8, pinned 1), the gather (psi 8, rows 4): 81 per
    # pair. Per particle: F-hat r 72, stress w/r 144, a w/r 48, u-hat w/r 48, result 48, x 24,
    # scalars 40, and the order-free norm's two sweeps 48.
    # Flops per pair: 21 + 18 + 6 + 6 = 51; per particle: the inverse 40, stress 80, norm 10.
    "SPG step estimate": dict(pair_bytes=81 / 2, particle_bytes=472 / 2, pair_flops=51 / 2,
                              particle_flops=130 / 2, gathers=4 / 2),
}

# Per renewal the transpose of every row is rebuilt (renewal.cpp: offsets, pairs 4, rows 4,
# psi 8, grad phi 24 written and the rows' phi 8 and grad phi 24 read: 72 per pair) and the
# renewed rows' neighbour search and shape functions are formed; amortised over the cycles
# between renewals (d3hsp's renewal count).
RENEWAL_PAIR_BYTES = 72


def parse_d3hsp(path):
    text = open(path).read()
    out = {}
    out["threads"] = int(re.search(r"Timing per phase \(wall clock, (\d+) thread", text).group(1))
    out["cycles"] = int(re.findall(r"at t = [0-9.e+-]+, cycle (\d+)", text)[-1])
    m = re.search(r"SPG part \d+: (\d+) particles, ([0-9.]+) neighbours per particle, (\d+) kernel "
                  r"renewals", text)
    out["particles"], out["neighbours"], out["renewals"] = int(m.group(1)), float(m.group(2)), \
        int(m.group(3))
    phases = {}
    block = text.split("Timing per phase", 1)[1]
    for line in block.splitlines()[1:]:
        m = re.match(r"  (.+?)\s+([0-9.]+) s\s+([0-9.]+) %", line)  # + range over processes
        if m:
            phases[m.group(1).strip()] = float(m.group(2))
        elif line.startswith("  total"):
            break
    out["phases"] = phases
    return out


def parse_ceilings(path, threads):
    text = open(path).read()
    c = {}
    for m in re.finditer(r"triad\s+(\d+) MiB threads (\d+):\s+([0-9.]+) GB/s", text):
        if int(m.group(2)) == threads:
            c[f"triad {m.group(1)}"] = float(m.group(3)) * 1e9
    for m in re.finditer(r"gather (\w+)\s+threads (\d+):\s+([0-9.]+) M pairs/s", text):
        if int(m.group(2)) == threads:
            c[f"gather {m.group(1)}"] = float(m.group(3)) * 1e6
    m = re.search(rf"flops threads {threads}:\s+([0-9.]+) GFLOP/s", text)
    c["flops"] = float(m.group(1)) * 1e9
    m = re.search(r"clock: ([0-9.]+) GHz", text)
    c["clock"] = float(m.group(1)) * 1e9 if m else 0.0
    m = re.search(r"issue: ([0-9.]+) instructions per cycle", text)
    c["issue"] = float(m.group(1)) if m else 0.0
    return c


def parse_instructions(path):
    counts = {}
    for line in open(path):
        m = re.match(r"(.+?) ([0-9]+)$", line.strip())
        if m:
            counts[m.group(1)] = float(m.group(2))
    return counts


def main():
    run = parse_d3hsp(sys.argv[1])
    ceil = parse_ceilings(sys.argv[2], run["threads"])
    instructions = parse_instructions(sys.argv[3]) if len(sys.argv) > 3 else {}
    steps = run["cycles"] * run["particles"]
    n = run["neighbours"]
    memory, cache = ceil["triad 1024"], ceil["triad 48"]
    print(f"roofline: {run['particles']} particles x {run['cycles']} cycles, {n:.1f} pairs per "
          f"particle, {run['threads']} thread(s); ceilings: memory {memory / 1e9:.1f} GB/s, "
          f"cache (48 MiB) {cache / 1e9:.1f} GB/s, {ceil['flops'] / 1e9:.1f} GFLOP/s, "
          f"indexed gather {ceil['gather ordered'] / 1e6:.0f} (ordered) / "
          f"{ceil['gather scattered'] / 1e6:.0f} (scattered) M pairs/s")
    print(f"  {'phase':<20} {'ns/step':>8} {'B/step':>7} {'flop/step':>9} {'B/flop':>6} "
          f"{'mem ns':>7} {'cache ns':>8} {'flop ns':>7} {'gath ns':>7} {'bound':>6} {'of bound':>8}"
          + (f" {'instr':>6} {'IPC':>5} {'issue ns':>8} {'of issue':>8}" if instructions else ""))
    rows = dict(PHASES)
    renewal_bytes = RENEWAL_PAIR_BYTES * n * run["renewals"] / max(run["cycles"], 1)
    rows["SPG renewal"] = dict(pair_bytes=0, particle_bytes=renewal_bytes, pair_flops=0,
                               particle_flops=0, gathers=0)
    measured_renewal = sum(run["phases"].get(k, 0.0) for k in
                           ("SPG neighbour search", "SPG shape functions", "SPG bond failure"))
    total_measured = total_bound = 0.0
    for name, m in rows.items():
        seconds = measured_renewal if name == "SPG renewal" else run["phases"].get(name, 0.0)
        ns = 1e9 * seconds / steps
        b = m["pair_bytes"] * n + m["particle_bytes"]
        f = m["pair_flops"] * n + m["particle_flops"]
        mem_ns, cache_ns, flop_ns = 1e9 * b / memory, 1e9 * b / cache, 1e9 * f / ceil["flops"]
        gather_ns = 1e9 * m["gathers"] * n / ceil["gather ordered"]
        bound = max(mem_ns, flop_ns)
        total_measured += ns
        total_bound += bound
        share = f"{100 * bound / ns:7.1f}%" if ns > 0 else "      -"
        ratio = f"{b / f:6.2f}" if f > 0 else "     -"
        line = (f"  {name:<20} {ns:8.1f} {b:7.0f} {f:9.0f} {ratio} {mem_ns:7.1f} {cache_ns:8.1f} "
                f"{flop_ns:7.1f} {gather_ns:7.1f} {'memory' if mem_ns >= flop_ns else 'flops':>6} "
                f"{share}")
        print(line + issue_columns(name, ns, run["threads"], instructions, ceil))
    print(f"  {'SPG phases':<20} {total_measured:8.1f} {'':>7} {'':>9} {'':>6} {'':>7} {'':>8} "
          f"{'':>7} {'':>7} {'':>6} {100 * total_bound / total_measured:7.1f}%")
    # The rest of the cycle, per particle-step for comparison.
    for name in ("elements", "contact"):
        if name in run["phases"]:
            ns = 1e9 * run["phases"][name] / steps
            print(f"  {name:<20} {ns:8.1f}   (bytes and flops not modelled: FE elements and "
                  f"contact nodes){issue_columns(name, ns, run['threads'], instructions, ceil)}")


def issue_columns(name, ns, threads, instructions, ceil):
    """Instructions per particle-step, the instructions per cycle they ran at (per core), the
    time they take at the issue ceiling and the measured phase's share of it."""
    if name not in instructions or not ceil["clock"] or not ceil["issue"] or ns <= 0:
        return ""
    count = instructions[name]
    ipc = count / (ns * 1e-9 * ceil["clock"] * threads)
    issue_ns = 1e9 * count / (ceil["issue"] * ceil["clock"] * threads)
    return f" {count:6.0f} {ipc:5.2f} {issue_ns:8.1f} {100 * issue_ns / ns:7.1f}%"


if __name__ == "__main__":
    main()
