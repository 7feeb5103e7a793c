#!/usr/bin/python3
"""Writes a keyword deck with an N x N x N block of hexahedra (N^3 elements, (N+1)^3 nodes) in
standard fixed columns, two-line *ELEMENT_SOLID layout, for the `mcdyna check` speed benchmark."""
import sys


def main() -> None:
    if len(sys.argv) != 3:
        sys.exit("usage: generate_mesh_deck.py N OUT.k")
    n, out = int(sys.argv[1]), sys.argv[2]
    m = n + 1
    with open(out, "w", buffering=1 << 24) as f:
        f.write("*KEYWORD\n*TITLE\nbenchmark block\n*CONTROL_TERMINATION\n1.0E-3\n")
        f.write("*PART\nblock\n         1         1         1\n*SECTION_SOLID\n         1         1\n")
        f.write("*MAT_ELASTIC\n         1    7.8E-9  210000.0       0.3\n*NODE\n")
        h = 1.0 / n
        lines = []
        nid = 0
        for k in range(m):
            z = f"{k * h:16.8f}"
            for j in range(m):
                y = f"{j * h:16.8f}"
                lines.clear()
                for i in range(m):
                    nid += 1
                    lines.append(f"{nid:8d}{i * h:16.8f}{y}{z}       0       0\n")
                f.write("".join(lines))
        f.write("*ELEMENT_SOLID\n")
        eid = 0
        for k in range(n):
            for j in range(n):
                lines.clear()
                for i in range(n):
                    eid += 1
                    a = 1 + i + m * j + m * m * k
                    nodes = (a, a + 1, a + 1 + m, a + m, a + m * m, a + 1 + m * m,
                             a + 1 + m + m * m, a + m + m * m)
                    lines.append(f"{eid:8d}       1\n" + "".join(f"{x:8d}" for x in nodes) + "\n")
                f.write("".join(lines))
        f.write("*END\n")


if __name__ == "__main__":
    main()
