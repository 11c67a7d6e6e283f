"""A PEP 517 build backend for `pip install .` from a clone, over the CMake build (pyproject.toml).

pip needs nothing downloaded: this file is the backend, in the tree, and it needs the standard
library only. build_wheel runs the `wheel` target of the CMake build in $CAMOPT_BUILD_DIR (default
build/ in the clone) and returns its build/dist/camopt-<version>-<tag>.whl, so the module is the
one that build already made; without a configured build there it configures one (Release, no tests,
benchmarks or docs) and builds the library and the module first. No sdist: the module is built by
CMake from the whole source tree (docs/api.md, "Python wheel").
"""
import os
import pathlib
import shutil
import subprocess
import sys

SOURCE = pathlib.Path(__file__).resolve().parents[1]


def _build_dir():
    return pathlib.Path(os.environ.get("CAMOPT_BUILD_DIR", SOURCE / "build")).resolve()


def _run(args):
    # pip captures the backend's stdout; the build's messages go to stderr (shown with pip -v).
    subprocess.run([str(a) for a in args], check=True, stdout=sys.stderr)


def get_requires_for_build_wheel(config_settings=None):
    return []


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    build = _build_dir()
    if not (build / "CMakeCache.txt").is_file():
        _run(["cmake", "-S", SOURCE, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DCAMOPT_BUILD_TESTS=OFF",
              "-DCAMOPT_BUILD_BENCH=OFF", "-DCAMOPT_BUILD_DOCS=OFF"])
    _run(["cmake", "--build", build, "--target", "wheel"])
    # The wheel's path, written by cmake/camopt_python.cmake when it configured the build.
    name_file = build / "python" / "wheel-path.txt"
    if not name_file.is_file():
        raise RuntimeError(f"{build} builds no Python module (configured with -DCAMOPT_BUILD_PYTHON=OFF?)")
    wheel = pathlib.Path(name_file.read_text().strip())
    shutil.copy2(wheel, pathlib.Path(wheel_directory) / wheel.name)
    return wheel.name


def build_sdist(sdist_directory, config_settings=None):
    raise RuntimeError("camopt has no source distribution: pip install from a clone (`pip install .`) "
                       "or a wheel built by `cmake --build build --target wheel`")
