#!/usr/bin/env bash
# The installed-headers tests (ctest InstalledHeaders.*), in two modes:
#   test_installed_headers.sh BUILD SOURCE install SHARD_REGEX...
#     installs the build BUILD into BUILD/headers-install, checks that it has no empty folder, that
#     every header of the source rooms is installed and that each installed header falls in exactly
#     one shard (so the shards together compile every header);
#   test_installed_headers.sh BUILD SOURCE compile NAME REGEX
#     compiles each installed header whose path (under include/camopt) matches REGEX on its own
#     against that install tree (cmake/headers_check), in BUILD/headers-check-NAME. A header that
#     the build BUILD has already compiled on its own, as the first line of its room's .cc compiled
#     alone (model/x.h, first included by model/x.cc: CMakeFiles/camopt_model.dir/model/x.cc.o), is
#     not compiled alone again: those go into one translation unit of the shard, which checks that
#     they resolve against the install tree with the package's flags.
# The shards (cmake/camopt_package.cmake) keep each test near 30 s on 2 idle cores; all 145 headers
# in one test took 190 s.
set -euo pipefail
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
mode=$3
shift 3
prefix="$build/headers-install"
if [ "$mode" = install ]; then
  rm -rf "$prefix"
  cmake --install "$build" --prefix "$prefix" >/dev/null
  empty=$(find "$prefix" -type d -empty)
  if [ -n "$empty" ]; then echo "empty folders installed:"; echo "$empty"; exit 1; fi
  missing=0
  for room in model objectives optimizers sizing studies cad; do
    while IFS= read -r h; do
      if [ ! -f "$prefix/include/camopt/$h" ]; then echo "not installed: $h"; missing=1; fi
    done < <(cd "$source" && find "$room" -name '*.h')
  done
  [ "$missing" -eq 0 ]
  bad=0
  count=0
  while IFS= read -r h; do
    n=0
    for re in "$@"; do if [[ "$h" =~ $re ]]; then n=$((n + 1)); fi; done
    if [ "$n" -ne 1 ]; then echo "$h is in $n shards (expected 1)"; bad=1; fi
    count=$((count + 1))
  done < <(cd "$prefix/include/camopt" && find . -name '*.h' | sed 's|^\./||')
  [ "$bad" -eq 0 ]
  echo "$count installed headers, each in one of $# shards"
  exit 0
fi
[ "$mode" = compile ] || { echo "usage: $0 BUILD SOURCE install REGEX... | compile NAME REGEX" >&2; exit 2; }
name=$1
regex=$2
work="$build/headers-check-$name"
rm -rf "$work"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
proven=()
while IFS= read -r h; do
  cc="${h%.h}.cc"
  [[ "$h" =~ $regex && -f "$source/$cc" && -f "$build/CMakeFiles/camopt_${h%%/*}.dir/$cc.o" ]] || continue
  # the .cc's first preprocessor line includes the header
  first=$(grep -m1 '^[[:space:]]*#' "$source/$cc" || true)
  if [[ "$first" =~ ^[[:space:]]*#[[:space:]]*include[[:space:]]*\"$h\" ]]; then proven+=("$h"); fi
done < <(cd "$prefix/include/camopt" && find . -name '*.h' | sed 's|^\./||' | sort)
cmake -S "$source/cmake/headers_check" -B "$work" -DCMAKE_PREFIX_PATH="$prefix" \
  "-DCAMOPT_HEADERS_MATCH=$regex" "-DCAMOPT_HEADERS_COMPILED_ALONE=$(IFS=';'; echo "${proven[*]}")" \
  "${launcher[@]}" >/dev/null
cmake --build "$work" -j"$(nproc)" >/dev/null
echo "the installed headers matching $regex compile on their own (${#proven[@]} of them compiled alone by the build, checked together here)"
