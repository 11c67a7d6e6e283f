#!/usr/bin/env python3
"""Numbers of two result.json trees side by side: the largest relative differences.

    python3 scripts/compare_results.py OLD_DIR NEW_DIR [--top N] [--floor X]

OLD_DIR and NEW_DIR hold one folder per example with a result.json each (the two sides
scripts/compare_examples.sh writes: WORK/old and WORK/new). For every example whose result.json
differs it prints the largest relative difference |new − old| / max(|old|, floor) over the numbers
(keys named or ending in evaluations, iterations, runs, solves, steps, simulations, seconds are
counted apart: they are work, not answers), the JSON pointers of the N largest, and every non-numeric
difference (a status, a string, a missing key) in full. Exit 1 when a non-numeric answer differs.
"""
import argparse
import json
import os
import sys

# Keys that count work (named so, or ending in _NAME), not answers.
WORK_WORDS = ("evaluations", "iterations", "runs", "solves", "steps", "simulations", "seconds")


def walk(a, b, path, out):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            p = path + "/" + str(k)
            if k not in a or k not in b:
                out["other"].append((p, a.get(k, "<absent>"), b.get(k, "<absent>")))
            else:
                walk(a[k], b[k], p, out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out["other"].append((path, f"{len(a)} items", f"{len(b)} items"))
        for i, (x, y) in enumerate(zip(a, b)):
            walk(x, y, f"{path}/{i}", out)
    elif isinstance(a, bool) or isinstance(b, bool) or not (
            isinstance(a, (int, float)) and isinstance(b, (int, float))):
        if a != b:
            out["other"].append((path, a, b))
    elif a != b:
        key = path.rsplit("/", 1)[-1]
        work = any(key == w or key.endswith("_" + w) for w in WORK_WORDS) or "count" in key
        out["work" if work else "numbers"].append((path, a, b))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--top", type=int, default=3)
    ap.add_argument("--floor", type=float, default=1e-9,
                    help="denominator floor of the relative difference")
    args = ap.parse_args()
    status = 0
    for name in sorted(os.listdir(args.new)):
        fo = os.path.join(args.old, name, "result.json")
        fn = os.path.join(args.new, name, "result.json")
        if not (os.path.isfile(fo) and os.path.isfile(fn)):
            continue
        with open(fo) as f:
            a = json.load(f)
        with open(fn) as f:
            b = json.load(f)
        out = {"numbers": [], "work": [], "other": []}
        walk(a, b, "", out)
        if not any(out.values()):
            continue
        rel = sorted(((abs(y - x) / max(abs(x), args.floor), p, x, y) for p, x, y in out["numbers"]),
                     reverse=True)
        worst = rel[0][0] if rel else 0.0
        print(f"{name}: {len(rel)} numbers differ, largest relative {worst:.2e}; "
              f"{len(out['work'])} work counts; {len(out['other'])} other")
        for r, p, x, y in rel[:args.top]:
            print(f"  {r:.2e}  {p}: {x!r} -> {y!r}")
        for p, x, y in out["other"]:
            print(f"  OTHER {p}: {json.dumps(x)[:120]} -> {json.dumps(y)[:120]}")
            status = 1
    return status


if __name__ == "__main__":
    sys.exit(main())
