#!/usr/bin/env bash
# Tests the painter page of `diffuv serve` in headless Chromium.
#
#   run_painter_test.sh DIFFUV_BINARY MESH
#
# Starts the server on a free port with MESH as mesh A and a copy of it as
# mesh B, both painted in height bands (scripts/height_labels.py), opens the
# page with ?test=1 (the page paints, undoes, saves, lays out and maps by
# itself, paints B the same way, lays it out, runs the correspondence and
# picks a point, and writes its checks into <pre id="test-result">), prints
# the checks, then takes screenshots of the normal page and of the
# correspondence view (?view=correspond) and checks they are not blank.
# DIFFUV_PAINTER_SCREENSHOT / DIFFUV_PAINTER_CORRESPOND_SCREENSHOT: where to
# keep the screenshots.
# Exit status: 0 passed, 1 failed, 77 skipped (no Chromium), 2 usage.
set -u

if [ $# -ne 2 ]; then
  echo "usage: $0 DIFFUV_BINARY MESH" >&2
  exit 2
fi
diffuv=$1
mesh=$2

browser=""
for name in chromium chromium-browser google-chrome-stable google-chrome; do
  if command -v "$name" >/dev/null 2>&1; then browser=$(command -v "$name"); break; fi
done
if [ -z "$browser" ]; then
  echo "SKIP: no chromium found"
  exit 77
fi
if ! command -v python3 >/dev/null 2>&1; then
  echo "SKIP: no python3 found"
  exit 77
fi

here=$(cd "$(dirname "$0")" && pwd)
tools="$here/painter_test_tools.py"
work=$(mktemp -d "${TMPDIR:-/tmp}/diffuv-painter-test.XXXXXX")
server_pid=""
cleanup() {
  if [ -n "$server_pid" ] && kill -0 "$server_pid" 2>/dev/null; then
    kill "$server_pid" 2>/dev/null
    wait "$server_pid" 2>/dev/null
  fi
  rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 1' INT TERM

# Mesh B: a copy of A (the page's checks want the same mesh on both sides:
# B painted as A has A's patches, and every vertex maps onto itself). Both
# start painted in four height bands, for the screenshots; the self test
# clears them first.
mesh_b="$work/copy_of_$(basename "$mesh")"
cp "$mesh" "$mesh_b"
if ! python3 "$here/../../scripts/height_labels.py" "$mesh" y 4 >"$work/bands.txt"; then
  echo "FAIL: cannot write the height bands of $mesh"
  exit 1
fi

# Start the server on a port the system picks; it prints
# "diffuv: serving http://127.0.0.1:PORT/" once it listens.
"$diffuv" serve "$mesh" "$mesh_b" --labels "$work/bands.txt" --labels-b "$work/bands.txt" --port 0 \
  >"$work/server.out" 2>"$work/server.err" &
server_pid=$!
port=""
for _ in $(seq 1 200); do
  port=$(sed -n 's|.*diffuv: serving http://127\.0\.0\.1:\([0-9][0-9]*\)/.*|\1|p' "$work/server.out" | head -n 1)
  [ -n "$port" ] && break
  if ! kill -0 "$server_pid" 2>/dev/null; then break; fi
  sleep 0.1
done
if [ -z "$port" ]; then
  echo "FAIL: the server exited or printed no address within 20 s"
  echo "--- server stdout"; cat "$work/server.out"
  echo "--- server stderr"; cat "$work/server.err"
  exit 1
fi
url="http://127.0.0.1:$port/"
echo "server: $url"

# SwiftShader gives WebGL without a GPU. The virtual time budget lets the
# page's timers run while Chromium waits for network answers. Without
# --run-all-compositor-stages-before-draw the WebGL canvas is black in about
# half of the screenshots.
flags=(--headless=new --no-sandbox --disable-gpu --use-angle=swiftshader
       --enable-unsafe-swiftshader --run-all-compositor-stages-before-draw
       --no-first-run --no-default-browser-check
       --disable-extensions --disable-dev-shm-usage --hide-scrollbars
       --user-data-dir="$work/profile")

status=0
timeout -k 5 40 "$browser" "${flags[@]}" --virtual-time-budget=30000 \
  --window-size=1000,700 --dump-dom "${url}?test=1" >"$work/dom.html" 2>"$work/browser.log"
if ! python3 "$tools" result "$work/dom.html"; then
  status=1
  echo "--- browser log (last lines)"; grep -v -e dbus -e 'GPU stall' "$work/browser.log" | tail -n 20
  echo "--- server stderr (last lines)"; tail -n 20 "$work/server.err"
fi

# Screenshots: the page (both meshes, painted, their patches), then the
# correspondence view with a picked point. The window is 1000 pixels wide:
# the 280-pixel panel, A's view to about x = 640, B's from there.
screenshot() { # NAME URL
  timeout -k 5 30 "$browser" "${flags[@]}" --virtual-time-budget=10000 \
    --window-size=1000,700 --screenshot="$work/$1.png" "$2" >"$work/$1.log" 2>&1
}
screenshot screenshot "$url"
screenshot correspond "${url}?view=correspond&pick=0"
for shot in screenshot correspond; do
  # count the colours right of the panel (both views), then in B's view alone
  if ! python3 "$tools" png-colors "$work/$shot.png" 10 300 || ! python3 "$tools" png-colors "$work/$shot.png" 10 660; then
    status=1
    echo "--- browser log of $shot (last lines)"; grep -v -e dbus -e 'GPU stall' "$work/$shot.log" | tail -n 20
  fi
done
# the picked point's marker (magenta, drawn over the surface) on A and its image on B
if ! python3 "$tools" png-color "$work/correspond.png" "marker on A" ff00d4 290 630 ||
   ! python3 "$tools" png-color "$work/correspond.png" "marker on B" ff00d4 650 1000; then
  status=1
fi
if [ -n "${DIFFUV_PAINTER_SCREENSHOT:-}" ] && [ -f "$work/screenshot.png" ]; then
  cp "$work/screenshot.png" "$DIFFUV_PAINTER_SCREENSHOT"
fi
if [ -n "${DIFFUV_PAINTER_CORRESPOND_SCREENSHOT:-}" ] && [ -f "$work/correspond.png" ]; then
  cp "$work/correspond.png" "$DIFFUV_PAINTER_CORRESPOND_SCREENSHOT"
fi

if [ $status -eq 0 ]; then echo "PASS"; else echo "FAILED"; fi
exit $status
