#!/usr/bin/env bash
# Makes the pictures of README.md and doc/*.md (doc/images/*.png), each with
# the command that the text next to it states.
#
# Usage: bash scripts/readme_images.sh BUILD [--correspondence] [--performance]
#   BUILD             a diffuv build tree (its src/diffuv is used), or the diffuv binary itself
#   --correspondence  also run the correspondence benchmark (BUILD/bench/diffuv_correspondence_bench,
#                     built here if missing; about 2 min) for doc/images/correspondence_*.png
#   --performance     also run the performance benchmark (BUILD/bench/diffuv_performance_bench,
#                     built here if missing; about 18 min) for doc/images/performance_*.png
#
# Without the options only the tool's pictures are made (a few seconds):
#   cow.png, cow_atlas.png, three_peaks_angle.png (README.md), man_atlas.png, cow_baked_normals.png,
#   cow_normals_texture.png, man_baked_normals.png, elephant_baked_colors.png (doc/atlas.md),
#   cow_layout_area.png, man_layout_area.png (doc/layout.md).
# The meshes are CGAL's, extracted from Debian's libcgal-demo
# (/usr/share/doc/libcgal-dev/data.tar.gz, as the build does) into a
# temporary folder in which the commands run, so that they name a mesh by its
# file name as README.md writes them. Every command is printed before it runs.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
usage="usage: bash scripts/readme_images.sh BUILD_DIR|DIFFUV_BINARY [--correspondence] [--performance]"
[ $# -ge 1 ] || { echo "$usage" >&2; exit 2; }
if [ -d "$1" ]; then
  build=$(cd "$1" && pwd)
  diffuv="$build/src/diffuv"
else
  diffuv=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
  build=$(dirname "$(dirname "$diffuv")")
fi
shift
correspondence=0
performance=0
for option in "$@"; do
  case "$option" in
    --correspondence) correspondence=1 ;;
    --performance) performance=1 ;;
    *) echo "$usage" >&2; exit 2 ;;
  esac
done
[ -x "$diffuv" ] || { echo "readme_images.sh: no diffuv binary at $diffuv (build the target diffuv_tool)" >&2; exit 2; }
data_tar=/usr/share/doc/libcgal-dev/data.tar.gz
[ -f "$data_tar" ] || { echo "readme_images.sh: $data_tar is missing: install libcgal-demo (bash scripts/setup.sh)" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
tar xzf "$data_tar" -C "$work" data/meshes/cow.off data/meshes/three_peaks.off data/meshes/man.off \
  data/meshes/elephant.off data/meshes/refined_elephant.off
images="$root/doc/images"
cd "$work/data/meshes"

run() {
  echo "+ $*"
  "$@" >/dev/null
}
picture() { # picture FROM TO: copies a picture into doc/images
  cp "$1" "$images/$2"
  echo "  -> doc/images/$2"
}

# README.md, "Quick start": the cow's automatic patches and their u, v isolines.
run "$diffuv" param cow.off -o out
picture out/cow.png cow.png

# README.md, "Quick start": the texture the cow's charts are packed into.
run "$diffuv" param cow.off --outputs atlas -o out
picture out/cow.atlas.png cow_atlas.png

# doc/atlas.md: man's packed texture.
run "$diffuv" param man.off --outputs atlas -o out
picture out/man.atlas.png man_atlas.png

# README.md: the paper's method (graph distances, no repair) folds at the bottom of two peaks.
run "$diffuv" render three_peaks.off --color angle --distance graph --no-repair --layout voronoi -o out
picture out/three_peaks.png three_peaks_angle.png

# doc/layout.md: the four-sided layout's area distortion.
run "$diffuv" render cow.off --color area -o out
picture out/cow.png cow_layout_area.png
run "$diffuv" render man.off --color area -o out
picture out/man.png man_layout_area.png
# doc/atlas.md: normal maps baked into cow's and man's packed textures, and the
# colours diffuv correspond carries onto the elephant, baked.
run "$diffuv" bake cow.off --what normals --resolution 512 -o out
picture out/cow.png cow_baked_normals.png
picture out/cow.normals.png cow_normals_texture.png
run "$diffuv" bake man.off --what normals --resolution 512 -o out
picture out/man.png man_baked_normals.png
run "$diffuv" segment elephant.off -o seg
run "$diffuv" correspond seg/elephant.patches.ply refined_elephant.off --transfer-labels -o corr
run "$diffuv" bake corr/transfer.ply -o out
picture out/transfer.png elephant_baked_colors.png

bench_program() { # bench_program TARGET: the path of a benchmark, built if missing
  if [ ! -x "$build/bench/$1" ]; then
    echo "+ cmake --build $build --target $1 -j2" >&2
    cmake --build "$build" --target "$1" -j2 >&2
  fi
  echo "$build/bench/$1"
}

# The benchmarks run from the checkout's root, as doc/correspondence.md and
# doc/performance.md write their commands, and leave their tables in bench-out/.
cd "$root"

# doc/correspondence.md: the accuracy table (printed) and its cumulative error curves.
if [ "$correspondence" = 1 ]; then
  bench=$(bench_program diffuv_correspondence_bench)
  echo "+ $bench --runs 3 -o bench-out/correspondence"
  status=0
  "$bench" --runs 3 -o bench-out/correspondence || status=$?
  # 1: a target missed, which the table reports; anything else is an error.
  [ "$status" -le 1 ] || exit "$status"
  for mesh in cow man elephant hand; do picture "bench-out/correspondence/correspondence_$mesh.png" "correspondence_$mesh.png"; done
fi

# doc/performance.md: time against size per mesh, time / (E log2 V), the heaps.
if [ "$performance" = 1 ]; then
  bench=$(bench_program diffuv_performance_bench)
  echo "+ $bench --meshes cow,man,lion-head --sizes 1000000 --max-vertices 1200000 --runs 5 --large-runs 1 --profile -o bench-out/performance"
  status=0
  "$bench" --meshes cow,man,lion-head --sizes 1000000 --max-vertices 1200000 --runs 5 --large-runs 1 --profile \
    -o bench-out/performance || status=$?
  # 1: a measurement that did not end "ok", which the table reports; anything else is an error.
  [ "$status" -le 1 ] || exit "$status"
  for mesh in cow man lion-head; do picture "bench-out/performance/time_$mesh.png" "performance_time_$mesh.png"; done
  picture bench-out/performance/scaling.png performance_scaling.png
  picture bench-out/performance/heaps.png performance_heaps.png
fi
