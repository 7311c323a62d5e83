#!/bin/sh
# The parallel efficiency of `mpirun -n 2 puncture sweep` against the serial sweep (issue #15),
# on a Latin hypercube around the paper's membrane (friction, critical I1, thickness, shear
# modulus; puncture points only).  Serial and MPI runs alternate; every MPI file must equal the
# serial one byte for byte.  Prints each run and:
#   wall-clock efficiency  T_serial / (2 T_mpi2), best run of each
#   CPU-time efficiency    serial CPU seconds / (rank 0's + rank 1's CPU seconds), best runs
#                          (user + system, each rank timed by /usr/bin/time inside mpirun)
# The wall-clock figure needs an idle machine with 2 free cores; the CPU figure counts the
# work (and any busy-waiting) whatever else runs.
#
#   scripts/measure-mpi-efficiency.sh [PUNCTURE] [POINTS] [RUNS]
#     PUNCTURE  the program (default build/apps/puncture/puncture)
#     POINTS    the sweep's points (default 60000: ~25 s of CPU at 0.41 ms a point)
#     RUNS      runs of each (default 3)
#   MPIRUN_FLAGS  extra mpirun flags (e.g. "--bind-to none" on a shared machine)
set -eu
exe=$(realpath "${1:-build/apps/puncture/puncture}")
points=${2:-60000}
runs=${3:-3}
work=$(mktemp -d "${TMPDIR:-/tmp}/mpi-efficiency.XXXXXX")
trap 'rm -rf "$work"' EXIT
# mpirun refuses root unless told (containers, CI).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

cat >"$work/spec.toml" <<SPEC
design = "latin-hypercube"
samples = $points
seed = 1
[parameters]
friction = { range = [0.1, 0.3] }
critical-i1 = { range = [85, 105] }
thickness = { range = [0.18, 0.22] }
shear-modulus = { range = [0.054, 0.066] }
SPEC

serial_runs=""
mpi_runs=""
i=1
while [ "$i" -le "$runs" ]; do
  rm -f "$work/serial.csv"
  /usr/bin/time -f "%e %U %S" -o "$work/serial.time" \
    "$exe" sweep "$work/spec.toml" -o "$work/serial.csv" --threads 1 --quiet
  serial_runs="$serial_runs $(awk '{ printf "%s:%.3f", $1, $2 + $3 }' "$work/serial.time")"
  rm -f "$work/mpi.csv" "$work"/rank.*
  # shellcheck disable=SC2086
  /usr/bin/time -f "%e" -o "$work/mpi.time" mpirun ${MPIRUN_FLAGS:-} -n 2 \
    sh -c 'exec /usr/bin/time -f "%U %S" -o "$0/rank.$OMPI_COMM_WORLD_RANK" "$@"' "$work" \
    "$exe" sweep "$work/spec.toml" -o "$work/mpi.csv" --threads 1 --quiet
  cmp -s "$work/serial.csv" "$work/mpi.csv" || {
    echo "mpirun -n 2 wrote another file than the serial run" >&2
    exit 1
  }
  cpu=$(cat "$work"/rank.* | awk '{ s += $1 + $2 } END { printf "%.3f", s }')
  ranks=$(awk '{ printf "%.3f ", $1 + $2 }' "$work/rank.0" "$work/rank.1")
  mpi_runs="$mpi_runs $(cat "$work/mpi.time"):$cpu"
  echo "run $i: serial $(cat "$work/serial.time" | awk '{ printf "%s s wall, %.3f s CPU", $1, $2 + $3 }');" \
    "mpirun -n 2 $(cat "$work/mpi.time") s wall, ranks ${ranks}s CPU"
  i=$((i + 1))
done

/usr/bin/python3 - "$points" "$serial_runs" "$mpi_runs" <<'PY'
import sys
points = int(sys.argv[1])
serial = [tuple(map(float, r.split(":"))) for r in sys.argv[2].split()]
mpi = [tuple(map(float, r.split(":"))) for r in sys.argv[3].split()]
ts, cs = min(w for w, _ in serial), min(c for _, c in serial)
tm, cm = min(w for w, _ in mpi), min(c for _, c in mpi)
print(f"{points} points, best of {len(serial)}: serial {ts:.2f} s wall, {cs:.2f} s CPU "
      f"({1e3 * cs / points:.3f} ms a point); mpirun -n 2 {tm:.2f} s wall, {cm:.2f} s CPU")
print(f"wall-clock efficiency T_serial / (2 T_mpi2) = {ts / (2 * tm):.3f}")
print(f"CPU-time efficiency serial CPU / both ranks' CPU = {cs / cm:.3f}")
PY
