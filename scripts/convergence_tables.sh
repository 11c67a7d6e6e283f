#!/usr/bin/env bash
# Runs `camopt run EXAMPLE --convergence` over the example studies and prints markdown tables (one
# per knob per example), then the estimated errors of the default settings (docs/performance.md,
# "Speed against error of every example", keeps a summary of those).
# Usage: scripts/convergence_tables.sh [CAMOPT_BINARY] [EXAMPLE.json ...]
# (default binary build/camopt, default examples: every study in studies/examples/). Wall times are
# this machine's and vary from run to run.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="${1:-$root/build/camopt}"
shift || true
if [ "$#" -gt 0 ]; then examples=("$@"); else examples=("$root"/studies/examples/*.json); fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for f in "${examples[@]}"; do
  name="$(basename "$f" .json)"
  # A roller catalogue is not a study.
  if python3 -c 'import json,sys; sys.exit(0 if isinstance(json.load(open(sys.argv[1])), dict) else 1)' "$f"; then
    code=0
    "$bin" run "$f" --convergence --quiet --out "$work/$name" > /dev/null || code=$?
    if [ "$code" -ne 0 ] && [ "$code" -ne 3 ]; then
      echo "camopt failed on $f (exit $code)" >&2
      exit 1
    fi
  fi
done
python3 - "$work" <<'EOF'
import json, os, sys

work = sys.argv[1]

def num(v, digits=6):
    if v is None:
        return "–"
    if isinstance(v, list):
        return "×".join(num(x, digits) for x in v)
    if isinstance(v, int):
        return str(v)
    return f"{v:.{digits}g}"

totals = []
for name in sorted(os.listdir(work)):
    path = os.path.join(work, name, "convergence.json")
    if not os.path.exists(path):
        continue
    c = json.load(open(path))
    kind = c["study"]
    if not c["knobs"]:
        print(f"#### {kind}: `{name}.json` — no knob\n\n{c.get('no_knob', '')}\n")
    for k in c["knobs"]:
        runs = k["runs"]
        order = f", order {k['order']:g} (Richardson)" if k.get("order") else ""
        print(f"#### {kind}: `{name}.json` — {k['name']} (`{k['paths'][0]}`{order})\n")
        head = [f"{num(r['value'])}{' (study)' if r['setting'] == 'study' else ''}" for r in runs]
        print("| output | " + " | ".join(head) + " | est. error of the study's setting | method |")
        print("|---" * (len(head) + 3) + "|")
        times = [("skipped: " + r["skipped"][:60]) if "skipped" in r else f"{r['wall_time_s']:.3g} s" for r in runs]
        print("| wall time | " + " | ".join(times) + " | | |")
        for h, o in k["outputs"].items():
            if o["values"][1] is None:
                continue
            err = "–"
            if o["method"] != "none":
                rel = o.get("relative_error")
                err = num(o["estimated_error"], 3) + (f" ({rel:.2g})" if rel is not None else "")
            print(f"| `{h}` | " + " | ".join(num(v, 7) for v in o["values"]) + f" | {err} | {o['method']} |")
        print()
    for h, t in c.get("estimated_error", {}).items():
        totals.append((kind, name, h, t))

print("#### Estimated error of each example's own settings (sum over its knobs)\n")
print("| study | output | value | estimated error | relative |")
print("|---|---|---|---|---|")
for kind, name, h, t in totals:
    rel = t.get("relative_error")
    print(f"| `{name}.json` | `{h}` | {num(t['value'], 7)} | {num(t['estimated_error'], 3)} | "
          f"{'–' if rel is None else f'{rel:.2g}'} |")
EOF
