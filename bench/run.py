#!/usr/bin/env python3
"""bench/run.py: runs the benchmark set, one process per (input, peer), and writes Markdown.

Called by bench/run.sh (which installs the peers and builds build-bench; its header lists the
options). Every measurement is `drange_bench_run --peer P --input F` under `timeout`, with an address
space limit, so a peer that runs too long shows "> T s" and one that runs out of memory "OOM".
"""
import argparse
import datetime
import os
import platform
import resource
import shlex
import subprocess
import sys
import time

import degenerate_families  # bench/, this script's directory

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

PEERS_BY_DIM = {
    2: ["cgal2", "cgal-dd", "cgal-dd-dyn", "qhull", "fortune"],
    3: ["cgal3", "cgal3-par", "cgal-dd", "cgal-dd-dyn", "qhull", "tetgen"],
    4: ["cgal-dd", "cgal-dd-dyn", "qhull"],
    5: ["cgal-dd", "cgal-dd-dyn", "qhull"],
}
# From 6D on, CGAL's dD triangulation runs with the static dimension only: the dynamic one was
# slower in every measured row (1.7 to 2.4 times the static one's time in 4D to 8D) and alone
# took 3.5 minutes of the standard set in 6D to 8D.
HIGH_D_PEERS = ["cgal-dd", "qhull"]
# drange on every core runs up to this dimension (the 2-core speed-up was 1.82 to 1.96 in 4D to
# 8D in every earlier run); above, it would add a minute to the standard set.
MAX_THREADED_D = 5
ALL_PEERS = ["cgal2", "cgal3", "cgal3-par", "cgal-dd", "cgal-dd-dyn", "qhull", "fortune", "tetgen"]
PEER_TITLES = {
    "cgal2": "CGAL 2D", "cgal3": "CGAL 3D", "cgal3-par": "CGAL 3D par", "cgal-dd": "CGAL dD static",
    "cgal-dd-dyn": "CGAL dD dynamic", "qhull": "Qhull", "fortune": "Fortune (Boost)", "tetgen": "TetGen",
}

# (distribution, n, d): the standard set of issue 4, and the quick subset.
STANDARD = [
    ("uniform", 100000, 2), ("uniform", 250000, 2), ("uniform", 500000, 2), ("uniform", 1000000, 2),
    ("gaussian", 1000000, 2), ("grid", 1000000, 2), ("sphere", 20000, 2),
    ("uniform", 100000, 3), ("uniform", 1000000, 3), ("gaussian", 200000, 3), ("grid", 216000, 3),
    ("uniform", 216000, 3), ("sphere", 2000, 3),
    ("uniform", 100000, 4), ("uniform", 20000, 5), ("uniform", 5000, 6), ("uniform", 2000, 7), ("uniform", 300, 8),
]
# Rows for drange alone: the uniform input of the 3D grid's size, for the grid-to-uniform ratio.
DRANGE_ONLY = {("uniform", 216000, 3)}
# The d = 7 and d = 8 targets of issue 4: sizes where the peers take over 10 minutes
# (`--beyond`, with a 600 s limit). In each dimension the smaller size is one where CGAL dD still
# finishes, so that a ratio is measured, and the larger one where it does not; bench/RESULTS.md
# has the run. A peer that timed out on uniform input is not run on more points.
BEYOND = [("uniform", 4500, 7), ("uniform", 9000, 7), ("uniform", 1500, 8), ("uniform", 2000, 8)]
# `--degenerate`: the probe inputs of bench/degenerate_families.py (points on curved sets that are
# not one input sphere: concentric spheres, spheres about several centres, rings, smooth
# surfaces; a plateau; decimal grids and rounded points), as ("family:NAME", n, d), against the
# peers of DEGENERATE_PEERS only.
DEGENERATE = [("family:" + name, n, d) for name, n, d in [
    ("two_circles", 20000, 2), ("bubbles2", 20000, 2), ("polar_grid", 20000, 2),
    ("two_spheres3", 20000, 3), ("five_spheres3", 20000, 3), ("layers3", 20000, 3), ("bubbles3", 20000, 3),
    ("cylinder_rings", 20000, 3), ("circle_in_3d", 20002, 3), ("cylinder", 20000, 3), ("torus", 20000, 3),
    ("ellipse", 20000, 2), ("ellipsoid", 20000, 3), ("ellipsoid_200k", 200000, 3), ("wavy_sphere", 20000, 3),
    ("hemisphere", 20000, 3), ("sphere_in_ball", 20000, 3), ("two_spheres4", 5000, 4), ("plateau", 20000, 3),
    ("decimal_grid3", 19683, 3), ("decimal_grid2", 20000, 2), ("rounded3", 20000, 3),
    ("rounded3_dense", 100000, 3), ("rounded4", 20000, 4), ("decimal_grid4", 10000, 4), ("decimal_grid5", 3125, 5),
    ("decimal_grid6", 729, 6), ("decimal_grid7", 1458, 7)]]
# And the surface families of issue 44 (boundaries of a square and a cube within 1e-10, the
# vertices of meshes, a freeform patch, a torus in R^4) at their default sizes, and cube_faces3
# at ten times its size too, named NAME_N.
DEGENERATE += [("family:" + degenerate_families.surface_file_name(name, n), n, degenerate_families.SURFACES[name][0])
               for name, n in degenerate_families.DEFAULT_SURFACE_ROWS + [("cube_faces3", 200000)]]
DEGENERATE_PEERS = {2: ["cgal2", "qhull"], 3: ["cgal3", "qhull"], 4: ["cgal-dd", "qhull"], 5: ["cgal-dd", "qhull"],
                    6: ["cgal-dd", "qhull"], 7: ["cgal-dd", "qhull"]}
QUICK = [("uniform", 100000, 2), ("grid", 90000, 2), ("uniform", 100000, 3), ("uniform", 10000, 4), ("uniform", 3000, 5)]
# Ablation: (distribution, n, d, variants).
ABLATION = [
    # "kdtree" (no optimisation) takes half a minute at this size: it is in the 20 000 row.
    ("uniform", 100000, 2, ["full", "no-bottom-up", "no-seed", "no-ball", "paper", "no-prune", "no-order"]),
    ("uniform", 20000, 2, ["full", "paper", "no-prune", "no-order", "kdtree", "scan"]),
    ("uniform", 20000, 3, ["full", "no-bottom-up", "no-seed", "no-ball", "paper", "no-prune", "no-order", "kdtree"]),
    # The hull's facets known beforehand act on large hulls (uniform points keep none).
    ("family:ellipsoid_200k", 200000, 3, ["full", "no-hull"]),
    ("family:ellipse", 20000, 2, ["full", "no-hull"]),
    ("sphere", 200000, 2, ["full", "no-hull"]),
]
QUICK_ABLATION = [("uniform", 20000, 2, ["full", "paper", "no-prune", "no-order", "kdtree", "scan"])]


def log(*args):
    print(*args, file=sys.stderr, flush=True)


def grid_label(dist, n, d):
    if dist != "grid":
        return None
    k = round(n ** (1.0 / d))
    return f"{k}^{d}" if k ** d == n else None


def input_file(build, data, dist, n, d):
    if dist.startswith("family:"):
        families = os.path.join(data, "families")
        path = os.path.join(families, dist[len("family:"):] + ".txt")
        if not os.path.exists(path):
            script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "degenerate_families.py")
            # A surface file alone (NAME_N); any other family with all the probe families, as
            # they share one random generator.
            name, _, size = dist[len("family:"):].rpartition("_")
            only = ["--surfaces-only", "--families", name, "--sizes", size] \
                if name in degenerate_families.SURFACES and size.isdigit() else []
            subprocess.run([sys.executable, script, families] + only, check=True, stdout=subprocess.DEVNULL)
        return path
    path = os.path.join(data, f"{dist}_{d}d_{n}.txt")
    if not os.path.exists(path):
        subprocess.run([os.path.join(build, "drange"), "generate", dist, str(n), str(d), "--seed", "1", "-o", path],
                       check=True)
    return path


def run_one(build, peer, path, timeout, mem_limit, threads=1, variant=None):
    cmd = [os.path.join(build, "bench", "drange_bench_run"), "--peer", peer, "--input", path, "--threads", str(threads)]
    if variant:
        cmd += ["--variant", variant]

    def limit():
        if mem_limit:
            resource.setrlimit(resource.RLIMIT_AS, (mem_limit, mem_limit))

    start = time.monotonic()
    try:
        p = subprocess.run(["timeout", "-s", "KILL", str(timeout)] + cmd, capture_output=True, text=True,
                           preexec_fn=limit)
    except OSError as e:
        return {"status": "error", "message": str(e)}
    wall = time.monotonic() - start
    result = {"status": "error", "wall": wall}
    for line in p.stdout.splitlines():
        if line.startswith("RESULT "):
            for token in line.split()[1:]:
                key, _, value = token.partition("=")
                result[key] = value
    if p.returncode == 137 or p.returncode == 124 or (p.returncode == -9):
        result["status"] = "timeout" if wall >= timeout - 1 else "oom"  # SIGKILL before the limit: the OOM killer
    elif p.returncode != 0 and result.get("status") == "ok":
        result["status"] = "error"
    elif result.get("status") == "error" and ("bad_alloc" in p.stderr or "memory" in p.stderr.lower()):
        result["status"] = "oom"
    if p.returncode not in (0,) and p.stderr:
        result["message"] = p.stderr.strip().splitlines()[-1][:200]
    log(f"  {peer:12s} {os.path.basename(path):28s} {variant or '':9s} -> {result.get('status')}"
        f" {result.get('seconds', '')} s  (wall {wall:.1f} s)")
    return result


def run_median(build, peer, path, timeout, mem_limit, repeat, threads=1, variant=None):
    """run_one `repeat` times; the run of median time, with every run's seconds under "runs". A first
    run that is not ok (timeout, OOM, n/a) is not repeated; a later failure is the result."""
    first = run_one(build, peer, path, timeout, mem_limit, threads, variant)
    if repeat <= 1 or first.get("status") != "ok":
        return first
    runs = [first] + [run_one(build, peer, path, timeout, mem_limit, threads, variant) for _ in range(repeat - 1)]
    failed = [r for r in runs if r.get("status") != "ok"]
    if failed:
        return failed[0]
    median = dict(sorted(runs, key=lambda r: float(r["seconds"]))[(len(runs) - 1) // 2])
    median["runs"] = " ".join(r["seconds"] for r in runs)
    return median


def selected_rows(rows, spec):
    """The rows named in spec ("dist:d:n,..."), which must all be in `rows`."""
    chosen = []
    for item in spec.split(","):
        try:
            dist, d, n = item.rsplit(":", 2)  # a family's DIST has a colon of its own
            row = (dist, int(n), int(d))
        except ValueError:
            sys.exit(f"bench/run.py: --rows: '{item}' is not DIST:D:N (e.g. uniform:5:20000)")
        if row not in rows:
            sys.exit(f"bench/run.py: --rows: '{item}' is not a row of this set")
        chosen.append(row)
    return chosen


def mib(r):
    return f"{int(r['peak_rss']) / 2**20:.0f}" if "peak_rss" in r else ""


def secs(r, timeout):
    s = r.get("status")
    if s == "ok":
        v = float(r["seconds"])
        return f"{v:.3f}" if v < 10 else f"{v:.1f}"
    if s == "timeout":
        return f"> {timeout} s"
    if s == "oom":
        return "OOM"
    if s in ("n/a", "not-built", "skipped"):
        return s
    return "error"


def ratio(ours, theirs, timeout, own_timeout):
    if ours.get("status") == "ok" and theirs.get("status") == "ok":
        return f"{float(ours['seconds']) / max(float(theirs['seconds']), 1e-9):.2f}"
    if ours.get("status") == "ok" and theirs.get("status") == "timeout":
        return f"< {float(ours['seconds']) / timeout:.2f}"
    if ours.get("status") == "timeout" and theirs.get("status") == "ok":
        return f"> {own_timeout / max(float(theirs['seconds']), 1e-9):.2f}"
    return ""


def commit():
    """The commit the build came from, with "+ changes" when tracked files differ from it, so that
    each generated table says what code it measured (bench/RESULTS.md quotes it)."""
    try:
        head = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                              text=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True).stdout.strip()
    except OSError:
        return "unknown"
    return (head or "unknown") + (" + uncommitted changes" if head and dirty else "")


def machine():
    lines = []
    model = cores = ""
    try:
        out = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
        for line in out.splitlines():
            if line.startswith("Model name:"):
                model = line.split(":", 1)[1].strip()
            if line.startswith("CPU(s):"):
                cores = line.split(":", 1)[1].strip()
    except OSError:
        pass
    ram = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2**30
    gxx = subprocess.run(["g++", "--version"], capture_output=True, text=True).stdout.splitlines()[0]
    lines.append(f"- CPU: {model}, {cores} logical CPUs; RAM {ram:.1f} GiB; {platform.system()} {platform.release()}")
    lines.append(f"- Compiler: {gxx}; Release build (build-bench)")
    pk = []
    for p in ["libcgal-dev", "libqhull-dev", "libboost-dev", "libtbb-dev", "libtet1.5-dev", "libeigen3-dev"]:
        v = subprocess.run(["dpkg-query", "-W", "-f", "${Version}", p], capture_output=True, text=True).stdout
        pk.append(f"{p} {v or 'not installed'}")
    lines.append("- Peers: " + ", ".join(pk))
    return lines


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--data", required=True)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--ablation-only", action="store_true")
    ap.add_argument("--beyond", action="store_true",
                    help="the 7D and 8D rows where the peers take over 10 minutes (about 70 min)")
    ap.add_argument("--degenerate", action="store_true",
                    help="the probe and surface inputs of bench/degenerate_families.py against CGAL and Qhull "
                         "(about 9 min)")
    ap.add_argument("--no-ablation", action="store_true")
    ap.add_argument("--repeat", type=int, default=1,
                    help="run each measurement N times and report the median (odd N: the middle run)")
    ap.add_argument("--rows", default="",
                    help="only these rows of the set, as DIST:D:N separated by commas (uniform:5:20000,...)")
    ap.add_argument("--timeout", type=int, default=None)
    ap.add_argument("--mem-limit-gib", type=float, default=16)
    ap.add_argument("--command", default="")
    ap.add_argument("-o", "--output", required=True)
    args = ap.parse_args()
    timeout = args.timeout or (30 if args.quick else 600 if args.beyond else 90)
    # drange gets a longer limit than the peers, so that a row where the peers time out still
    # says how long drange took (the ratio is then an upper bound: "< x").
    own_timeout = 3 * timeout
    mem_limit = int(args.mem_limit_gib * 2**30) if args.mem_limit_gib > 0 else 0
    os.makedirs(args.data, exist_ok=True)
    rows = QUICK if args.quick else BEYOND if args.beyond else DEGENERATE if args.degenerate else STANDARD
    ablation = QUICK_ABLATION if args.quick else [] if args.beyond or args.degenerate else ABLATION
    peers_by_dim = DEGENERATE_PEERS if args.degenerate else PEERS_BY_DIM
    if args.repeat < 1:
        sys.exit("bench/run.py: --repeat must be at least 1")
    if args.rows:
        rows = selected_rows(rows, args.rows)
        ablation = []
    if args.ablation_only:
        rows = []
    if args.no_ablation:
        ablation = []

    started = time.monotonic()
    load_before = open("/proc/loadavg").read().split()[:3]
    out = []
    title = "quick" if args.quick else "beyond the peers'" if args.beyond else "degenerate families'" if args.degenerate else "standard"
    if args.rows:
        title = "selected rows of the " + title
    out.append(f"# drange benchmark ({title} set)")
    out.append("")
    out.append(f"Command: `{args.command}`  ")
    out.append(f"Commit: {commit()}  ")
    out.append(f"Date: {datetime.datetime.now().strftime('%Y-%m-%d %H:%M')}; per-run timeout {timeout} s; "
               f"address-space limit {args.mem_limit_gib:g} GiB per run")
    out.append("")
    out.extend(machine())
    out.append(f"- Load average before: {' '.join(load_before)}")

    results = []  # (row, peer, result) for the CSV
    table = []
    if rows:
        peers_in_set = [p for p in ALL_PEERS if any(p in peers_by_dim.get(d, HIGH_D_PEERS) for _, _, d in rows)]
        cores = os.cpu_count() or 1
        head = ["input", "d", "n", "drange s", "drange MiB", "bytes/simplex", "calls/simplex", "simplices",
                f"drange {cores} threads s", "speed-up"]
        for p in peers_in_set:
            t = PEER_TITLES[p]
            head += [f"{t} s", f"{t} MiB", f"drange/{t}"]
        table.append("| " + " | ".join(head) + " |")
        table.append("|" + "---|" * len(head))
        # Peers that timed out or ran out of memory on uniform input, with every (d, n) where they
        # did: not run on uniform input of a higher d with at least as many points, or of the same
        # d with more (more work). Every failure counts, not only the first: Qhull's 7D 4 500 says
        # nothing about 8D 1 500 (fewer points), its 8D 1 000 does.
        failed_at = {}
        for dist, n, d in rows:
            path = input_file(args.build, args.data, dist, n, d)
            log(f"{dist} {d}D {n}")
            ours = run_median(args.build, "drange", path, own_timeout, mem_limit, args.repeat)
            results.append((dist, n, d, "drange", ours))
            label = grid_label(dist, n, d)
            cells = [dist.removeprefix("family:") + (f" {label}" if label else ""), str(d), f"{n:,}".replace(",", " "),
                     secs(ours, own_timeout), mib(ours)]
            if ours.get("status") == "ok":
                own = int(ours["peak_rss"]) - int(ours["input_rss"])
                cells += [f"{own / max(int(ours['simplices']), 1):.0f}", ours.get("calls_per_simplex", ""),
                          ours["simplices"]]
            else:
                cells += ["", "", ""]
            # All cores: the same output (tests/threads_test.cpp), so only the time is new.
            speedup = ""
            if d <= MAX_THREADED_D:
                threaded = run_median(args.build, "drange", path, own_timeout, mem_limit, args.repeat, threads=cores)
                results.append((dist, n, d, f"drange:threads={cores}", threaded))
                if ours.get("status") == "ok" and threaded.get("status") == "ok":
                    speedup = f"{float(ours['seconds']) / max(float(threaded['seconds']), 1e-9):.2f}"
                cells += [secs(threaded, own_timeout), speedup]
            else:
                cells += ["not run", ""]
            applicable = [] if (dist, n, d) in DRANGE_ONLY else peers_by_dim.get(d, HIGH_D_PEERS)
            for p in peers_in_set:
                if (dist, n, d) in DRANGE_ONLY:
                    cells += ["not run", "", ""]
                    continue
                if p not in applicable:
                    cells += ["n/a", "", ""]
                    continue
                if dist == "uniform" and any(fd < d and fn <= n or fd == d and fn < n
                                             for fd, fn in failed_at.get(p, [])):
                    r = {"status": "skipped"}
                    log(f"  {p:12s} skipped (timed out or out of memory on a smaller uniform input)")
                else:
                    threads = 2 if p == "cgal3-par" else 1
                    r = run_median(args.build, p, path, timeout, mem_limit, args.repeat, threads=threads)
                    if r.get("status") in ("timeout", "oom") and dist == "uniform":
                        failed_at.setdefault(p, []).append((d, n))
                results.append((dist, n, d, p, r))
                simp = ""
                if r.get("status") == "ok" and ours.get("status") == "ok" and r.get("simplices") != ours.get("simplices"):
                    simp = f" ({r['simplices']} simplices)" if p != "fortune" else f" ({r['simplices']} Voronoi vertices)"
                cells += [secs(r, timeout) + simp, mib(r), ratio(ours, r, timeout, own_timeout)]
            table.append("| " + " | ".join(cells) + " |")

    abl = []
    if ablation:
        abl.append("| input | d | n | variant | total s | search s | calls/simplex | points tested/simplex | simplices |")
        abl.append("|---|---|---|---|---|---|---|---|---|")
        for dist, n, d, variants in ablation:
            path = input_file(args.build, args.data, dist, n, d)
            log(f"ablation {dist} {d}D {n}")
            for v in variants:
                r = run_median(args.build, "drange", path, timeout, mem_limit, args.repeat, variant=v)
                results.append((dist, n, d, f"drange:{v}", r))
                if r.get("status") == "ok":
                    abl.append(f"| {dist} | {d} | {n} | {v} | {secs(r, timeout)} | {float(r['search_seconds']):.3f} | "
                               f"{r['calls_per_simplex']} | {r['tested_per_simplex']} | {r['simplices']} |")
                else:
                    abl.append(f"| {dist} | {d} | {n} | {v} | {secs(r, timeout)} | | | | |")

    load_after = open("/proc/loadavg").read().split()[:3]
    elapsed = time.monotonic() - started
    out.append(f"- Load average after: {' '.join(load_after)}; the whole run took {elapsed / 60:.1f} min")
    if args.repeat > 1:
        out.append(f"- Each time is the median of {args.repeat} runs of the same process (a run that timed out or "
                   f"ran out of memory is not repeated); the CSV lists every run's seconds")
    out.append("")
    out.append("Times are construction only (file reading excluded; conversion to each peer's point type "
               "excluded), one process per measurement, one thread except `CGAL 3D par` (2 threads) and "
               "`drange N threads` (every core; speed-up = drange s / drange N threads s). "
               "MiB is the process's peak RSS (getrusage), input points included; bytes/simplex is drange's "
               "peak RSS minus the RSS after reading the input, divided by the simplices. Ratio = drange seconds / "
               "peer seconds: below 1 drange is faster. A count in parentheses is a peer's simplex count where it "
               "differs from drange's (Fortune counts Voronoi vertices: fewer than triangles on cocircular input). "
               f"`skipped`: the peer timed out or ran out of memory on uniform input of a lower d with no more points "
               f"(or of the same d with fewer), and was not run. drange's own limit is {own_timeout} s, so that its time is known where a peer times out; "
               f"a ratio `< x` is then drange's time over the peer's limit. drange on every core runs up to "
               f"{MAX_THREADED_D}D; CGAL dD dynamic up to 5D (slower than the static dimension in every row). "
               f"A row with `not run` in every peer's column is for drange alone (a uniform input of a grid's size).")
    out.append("")
    if table:
        out.append("## Construction")
        out.append("")
        out.extend(table)
        out.append("")
    if abl:
        out.append("## Ablation (drange --variant)")
        out.append("")
        out.extend(abl)
        out.append("")
    with open(args.output, "w") as f:
        f.write("\n".join(out) + "\n")
    with open(os.path.splitext(args.output)[0] + ".csv", "w") as f:
        f.write("distribution,n,d,peer,status,simplices,seconds,peak_rss,input_rss,calls_per_simplex,search_seconds,"
                "runs\n")
        for dist, n, d, p, r in results:
            f.write(",".join(str(x) for x in [dist, n, d, p, r.get("status", ""), r.get("simplices", ""),
                                               r.get("seconds", ""), r.get("peak_rss", ""), r.get("input_rss", ""),
                                               r.get("calls_per_simplex", ""), r.get("search_seconds", ""),
                                               r.get("runs", r.get("seconds", ""))]) + "\n")
    log(f"wrote {args.output} ({elapsed / 60:.1f} min)")


if __name__ == "__main__":
    main()
