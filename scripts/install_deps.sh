#!/usr/bin/env bash
# Installs camopt's build and test dependencies from Debian's packages (needs root or sudo).
set -euo pipefail
# Usage: scripts/install_deps.sh            every package: the program, its tests, benchmarks,
#                                           Python module, API docs (.ci/run, scripts/test.sh)
#        scripts/install_deps.sh --program  only what building and running `camopt` needs: the
#                                           two parts below, one after the other
#        scripts/install_deps.sh --program-native  the Debian packages the compiler needs
#        scripts/install_deps.sh --web      Node.js, npm and the studio's npm packages (uPlot), which
#                                           the build only copies: scripts/setup.sh installs them
#                                           while the program compiles
PROGRAM_PACKAGES=(build-essential cmake pkg-config ccache
  libeigen3-dev libnlopt-cxx-dev coinor-libipopt-dev libceres-dev nlohmann-json3-dev
  libcli11-dev libfftw3-dev libsundials-dev
  # Geometry files: OpenCASCADE for STEP solids and their STL meshes where a profile is not
  # star-shaped (libtbb-dev: OCCT's CMake targets link it).
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-data-exchange-dev libocct-ocaf-dev libtbb-dev
  # Sweeps: Boost.Random's Sobol sequence. The SHA-256 of provenance (studies/provenance.cc)
  # from a maintained library.
  libboost-dev nettle-dev
  # `camopt serve`, the studio (studies/serve.cc): cpp-httplib, a maintained C++ HTTP library.
  libcpp-httplib-dev)
TEST_PACKAGES=(libgtest-dev libgmock-dev libbenchmark-dev
  # The independent readers the tests check the geometry files with.
  python3-ezdxf python3-numpy admesh
  # The Python module (pybind11), its tests and example (NumPy, matplotlib) and the
  # schema tests (jsonschema), all for Debian's /usr/bin/python3.
  pybind11-dev python3-dev python3-matplotlib python3-jsonschema
  # The wheel's test (Python.wheel): `python3 -m venv` with pip in the venv (python3-venv brings
  # ensurepip's bundled pip wheel, python3-pip-whl); readelf is binutils, from build-essential.
  python3-venv
  # MPI for `mpirun -n N camopt sweep` (optional for the program; its test runs two ranks).
  libopenmpi-dev openmpi-bin
  # report.html: the test that opens it in headless Chromium and checks its screenshot.
  chromium python3-pil
  # `camopt export --to mujoco`: tests/export_test.cc loads the MJCF model with the real MuJoCo
  # (2.2.2 in Debian 12) and simulates its static deflection; the program itself does not link it.
  libmujoco-dev
  # The API reference from the headers' comments (cmake/camopt_docs.cmake).
  doxygen)
PACKAGES=("${PROGRAM_PACKAGES[@]}")
# --program: without the packages' recommendations (Debian 12, the program's list: 389 packages,
# 340 MB instead of 469 packages, 468 MB; git, gdb, valgrind, X11 and Perl libraries among those
# left out), none of which building or running camopt uses (the setup's build and example run in a
# fresh minbase chroot, docs/performance.md "Setup"). The full list keeps them: the tests' readers,
# Chromium and Matplotlib are installed as Debian intends.
APT_OPTIONS=()
web=1
case "${1:-}" in
  --program) APT_OPTIONS=(--no-install-recommends) ;;
  --program-native) APT_OPTIONS=(--no-install-recommends) web=0 ;;
  --web) APT_OPTIONS=(--no-install-recommends) PACKAGES=() ;;
  "") PACKAGES+=("${TEST_PACKAGES[@]}") ;;
  *) echo "usage: $0 [--program | --program-native | --web]" >&2; exit 2 ;;
esac
# The studio's front end takes uPlot (charts) from npm, and its browser test puppeteer-core
# (web/package.json, versions fixed by web/package-lock.json): Node.js and npm from Debian when the
# machine has none (puppeteer-core 24 needs Node >= 18: Debian 12's nodejs is 18).
if [ $web = 1 ] && { ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; }; then
  PACKAGES+=(nodejs npm)
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${APT_OPTIONS[@]}" "${missing[@]}"
fi
# The front end's npm packages, exactly as locked, into web/node_modules (the build copies uPlot's
# files into build/web; nothing is fetched when the studio runs). --program and --web: without the
# browser test's puppeteer-core (a devDependency).
if [ $web = 1 ]; then
  NPM_OMIT=()
  if [ -n "${1:-}" ]; then NPM_OMIT=(--omit=dev); fi
  (cd "$(dirname "$0")/../web" && npm ci --no-audit --no-fund --loglevel=error "${NPM_OMIT[@]}")
fi
