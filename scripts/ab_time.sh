#!/usr/bin/env bash
# scripts/ab_time.sh: compares two drange builds on one input, one thread, runs interleaved
# so that a change of machine load hits both alike; prints the minimum of time_search and
# time_total of each, and B's search time over A's. The search-time figures in commit messages
# ("min of 3, interleaved") come from this. The pairs alternate their order (A B, B A, A B,
# ...) because on a noisy machine whichever binary runs first in a pair can come out faster:
# alternating lets that bias hit both builds alike.
#
#   scripts/ab_time.sh N POINTS DRANGE_A DRANGE_B [delaunay options...]
#
# Each run takes the shared lock of /tmp/drange-machine.lock (single-thread timings may run
# two at a time on a 2-core machine; a 2-thread timing takes it exclusively).
set -euo pipefail
if [ $# -lt 4 ]; then
  sed -n '2,10p' "$0" >&2
  exit 2
fi
runs=$1 points=$2 a=$3 b=$4
shift 4
search_a=() search_b=() total_a=() total_b=()
field() { grep -o "$1=[0-9.]*" | cut -d= -f2; }
for run in $(seq "$runs"); do
  order="a b"
  [ $((run % 2)) -eq 0 ] && order="b a"
  for side in $order; do
    exe=${!side}
    stats=$(flock -s /tmp/drange-machine.lock "$exe" delaunay "$points" -o /dev/null --stats -q --threads 1 "$@" 2>&1)
    if [ "$side" = a ]; then
      search_a+=("$(field time_search <<<"$stats")"); total_a+=("$(field time_total <<<"$stats")")
    else
      search_b+=("$(field time_search <<<"$stats")"); total_b+=("$(field time_total <<<"$stats")")
    fi
  done
done
least() { printf '%s\n' "$@" | sort -g | head -1; }
sa=$(least "${search_a[@]}") sb=$(least "${search_b[@]}")
echo "$(basename "$points"): time_search A=$sa B=$sb B/A=$(awk "BEGIN { printf \"%.3f\", $sb / $sa }")" \
     "time_total A=$(least "${total_a[@]}") B=$(least "${total_b[@]}")"
