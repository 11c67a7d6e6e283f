#!/usr/bin/env bash
# One command from a fresh clone: install dependencies, build, run an example study.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh --program-native  # what the compiler needs; scripts/test.sh adds the rest
# Node.js, npm and the studio's chart package install while the program compiles (the build only
# copies uPlot's two files into build/web, at the end below).
web_log=$(mktemp)
bash scripts/install_deps.sh --web >"$web_log" 2>&1 &
web_pid=$!
# A failed build leaves the package manager to finish rather than cut it off.
trap 'wait "$web_pid" 2>/dev/null || true' EXIT
CAMOPT_WEB_PENDING=1 bash scripts/build.sh --program  # the program alone; scripts/test.sh builds the tests
if ! wait "$web_pid"; then
  cat "$web_log" >&2
  echo "setup: installing Node.js and the studio's npm packages failed (above); the program is built" >&2
  exit 1
fi
trap - EXIT
rm -f "$web_log"
bash scripts/build.sh --program  # configured again: the studio's files with uPlot's into build/web
./build/camopt run studies/examples/lcr_ii.json --out results/lcr_ii
echo "example results in results/lcr_ii/ (result.json, CSV, SVG, DXF)"
