#!/usr/bin/env bash
# One command from a fresh clone: install dependencies, build, run an example study.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh --program  # the packages the program needs; scripts/test.sh adds the rest
bash scripts/build.sh --program         # the program alone; scripts/test.sh builds the tests
./build/camopt run studies/examples/lcr_ii.json --out results/lcr_ii
echo "example results in results/lcr_ii/ (result.json, CSV, SVG, DXF)"
