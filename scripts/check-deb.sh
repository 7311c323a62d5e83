#!/usr/bin/env bash
# The Debian package as a user gets it: `cpack -G DEB` in BUILD_DIR (default build), installed
# with apt (which resolves its Depends), the installed program run on the paper's default case
# from another folder, then the package removed again.  Needs root or sudo.  Run by .ci/run.
set -euo pipefail
build_dir="$(cd "${1:-build}" && pwd)"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
(cd "$build_dir" && rm -f puncture_*.deb && cpack -G DEB > cpack.log)
deb=$(ls "$build_dir"/puncture_*.deb)
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "$deb" > /dev/null
trap 'DEBIAN_FRONTEND=noninteractive $SUDO apt-get remove -y -qq puncture > /dev/null' EXIT
cd "$(mktemp -d)"
installed=/usr/bin/puncture
"$installed" --version
out=$("$installed")
# The installed program and the build tree's agree on the paper's puncture force.
want=$("$build_dir/apps/puncture/puncture" | grep "puncture force")
got=$(printf '%s\n' "$out" | grep "puncture force")
if [ "$got" != "$want" ]; then
  echo "check-deb: the installed puncture prints '$got', the build tree's '$want'" >&2
  exit 1
fi
echo "check-deb: $(basename "$deb") installed and run: $got"
