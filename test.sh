#!/usr/bin/env bash
# Every test: set up (packages, build), then the whole CTest suite on all cores.
set -euo pipefail
root=$(cd "$(dirname "$0")" && pwd)
source "$root/scripts/setup.sh"
ctest --test-dir "${DRANGE_BUILD_DIR:-$root/build}" --output-on-failure -j"$(nproc)" "$@"
