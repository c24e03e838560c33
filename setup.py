"""pip packaging: the extension module is built by the project's CMake build.

Works offline: `pip install --no-build-isolation .` (setuptools, CMake, a C++20
compiler, pybind11 and oneTBB come from Debian packages; see scripts/setup.sh).
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
# The version is the one of project(sillage VERSION ...) in CMakeLists.txt (also sillage.__version__).
VERSION = re.search(r"project\(sillage VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        # SILLAGE_BUILD_DIR: a build directory of this project configured with the Python module
        # (scripts/build.sh's build/): the module is built there (nothing to do when it is up to
        # date) instead of configuring and compiling everything again in a directory of pip's.
        reuse = os.environ.get("SILLAGE_BUILD_DIR")
        build_dir = Path(reuse).resolve() if reuse else Path(self.build_temp).resolve() / "cmake"
        if reuse and not (build_dir / "CMakeCache.txt").is_file():
            raise RuntimeError(f"SILLAGE_BUILD_DIR={reuse}: not a configured CMake build directory")
        if not reuse:
            build_dir.mkdir(parents=True, exist_ok=True)
            subprocess.check_call([
                "cmake", "-S", str(ROOT), "-B", str(build_dir),
                "-DCMAKE_BUILD_TYPE=Release",
                "-DSILLAGE_BUILD_TESTS=OFF", "-DSILLAGE_BUILD_BENCH=OFF", "-DSILLAGE_BUILD_EXAMPLES=OFF",
                f"-DPython3_EXECUTABLE={sys.executable}",
            ])
        jobs = str(os.cpu_count() or 2)
        subprocess.check_call(["cmake", "--build", str(build_dir), "--target", "_sillage", "-j", jobs])
        built = next((build_dir / "python" / "sillage").glob("_sillage*.so"))
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(
    version=VERSION,
    packages=["sillage"],
    package_dir={"sillage": "python/sillage"},
    ext_modules=[Extension("sillage._sillage", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
