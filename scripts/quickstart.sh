#!/usr/bin/env bash
# Quick start (a): set up, build in Release, run `diffuv param` on CGAL's cow.off (automatic patches).
# Results are written to ./diffuv-out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target diffuv_tool
build/src/diffuv param -o diffuv-out "$@"
