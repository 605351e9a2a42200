#!/usr/bin/env python3
"""Times `drange delaunay --only` (the stars of a few points) against the whole construction.

    python3 bench/local_stars.py [--drange build/drange] [--n 1000000] [--dim 3] [--ids 100] [--runs 3]

Both on one thread, the direct algorithm, on the same generated uniform points. The figure that
matters is the time after the kd-tree (first facet + search), where the stars' cost should grow
with the stars and not with the input; the kd-tree is the same work in both. Prints each run's
phase times from --stats and the median ratio.
"""
import argparse
import os
import random
import statistics
import subprocess
import tempfile


def run_stats(command):
    err = subprocess.run(command, check=True, capture_output=True, text=True).stderr
    fields = dict(word.split("=", 1) for word in err.split() if "=" in word)
    return {key: float(fields[key].rstrip("s")) for key in ("time_kdtree", "time_first_facet", "time_search", "time_total")}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--drange", default="build/drange")
    parser.add_argument("--n", type=int, default=1000000)
    parser.add_argument("--dim", type=int, default=3)
    parser.add_argument("--ids", type=int, default=100)
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        points = os.path.join(tmp, "points.txt")
        subprocess.run([args.drange, "generate", "uniform", str(args.n), str(args.dim), "--seed", "1", "-o", points], check=True)
        ids = ",".join(str(i) for i in random.Random(5).sample(range(args.n), args.ids))
        common = [args.drange, "delaunay", points, "-o", os.path.join(tmp, "out.txt"), "--threads", "1", "--stats", "-q"]
        rows = {"full": [], "stars": []}
        for _ in range(args.runs):
            rows["full"].append(run_stats(common + ["--algorithm", "direct"]))
            rows["stars"].append(run_stats(common + ["--only", ids]))
        for name, runs in rows.items():
            for r in runs:
                print(f"{name:5} kdtree={r['time_kdtree']:.3f}s first_facet={r['time_first_facet']:.3f}s "
                      f"search={r['time_search']:.3f}s total={r['time_total']:.3f}s")
        after = {name: statistics.median(r["time_first_facet"] + r["time_search"] for r in runs) for name, runs in rows.items()}
        total = {name: statistics.median(r["time_total"] for r in runs) for name, runs in rows.items()}
        print(f"n={args.n} d={args.dim} ids={args.ids}: after the kd-tree, stars {after['stars']:.3f}s / full "
              f"{after['full']:.3f}s = {100 * after['stars'] / after['full']:.2f}%; whole runs "
              f"{100 * total['stars'] / total['full']:.2f}%")


if __name__ == "__main__":
    main()
