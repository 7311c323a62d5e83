"""`pip install .`: setuptools drives CMake to build the compiled module `puncture._puncture`.

The pure-Python modules come from python/puncture; the version from CMakeLists.txt, its one
place.  CMake builds in setuptools' temporary folder with the tests, benchmarks and examples off,
or, when PUNCTURE_BUILD_DIR names an already configured build tree, there (only the extension's
target is built: a developer's tree is reused, not reconfigured).
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


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    match = re.search(r"project\(puncture VERSION ([0-9]+\.[0-9]+\.[0-9]+)", text)
    if not match:
        raise RuntimeError("CMakeLists.txt: no 'project(puncture VERSION x.y.z' line")
    return match.group(1)


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        target = Path(self.get_ext_fullpath(ext.name)).resolve()
        given = os.environ.get("PUNCTURE_BUILD_DIR")
        if given:
            build = Path(given).resolve()
        else:
            build = Path(self.build_temp).resolve() / "cmake"
            subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build),
                            "-DCMAKE_BUILD_TYPE=Release",
                            f"-DPython_EXECUTABLE={sys.executable}",
                            "-DPUNCTURE_BUILD_PYTHON=ON", "-DPUNCTURE_BUILD_TESTS=OFF",
                            "-DPUNCTURE_BUILD_BENCHMARKS=OFF", "-DPUNCTURE_BUILD_EXAMPLES=OFF"],
                           check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "--target", "_puncture", "-j", jobs],
                       check=True)
        built = sorted((build / "python" / "puncture").glob("_puncture*.so"))
        if not built:
            raise RuntimeError(f"{build}: CMake built no python/puncture/_puncture*.so "
                               "(is PUNCTURE_BUILD_PYTHON on there?)")
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


setup(
    version=project_version(),
    packages=["puncture"],
    package_dir={"": "python"},
    ext_modules=[CMakeExtension("puncture._puncture")],
    cmdclass={"build_ext": CMakeBuild},
    # Not ./build: that is the CMake build tree of README's commands.
    options={"build": {"build_base": "build-pip"}},
    zip_safe=False,
)
