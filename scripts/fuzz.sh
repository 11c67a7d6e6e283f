#!/usr/bin/env bash
# Fuzzes one libFuzzer target for SECONDS (default 600) under ASan + UBSan:
#   bash scripts/fuzz.sh [TARGET] SECONDS
#   TARGET  study    study files through the runner (fuzz/study_fuzzer.cc; the default)
#           sweep    sweep files through `camopt sweep` (fuzz/sweep_fuzzer.cc)
#           request  raw HTTP requests to an in-process studio (fuzz/http_fuzzer.cc)
# Builds build-fuzz/ with clang (CMake option CAMOPT_FUZZ), seeds a scratch corpus
# build-fuzz/corpus-TARGET/ from the target's corpus in tests/ (fuzz_corpus/, fuzz_corpus_sweeps/,
# fuzz_corpus_requests/), and writes any failing input to build-fuzz/artifacts-TARGET/. Minimize
# one with  build-fuzz/camopt_fuzz[_sweep|_request] -minimize_crash=1 CRASH  (or -merge=1) before
# adding it to the corpus in tests/ (replayed on every build by FuzzCorpus.*).
# The final libFuzzer statistics (runs, coverage, exec/s) are printed at the end and saved in
# build-fuzz/fuzz-TARGET.log. With CAMOPT_FUZZ_STACKS=1 the request target looks at a request still
# open after 1.5 s (the port's sockets with ss, every thread's stack with gdb) and, at a defect,
# prints the runs' processes, the stacks and whether the server answers again.
set -euo pipefail
cd "$(dirname "$0")/.."
TARGET=study
case "${1:-}" in study|sweep|request) TARGET="$1"; shift ;; esac
SECONDS_TO_RUN="${1:-600}"
case "$TARGET" in
  study)   BIN=camopt_fuzz;         SEEDS=tests/fuzz_corpus;          DICT=tests/fuzz_corpus.dict; MAXLEN=65536 ;;
  sweep)   BIN=camopt_fuzz_sweep;   SEEDS=tests/fuzz_corpus_sweeps;   DICT=tests/fuzz_corpus.dict; MAXLEN=65536 ;;
  request) BIN=camopt_fuzz_request; SEEDS=tests/fuzz_corpus_requests; DICT=tests/fuzz_requests.dict; MAXLEN=131072 ;;
esac
CXX_FUZZ="${CXX_FUZZ:-$(command -v clang++ || command -v clang++-14 || true)}"
if [ -z "$CXX_FUZZ" ]; then echo "scripts/fuzz.sh: clang++ is needed (apt-get install clang)" >&2; exit 2; fi
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER="$CXX_FUZZ" \
  -DCAMOPT_FUZZ=ON -DCAMOPT_BUILD_TESTS=OFF -DCAMOPT_BUILD_BENCH=OFF >/dev/null
cmake --build build-fuzz --target "$BIN" -j"${JOBS:-2}"
# Absolute paths: the request target's studio works in its served folder (it changes the
# process's working folder, as `camopt serve` does), and libFuzzer reads and writes these after.
CORPUS=$PWD/build-fuzz/corpus-$TARGET ARTIFACTS=$PWD/build-fuzz/artifacts-$TARGET DICT=$PWD/$DICT
mkdir -p "$CORPUS" "$ARTIFACTS"
cp -n "$SEEDS"/* "$CORPUS"/ 2>/dev/null || true
# Leaks are not defects of a one-shot CLI run; the study runner's allocations are checked by ASan.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=0:allocator_may_return_null=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
"build-fuzz/$BIN" "$CORPUS" -max_total_time="$SECONDS_TO_RUN" -timeout=30 \
  -rss_limit_mb=3072 -max_len="$MAXLEN" -print_final_stats=1 -artifact_prefix="$ARTIFACTS/" \
  -dict="$DICT" 2>&1 | tee "build-fuzz/fuzz-$TARGET.log" | grep -E "^#[0-9]+.*(DONE|pulse)|stat::|ERROR|SUMMARY" || true
# libFuzzer also writes slow-unit-* files (units over -report_slow_units seconds): a note, not a
# failure; crashes, timeouts, leaks and out-of-memory units are.
failures="$(ls -A "$ARTIFACTS" | grep -v '^slow-unit-' || true)"
test -z "$failures" || { echo "scripts/fuzz.sh: failures in $ARTIFACTS/: $failures" >&2; exit 1; }
