#!/usr/bin/env bash
# Builds diffuv's libFuzzer targets (test/fuzz) with clang++ in build-fuzz and
# runs each for a bounded time on a copy of its seed corpus. Exits non-zero if
# a fuzzer finds a crash, a hang or a memory blow-up, and prints where the
# reproducer is.
#
# Usage: scripts/fuzz.sh [SECONDS] [TARGET...]
#   SECONDS   time per target (default: $FUZZ_SECONDS, else 60)
#   TARGET    label_file selection_file painted_colors mesh_param (default: all)
# Environment:
#   FUZZ_SECONDS     time per target, if not given as the first argument
#   FUZZ_JOBS        targets run at the same time (default: the number of cores, at most 4)
#   FUZZ_BUILD_DIR   the build folder (default: build-fuzz)
#   FUZZ_BUILD_JOBS  parallel compile jobs (default: the number of cores)
#   FUZZ_SEED        libFuzzer's random seed (default: a new one each run).
#                    With a fixed seed a run is repeatable: the same mutations
#                    in the same order, so a shorter run (a slower machine)
#                    tries a prefix of what a longer one tried. CI fixes it,
#                    so that CI cannot turn red on a bug that the change under
#                    test did not bring; runs without it explore further.
#   CXX              the compiler (default: clang++)
#
# Installs nothing: run `bash scripts/setup.sh` first (clang, libclang-rt-dev).
# The corpora are copied to $FUZZ_BUILD_DIR/fuzz-run/<target>/corpus, so
# nothing new is written to the source tree; each run starts from the seeds.
#
# The seeds are test/fuzz/corpus/<target> and test/fuzz/regressions/<target>
# (the inputs that once crashed, also replayed by test/test_fuzz_regressions.cpp).
# A reproducer is replayed with: $FUZZ_BUILD_DIR/test/fuzz/fuzz_<target> <file>
# (DIFFUV_FUZZ_VERBOSE=1 also prints what the readers said); save it in
# test/fuzz/regressions/<target>/ once the bug is fixed.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds="${FUZZ_SECONDS:-60}"
if [ $# -gt 0 ] && [[ "$1" =~ ^[0-9]+$ ]]; then
  seconds="$1"
  shift
fi
all_targets=(label_file selection_file painted_colors mesh_param)
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=("${all_targets[@]}")
for t in "${targets[@]}"; do
  if [[ ! " ${all_targets[*]} " =~ " $t " ]]; then
    echo "fuzz: unknown target \"$t\" (expected: ${all_targets[*]})" >&2
    exit 2
  fi
done

cores="$(nproc 2>/dev/null || echo 2)"
jobs="${FUZZ_JOBS:-$(( cores < 4 ? cores : 4 ))}"
build="${FUZZ_BUILD_DIR:-build-fuzz}"
cxx="${CXX:-clang++}"
if ! command -v "$cxx" >/dev/null; then
  echo "fuzz: $cxx not found: run bash scripts/setup.sh (packages clang, libclang-rt-dev)" >&2
  exit 2
fi

# Per target: the longest input (bytes) and a dictionary. Small inputs keep
# the mesh pipeline fast (thousands of runs per second on the parsers, about
# a thousand on mesh_param, on one core).
max_len_of() {
  case "$1" in
    label_file) echo 2048 ;;
    selection_file) echo 1024 ;;
    painted_colors) echo 4096 ;;
    mesh_param) echo 2048 ;;
  esac
}
dict_of() {
  case "$1" in
    label_file|selection_file) echo test/fuzz/dictionaries/text.dict ;;
    painted_colors|mesh_param) echo test/fuzz/dictionaries/mesh.dict ;;
  esac
}

start=$SECONDS
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DDIFFUV_BUILD_FUZZERS=ON -DDIFFUV_BUILD_TESTS=OFF -DDIFFUV_BUILD_TOOL=OFF \
  -DDIFFUV_BUILD_EXAMPLES=OFF -DDIFFUV_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$build" -j"${FUZZ_BUILD_JOBS:-$cores}" --target $(printf 'fuzz_%s ' "${targets[@]}")
echo "fuzz: built in $(( SECONDS - start )) s; running ${targets[*]} for $seconds s each, $jobs at a time, seed ${FUZZ_SEED:-random}"

run="$build/fuzz-run"
# The targets write each input to a file (diffuv's readers take file names):
# in memory when /dev/shm exists, in a folder removed at the end.
tmp="$(mktemp -d /dev/shm/diffuv-fuzz.XXXXXX 2>/dev/null || mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
export DIFFUV_FUZZ_TMPDIR="$tmp"
fuzz_one() {
  local t="$1" dir="$run/$1"
  rm -rf "$dir"
  mkdir -p "$dir/corpus" "$dir/artifacts"
  cp -R "test/fuzz/corpus/$t/." "$dir/corpus/"
  if [ -d "test/fuzz/regressions/$t" ]; then cp -R "test/fuzz/regressions/$t/." "$dir/corpus/"; fi
  # -timeout: a hang of more than 10 s on a small input is a bug;
  # -rss_limit_mb also caps a single allocation (-malloc_limit_mb).
  local rc=0
  UBSAN_OPTIONS="print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}" \
  "$build/test/fuzz/fuzz_$t" "$dir/corpus" \
    -max_total_time="$seconds" -max_len="$(max_len_of "$t")" -dict="$(dict_of "$t")" \
    -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 ${FUZZ_SEED:+-seed=$FUZZ_SEED} \
    -artifact_prefix="$dir/artifacts/" >"$dir/log.txt" 2>&1 || rc=$?
  echo "$rc" >"$dir/rc"
}

running=0
for t in "${targets[@]}"; do
  if [ "$running" -ge "$jobs" ]; then
    wait -n || true
    running=$(( running - 1 ))
  fi
  fuzz_one "$t" &
  running=$(( running + 1 ))
done
wait

status=0
for t in "${targets[@]}"; do
  dir="$run/$t"
  rc="$(cat "$dir/rc" 2>/dev/null || echo '?')"
  runs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$dir/log.txt" | tail -1)"
  speed="$(sed -n 's/^stat::average_exec_per_sec: *//p' "$dir/log.txt" | tail -1)"
  found=("$dir"/artifacts/*)
  [ -e "${found[0]}" ] || found=()
  if [ "$rc" = 0 ] && [ ${#found[@]} -eq 0 ]; then
    echo "fuzz: $t ok: ${runs:-?} runs, ${speed:-?} per second"
  else
    status=1
    echo "fuzz: $t FAILED (exit code $rc) after ${runs:-?} runs; log: $dir/log.txt"
    grep -E "^==[0-9]+==ERROR|SUMMARY:|runtime error:|ALARM|out-of-memory|invariant broken|uncaught|terminate" \
      "$dir/log.txt" | head -5 | sed 's/^/  /' || true
    for f in "${found[@]}"; do
      echo "  reproducer: $f"
      echo "  replay: $build/test/fuzz/fuzz_$t $f"
    done
  fi
done
echo "fuzz: done in $(( SECONDS - start )) s"
exit $status
