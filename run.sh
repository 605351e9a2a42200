#!/usr/bin/env bash
# The main job: set up (packages, build), then run `drange` with the arguments given.
# With no arguments it triangulates a built-in default (100 000 uniform points in 3D) and
# prints a summary; `./run.sh --help` lists the commands.
set -euo pipefail
root=$(cd "$(dirname "$0")" && pwd)
source "$root/scripts/setup.sh"
drange="${DRANGE_BUILD_DIR:-$root/build}/drange"
# No arguments: the built-in default, whatever standard input is (drange delaunay would read a
# redirected standard input, as qdelaunay does).
if [ $# -eq 0 ]; then exec "$drange" delaunay < /dev/null; fi
exec "$drange" "$@"
