#!/usr/bin/env python3
"""Helpers of run_painter_test.sh (Python standard library only).

  painter_test_tools.py result DOM_FILE
      Reads the DOM Chromium dumped (--dump-dom) of the painter page opened
      with ?test=1, takes the JSON the page wrote into <pre id="test-result">,
      prints every check and exits 1 if one failed or the result is missing.

  painter_test_tools.py png-colors PNG_FILE MIN_COLORS [LEFT]
      Decodes a PNG screenshot (8-bit RGB or RGBA, not interlaced) and exits 1
      unless it has more than MIN_COLORS distinct colours in its pixel columns
      from LEFT on (default 0; the painter's panel is 280 pixels wide, so a
      LEFT past it looks at the 3D view only).

  painter_test_tools.py png-color PNG_FILE NAME RRGGBB LEFT RIGHT [MIN_PIXELS]
      Exits 1 unless at least MIN_PIXELS (default 20) pixels in the columns
      LEFT <= x < RIGHT have the colour RRGGBB (each channel within 8): the
      picked point's marker (an unlit magenta ball) in one mesh's view.

  painter_test_tools.py animal-labels MESH.off LEG_HEIGHT HEAD_X HEAD_Y [flip]
      Prints a label file (one label a face) for a four-legged animal standing
      along x with y up: legs 0 to 3 (front left, front right, hind left,
      hind right: the four largest pieces below LEG_HEIGHT), head 4 (the
      largest piece beyond HEAD_X and above HEAD_Y), front body 5, hind body
      6; heights and lengths are fractions of the bounding box; "flip" for an
      animal facing -x. Stray islands of a label join their neighbours.
      doc/images/painter_correspond.png: cow.off 0.25 0.78 0.45 (A) and
      bull.off 0.25 0.8 0.45 flip (B).
"""
from collections import defaultdict
import html
import json
import os
import re
import struct
import sys
import zlib


def check_result(dom_file):
    with open(dom_file, encoding="utf-8", errors="replace") as f:
        dom = f.read()
    match = re.search(r'<pre id="test-result"[^>]*>(.*?)</pre>', dom, re.S)
    if not match or not match.group(1).strip():
        print("FAIL: the page wrote no test result (see the browser log)")
        return 1
    try:
        result = json.loads(html.unescape(match.group(1)))
    except ValueError as e:
        print("FAIL: the test result is not JSON: %s" % e)
        print(match.group(1)[:2000])
        return 1
    checks = result.get("checks") or []
    if not checks:
        print("FAIL: the test result has no checks")
        return 1
    failed = 0
    for c in checks:
        ok = c.get("ok") is True
        failed += not ok
        print("%s  %-18s %s" % ("ok  " if ok else "FAIL", c.get("name"),
                                json.dumps(c.get("detail"), separators=(",", ":"))))
    print("%d of %d checks passed (%s faces)" % (len(checks) - failed, len(checks), result.get("faces")))
    return 1 if failed else 0


def read_off_file(path):
    """Points and faces of an OFF file: scripts/height_labels.py's reader."""
    scripts = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'scripts')
    if scripts not in sys.path:
        sys.path.insert(0, scripts)
    from height_labels import read_off
    return read_off(path)


def animal_labels(path, leg_height, head_x, head_y, flip=False):
    points, faces = read_off_file(path)
    lo = [min(p[d] for p in points) for d in range(3)]
    hi = [max(p[d] for p in points) for d in range(3)]
    count = len(faces)
    place = []  # each face's centroid, as fractions of the box
    for face in faces:
        c = [sum(points[v][d] for v in face) / len(face) for d in range(3)]
        n = [(c[d] - lo[d]) / (hi[d] - lo[d]) for d in range(3)]
        if flip:
            n[0], n[2] = 1 - n[0], 1 - n[2]
        place.append(n)
    faces_of_edge = defaultdict(list)
    for i, face in enumerate(faces):
        for k in range(len(face)):
            a, b = face[k], face[(k + 1) % len(face)]
            faces_of_edge[(min(a, b), max(a, b))].append(i)
    neighbours = defaultdict(list)
    for shared in faces_of_edge.values():
        for i in shared:
            neighbours[i].extend(j for j in shared if j != i)

    def pieces(member):  # connected sets of member faces, largest first
        seen = [False] * count
        result = []
        for start in range(count):
            if seen[start] or not member[start]:
                continue
            seen[start] = True
            stack, piece = [start], []
            while stack:
                f = stack.pop()
                piece.append(f)
                for g in neighbours[f]:
                    if not seen[g] and member[g]:
                        seen[g] = True
                        stack.append(g)
            result.append(piece)
        return sorted(result, key=len, reverse=True)

    label = [5 if place[f][0] >= 0.5 else 6 for f in range(count)]
    legs = pieces([place[f][1] < leg_height for f in range(count)])[:4]
    middles = [[sum(place[f][d] for f in leg) / len(leg) for d in range(3)] for leg in legs]
    mid_x = sum(m[0] for m in middles) / len(middles)
    for leg, m in zip(legs, middles):
        front = m[0] > mid_x
        pair = [k for k in middles if (k[0] > mid_x) == front]
        mid_z = sum(k[2] for k in pair) / len(pair)
        for f in leg:
            label[f] = (0 if front else 2) + (0 if m[2] > mid_z else 1)
    head = pieces([place[f][0] > head_x and place[f][1] > head_y for f in range(count)])
    for f in head[0] if head else []:
        label[f] = 4
    for _ in range(3):  # stray islands of a label: the label around them
        for l in range(7):
            for island in pieces([label[f] == l for f in range(count)])[1:]:
                around = defaultdict(int)
                for f in island:
                    for g in neighbours[f]:
                        if label[g] != l:
                            around[label[g]] += 1
                if around:
                    new = max(around, key=around.get)
                    for f in island:
                        label[f] = new
    return label


def png_pixels(path):
    """Returns (width, height, channels, rows) with rows a list of bytes."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG file")
    pos, idat, header = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
    width, height, depth, color_type, _, _, interlace = header
    if depth != 8 or color_type not in (2, 6) or interlace:
        raise ValueError("only 8-bit RGB/RGBA non-interlaced PNGs are read "
                         "(depth %d, colour type %d, interlace %d)" % (depth, color_type, interlace))
    channels = 3 if color_type == 2 else 4
    raw = zlib.decompress(b"".join(idat))
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up = previous[i]
            up_left = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + ((left + up) >> 1)) & 255
            elif kind == 4:  # Paeth
                p = left + up - up_left
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - up_left)
                pred = left if pa <= pb and pa <= pc else (up if pb <= pc else up_left)
                line[i] = (line[i] + pred) & 255
        rows.append(bytes(line))
        previous = line
    return width, height, channels, rows


def check_png_colors(path, min_colors, left=0):
    try:
        width, height, channels, rows = png_pixels(path)
    except (OSError, ValueError, zlib.error, TypeError) as e:
        print("FAIL  screenshot         cannot read %s: %s" % (path, e))
        return 1
    colors = set()
    for row in rows:
        for i in range(left * channels, len(row), channels):
            colors.add(row[i:i + 3])
    ok = len(colors) > min_colors
    print("%s  %-18s %d x %d, %d distinct colours right of x = %d"
          % ("ok  " if ok else "FAIL", "screenshot", width, height, len(colors), left))
    return 0 if ok else 1


def check_png_color(path, name, color, left, right, min_pixels=20):
    try:
        width, height, channels, rows = png_pixels(path)
    except (OSError, ValueError, zlib.error, TypeError) as e:
        print("FAIL  %-18s cannot read %s: %s" % (name, path, e))
        return 1
    want = bytes.fromhex(color)
    count = 0
    for row in rows:
        for i in range(max(0, left) * channels, min(width, right) * channels, channels):
            if all(abs(row[i + k] - want[k]) <= 8 for k in range(3)):
                count += 1
    ok = count >= min_pixels
    print("%s  %-18s %d pixels of #%s in columns %d to %d"
          % ("ok  " if ok else "FAIL", name, count, color, left, right))
    return 0 if ok else 1


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "result":
        sys.exit(check_result(sys.argv[2]))
    if len(sys.argv) in (4, 5) and sys.argv[1] == "png-colors":
        sys.exit(check_png_colors(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]) if len(sys.argv) == 5 else 0))
    if len(sys.argv) in (7, 8) and sys.argv[1] == "png-color":
        sys.exit(check_png_color(sys.argv[2], sys.argv[3], sys.argv[4], int(sys.argv[5]), int(sys.argv[6]),
                                 int(sys.argv[7]) if len(sys.argv) == 8 else 20))
    if len(sys.argv) in (6, 7) and sys.argv[1] == "animal-labels":
        labels = animal_labels(sys.argv[2], float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5]),
                               len(sys.argv) == 7 and sys.argv[6] == "flip")
        print("\n".join(map(str, labels)))
        sys.exit(0)
    print(__doc__)
    sys.exit(2)
