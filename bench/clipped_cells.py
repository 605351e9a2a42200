#!/usr/bin/python3
"""Time and peak memory of the clipped cells: drange voronoi --cells FILE.txt against voro++.

Usage: python3 bench/clipped_cells.py DRANGE [--points N] [--runs R] [--dir DIR]

Generates N uniform 3D points in the unit cube (`drange generate uniform N 3`, seed 1), writes
them for voro++ as "id x y z" lines, and runs, R rounds interleaved, each command under
`/usr/bin/time -f "%e %U %M"`:
  drange voronoi POINTS --cells CELLS.txt --box 0,0,0,1,1,1 -q --threads 1
  drange voronoi POINTS --cells CELLS.txt --box 0,0,0,1,1,1 -q --threads 2
  voro++ -c '%i %v' -o 0 1 0 1 0 1 VORO_POINTS           (when voro++ is installed)
  drange voronoi POINTS --cells CELLS.vtu --box 0,0,0,1,1,1 -q -o /dev/null --threads 1
Prints per command the minimum and median wall seconds, user seconds (all threads; on a machine
shared with other work the wall time of a run depends on the cores it got) and peak resident
memory (MB), and checks that the text cells of 1 and 2 threads are the same bytes.
"""
import argparse
import os
import shutil
import statistics
import subprocess
import tempfile


def timed(command):
    done = subprocess.run(["/usr/bin/time", "-f", "%e %U %M", *command], capture_output=True, text=True, check=True)
    seconds, user, kilobytes = done.stderr.strip().splitlines()[-1].split()
    return float(seconds), float(user), int(kilobytes) / 1024


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("drange")
    parser.add_argument("--points", type=int, default=200000)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--dir", default=None)
    args = parser.parse_args()
    directory = args.dir or tempfile.mkdtemp(prefix="clipped_cells_")
    points = os.path.join(directory, f"u3_{args.points}.txt")
    subprocess.run([args.drange, "generate", "uniform", str(args.points), "3", "-o", points], check=True)
    voro_points = os.path.join(directory, f"voro_{args.points}.txt")
    with open(points) as source, open(voro_points, "w") as out:
        for i, line in enumerate(source.read().split("\n")[2:]):
            if line.strip():
                out.write(f"{i} {line}\n")
    box = ["--box", "0,0,0,1,1,1", "-q"]
    commands = {
        "drange --cells .txt, --threads 1": [args.drange, "voronoi", points, "--cells", os.path.join(directory, "c1.txt"), *box, "--threads", "1"],
        "drange --cells .txt, --threads 2": [args.drange, "voronoi", points, "--cells", os.path.join(directory, "c2.txt"), *box, "--threads", "2"],
    }
    if shutil.which("voro++"):
        commands["voro++ -c '%i %v' -o"] = ["voro++", "-c", "%i %v", "-o", "0", "1", "0", "1", "0", "1", voro_points]
    commands["drange --cells .vtu, --threads 1"] = [args.drange, "voronoi", points, "--cells", os.path.join(directory, "c.vtu"), *box, "-o", os.devnull, "--threads", "1"]
    results = {name: [] for name in commands}
    for _ in range(args.runs):
        for name, command in commands.items():
            results[name].append(timed(command))
    same = open(os.path.join(directory, "c1.txt"), "rb").read() == open(os.path.join(directory, "c2.txt"), "rb").read()
    print(f"{args.points} uniform 3D points, {args.runs} runs; text cells of 1 and 2 threads the same bytes: {same}")
    print("| command | wall s, min | wall s, median | user s, min | user s, median | peak MB, min | peak MB, median |")
    print("|---|---|---|---|---|---|---|")
    for name, runs in results.items():
        wall, user, memory = ([run[i] for run in runs] for i in range(3))
        print(f"| {name} | {min(wall):.2f} | {statistics.median(wall):.2f} | {min(user):.2f} | {statistics.median(user):.2f} "
              f"| {min(memory):.0f} | {statistics.median(memory):.0f} |")


if __name__ == "__main__":
    main()
