"""drange.interpolate's LinearNDInterpolator and CloughTocher2DInterpolator against
scipy.interpolate's on N random 2D samples evaluated at M random points: wall time of the
construction (for Clough-Tocher, with the gradient estimation) and of the first evaluation
(which includes the barycentric transforms in both), as a user sees them. Not run by the tests.

    PYTHONPATH=build/python /usr/bin/python3 bench/interpolate_vs_scipy.py [--n N] [--m M] [--seed S]

Prints, for each class, the times and the ratio drange/scipy (below 1: drange faster), and the
largest difference between the two results where both interpolate.
"""
import argparse
import os
import time

import numpy as np
import scipy
import scipy.interpolate

import drange
import drange.interpolate


def timed(function):
    start = time.perf_counter()
    result = function()
    return result, time.perf_counter() - start


def run(module, name, points, values, xi):
    interpolant, build = timed(lambda: getattr(module, name)(points, values))
    result, evaluate = timed(lambda: interpolant(xi))
    return result, build, evaluate


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1_000_000, help="sample points (default 1 000 000)")
    parser.add_argument("--m", type=int, default=1_000_000, help="query points (default 1 000 000)")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    points = rng.random((args.n, 2))
    values = np.sin(4 * points[:, 0]) * np.cos(3 * points[:, 1])
    xi = rng.random((args.m, 2))

    print(f"2D, N = {args.n} samples, M = {args.m} queries, {os.cpu_count()} cores; "
          f"drange {drange.__version__}, scipy {scipy.__version__}")
    for name in ("LinearNDInterpolator", "CloughTocher2DInterpolator"):
        ours = run(drange.interpolate, name, points, values, xi)
        theirs = run(scipy.interpolate, name, points, values, xi)
        print(f"\n{name:26} {'drange s':>10} {'scipy s':>10} {'ratio':>7}")
        for row, index in (("build", 1), ("evaluate", 2)):
            print(f"{row:26} {ours[index]:10.3f} {theirs[index]:10.3f} {ours[index] / theirs[index]:7.3f}")
        total_ours, total_theirs = ours[1] + ours[2], theirs[1] + theirs[2]
        print(f"{'total':26} {total_ours:10.3f} {total_theirs:10.3f} {total_ours / total_theirs:7.3f}")
        both = ~np.isnan(ours[0]) & ~np.isnan(theirs[0])
        print(f"largest difference where both interpolate: {np.abs(ours[0][both] - theirs[0][both]).max():.3g}; "
              f"NaN (outside the hull): drange {np.isnan(ours[0]).sum()}, scipy {np.isnan(theirs[0]).sum()}")


if __name__ == "__main__":
    main()
