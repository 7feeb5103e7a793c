#!/usr/bin/python3
"""The damped oscillator's closed form for spring_damper.k: m 1 kg, k 100 N/m, c 2 N s/m, started
at x 0 with 1 m/s: x(t) = v0 / wd exp(-zeta w t) sin(wd t). Writes reference.csv (time, x_disp)."""
import math

m, k, c, v0 = 1.0, 100.0, 2.0, 1.0
w = math.sqrt(k / m)
zeta = c / (2.0 * m * w)
wd = w * math.sqrt(1.0 - zeta * zeta)
with open(__file__.replace("reference.py", "reference.csv"), "w") as f:
    f.write("time,x_disp\n")
    for i in range(2001):
        t = i * 1e-3
        f.write(f"{t:.6e},{v0 / wd * math.exp(-zeta * w * t) * math.sin(wd * t):.9e}\n")
