#!/usr/bin/env python3
"""Speed-up of drange delaunay from one thread to several, for one or more builds side by side.

    python3 bench/thread_speedup.py FILE [FILE ...] --builds build/drange OTHER/drange
                                    [--threads 1 2] [--rounds 5]

For each round, each file, each build and each thread count (interleaved, so that a slow spell
of the machine hits them alike), runs `DRANGE delaunay FILE -o /dev/null -q --stats --threads T`
under /usr/bin/time and reads time_search and time_total from --stats and the wall time. Prints
the medians per file, build and thread count, and each build's speed-up from the first thread
count to the others (the ratio of the medians).
"""
import argparse
import os
import re
import statistics
import subprocess
import sys


def run(drange, path, threads):
    command = ["/usr/bin/time", "-f", "wall=%e", drange, "delaunay", path, "-o", os.devnull, "-q", "--stats",
               "--threads", str(threads)]
    done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        sys.exit(f"thread_speedup.py: {' '.join(command)} failed:\n{done.stderr}")
    figures = {}
    for key in ("time_search", "time_total", "wall"):
        match = re.search(rf"\b{key}=([0-9.]+)", done.stderr)
        if not match:
            sys.exit(f"thread_speedup.py: no {key} in the output of {' '.join(command)}")
        figures[key] = float(match.group(1))
    return figures


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="+")
    parser.add_argument("--builds", nargs="+", default=["build/drange"])
    parser.add_argument("--threads", nargs="+", type=int, default=[1, 2])
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    runs = {}
    for _ in range(args.rounds):
        for path in args.files:
            for build in args.builds:
                for threads in args.threads:
                    runs.setdefault((path, build, threads), []).append(run(build, path, threads))
    keys = ("time_search", "time_total", "wall")
    medians = {key: {k: statistics.median(r[k] for r in value) for k in keys} for key, value in runs.items()}
    for path in args.files:
        for build in args.builds:
            first = medians[(path, build, args.threads[0])]
            for threads in args.threads:
                m = medians[(path, build, threads)]
                line = " ".join(f"{k}={m[k]:.3f}s" for k in keys)
                speedup = " ".join(f"{k}={first[k] / m[k]:.2f}" for k in keys)
                print(f"{os.path.basename(path)} {build} threads={threads} {line} speed-up: {speedup}")


if __name__ == "__main__":
    main()
