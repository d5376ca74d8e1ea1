#!/usr/bin/env python3
"""diffuv's default atlas next to Blender's Smart UV Project, on the same meshes.

Runs `diffuv param` (default settings) and, when Blender is installed
(Debian package `blender`), Smart UV Project headless at its defaults; both
OBJ files are measured by `diffuv measure` (diffuv's own measure_distortion(),
chart by chart, means weighted by 3D area). Prints a Markdown table.

usage: scripts/compare_blender.py [--build BUILD] [--runs N] [--out DIR] [--bands AXIS:N] [MESH ...]
MESH: a path, or a name of CGAL's data set (build/data/meshes/NAME.off).
--bands AXIS:N labels each mesh in N height bands along AXIS
(scripts/height_labels.py) and runs `diffuv param --labels` on them: the
layout inside painted regions (e.g. --bands y:4 cow, --bands z:6 man).
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
MESHES = ["cow", "man", "bull", "armadillo", "bunny00", "camel", "bear", "homer", "triceratops", "elephant"]


def run(command):
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("failed (%d): %s\n%s" % (result.returncode, " ".join(command), result.stderr))
    return result.stdout


def measure(diffuv, obj):
    lines = run([diffuv, "measure", obj]).splitlines()
    header = next(i for i, line in enumerate(lines) if line.split()[:2] == ["charts", "not_1-to-1"])
    values = lines[header + 1].split()
    keys = ["charts", "not_injective", "flipped", "degen", "overlaps", "angle", "area", "l2", "linf",
            "texels", "shared", "density10"]
    return dict(zip(keys, [float(v) for v in values]))


def diffuv_run(diffuv, mesh, out, runs, bands=None):
    command = [diffuv, "param", mesh, "-o", out]
    if bands:
        axis, count = bands.split(":")
        os.makedirs(out, exist_ok=True)
        labels = os.path.join(out, "bands.txt")
        with open(labels, "w") as f:
            f.write(run([sys.executable, os.path.join(HERE, "height_labels.py"), mesh, axis, count]))
        command += ["--labels", labels]
    times = []
    for _ in range(runs):
        text = run(command)
        stages = re.search(r"stages: (.*)", text).group(1)
        parsed = {}
        for name, value, unit in re.findall(r"(\w+) ([0-9.]+) (ms|s)", stages):
            parsed[name] = float(value) * (1000.0 if unit == "s" else 1.0)
        times.append(parsed)
    vertices = int(re.search(r": (\d+) vertices", text).group(1))
    total = re.search(r"^total\s+\d+\s+\d+\s+[0-9.]+\s+(\d+)", text, re.M)
    moved = int(total.group(1)) if total else 0
    stem = os.path.splitext(os.path.basename(mesh))[0]
    result = measure(diffuv, os.path.join(out, stem + ".obj"))
    result["moved"] = 100.0 * moved / max(vertices, 1)
    result["patches_ms"] = statistics.median(t["patches"] for t in times)
    result["map_ms"] = statistics.median(t["map"] for t in times)
    return result


def blender_run(mesh_obj, out, runs):
    seconds = []
    target = os.path.join(out, "blender.obj")
    for _ in range(runs):
        text = run(["blender", "-b", "--python", os.path.join(HERE, "blender_smart_uv.py"), "--", mesh_obj, target])
        seconds.append(float(re.search(r"smart_project_seconds ([0-9.]+)", text).group(1)))
    return target, statistics.median(seconds) * 1000.0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("meshes", nargs="*", default=MESHES)
    parser.add_argument("--build", default=os.path.join(HERE, "..", "build"))
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--out", default="compare-out")
    parser.add_argument("--bands", help="AXIS:N, e.g. y:4: label the meshes in N height bands first")
    args = parser.parse_args()
    diffuv = os.path.join(args.build, "src", "diffuv")
    if not os.path.exists(diffuv):
        sys.exit("no %s: build diffuv first (bash scripts/test.sh)" % diffuv)
    blender = shutil.which("blender") is not None
    if not blender:
        print("blender not found (apt-get install blender): only diffuv is measured", file=sys.stderr)
    rows = []
    for name in args.meshes:
        mesh = name if os.path.exists(name) else os.path.join(args.build, "data", "meshes", name + ".off")
        stem = os.path.splitext(os.path.basename(mesh))[0]
        out = os.path.join(args.out, stem)
        d = diffuv_run(diffuv, mesh, out, args.runs, args.bands)
        b = None
        if blender:
            # Blender reads OBJ: diffuv's own output has the same vertices in the same order.
            target, ms = blender_run(os.path.join(out, stem + ".obj"), out, args.runs)
            b = measure(diffuv, target)
            b["ms"] = ms
        rows.append((stem, d, b))
        print("measured", stem, file=sys.stderr)
    # texture: texels of a 1024 x 1024 texture whose centre lies in a chart;
    # density: share of the 3D area in charts within 10 % of the median texel density.
    print("| mesh | diffuv charts | not 1-to-1 | moved | L2 | area | angle | texture | density ±10 % | layout ms | map ms |"
          " Blender charts | not 1-to-1 | L2 | area | angle | texture | density ±10 % | Blender ms |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for stem, d, b in rows:
        line = "| %s | %d | %d | %.2f %% | %.3f | %.3f | %.3f | %.1f %% | %.1f %% | %.0f | %.0f |" % (
            stem, d["charts"], d["not_injective"], d["moved"], d["l2"], d["area"], d["angle"], d["texels"],
            d["density10"], d["patches_ms"], d["map_ms"])
        if b:
            line += " %d | %d | %.3f | %.3f | %.3f | %.1f %% | %.1f %% | %.0f |" % (
                b["charts"], b["not_injective"], b["l2"], b["area"], b["angle"], b["texels"], b["density10"], b["ms"])
        else:
            line += " - | - | - | - | - | - | - | - |"
        print(line)


if __name__ == "__main__":
    main()
