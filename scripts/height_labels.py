#!/usr/bin/env python3
"""Writes a region label file that paints a mesh in horizontal bands.

    height_labels.py MESH.off AXIS BANDS > labels.txt

Each face gets the band (0 .. BANDS-1) of its centroid along AXIS (x, y or z).
A quick stand-in for painted regions: on a standing animal or person the
lowest band falls apart into feet, which are caps (one neighbour all around),
the case the paper splits in two. Used by doc/measurements.md.
"""
import sys


def read_off(path):
    tokens = []
    with open(path) as f:
        for line in f:
            tokens.extend(line.split('#', 1)[0].split())
    if not tokens or tokens[0] != 'OFF':
        sys.exit(f'{path}: not an OFF file')
    nv, nf = int(tokens[1]), int(tokens[2])
    i = 4
    points = [tuple(map(float, tokens[i + 3 * k:i + 3 * k + 3])) for k in range(nv)]
    i += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(tokens[i])
        faces.append([int(t) for t in tokens[i + 1:i + 1 + n]])
        i += 1 + n
    return points, faces


def main():
    if len(sys.argv) != 4 or sys.argv[2] not in 'xyz':
        sys.exit(__doc__)
    points, faces = read_off(sys.argv[1])
    axis, bands = 'xyz'.index(sys.argv[2]), int(sys.argv[3])
    lo = min(p[axis] for p in points)
    hi = max(p[axis] for p in points)
    for face in faces:
        c = sum(points[v][axis] for v in face) / len(face)
        print(min(bands - 1, int((c - lo) / (hi - lo) * bands)))


if __name__ == '__main__':
    main()
