#!/usr/bin/env bash
# Builds the whole test suite with AddressSanitizer + UndefinedBehaviorSanitizer in build-asan/
# (CMake option CAMOPT_SANITIZE) and runs it. Exits non-zero when a test fails or a sanitizer
# reports (UBSan is built not to recover, ASan aborts on its first report). .ci/run calls it after
# the README's test command; it takes about 10 minutes on 2 cores from a clean build.
set -euo pipefail
cd "$(dirname "$0")/.."
CXX_SAN="${CXX_SAN:-}"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCAMOPT_SANITIZE=ON \
  -DCAMOPT_BUILD_BENCH=OFF ${CXX_SAN:+-DCMAKE_CXX_COMPILER="$CXX_SAN"} >/dev/null
cmake --build build-asan -j"$(nproc)"
# Leak checking is off: the libraries (Ceres/glog, Ipopt) keep allocations to exit, and a CLI run
# is one process. Container-overflow checks are off: Ceres and NLopt are not instrumented, and
# vectors passed across that boundary give false reports.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=0:detect_container_overflow=0:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
ctest --test-dir build-asan --output-on-failure -j"$(nproc)"
