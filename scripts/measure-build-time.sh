#!/bin/sh
# The CPU time of a fresh default build: every compile's and link's user + system seconds,
# summed (the machine's load changes the wall time, much less the CPU time).  Builds a clean
# clone of HEAD in a temporary directory without ccache, with -j2 as the README does.
#   scripts/measure-build-time.sh [extra cmake arguments]
# Prints the total and the ten costliest steps; MEASURE_LOG=file keeps every step's time.
set -eu
repo=$(git rev-parse --show-toplevel)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
git clone -q "$repo" "$work/src"
cat > "$work/timed.sh" <<'LAUNCHER'
#!/bin/sh
exec /usr/bin/time -a -o "$TIMED_LOG" -f "%U %S %C" "$@"
LAUNCHER
chmod +x "$work/timed.sh"
export TIMED_LOG="$work/steps.log" CCACHE_DISABLE=1
cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER_LAUNCHER="$work/timed.sh" -DCMAKE_CXX_LINKER_LAUNCHER="$work/timed.sh" \
  "$@" > "$work/configure.log"
cmake --build "$work/build" -j2 > "$work/build.log" 2>&1
if [ -n "${MEASURE_LOG:-}" ]; then cp "$TIMED_LOG" "$MEASURE_LOG"; fi
awk '{ t = $1 + $2; total += t; out = "";
       for (i = 3; i <= NF; i++) if ($i == "-o") out = $(i + 1);
       printf "%8.1f s  %s\n", t, out }
     END { printf "%8.1f s  total (%.1f CPU-minutes, %d steps)\n", total, total / 60, NR }' \
  "$TIMED_LOG" | sort -rn | head -11
