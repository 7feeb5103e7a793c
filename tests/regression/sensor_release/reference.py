#!/usr/bin/python3
"""The closed form for sensor_release.k: a 1 kg cube on 100 N/m of springs (w 10 rad/s) pushed at
0.5 m/s; the motion turns off when its force K u passes 10 N (u 0.1 m, t 0.2 s), the cube swings
u = u1 cos(w s) + (v / w) sin(w s), s = t - 0.2, and the motion drives it again TIMWIN + TDELAY
(0.15 s) after it first passes behind its start. Writes reference.csv (time, x_disp)."""
import math

k, m, v = 100.0, 1.0, 0.5
w = math.sqrt(k / m)
t_off = 10.0 / (k * v)                               # 0.2 s
u_off = v * t_off                                    # 0.1 m
t_behind = t_off + (math.pi - math.atan2(u_off * w, v)) / w   # u = 0 on the way back
t_on = t_behind + 0.05 + 0.1                         # TIMWIN + TDELAY


def swing(t):
    s = t - t_off
    return u_off * math.cos(w * s) + v / w * math.sin(w * s)


def u(t):
    if t <= t_off:
        return v * t
    if t <= t_on:
        return swing(t)
    return swing(t_on) + v * (t - t_on)


if __name__ == "__main__":
    print(f"off at {t_off:.6f} s, behind its start at {t_behind:.6f} s, on at {t_on:.6f} s, "
          f"u there {swing(t_on):.6f} m")
    with open(__file__.replace("reference.py", "reference.csv"), "w") as f:
        f.write("time,x_disp\n")
        for i in range(1001):
            t = i * 1e-3
            f.write(f"{t:.6e},{u(t):.9e}\n")
