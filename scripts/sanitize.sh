#!/usr/bin/env bash
# The test suite under AddressSanitizer + UndefinedBehaviorSanitizer (PUNCTURE_SANITIZE): a
# separate build in build-sanitize/ (Release with -g; the Python module is left out, as it would
# need the sanitizer runtime preloaded into the interpreter).  Any finding aborts the test that
# met it, so "100% tests passed" means zero findings.  Extra arguments go to ctest, e.g.
#   scripts/sanitize.sh -L solver        one label
#   scripts/sanitize.sh -E reliability   all but the random sweep
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Release -DPUNCTURE_SANITIZE=ON \
  -DPUNCTURE_BUILD_PYTHON=OFF -DPUNCTURE_BUILD_BENCHMARKS=OFF -DPUNCTURE_BUILD_EXAMPLES=OFF
cmake --build build-sanitize -j"$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir build-sanitize --output-on-failure "$@"
