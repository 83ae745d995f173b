"""setuptools driving CMake: builds the scbt Python module (target scbt_python, python/) and
puts it, with its type stub, into the wheel. Called by `pip install .` (pyproject.toml).

Environment:
  SCBT_CMAKE_BUILD_DIR  an existing CMake build tree of this source (e.g. `build`): only
                        `cmake --build DIR --target scbt_python` runs there (nothing when it is
                        up to date); its module must have this interpreter's ABI suffix.
                        Otherwise a tree of its own is configured in build/pip-<python tag>
                        with tests, benchmarks and ROS off, and only scbt_python is built.
  SCBT_BUILD_JOBS       parallel compile jobs (default 2).
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def project_version():
    """The version's one place: project(scbt VERSION x.y.z) in the top-level CMakeLists.txt."""
    text = (ROOT / "CMakeLists.txt").read_text()
    match = re.search(r"^project\(scbt VERSION ([0-9.]+)", text, re.MULTILINE)
    if not match:
        sys.exit("setup.py: no project(scbt VERSION ...) in CMakeLists.txt")
    return match.group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        tree = os.environ.get("SCBT_CMAKE_BUILD_DIR")
        if tree:
            tree = pathlib.Path(tree).resolve()
            if not (tree / "CMakeCache.txt").is_file():
                sys.exit(f"setup.py: SCBT_CMAKE_BUILD_DIR={tree} is not a CMake build tree")
        else:
            tree = ROOT / "build" / f"pip-{sys.implementation.cache_tag}"
            subprocess.check_call([
                "cmake", "-S", str(ROOT), "-B", str(tree), "-DCMAKE_BUILD_TYPE=Release",
                f"-DPython3_EXECUTABLE={sys.executable}", "-DSCBT_BUILD_TESTS=OFF",
                "-DSCBT_BUILD_BENCH=OFF", "-DSCBT_BUILD_ROS=OFF", "-DSCBT_BUILD_PYTHON=ON",
            ])
        jobs = os.environ.get("SCBT_BUILD_JOBS", "2")
        subprocess.check_call(
            ["cmake", "--build", str(tree), "--target", "scbt_python", "-j", jobs])
        module = tree / "python" / f"scbt{suffix}"
        if not module.is_file():
            found = sorted(p.name for p in (tree / "python").glob("scbt*.so"))
            sys.exit(f"setup.py: {module.name} not built in {tree / 'python'} (found {found}): "
                     "that tree was configured for another Python")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(module, target)
        shutil.copyfile(ROOT / "python" / "scbt.pyi", target.parent / "scbt.pyi")


STAGING = ROOT / "build" / "setuptools"
STAGING.mkdir(parents=True, exist_ok=True)

setup(
    version=project_version(),
    # setuptools' own staging (lib.*, bdist.*, scbt.egg-info) beside the CMake trees, out of git's way.
    options={
        "build": {"build_base": str(STAGING)},
        "egg_info": {"egg_base": str(STAGING)},
    },
    ext_modules=[Extension("scbt", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
