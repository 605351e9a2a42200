"""Running in a Python program: the GIL is released while the engine computes, Ctrl-C stops a
long run, progress is reported, and the thread count does not change the result."""
import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import drange
from conftest import sample

LONG_INPUT = (400000, 2)  # about a second of work


def test_other_python_threads_run_during_a_computation():
    points = sample("uniform", *LONG_INPUT, seed=1)
    done = threading.Event()
    result = {}

    def work():
        result["tri"] = drange.Delaunay(points, threads=1)
        done.set()

    worker = threading.Thread(target=work)
    ticks = 0
    worker.start()
    while not done.is_set():
        ticks += 1  # runs only while the worker does not hold the GIL
        time.sleep(0.001)
    worker.join()
    assert result["tri"].nsimplex > 0
    assert ticks > 20


def test_ctrl_c_interrupts_a_long_run():
    points = sample("uniform", 3000000, 2, seed=1)  # several seconds of work
    seen = []
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            drange.Delaunay(points, threads=1, progress=seen.append)
    finally:
        timer.cancel()
    # Stopped early, not at the end (about 6 million triangles); counted in simplices rather
    # than seconds, so that a loaded machine cannot fail the test.
    assert len(seen) < 60 and (not seen or seen[-1] < 4000000)


def test_ctrl_c_in_a_separate_interpreter():
    # The same from a fresh process, the way a user meets it: the script must end with
    # KeyboardInterrupt, not run to completion.
    script = (
        "import os, signal, threading, numpy as np, drange\n"
        "p = np.random.default_rng(1).random((3000000, 2))\n"
        "threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT)).start()\n"
        "try:\n"
        "    drange.Delaunay(p, threads=1)\n"
        "    print('completed')\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted')\n"
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert done.stdout.strip() == "interrupted", done.stderr


def test_progress_reports_increasing_counts():
    seen = []
    tri = drange.Delaunay(sample("uniform", 100000, 2, seed=2), progress=seen.append)
    assert seen[:-1] == [65536 * (i + 1) for i in range(len(seen) - 1)]
    assert seen[-1] == tri.nsimplex


@pytest.mark.parametrize("kind,n,d", [("uniform", 20000, 2), ("uniform", 5000, 3), ("gaussian", 1000, 4)])
def test_thread_count_does_not_change_the_result(kind, n, d):
    points = sample(kind, n, d, seed=n)
    one = drange.Delaunay(points, threads=1)
    for threads in (0, 2, 3):
        other = drange.Delaunay(points, threads=threads)
        assert np.array_equal(one.simplices, other.simplices)
        assert np.array_equal(one.neighbors, other.neighbors)
    assert drange.Delaunay(points, threads=2).statistics["threads"] == 2


def test_find_simplex_gives_the_same_answers_on_every_thread_count():
    points = sample("uniform", 5000, 2, seed=3)
    queries = np.random.default_rng(4).uniform(-0.1, 1.1, (50000, 2))
    one = drange.Delaunay(points, threads=1).find_simplex(queries)
    for threads in (0, 2, 3):
        assert np.array_equal(one, drange.Delaunay(points, threads=threads).find_simplex(queries))
    assert (one >= 0).sum() > 30000 and (one == -1).sum() > 5000
