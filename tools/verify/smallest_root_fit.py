#!/usr/bin/python3
"""The coefficients of src/solver/spg/smallest_stretch.hpp: the smallest root of
t^3 - 3 t - 2 r = 0, t = 2 cos((acos r + 2 pi) / 3), as a polynomial in u = sqrt(1 - r) on
[0, sqrt 2], interpolated at Chebyshev nodes (degree 13). Prints the coefficients, highest power
first as the header's Horner loop takes them, and the largest error on a fine grid.

Usage: /usr/bin/python3 tools/verify/smallest_root_fit.py [DEGREE]"""
import sys

import numpy as np
from numpy.polynomial import chebyshev, polynomial

DEGREE = int(sys.argv[1]) if len(sys.argv) > 1 else 13
LENGTH = np.sqrt(2.0)


def smallest_root(u):
    # acos(1 - u^2) = 2 asin(u / sqrt 2), which keeps its digits for small u.
    return 2.0 * np.cos((2.0 * np.arcsin(u / LENGTH) + 2.0 * np.pi) / 3.0)


nodes = np.cos(np.pi * (np.arange(200) + 0.5) / 200)  # on [-1, 1]
fit = chebyshev.chebfit(nodes, smallest_root((nodes + 1.0) * LENGTH / 2.0), DEGREE)
in_x = chebyshev.cheb2poly(fit)
in_u = np.zeros(1)
for a in in_x[::-1]:  # x = 2 u / sqrt 2 - 1
    in_u = polynomial.polyadd(polynomial.polymul(in_u, [-1.0, 2.0 / LENGTH]), [a])
grid = np.linspace(0.0, LENGTH, 200001)
value = np.zeros_like(grid)
for a in in_u[::-1]:
    value = value * grid + a
print("largest error on [0, sqrt 2]: %.3g" % np.abs(value - smallest_root(grid)).max())
print(", ".join("%.17g" % a for a in in_u[::-1]))
