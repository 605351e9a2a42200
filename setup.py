"""setuptools' half of `pip install .`: the extension `drange._drange` is built by CMake.

The metadata is in pyproject.toml. CMake configures the whole project with its tests and install
rules off, builds only the `_drange` target (the library and the module) and the file it makes
is copied where setuptools packs the extension. Environment:
    DRANGE_CMAKE_BUILD_DIR   the CMake build folder (default: one under setuptools' build_temp);
                             a folder kept between installs makes a reinstall incremental
    DRANGE_CMAKE_ARGS        extra arguments for CMake's configure step (split on spaces)
    CMAKE_BUILD_PARALLEL_LEVEL, CMAKE_CXX_COMPILER_LAUNCHER (ccache), CXX: CMake's own.
"""
import glob
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])  # CMake knows the sources


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = os.path.abspath(os.environ.get("DRANGE_CMAKE_BUILD_DIR") or os.path.join(self.build_temp, "cmake"))
        configure = ["cmake", "-S", ROOT, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                     "-DDRANGE_BUILD_TESTS=OFF", "-DDRANGE_INSTALL=OFF", "-DDRANGE_BUILD_PYTHON=ON",
                     f"-DPython3_EXECUTABLE={sys.executable}"]
        configure += os.environ.get("DRANGE_CMAKE_ARGS", "").split()
        build = ["cmake", "--build", build_dir, "--target", "_drange"]
        if "CMAKE_BUILD_PARALLEL_LEVEL" not in os.environ:
            build += ["-j", str(os.cpu_count() or 1)]
        subprocess.run(configure, check=True)
        subprocess.run(build, check=True)
        # The module's file name carries the interpreter's suffix (cpython-311-x86_64-linux-gnu.so),
        # as setuptools expects it.
        built = glob.glob(os.path.join(build_dir, "python", "drange", "_drange*"))
        if len(built) != 1:
            raise RuntimeError(f"CMake built {len(built)} files _drange* in {build_dir}/python/drange; expected one "
                               "(is pybind11-dev installed? CMake's warnings above say what is missing)")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)


setup(ext_modules=[CMakeExtension("drange._drange")], cmdclass={"build_ext": CMakeBuild},
      # setuptools' folders apart from CMake's ./build, which the README's commands use.
      options={"build": {"build_base": os.environ.get("DRANGE_SETUPTOOLS_BUILD", "build-setuptools")},
               "egg_info": {"egg_base": os.environ.get("DRANGE_SETUPTOOLS_BUILD", "build-setuptools")}})
