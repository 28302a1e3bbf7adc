# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The extension module archgeo._archgeo, built by CMake (pyproject.toml has
the package's metadata).

The CMake build goes to build/pip (or $ARCHGEO_CMAKE_BUILD_DIR): Release,
without tests, for the interpreter running pip; parallel jobs from
$CMAKE_BUILD_PARALLEL_LEVEL (default: every core). A second install reuses it.
"""
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeBuild(build_ext):
    """Configures and builds the target archgeo_python, then copies the module."""

    def build_extension(self, ext):
        build = os.environ.get("ARCHGEO_CMAKE_BUILD_DIR", os.path.join(ROOT, "build", "pip"))
        subprocess.run(["cmake", "-S", ROOT, "-B", build, "-G", "Ninja",
                        "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_TESTING=OFF",
                        "-DARCHGEO_PYTHON=ON", f"-DPython3_EXECUTABLE={sys.executable}"],
                       check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", build, "--target", "archgeo_python", "-j", jobs],
                       check=True)
        package = os.path.join(build, "python", "archgeo")
        built = [f for f in os.listdir(package) if f.startswith("_archgeo.") and f.endswith(".so")]
        if len(built) != 1:
            sys.exit(f"setup.py: expected one _archgeo*.so in {package}, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(os.path.join(package, built[0]), target)


setup(ext_modules=[Extension("archgeo._archgeo", sources=[])],
      cmdclass={"build_ext": CMakeBuild})
