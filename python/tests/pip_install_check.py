"""`pip install` from the source tree into a scratch folder, then drange imported from there alone.

Usage: pip_install_check.py SOURCE_DIR WORK_DIR. Runs the README's install command with
--target WORK_DIR/site (no prefix, no venv: nothing outside WORK_DIR is written; Debian's
EXTERNALLY-MANAGED guard does not apply to --target), then, from /, an interpreter that does not
see PYTHONPATH or the source tree imports the installed package, checks that it is the one in
WORK_DIR/site, and triangulates. The CMake build folder WORK_DIR/cmake is kept between runs, so
a rerun only checks that the module is up to date (the first run compiles, through ccache when
CMAKE_CXX_COMPILER_LAUNCHER names it).
"""
import os
import shutil
import subprocess
import sys

source, work = (os.path.abspath(p) for p in sys.argv[1:3])
os.makedirs(work, exist_ok=True)
site = os.path.join(work, "site")
shutil.rmtree(site, ignore_errors=True)
shutil.rmtree(os.path.join(work, "setuptools"), ignore_errors=True)
env = dict(os.environ, DRANGE_CMAKE_BUILD_DIR=os.path.join(work, "cmake"),
           DRANGE_SETUPTOOLS_BUILD=os.path.join(work, "setuptools"), PIP_NO_INPUT="1")
subprocess.run([sys.executable, "-m", "pip", "install", "--no-build-isolation", "--no-deps", "--no-cache-dir",
                "--no-index", "--disable-pip-version-check", "--root-user-action=ignore", "--target", site, source],
               check=True, env=env, cwd=work)

check = f"""
import sys
sys.path.insert(0, {site!r})
import numpy as np
import drange
assert drange.__file__.startswith({site!r}), drange.__file__
tri = drange.Delaunay(np.array([[0, 0], [1, 0], [0, 1], [1, 1], [0.5, 0.25]]))
assert tri.nsimplex == 4 and drange.check_triangulation(tri.points, tri.simplices)["valid"]
print("installed drange triangulates:", tri.nsimplex, "simplices")
"""
# -I: neither PYTHONPATH nor the user's site folder nor the current folder is on the path.
subprocess.run([sys.executable, "-I", "-c", check], check=True, cwd="/")
