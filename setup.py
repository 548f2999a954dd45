"""Builds the extension `hoct._hoct` with the project's CMake (only the `_hoct` target: the
library and its Python binding) for the Python interpreter that runs the build, and installs it
with the pure-Python package python/hoct. Metadata lives in pyproject.toml.

HOCT_PIP_BUILD_DIR, if set, is the CMake build directory to use (kept between installs);
HOCT_PIP_JOBS the number of parallel compile jobs (default: all cores).
"""
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = os.environ.get("HOCT_PIP_BUILD_DIR")
        build_dir = pathlib.Path(build_dir) if build_dir else pathlib.Path(self.build_temp).resolve() / "cmake"
        build_dir.mkdir(parents=True, exist_ok=True)
        configure = ["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                     "-DHOCT_BUILD_TESTS=OFF", "-DHOCT_BUILD_PARAVIEW=OFF",
                     f"-DPYTHON_EXECUTABLE={sys.executable}"]
        if shutil.which("ninja") and not (build_dir / "CMakeCache.txt").exists():
            configure += ["-G", "Ninja"]
        jobs = os.environ.get("HOCT_PIP_JOBS") or str(os.cpu_count() or 1)
        subprocess.check_call(configure)
        subprocess.check_call(["cmake", "--build", str(build_dir), "--target", "_hoct", "-j", jobs])
        built = sorted((build_dir / "python" / "hoct").glob("_hoct*.so"))
        if not built:
            raise RuntimeError(f"the CMake build produced no _hoct module under {build_dir}")
        dest = pathlib.Path(self.get_ext_fullpath(ext.name))
        dest.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built[0], dest)


setup(
    packages=["hoct"],
    package_dir={"hoct": "python/hoct"},
    ext_modules=[CMakeExtension("hoct._hoct")],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
