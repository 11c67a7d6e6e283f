#!/usr/bin/env bash
# One command from a fresh clone: install dependencies, build, run an example study.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh camopt  # the program the example needs; scripts/test.sh builds the rest
./build/camopt run studies/examples/lcr_ii.json --out results/lcr_ii
echo "example results in results/lcr_ii/ (result.json, CSV, SVG, DXF)"
