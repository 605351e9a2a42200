#!/usr/bin/env bash
# scripts/same_output.sh: checks that two drange builds write byte-identical output, for a change
# that must not alter it (a restructuring, a speed-up): every output file is compared with cmp.
#
#   scripts/same_output.sh DRANGE_A DRANGE_B [--quick]
#
# Inputs, generated once into $SAME_OUTPUT_DATA (default /tmp/drange-same-output):
#   - every family of bench/degenerate_families.py (concentric spheres, smooth surfaces, decimal
#     grids in 2D to 7D, ...);
#   - the standard set of bench/run.py (STANDARD: uniform, gaussian, grid and sphere in 2D and 3D
#     up to 1 000 000 points, and the uniform rows of 2D to 8D) and the ablation's own inputs
#     (sphere 2D 200 000, uniform 2D and 3D 20 000), made as bench/run.py makes them:
#     `DRANGE_A generate DIST N D --seed 1`. One row is scaled down: uniform 7D has 1 000 points,
#     not 2 000 (a run of 2 000 takes about a minute on one core; the others take at most ~20 s).
# For each input, on 1 and 2 threads, both builds run
#     delaunay INPUT -o simplices.txt --neighbors neighbors.txt -q --threads T
# and, on the 2D and 3D inputs and the 4D decimal_grid4,
#     voronoi INPUT -o voronoi.json -q --threads T
# (vertices, ridge_points, ridge_vertices, regions, point_region, volumes). Then, on 1 thread,
# every --variant but full on a few small inputs (a 3D sphere, a 5D decimal grid, uniform 8D;
# --quick: the sphere alone): a variant switches parts of the engine off, which the default
# runs never exercise. Skipped for voronoi:
# uniform 3D 1 000 000 (1.2 GB of JSON per run; uniform 3D 216 000 stands for it). Each run's exit
# status and standard error are compared too, and a run that fails counts as a difference.
#
# Prints one line per input and thread count (`same` or `DIFFERENT: FILE...`), then a summary;
# exits 1 on any difference, 2 on a usage error. Where the simplices differ as bytes but not as a
# set (sorted vertex ids, sorted rows: another --algorithm lists them in another order), the
# line says `same set, other order: FILE...` instead and does not count as a difference; the
# neighbours and the Voronoi diagram then differ in their numbering only if their simplices do. The first differing pair of outputs is kept in
# $SAME_OUTPUT_DATA/first-difference. Runs take scripts/ab_time.sh's lock (/tmp/drange-machine.lock):
# the two 1-thread runs share it and run side by side, a 2-thread run holds it alone.
#
# The full run takes about ten minutes on 2 cores; --quick, a subset touching 2D to 8D, the
# degenerate families' exact stages, voronoi and the variants on the sphere, about two.
set -uo pipefail

usage() { sed -n '2,5p' "$0" >&2; exit 2; }
if [ $# -lt 2 ] || [ $# -gt 3 ] || { [ $# -eq 3 ] && [ "$3" != --quick ]; }; then usage; fi
a=$(realpath "$1") b=$(realpath "$2") quick=0
[ $# -eq 3 ] && quick=1
for exe in "$a" "$b"; do [ -x "$exe" ] || { echo "same_output.sh: $exe is not an executable" >&2; exit 2; }; done
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
data=${SAME_OUTPUT_DATA:-/tmp/drange-same-output}
lock=/tmp/drange-machine.lock

# The standard set (bench/run.py's STANDARD, 7D scaled down) and the ablation's inputs: DIST N D.
generated="uniform 100000 2
uniform 250000 2
uniform 500000 2
uniform 1000000 2
gaussian 1000000 2
grid 1000000 2
sphere 20000 2
uniform 100000 3
uniform 1000000 3
gaussian 200000 3
grid 216000 3
uniform 216000 3
sphere 2000 3
uniform 100000 4
uniform 20000 5
uniform 5000 6
uniform 1000 7
uniform 300 8
uniform 20000 2
uniform 20000 3
sphere 200000 2"
quick_inputs="two_circles five_spheres3 decimal_grid3 plateau rounded3 two_spheres4 decimal_grid4 decimal_grid5
  decimal_grid6 uniform_2d_100000 sphere_2d_20000 uniform_3d_100000 sphere_3d_2000 uniform_4d_100000 uniform_8d_300"
no_voronoi="uniform_3d_1000000"
voronoi_4d="decimal_grid4"
listed() { local word; for word in $2; do [ "$word" = "$1" ] && return 0; done; return 1; }  # NAME LIST

# Inputs, generated once: a marker file says the families' directory is complete.
mkdir -p "$data/families" || exit 2
if [ ! -f "$data/families/.complete" ]; then
  echo "same_output.sh: writing the degenerate families into $data/families" >&2
  python3 "$root/bench/degenerate_families.py" "$data/families" >/dev/null || exit 2
  touch "$data/families/.complete"
fi
inputs=("$data"/families/*.txt)
while read -r dist n d; do
  file="$data/${dist}_${d}d_${n}.txt"  # bench/run.py's names
  if [ ! -f "$file" ]; then
    "$a" generate "$dist" "$n" "$d" --seed 1 -o "$file" || exit 2  # the file appears only when complete
  fi
  inputs+=("$file")
done <<<"$generated"

variant_inputs="sphere_3d_2000 decimal_grid5 uniform_8d_300"
variants="scan kdtree no-prune no-order paper no-bottom-up no-seed no-ball no-shell no-tie-memory no-hull fifo spatial"

# run EXE DIR THREADS INPUT VORONOI [VARIANT]: the outputs into DIR, with each command's exit
# status and standard error in DIR/status.
run() {
  local exe=$1 dir=$2 threads=$3 input=$4 voronoi=$5 variant=${6:-full} rc
  mkdir -p "$dir"
  rc=0; "$exe" delaunay "$input" -o "$dir/simplices.txt" --neighbors "$dir/neighbors.txt" -q \
    --threads "$threads" --variant "$variant" 2>"$dir/delaunay.err" || rc=$?
  echo "delaunay exit $rc" >>"$dir/status"; cat "$dir/delaunay.err" >>"$dir/status"; rm "$dir/delaunay.err"
  if [ "$voronoi" = 1 ]; then
    rc=0; "$exe" voronoi "$input" -o "$dir/voronoi.json" -q --threads "$threads" 2>"$dir/voronoi.err" || rc=$?
    echo "voronoi exit $rc" >>"$dir/status"; cat "$dir/voronoi.err" >>"$dir/status"; rm "$dir/voronoi.err"
  fi
}
# locked MODE COMMAND...: COMMAND under the machine's lock, shared (-s) or alone (-x).
locked() { local mode=$1; shift; ( flock "$mode" 9 && "$@" ) 9>>"$lock"; }

work=$(mktemp -d "$data/run.XXXXXX") || exit 2
trap 'rm -rf "$work"' EXIT
rm -rf "$data/first-difference"
same=0 same_set=0 different=0 started=$SECONDS
# The simplices of a qhull-layout file as a set: each row's ids sorted, the rows sorted.
simplex_set() { tail -n +2 "$1" | /usr/bin/python3 -c 'import sys; print("\n".join(sorted(" ".join(sorted(l.split(), key=int)) for l in sys.stdin)))'; }
# compare LABEL: the outputs in $work/a and $work/b, one line of verdict.
compare() {
  local differ="" file
  for file in $( (ls "$work/a"; ls "$work/b") | sort -u); do
    cmp -s "$work/a/$file" "$work/b/$file" || differ+=" $file"
  done
  if grep -q "exit [^0]" "$work/a/status" "$work/b/status"; then differ+=" (a run failed: see status)"; fi
  if [ -z "$differ" ]; then
    echo "${1}same"; same=$((same + 1))
  elif [[ "$differ" == *simplices.txt* && "$differ" != *status* ]] &&
       cmp -s <(simplex_set "$work/a/simplices.txt") <(simplex_set "$work/b/simplices.txt"); then
    echo "${1}same set, other order:$differ"; same_set=$((same_set + 1))
  else
    echo "${1}DIFFERENT:$differ"; different=$((different + 1))
    if [ ! -e "$data/first-difference" ]; then mv "$work" "$data/first-difference"; mkdir "$work"; fi
  fi
}
for input in "${inputs[@]}"; do
  name=$(basename "$input" .txt)
  if [ $quick -eq 1 ] && ! listed "$name" "$quick_inputs"; then continue; fi
  d=$(head -1 "$input")  # Qhull's format: the dimension first
  voronoi=0
  if { [ "$d" -le 3 ] && ! listed "$name" "$no_voronoi"; } || listed "$name" "$voronoi_4d"; then voronoi=1; fi
  for threads in 1 2; do
    rm -rf "$work/a" "$work/b"
    if [ $threads -eq 1 ]; then
      locked -s run "$a" "$work/a" 1 "$input" $voronoi & locked -s run "$b" "$work/b" 1 "$input" $voronoi & wait
    else
      locked -x run "$a" "$work/a" "$threads" "$input" $voronoi
      locked -x run "$b" "$work/b" "$threads" "$input" $voronoi
    fi
    compare "$(printf '%-22s %dD  threads %d  ' "$name" "$d" "$threads")"
  done
  if listed "$name" "$variant_inputs" && { [ $quick -eq 0 ] || [ "$name" = sphere_3d_2000 ]; }; then
    for variant in $variants; do
      rm -rf "$work/a" "$work/b"
      locked -s run "$a" "$work/a" 1 "$input" 0 "$variant" & locked -s run "$b" "$work/b" 1 "$input" 0 "$variant" & wait
      compare "$(printf '%-22s %dD  %-14s ' "$name" "$d" "$variant")"
    done
  fi
done
echo "same_output.sh: $same same, $same_set same set in another order, $different different ($(( (SECONDS - started) / 60 )) min $(( (SECONDS - started) % 60 )) s)"
[ $different -eq 0 ]
