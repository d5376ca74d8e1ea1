#!/usr/bin/env bash
# The test suite built with AddressSanitizer and UndefinedBehaviorSanitizer
# (a separate build folder, clang++ by default). Any report fails the run.
# Leaves out the sweep and the install-consumer test, and builds no tool, so
# the tests that run the tool (test_cli_*.cpp but test_cli_text.cpp) are not
# compiled here (test/CMakeLists.txt): they run in the normal build. The
# instrumented tool compiled as long as the whole instrumented suite (measured
# 2026-12-02: about 1,200 s of CPU each), for code that the library tests and
# the fuzz targets (scripts/fuzz.sh: the readers and the whole pipeline)
# already run instrumented.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
build=${SANITIZE_BUILD_DIR:-build-sanitize}
# clang++ (installed by setup.sh for the fuzz targets) compiles the instrumented
# suite in about 10 min on 2 cores where g++ takes 18 (measured 2026-11-26); it
# also warns about what g++ leaves quiet here (-Wswitch). SANITIZE_CXX=g++ for g++.
cxx=${SANITIZE_CXX:-clang++}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DDIFFUV_SANITIZE=ON -DCMAKE_CXX_COMPILER="$cxx" \
  -DDIFFUV_BUILD_EXAMPLES=OFF -DDIFFUV_BUILD_BENCHMARKS=OFF -DDIFFUV_BUILD_TOOL=OFF >/dev/null
cmake --build "$build" --target diffuv_tests -j"$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" -LE "sweep|consumer" "$@"
