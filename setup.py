"""`pip install .` builds the Python module with the project's own CMake (the
release settings, only the module's target) and installs it with its type
stubs (python/aapat-stubs, PEP 561). Debian 12 has no scikit-build, so
setuptools drives CMake here: the same sources, flags and dependencies as
`cmake --preset release`, from Debian's packages (scripts/install-deps.sh),
with no network."""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

root = pathlib.Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        # AAPAT_CMAKE_BUILD_DIR: a build folder already configured (e.g.
        # build/release, as the test script does): only the module's target is
        # brought up to date there, instead of configuring build/pip afresh.
        given = os.environ.get("AAPAT_CMAKE_BUILD_DIR")
        build = pathlib.Path(given).resolve() if given else root / "build" / "pip"
        if not given:
            subprocess.run(
                ["cmake", "-S", str(root), "-B", str(build), "-G", "Ninja",
                 "-DCMAKE_BUILD_TYPE=Release", "-DAAPAT_BUILD_TESTS=OFF", "-DAAPAT_BUILD_BENCH=OFF",
                 "-DAAPAT_BUILD_VK_COMPARE=OFF", "-DAAPAT_MPI=OFF", "-DAAPAT_BUILD_PYTHON=ON",
                 f"-DPython_EXECUTABLE={sys.executable}"], check=True)
        jobs = str(os.cpu_count() or 2)
        subprocess.run(["cmake", "--build", str(build), "--target", "aapat_python", "-j", jobs],
                       check=True)
        built = next((build / "python").glob("aapat*.so"))
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


version = re.search(r"project\(aapat VERSION ([0-9.]+)",
                    (root / "CMakeLists.txt").read_text()).group(1)
setup(
    version=version,
    ext_modules=[CMakeExtension("aapat")],
    cmdclass={"build_ext": CMakeBuild},
    packages=["aapat-stubs"],
    package_dir={"aapat-stubs": "python/aapat-stubs"},
    package_data={"aapat-stubs": ["__init__.pyi"]},
    zip_safe=False,
)
