#!/usr/bin/env bash
# Coverage-guided fuzzing of the CSV reader and the --config reader with libFuzzer, under
# AddressSanitizer + UBSan, in a separate clang build (build-fuzz/).  Each target runs for
# SECONDS (default 600) from the committed corpus in tests/fuzz/corpus/<target>/; the inputs
# that reach new code are merged back into that corpus (commit them).  A finding stops the run
# with the input saved as build-fuzz/<target>-crash-*; exit status non-zero.
#   scripts/fuzz.sh            both targets, 10 minutes each
#   scripts/fuzz.sh 60 csv     one target, one minute
# Needs clang and its runtime (Debian: clang-14, libclang-rt-14-dev).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
shift || true
targets=("${@:-csv config}")
read -r -a targets <<< "${targets[*]}"
cxx=$(command -v clang++-14 || command -v clang++ || true)
if [ -z "$cxx" ]; then
  echo "fuzz.sh: needs clang++ (apt-get install clang-14 libclang-rt-14-dev)" >&2
  exit 1
fi
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" \
  -DPUNCTURE_FUZZ=ON -DPUNCTURE_BUILD_PYTHON=OFF -DPUNCTURE_BUILD_BENCHMARKS=OFF \
  -DPUNCTURE_BUILD_EXAMPLES=OFF
cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]/%/_fuzzer}"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
for target in "${targets[@]}"; do
  corpus=tests/fuzz/corpus/$target
  work=build-fuzz/corpus-$target
  mkdir -p "$work"
  echo "fuzz.sh: $target for $seconds s"
  # -rss_limit_mb: the machine's 24 GiB are shared; -max_len: config and CSV files are small.
  (cd build-fuzz && "./tests/fuzz/${target}_fuzzer" -max_total_time="$seconds" -max_len=4096 \
     -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$target-" \
     "corpus-$target" "../$corpus")
  # Keep only the inputs that add coverage to what is committed.
  "./build-fuzz/tests/fuzz/${target}_fuzzer" -merge=1 "$corpus" "$work"
done
