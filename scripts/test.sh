#!/usr/bin/env bash
# Installs what the tests need, builds and runs the whole test suite (gtest through ctest). Exits non-zero when a test fails.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh  # what the tests need beyond the program (a no-op when installed)
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
