#!/usr/bin/env bash
# Installs camopt's build and test dependencies from Debian's packages (needs root or sudo).
set -euo pipefail
PACKAGES=(build-essential cmake pkg-config
  libeigen3-dev libnlopt-cxx-dev coinor-libipopt-dev libceres-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev libfftw3-dev libsundials-dev ccache
  # Geometry files: OpenCASCADE for STEP solids and their STL meshes (libtbb-dev: OCCT's
  # CMake targets link it), and the independent readers the tests check the files with.
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-data-exchange-dev libtbb-dev python3-ezdxf python3-numpy admesh
  # The Python module (pybind11), its tests and example (NumPy, matplotlib) and the
  # schema tests (jsonschema), all for Debian's /usr/bin/python3.
  pybind11-dev python3-dev python3-matplotlib python3-jsonschema
  # Sweeps: Boost.Random's Sobol sequence; MPI for `mpirun -n N camopt sweep` (optional).
  libboost-dev libopenmpi-dev openmpi-bin
  # report.html: the test that opens it in headless Chromium and checks its screenshot.
  chromium python3-pil
  # The SHA-256 of provenance (studies/provenance.cc) from a maintained library; the API
  # reference from the headers' comments (cmake/camopt_docs.cmake).
  nettle-dev doxygen)
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}"
fi
