#!/usr/bin/env bash
# Tests the painter page of `diffuv serve` in headless Chromium.
#
#   run_painter_test.sh DIFFUV_BINARY MESH
#
# Starts the server on a free port, opens the page with ?test=1 (the page
# paints, undoes, saves, lays out and maps by itself and writes its checks
# into <pre id="test-result">), prints the checks, then takes a screenshot
# of the normal page and checks it is not blank.
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

# Start the server on a port the system picks; it prints
# "diffuv: serving http://127.0.0.1:PORT/" once it listens.
"$diffuv" serve "$mesh" --port 0 >"$work/server.out" 2>"$work/server.err" &
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

timeout -k 5 30 "$browser" "${flags[@]}" --virtual-time-budget=10000 \
  --window-size=1000,700 --screenshot="$work/screenshot.png" "$url" >"$work/shot.log" 2>&1
# count the colours right of the 280-pixel panel: the 3D view's
if ! python3 "$tools" png-colors "$work/screenshot.png" 10 300; then
  status=1
  echo "--- browser log (last lines)"; grep -v -e dbus -e 'GPU stall' "$work/shot.log" | tail -n 20
fi
if [ -n "${DIFFUV_PAINTER_SCREENSHOT:-}" ] && [ -f "$work/screenshot.png" ]; then
  cp "$work/screenshot.png" "$DIFFUV_PAINTER_SCREENSHOT"
fi

if [ $status -eq 0 ]; then echo "PASS"; else echo "FAILED"; fi
exit $status
