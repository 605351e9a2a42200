#!/usr/bin/env bash
# Installs what drange needs (Debian packages) when missing, then configures and builds it in
# ./build. Sourced by run.sh and test.sh, so each of them works on a fresh machine.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
packages=(g++ cmake make libgmp-dev libgtest-dev qhull-bin libcgal-dev libeigen3-dev libboost-dev
          python3-numpy python3-scipy librsvg2-bin python3-dev pybind11-dev python3-pytest python3-matplotlib
          python3-pip python3-setuptools python3-wheel python3-venv openmpi-bin libopenmpi-dev)

source "$root/scripts/install_packages.sh"
install_packages "drange setup" "${packages[@]}"

build="${DRANGE_BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)" >&2
