#!/usr/bin/env bash
# Regenerates the tables of doc/quality.md: every distance backend with and
# without the fold repair, next to CGAL's parameterizers, on the same patches
# with the same corners. Usage: scripts/quality_tables.sh [build-dir] [runs]
set -euo pipefail
build=${1:-build}
runs=${2:-5}
tool="$build/src/diffuv"
data="$build/data/meshes"
methods=diffuv-graph-raw,diffuv-graph,diffuv-fmm-raw,diffuv-fmm,diffuv-exact-raw,diffuv-exact,tutte,mean_value,authalic,conformal,lscm,arap
for mesh in nefertiti mushroom three_peaks lion-head mannequin-devil cow man; do
  m=$methods
  # Exact geodesics take seconds per patch on the closed meshes' many patches; skip them there.
  case $mesh in cow|man) m=${methods//diffuv-exact-raw,diffuv-exact,/} ;; esac
  echo '```'
  "$tool" compare "$data/$mesh.off" --runs "$runs" --methods "$m"
  echo '```'
  echo
done
echo '```'
"$tool" compare "$data/nefertiti.off" --corners "$build/data/selections/square_corners.selection.txt" --runs "$runs" --methods "$methods"
echo '```'
