#!/usr/bin/env bash
# Runs every example study with two builds and compares the output folders file by file.
#   scripts/compare_examples.sh OLD_CAMOPT NEW_CAMOPT [WORK_DIR]
# Prints one line per example ("same" or the files that differ) and exits 1 when any differs.
# A refactoring that must keep results unchanged is checked with it against the previous commit's
# build (git worktree add /tmp/old HEAD~1 && cmake -S /tmp/old -B /tmp/old/build && ...).
set -uo pipefail
old=$(realpath "$1"); new=$(realpath "$2"); work=$(realpath -m "${3:-$(mktemp -d)}")
mkdir -p "$work/old" "$work/new"
cd "$(dirname "$0")/.."
status=0
for f in studies/examples/*.json; do
  name=$(basename "$f" .json)
  grep -q '"study"' "$f" || continue  # data files (a roller catalogue) are not studies
  for side in old new; do
    bin=$old; [ "$side" = new ] && bin=$new
    rm -rf "$work/$side/$name"
    "$bin" run "$f" --out "$work/$side/$name" --quiet > /dev/null 2> "$work/$side-$name.stderr" ||
      echo "$name: $side build exited $? ($(head -c 200 "$work/$side-$name.stderr"))"
  done
  if d=$(diff -rq "$work/old/$name" "$work/new/$name"); then
    echo "$name: same"
  else
    echo "$name: differs"; echo "$d" | sed 's/^/  /'; status=1
  fi
done
exit $status
