#!/usr/bin/env bash
# Fuzzes the study runner with libFuzzer for SECONDS (default 600) under ASan + UBSan.
#   bash scripts/fuzz.sh 1800
# Builds build-fuzz/ with clang (CMake option CAMOPT_FUZZ), seeds a scratch corpus from
# tests/fuzz_corpus/ (the examples and minimized inputs), and writes any crashing input to
# build-fuzz/artifacts/. New interesting inputs stay in build-fuzz/corpus/; minimize one with
#   build-fuzz/camopt_fuzz -minimize_crash=1 CRASH   (or -merge=1) before adding it to tests/fuzz_corpus/.
# The final libFuzzer statistics line (runs, coverage, exec/s) is printed at the end and saved
# in build-fuzz/fuzz.log.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_TO_RUN="${1:-600}"
CXX_FUZZ="${CXX_FUZZ:-$(command -v clang++ || command -v clang++-14 || true)}"
if [ -z "$CXX_FUZZ" ]; then echo "scripts/fuzz.sh: clang++ is needed (apt-get install clang)" >&2; exit 2; fi
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER="$CXX_FUZZ" \
  -DCAMOPT_FUZZ=ON -DCAMOPT_BUILD_TESTS=OFF -DCAMOPT_BUILD_BENCH=OFF >/dev/null
cmake --build build-fuzz --target camopt_fuzz -j"${JOBS:-2}"
mkdir -p build-fuzz/corpus build-fuzz/artifacts
cp -n tests/fuzz_corpus/* build-fuzz/corpus/ 2>/dev/null || true
# Leaks are not defects of a one-shot CLI run; the study runner's allocations are checked by ASan.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=0:allocator_may_return_null=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
build-fuzz/camopt_fuzz build-fuzz/corpus -max_total_time="$SECONDS_TO_RUN" -timeout=30 \
  -rss_limit_mb=3072 -max_len=65536 -print_final_stats=1 -artifact_prefix=build-fuzz/artifacts/ \
  -dict=tests/fuzz_corpus.dict 2>&1 | tee build-fuzz/fuzz.log | grep -E "^#[0-9]+.*(DONE|pulse)|stat::|ERROR|SUMMARY" || true
# libFuzzer also writes slow-unit-* files (units over -report_slow_units seconds): a note, not a
# failure; crashes, timeouts, leaks and out-of-memory units are.
failures="$(ls -A build-fuzz/artifacts | grep -v '^slow-unit-' || true)"
test -z "$failures" || { echo "scripts/fuzz.sh: failures in build-fuzz/artifacts/: $failures" >&2; exit 1; }
