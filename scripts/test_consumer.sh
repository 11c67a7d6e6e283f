#!/usr/bin/env bash
# The CMake package test (ctest ConsumerProject.*): installs the build BUILD into
# BUILD/consumer-install, then configures and builds examples/consumer against that install tree
# only (no path into the source or build tree) and runs it. Usage: test_consumer.sh BUILD SOURCE
set -euo pipefail
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
prefix="$build/consumer-install"
work="$build/consumer-build"
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
test -x "$prefix/bin/camopt"
test -f "$prefix/lib/cmake/camopt/camoptConfig.cmake"
test -f "$prefix/lib/cmake/camopt/camoptConfigVersion.cmake"
test -f "$prefix/include/camopt/studies/study.h"
"$prefix/bin/camopt" --version
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S "$source/examples/consumer" -B "$work" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$prefix" "${launcher[@]}" >/dev/null
cmake --build "$work" >/dev/null
"$work/camopt_consumer"
