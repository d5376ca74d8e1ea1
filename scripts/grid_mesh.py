#!/usr/bin/env python3
"""Writes the square grids of the whole-run measurements (issue #20) as OFF.

Usage: python3 scripts/grid_mesh.py [--n 1050] [--surface smooth|crumpled] OUT.off

n x n vertices on the unit square (1050: 1.1M vertices, 2.2M triangles), two
triangles per cell, coordinates written with 17 significant digits:
- smooth:   z = 0.1 sin(6x) cos(6y), a gently curved disc (one chart);
- crumpled: z = 0.1 sin(0.01 i j), the surface of bench/reading's grid1m, which
  folds at the grid's own spacing once i j is large (fine for reading, a hard
  case for the layout).
"""
import argparse
import math


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n", type=int, default=1050)
    ap.add_argument("--surface", choices=("smooth", "crumpled"), default="smooth")
    ap.add_argument("out")
    a = ap.parse_args()
    n = a.n
    if n < 2:
        raise SystemExit("--n must be at least 2")
    with open(a.out, "w") as f:
        f.write(f"OFF\n{n * n} {2 * (n - 1) * (n - 1)} 0\n")
        for j in range(n):
            y = j / (n - 1)
            rows = []
            for i in range(n):
                x = i / (n - 1)
                z = 0.1 * math.sin(6 * x) * math.cos(6 * y) if a.surface == "smooth" else 0.1 * math.sin(0.01 * i * j)
                rows.append(f"{x!r} {y!r} {z!r}\n")
            f.write("".join(rows))
        for j in range(n - 1):
            lines = []
            for i in range(n - 1):
                p = j * n + i
                lines.append(f"3 {p} {p + 1} {p + n + 1}\n3 {p} {p + n + 1} {p + n}\n")
            f.write("".join(lines))


if __name__ == "__main__":
    main()
