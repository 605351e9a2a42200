#!/usr/bin/env python3
"""bench/stability.py: how drange's time on points from surfaces compares with its time on
uniform points of the same dimension and size, and with CGAL's (issue 44). It measures; it
asserts nothing.

    bench/stability.py [--sizes 20000,200000] [--families NAME,...] [--drange-args="ARGS"]
                       [--qhull] [--no-cgal] [--check] [--timeout S] [--build DIR] [--drange PATH]
                       [--data DIR] [-o FILE]

For every size and every surface family of bench/degenerate_families.py (default: all those in
2D and 3D; torus4 when named in --families), and for uniform points of each dimension met at
each size (`drange generate uniform N D --seed 1`, as bench/run.py), it runs, one process each
and one thread each:
  drange     DRANGE delaunay FILE -o /dev/null --stats --threads 1 ARGS   (time_total and
             simplices of --stats: the construction, reading excluded)
  CGAL       drange_bench_run --peer cgal2 | cgal3 | cgal-dd --input FILE (construction only)
  Qhull      drange_bench_run --peer qhull --input FILE                   (with --qhull)
and prints one Markdown table (also written to -o FILE): input, d, n, simplices, drange s, drange
microseconds per simplex, its growth (per simplex, over the same input's at the smallest size
listed), the ratio of drange's time to uniform's of the same d and n, CGAL s and drange / CGAL,
and Qhull's where asked. --check also writes drange's simplices and validates them with
`drange check` (exact; slow at millions of points).

The files go to DATA/families (surface families, NAME_N.txt, written when missing) and DATA
(uniform). build-bench comes from `bench/run.sh` (or `cmake -B build-bench
-DDRANGE_BUILD_BENCH=ON`); --drange names another drange binary (e.g. a build of another
branch) while the peers stay those of --build.

Examples:
    bench/stability.py --sizes 20000,200000,2000000 --timeout 1200 -o /tmp/growth.md
    bench/stability.py --families cube_faces3,square_edges2 --drange-args="--algorithm incremental"
    bench/stability.py --families torus4 --sizes 2000,5000 --qhull
"""
import argparse
import os
import resource
import shlex
import subprocess
import sys
import tempfile
import time

import degenerate_families
import run

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
CGAL_PEER = {2: "cgal2", 3: "cgal3"}  # cgal-dd from 4D


def run_drange(drange, path, extra, timeout, mem_limit, check):
    """One `drange delaunay --stats` run: a dict with status, simplices and seconds (time_total),
    and with --check "valid" (yes / no)."""
    with tempfile.TemporaryDirectory() as scratch:
        output = os.path.join(scratch, "simplices.txt") if check else "/dev/null"
        cmd = [drange, "delaunay", path, "-o", output, "--stats", "--threads", "1"] + extra

        def limit():
            if mem_limit:
                resource.setrlimit(resource.RLIMIT_AS, (mem_limit, mem_limit))

        start = time.monotonic()
        p = subprocess.run(["timeout", "-s", "KILL", str(timeout)] + cmd, capture_output=True, text=True,
                           preexec_fn=limit)
        wall = time.monotonic() - start
        result = {"status": "error", "wall": wall}
        if p.returncode in (124, 137, -9):
            result["status"] = "timeout" if wall >= timeout - 1 else "oom"
        elif p.returncode == 5:
            result["status"] = "oom"
        elif p.returncode != 0:
            result["message"] = (p.stderr.strip().splitlines() or ["exit code %d" % p.returncode])[0][:200]
        stats = {}
        for line in p.stderr.splitlines():
            if "time_total=" in line:
                stats = dict(token.partition("=")[::2] for token in line.split() if "=" in token)
        if p.returncode == 0:
            if "simplices" not in stats or "time_total" not in stats:
                result["message"] = "no simplices= and time_total= in --stats"
            else:
                result.update(status="ok", simplices=stats["simplices"], seconds=stats["time_total"].rstrip("s"))
        if check and result["status"] == "ok":
            c = subprocess.run(["timeout", str(timeout), drange, "check", path, output, "--quiet"])
            result["valid"] = {0: "yes", 1: "NO", 124: "timed out"}.get(c.returncode, f"exit {c.returncode}")
    run.log(f"  drange       {os.path.basename(path):28s} -> {result['status']} {result.get('seconds', '')} s"
            f"  (wall {wall:.1f} s){' ' + result.get('message', '') if result['status'] == 'error' else ''}")
    return result


def seconds(r, timeout):
    return "not run" if r.get("status") == "not run" else run.secs(r, timeout)


def quotient(a, b, fmt="{:.2f}"):
    return fmt.format(a / b) if a is not None and b else ""


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sizes", default="20000,200000", help="the sizes, N,N,... (default 20000,200000)")
    ap.add_argument("--families", default="",
                    help="surface families of bench/degenerate_families.py (default: every 2D and 3D one)")
    ap.add_argument("--drange-args", default="",
                    help="more arguments for drange delaunay, e.g. --drange-args='--algorithm incremental'")
    ap.add_argument("--qhull", action="store_true", help="also run Qhull")
    ap.add_argument("--no-cgal", action="store_true", help="do not run CGAL")
    ap.add_argument("--check", action="store_true", help="validate drange's output with drange check")
    ap.add_argument("--timeout", type=int, default=300, help="seconds per run (default 300)")
    ap.add_argument("--mem-limit-gib", type=float, default=16, help="address space per run (default 16; 0: none)")
    ap.add_argument("--build", default=os.path.join(ROOT, "build-bench"), help="the bench build (default build-bench)")
    ap.add_argument("--drange", default="", help="the drange binary (default: BUILD/drange)")
    ap.add_argument("--data", default=os.path.join(HERE, "data"), help="where the inputs go (default bench/data)")
    ap.add_argument("-o", "--output", default="", help="also write the table here")
    args = ap.parse_args()
    try:
        sizes = [int(x) for x in args.sizes.split(",")]
    except ValueError:
        ap.error(f"--sizes: '{args.sizes}' is not a list of integers")
    names = args.families.split(",") if args.families else \
        [name for name, (dim, _) in degenerate_families.SURFACES.items() if dim <= 3]
    unknown = [name for name in names if name not in degenerate_families.SURFACES]
    if unknown:
        ap.error(f"--families: unknown {', '.join(unknown)} (known: {', '.join(degenerate_families.SURFACES)})")
    drange = args.drange or os.path.join(args.build, "drange")
    runner = os.path.join(args.build, "bench", "drange_bench_run")
    for program in [drange] + ([runner] if args.qhull or not args.no_cgal else []):
        if not os.access(program, os.X_OK):
            sys.exit(f"bench/stability.py: {program} is not built (bench/run.sh --rows ... or cmake --build build-bench)")
    extra = shlex.split(args.drange_args)
    mem_limit = int(args.mem_limit_gib * 2**30) if args.mem_limit_gib > 0 else 0

    dims = sorted({degenerate_families.SURFACES[name][0] for name in names})
    rows = []  # (label, dist for run.input_file, n, d): by dimension, then input, then size
    for d in dims:
        rows += [(f"uniform{d}", "uniform", n, d) for n in sizes]
        rows += [(name, "family:" + degenerate_families.surface_file_name(name, n), n, d)
                 for name in names if degenerate_families.SURFACES[name][0] == d for n in sizes]

    os.makedirs(args.data, exist_ok=True)
    started = time.monotonic()
    measured = {}  # (label, n) -> (drange result, cgal result, qhull result)
    for label, dist, n, d in rows:
        path = run.input_file(args.build, args.data, dist, n, d)
        run.log(f"{label} {n}")
        ours = run_drange(drange, path, extra, args.timeout, mem_limit, args.check)
        cgal = {"status": "not run"} if args.no_cgal else \
            run.run_one(args.build, CGAL_PEER.get(d, "cgal-dd"), path, args.timeout, mem_limit)
        qhull = run.run_one(args.build, "qhull", path, args.timeout, mem_limit) if args.qhull else None
        measured[label, n] = (ours, cgal, qhull)

    def time_of(r):
        return float(r["seconds"]) if r and r.get("status") == "ok" else None

    def per_simplex(r):
        return time_of(r) / max(int(r["simplices"]), 1) if time_of(r) is not None else None

    head = ["input", "d", "n", "simplices", "drange s", "drange us/simplex", "growth", "drange / uniform",
            "CGAL s", "drange / CGAL"]
    if args.qhull:
        head += ["Qhull s", "drange / Qhull"]
    if args.check:
        head += ["valid"]
    table = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for label, dist, n, d in rows:
        ours, cgal, qhull = measured[label, n]
        first = per_simplex(measured[label, sizes[0]][0])
        uniform = time_of(measured[f"uniform{d}", n][0])
        cells = [label, str(d), f"{n:,}".replace(",", " "), ours.get("simplices", ""), seconds(ours, args.timeout),
                 quotient(per_simplex(ours), 1e-6, "{:.2f}"), quotient(per_simplex(ours), first),
                 quotient(time_of(ours), uniform), seconds(cgal, args.timeout)]
        if cgal.get("status") == "ok" and ours.get("status") == "ok" and cgal["simplices"] != ours["simplices"]:
            cells[-1] += f" ({cgal['simplices']} simplices)"
        cells.append(quotient(time_of(ours), time_of(cgal)))
        if args.qhull:
            cells += [seconds(qhull, args.timeout), quotient(time_of(ours), time_of(qhull))]
        if args.check:
            cells.append(ours.get("valid", ""))
        table.append("| " + " | ".join(cells) + " |")

    out = [f"Command: `bench/stability.py {' '.join(shlex.quote(a) for a in sys.argv[1:])}`  ",
           f"Commit: {run.commit()}; drange: {drange}; per-run timeout {args.timeout} s; "
           f"the whole run took {(time.monotonic() - started) / 60:.1f} min", ""]
    out += run.machine() + [""]
    out.append("One thread, one process per run. drange s is `--stats` time_total (construction, reading "
               "excluded); CGAL's and Qhull's are their construction (bench/run_one.cpp). growth = drange's "
               f"time per simplex over the same input's at {sizes[0]} points; drange / uniform = drange's time "
               "over its time on uniform points of the same d and n; drange / CGAL and drange / Qhull: below 1 "
               "drange is faster. A count in parentheses is CGAL's where it differs from drange's (cospherical "
               "points have several Delaunay triangulations, not all of one size).")
    out.append("")
    out += table
    text = "\n".join(out) + "\n"
    sys.stdout.write(text)
    if args.output:
        with open(args.output, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
