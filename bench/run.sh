#!/usr/bin/env bash
# bench/run.sh: drange against its peers (issue 4). Installs what is missing (Debian packages,
# as scripts/setup.sh does), builds ./build-bench with -DDRANGE_BUILD_BENCH=ON (Release),
# generates the inputs into bench/data (git-ignored) and runs every (input, peer) pair in a
# process of its own, with a timeout; writes one Markdown table (and a .csv of the raw lines),
# headed by the command, the commit and the machine. bench/RESULTS.md keeps the newest
# generated file of each set: a new run's file replaces its set's section there.
#
#   bench/run.sh [--quick] [--ablation] [--beyond] [--degenerate] [--micro] [--timeout S] [--repeat N]
#                [--rows DIST:D:N,...] [-o FILE]
#
#   (none)       the standard set and the ablation          -> bench/results.md
#   --quick      a subset, under 2 minutes on 2 cores        -> bench/results-quick.md
#   --ablation   the ablation table alone                   -> bench/results-ablation.md
#   --beyond     7D 4 500 and 9 000 points, 8D 1 500 and 2 000, 600 s limit (about 70 min)
#                                                           -> bench/results-beyond.md
#   --degenerate the probe inputs of bench/degenerate_families.py (concentric spheres, bubbles,
#                rings, smooth surfaces, a terrain's plateau, decimal grids) and its surface families
#                (a cube's faces, mesh vertices, a freeform patch) against CGAL and Qhull (about 9 min)
#                                                           -> bench/results-degenerate.md
#   --micro      also run the Google Benchmark microbenchmarks (appended to the file)
#   --repeat N   each measurement N times, the median reported (the machine's noise: one run
#                of a cell moved by up to 8% between two runs of the set)
#   --rows ...   only these rows of the set, no ablation (e.g. --rows uniform:5:20000,uniform:6:5000,
#                or --degenerate --rows family:cube_faces3_20000:3:20000)
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
command_line="bench/run.sh $*"
quick=0; ablation=0; beyond=0; degenerate=0; micro=0; output=""; timeout=(); extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --ablation) ablation=1 ;;
    --beyond) beyond=1 ;;
    --degenerate) degenerate=1 ;;
    --micro) micro=1 ;;
    --timeout) timeout=(--timeout "$2"); shift ;;
    --repeat) extra+=(--repeat "$2"); shift ;;
    --rows) extra+=(--rows "$2"); shift ;;
    -o) output="$2"; shift ;;
    -h|--help) sed -n '2,25p' "$0"; exit 0 ;;
    *) echo "bench/run.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done

packages=(g++ cmake make libgmp-dev libcgal-dev libeigen3-dev libboost-dev libqhull-dev libtbb-dev libbenchmark-dev
          python3 util-linux)
# TetGen's library, where the distribution has it (Debian 12: libtet1.5-dev).
if apt-cache show libtet1.5-dev >/dev/null 2>&1; then packages+=(libtet1.5-dev); fi
source "$root/scripts/install_packages.sh"
install_packages bench "${packages[@]}"

build="$root/build-bench"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DDRANGE_BUILD_BENCH=ON -DDRANGE_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" >&2

args=(--build "$build" --data "$root/bench/data" --command "$command_line" "${timeout[@]}" "${extra[@]}")
if [ $quick -eq 1 ]; then
  args+=(--quick); output="${output:-$root/bench/results-quick.md}"
elif [ $beyond -eq 1 ]; then
  args+=(--beyond); output="${output:-$root/bench/results-beyond.md}"
elif [ $degenerate -eq 1 ]; then
  args+=(--degenerate); output="${output:-$root/bench/results-degenerate.md}"
elif [ $ablation -eq 1 ]; then
  args+=(--ablation-only); output="${output:-$root/bench/results-ablation.md}"
else
  output="${output:-$root/bench/results.md}"
fi
/usr/bin/python3 "$root/bench/run.py" "${args[@]}" -o "$output"

if [ $micro -eq 1 ] && [ -x "$build/bench/drange_bench_micro" ]; then
  {
    echo
    echo "## Microbenchmarks (Google Benchmark)"
    echo
    echo '```'
    "$build/bench/drange_bench_micro" --benchmark_min_time=0.2 2>&1
    echo '```'
  } >> "$output"
fi
echo "bench: wrote $output" >&2
