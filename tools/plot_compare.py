#!/usr/bin/python3
"""Plot for `mcdyna compare --plot`: both curves of every compared column and their difference.

Usage: plot_compare.py RESAMPLED.csv OUT.png LABEL_A LABEL_B
RESAMPLED.csv is what `mcdyna compare --csv` writes: x, then "A name", "B name" per column.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MAX_COLUMNS = 8


def main():
    data, out, label_a, label_b = sys.argv[1:5]
    with open(data, newline="") as f:
        rows = list(csv.reader(f))
    header, values = rows[0], [[float(v) for v in r] for r in rows[1:] if r]
    x = [r[0] for r in values]
    pairs = [(k, k + 1) for k in range(1, len(header) - 1, 2)]
    if len(pairs) > MAX_COLUMNS:
        print(f"plot_compare: drawing the first {MAX_COLUMNS} of {len(pairs)} columns")
        pairs = pairs[:MAX_COLUMNS]
    fig, axes = plt.subplots(len(pairs), 2, figsize=(11, 2.6 * len(pairs) + 0.6), squeeze=False,
                             gridspec_kw={"width_ratios": [2, 1]})
    for row, (ka, kb) in enumerate(pairs):
        a = [r[ka] for r in values]
        b = [r[kb] for r in values]
        name = header[ka][2:]
        ax, axd = axes[row]
        ax.plot(x, b, "k-", lw=1.6, label=f"B {label_b}")
        ax.plot(x, a, "C3--", lw=1.2, label=f"A {label_a}")
        ax.set_ylabel(name if name == header[kb][2:] else f"{name} / {header[kb][2:]}")
        ax.grid(alpha=0.3)
        axd.plot(x, [p - q for p, q in zip(a, b)], "C0-", lw=1.0)
        axd.axhline(0.0, color="k", lw=0.5)
        axd.set_ylabel("A - B")
        axd.grid(alpha=0.3)
        if row == 0:
            ax.legend(fontsize=8, loc="best")
    for ax in axes[-1]:
        ax.set_xlabel(header[0])
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
