#!/usr/bin/env bash
# What is one-to-one, measured (doc/quality.md, README.md): runs `diffuv param`
# on the meshes the README names, with diffuv's own patches and with height
# bands as labels, and on the sweep's meshes that are not all one-to-one
# (cmake/sweep_tests.cmake), and prints one Markdown row per run from the
# table the tool prints: charts, charts that are not injective, and the
# flipped, degenerate, flat and overlapping triangles of all of them, with the
# charts that have a flipped or overlapping triangle or a degenerate one that
# is not flat (the ones the README's claim would not cover).
#
# Usage: bash scripts/injectivity_table.sh BUILD    (a build tree with src/diffuv and data/meshes)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:?usage: bash scripts/injectivity_table.sh BUILD}" && pwd)
diffuv="$build/src/diffuv"
meshes="$build/data/meshes"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

row() { # row NAME ARGS...: one run of diffuv param, one row
  local name=$1
  shift
  "$diffuv" param "$@" -o "$work/out" >"$work/table.txt" 2>/dev/null
  python3 - "$name" "$work/table.txt" <<'EOF'
import sys
name, path = sys.argv[1], sys.argv[2]
charts = not_injective = unexplained = 0
total = None
for line in open(path):
    t = line.split()
    if t and t[0] == "total":
        total = t
    if len(t) < 13 or not t[0].isdigit():
        continue
    try:  # columns from the right: ... flipped degen flat overlaps angle_avg ... injective
        flipped, degen, flat, overlaps = int(t[-11]), int(t[-10]), int(t[-9]), int(t[-8])
    except ValueError:
        continue  # a patch that could not be mapped
    charts += 1
    not_injective += t[-1] != "yes"
    unexplained += flipped > 0 or overlaps > 0 or degen > flat
print(f"| {name} | {charts} | {not_injective} | {total[-11]} | {total[-10]} | {total[-9]} | {total[-8]} | {unexplained} |")
EOF
}

echo "| mesh | charts | not injective | flipped | degenerate | flat | overlaps | charts with a fold, an overlap or a degenerate triangle that is not flat |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
for m in cow man bull elephant refined_elephant mushroom three_peaks; do row "$m" "$meshes/$m.off"; done
row "nefertiti, CGAL's corners" "$meshes/nefertiti.off" --corners "$build/data/selections/square_corners.selection.txt"
for bands in 3 4 6; do
  python3 "$root/scripts/height_labels.py" "$meshes/bull.off" z "$bands" >"$work/bull.labels.txt"
  row "bull, $bands height bands (z)" "$meshes/bull.off" --labels "$work/bull.labels.txt"
done
python3 "$root/scripts/height_labels.py" "$meshes/man.off" z 6 >"$work/man.labels.txt"
row "man, 6 height bands (z)" "$meshes/man.off" --labels "$work/man.labels.txt"
for m in b9_mesh blobby_3cc boeing cheese couplingdown elephant-with-holes mech-holes-shark; do
  row "$m" "$meshes/$m.off"
done
