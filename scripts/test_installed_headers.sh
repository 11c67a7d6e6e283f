#!/usr/bin/env bash
# The installed-headers test (ctest InstalledHeaders.*): installs the build BUILD into
# BUILD/headers-install, checks that it has no empty folder and that every header of the source
# rooms is installed, then compiles each installed header on its own against the install tree
# (cmake/headers_check). Usage: test_installed_headers.sh BUILD SOURCE
set -euo pipefail
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
prefix="$build/headers-install"
work="$build/headers-check"
rm -rf "$prefix" "$work"
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
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S "$source/cmake/headers_check" -B "$work" -DCMAKE_PREFIX_PATH="$prefix" "${launcher[@]}" >/dev/null
cmake --build "$work" -j"$(nproc)" >/dev/null
echo "$(find "$prefix/include/camopt" -name '*.h' | wc -l) installed headers compile on their own"
