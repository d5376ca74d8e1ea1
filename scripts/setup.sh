#!/usr/bin/env bash
# Installs every Debian package diffuv's build, tests and examples need.
# Idempotent: does nothing (and prints nothing) when all are present.
set -euo pipefail

packages=(
  cmake g++ make ccache
  libcgal-dev libgmp-dev libmpfr-dev   # CGAL: Surface_mesh, BGL traits, kd-tree, IO, parameterizers
  libcgal-demo                         # CGAL's data set: data.tar.gz / examples.tar.gz
  libboost-dev libboost-graph-dev      # Boost.Graph (Dijkstra reference), Boost.Heap
  libeigen3-dev                        # linear algebra for CGAL's parameterizers
  libtbb-dev                           # oneTBB: patches mapped in parallel
  libgtest-dev                         # tests
  libcli11-dev                         # the diffuv command line
  libstb-dev                           # stb_image_write and stb_rect_pack: PNG textures, renders, the packed atlas
  libtinygltf-dev                      # glTF 2.0 files (the textured mesh for three.js, Blender, game engines)
  zlib1g-dev                           # the checker texture as an indexed PNG, deflated row by row
  pkg-config libcpp-httplib-dev        # diffuv serve: the painter's local web server (found through pkg-config)
  nlohmann-json3-dev                   # diffuv serve: the JSON of its API
  libjs-three                          # the painter page's 3D view (three.js, served by diffuv serve)
  chromium                             # the painter page tested in a real headless browser
  python3                              # scripts/height_labels.py, and XML checks in tests
  clang libclang-rt-dev                # libFuzzer targets (test/fuzz, scripts/fuzz.sh)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
