"""Runs scipy's own tests of its Qhull classes (scipy/spatial/tests/test_qhull.py, as installed)
with drange's classes in their place (drange_in_place.py), and compares the outcome with
known_differences.txt: every test must pass except those listed there, and each listed one
must still fail (so that a fix shows, and the list stays true). Prints the count; exits 1 on
any test whose outcome is not the expected one. docs/formats.md explains each difference.

    PYTHONPATH=build/python python3 python/tests/scipy_suite/run_scipy_suite.py
"""
import os
import sys

import pytest
import scipy.spatial

HERE = os.path.dirname(os.path.abspath(__file__))


class Outcomes:
    def __init__(self):
        self.failed, self.passed = set(), set()

    def pytest_runtest_logreport(self, report):
        name = report.nodeid.split("::", 1)[1]
        if report.failed:
            self.failed.add(name)
        elif report.passed and report.when == "call":
            self.passed.add(name)


def known_differences():
    with open(os.path.join(HERE, "known_differences.txt")) as listing:
        lines = (line.split("#", 1)[0].strip() for line in listing)
        return {line for line in lines if line}


def main():
    suite = os.path.join(os.path.dirname(scipy.spatial.__file__), "tests", "test_qhull.py")
    if not os.path.exists(suite):
        print(f"scipy's test file is not installed ({suite}): not tested")
        return 0
    sys.path.insert(0, HERE)
    outcomes = Outcomes()
    pytest.main([suite, "-q", "-p", "no:cacheprovider", "-p", "drange_in_place", "--tb=short",
                 "-W", "ignore::pytest.PytestRemovedIn8Warning"], plugins=[outcomes])
    expected = known_differences()
    unexpected_failures = sorted(outcomes.failed - expected)
    unexpected_passes = sorted(expected & outcomes.passed)
    missing = sorted(expected - outcomes.failed - outcomes.passed)
    total = len(outcomes.failed | outcomes.passed)
    print(f"scipy's test_qhull.py against drange: {len(outcomes.passed)} of {total} passed, "
          f"{len(outcomes.failed & expected)} known differences (known_differences.txt)")
    for name in unexpected_failures:
        print(f"UNEXPECTED FAILURE: {name}")
    for name in unexpected_passes:
        print(f"NOW PASSES (remove it from known_differences.txt): {name}")
    for name in missing:
        print(f"LISTED BUT NOT RUN: {name}")
    return 1 if unexpected_failures or unexpected_passes or missing else 0


if __name__ == "__main__":
    sys.exit(main())
