#!/usr/bin/env bash
# Builds and runs the whole test suite (gtest through ctest). Exits non-zero when a test fails.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
