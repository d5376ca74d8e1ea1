#!/usr/bin/env python3
"""Whole-process times of `diffuv param` (issue #20): medians of several runs.

Usage: python3 scripts/whole_run.py [--tool build/src/diffuv] [--runs 5] [MESH ...]
Default meshes: cow.off and man.off of CGAL's data set (build/data/meshes).
Each run is the whole process (wall clock, read to last file written) with
default outputs, then with `--outputs uv --no-measure -q` (a batch user's
run); the stage times are those the tool prints. Prints a Markdown table
with each target (cow <= 40 ms, man <= 150 ms) next to its measurement.
"""
import argparse
import os
import re
import statistics
import subprocess
import tempfile
import time

TARGETS = {"cow": 40.0, "man": 150.0}


def run_once(tool, mesh, extra, out):
    start = time.perf_counter()
    r = subprocess.run([tool, "param", mesh, "-o", out] + extra, capture_output=True, text=True)
    wall = (time.perf_counter() - start) * 1000
    if r.returncode != 0:
        raise SystemExit(f"{mesh}: exit {r.returncode}: {r.stderr}")
    stages = {}
    m = re.search(r"^stages: (.*)$", r.stdout, re.M)
    if m:
        for part in m.group(1).split(", "):
            name, value, unit = part.split(" ")[:3]
            stages[name] = float(value) * (1000 if unit == "s" else 1)
    return wall, stages


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tool", default=os.path.join(root, "build", "src", "diffuv"))
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("meshes", nargs="*")
    a = ap.parse_args()
    meshes = a.meshes or [os.path.join(root, "build", "data", "meshes", m) for m in ("cow.off", "man.off")]
    print("| mesh | run | whole process ms | read | patches | map | measure | write | target | met |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---|")
    with tempfile.TemporaryDirectory() as out:
        for mesh in meshes:
            name = os.path.splitext(os.path.basename(mesh))[0]
            for label, extra in (("default", []), ("--outputs uv --no-measure -q", ["--outputs", "uv", "--no-measure", "-q"])):
                walls, stages = [], {}
                for _ in range(a.runs):
                    wall, s = run_once(a.tool, mesh, extra, out)
                    walls.append(wall)
                    for k, v in s.items():
                        stages.setdefault(k, []).append(v)
                med = statistics.median(walls)
                cell = lambda k: f"{statistics.median(stages[k]):.0f}" if k in stages else "-"
                target = TARGETS.get(name)
                met = "" if target is None or label != "default" else ("yes" if med <= target else "no")
                print(f"| {name} | {label} | {med:.0f} | {cell('read')} | {cell('patches')} | {cell('map')} | "
                      f"{cell('measure')} | {cell('write')} | {'' if target is None else f'{target:.0f}'} | {met} |")


if __name__ == "__main__":
    main()
