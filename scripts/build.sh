#!/usr/bin/env bash
# Configures and builds camopt in build/ (Release). With target names, builds only those
# (scripts/setup.sh builds `camopt`, the program the example needs; scripts/test.sh builds all).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j"$(nproc)" "${targets[@]}"
