#!/usr/bin/env bash
# Installs the Debian packages puncture needs to build, test and benchmark (Ceres Solver: the
# bounded least squares of the fits), and for the Python
# bindings and plots (scipy: an independent check of the inflation solver in the Python tests),
# and for packaging: help2man (the man page) and dpkg-dev (dpkg-shlibdeps, the Depends of
# `cpack -G DEB`), toml11 (the sweep specs of `puncture sweep`), Open MPI (`mpirun -n P
# puncture sweep`; its test), Dask (the Python sweep example over a cluster; its test), for
# `pip install .`: python3-venv, setuptools and wheel, and for the docs site
# (scripts/build-docs.sh): Doxygen, Sphinx, Breathe, MyST and the Read the Docs theme.
set -euo pipefail
packages=(build-essential cmake libboost-dev libeigen3-dev libcli11-dev nlohmann-json3-dev
          libfmt-dev libgtest-dev libbenchmark-dev librapidcheck-dev libceres-dev libtoml11-dev
          python3-dev pybind11-dev python3-pybind11 python3-numpy python3-matplotlib
          python3-pytest python3-scipy help2man dpkg-dev libtoml11-dev
          libopenmpi-dev openmpi-bin python3-dask python3-distributed
          python3-venv python3-setuptools python3-wheel
          doxygen python3-sphinx python3-breathe python3-myst-parser python3-sphinx-rtd-theme)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}"
fi
