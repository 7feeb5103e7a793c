"""Numeric CSV files of named columns (one header row, %.9e), shared by the verification scripts
and tools/study.py's run records."""
import numpy as np


def write_columns(path, names, columns):
    with open(path, "w") as f:
        f.write(",".join(names) + "\n")
        for row in zip(*columns):
            f.write(",".join(f"{v:.9e}" for v in row) + "\n")


def read_columns(path):
    """The columns of a file written by write_columns, in order."""
    data = np.genfromtxt(path, delimiter=",", names=True)
    return [data[n] for n in data.dtype.names]
