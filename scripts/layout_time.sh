#!/bin/bash
# Layout time against map time (issue #18): medians of 3 runs of
# `diffuv param MESH` (default settings), read from its `stages:` line.
#
#   scripts/layout_time.sh [DIFFUV] [MESH ...]
#
# DIFFUV defaults to build/src/diffuv; meshes default to the ten of
# doc/layout.md, from build/data/meshes. Prints: mesh patches_ms map_ms ratio.
set -euo pipefail
exe=${1:-build/src/diffuv}
shift || true
meshes=("$@")
[ ${#meshes[@]} -gt 0 ] || meshes=(cow man bull armadillo bunny00 camel bear homer triceratops elephant)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
ms() { awk '{v = $1; if($2 == "s") v *= 1000; print v}'; }
median() { sort -g | sed -n 2p; }
printf '%-12s %10s %8s %6s\n' mesh patches_ms map_ms ratio
for m in "${meshes[@]}"; do
  file=$m
  [ -f "$file" ] || file=build/data/meshes/$m.off
  patches=() maps=()
  for run in 1 2 3; do
    line=$("$exe" param "$file" -o "$out" 2>&1 | grep '^stages:')
    patches+=("$(echo "$line" | sed -E 's/.*patches ([0-9.]+ m?s).*/\1/' | ms)")
    maps+=("$(echo "$line" | sed -E 's/.*map ([0-9.]+ m?s).*/\1/' | ms)")
  done
  p=$(printf '%s\n' "${patches[@]}" | median)
  q=$(printf '%s\n' "${maps[@]}" | median)
  awk -v m="$(basename "$m" .off)" -v p="$p" -v q="$q" 'BEGIN { printf "%-12s %10s %8s %6.1f\n", m, p, q, p / q }'
done
