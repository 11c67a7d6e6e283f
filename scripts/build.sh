#!/usr/bin/env bash
# Configures and builds camopt in build/ (Release).
#   scripts/build.sh --program   the `camopt` program alone, configured without the tests,
#                                benchmarks, Python module and API docs (scripts/setup.sh)
#   scripts/build.sh [TARGET...] everything (scripts/test.sh), or only the named targets
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--program" ]; then
  # CAMOPT_WEB_PENDING=1: the studio's npm packages are being installed (scripts/setup.sh), so their
  # absence is not worth a warning yet.
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCAMOPT_BUILD_TESTS=OFF -DCAMOPT_BUILD_BENCH=OFF \
    -DCAMOPT_BUILD_PYTHON=OFF -DCAMOPT_BUILD_DOCS=OFF -DCAMOPT_WEB_PENDING="${CAMOPT_WEB_PENDING:-0}" >/dev/null
  cmake --build build -j"$(nproc)" --target camopt
  exit 0
fi
# After a --program configure: everything back on, and MPI looked for again (its option's default
# is whether MPI was found, which the program-only configure may have cached as OFF).
mpi=()
if grep -q '^CAMOPT_BUILD_TESTS:BOOL=OFF' build/CMakeCache.txt 2>/dev/null; then mpi=(-UCAMOPT_MPI); fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCAMOPT_BUILD_TESTS=ON -DCAMOPT_BUILD_BENCH=ON \
  -DCAMOPT_BUILD_PYTHON=ON -DCAMOPT_BUILD_DOCS=ON -DCAMOPT_WEB_PENDING=0 "${mpi[@]}" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j"$(nproc)" "${targets[@]}"
