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
"""
import html
import json
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


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "result":
        sys.exit(check_result(sys.argv[2]))
    if len(sys.argv) in (4, 5) and sys.argv[1] == "png-colors":
        sys.exit(check_png_colors(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]) if len(sys.argv) == 5 else 0))
    print(__doc__)
    sys.exit(2)
