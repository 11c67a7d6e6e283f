#!/usr/bin/env python3
"""The speed targets' benchmarks, two builds alternated in one run (docs/performance.md, top table).

    python3 scripts/speed_targets.py NEW_BUILD_DIR [OLD_BUILD_DIR] [--rounds N] [--cpu K]

Each round runs every target's benchmark once with each build's camopt_bench (pinned to CPU K with
taskset, 0 by default), the builds' order swapped every round, so that both see the same machine
state. Prints, per target, the smallest and the median CPU time of each build and their ratio, and
the first build's time scaled to the machine speed of the day the targets were set (one FFT pair
of the LTCA's grid in 27 µs; measured here in the same rounds as a yardstick). A benchmark the
older build does not have (another name or arguments) is left empty. The geometry
files' share is measured by scripts/geometry_share.py, the setup by a fresh machine (README).
"""
import json
import os
import shutil
import statistics
import subprocess
import sys

# The machine's own speed, measured in the same rounds: the time of one FFT pair of the LTCA's
# padded grid (the issue that set the targets measured 27 µs on the machine of that day; this
# shared machine has since run it in 27–41 µs by the hour).
YARDSTICK = "machine yardstick: one FFT pair, 80² padded"
ISSUE_FFT_PAIR_US = 27.0

# (target, line, unit, benchmark of the new build, benchmark of an older build or None)
TARGETS = [
    ("LTCA cycle, 60 angles over 2π, 40 × 40 cells", "≤ 100 ms", "ms",
     "BM_CycloidMeshCycle60/0", "BM_CycloidMeshCycle60/0"),
    ("LCM cycle value, crank slope on", "", "ms",
     "BM_CycloidCycle60Gradient/0/1/1", "BM_CycloidCycle60Gradient/0/1"),
    ("LCM cycle value + gradient (f, Δa, Δρ), slope on", "≤ 1.5 × value", "ms",
     "BM_CycloidCycle60Gradient/1/100/1", "BM_CycloidCycle60Gradient/1/100"),
    ("LCM cycle value, slope off (the loops)", "", "ms",
     "BM_CycloidCycle60Gradient/0/100/0", None),
    ("LCM cycle value + gradient, slope off", "≤ 1.5 × value", "ms",
     "BM_CycloidCycle60Gradient/1/100/0", None),
    ("crowned LCR sizing (example, 4 combinations)", "≤ 2 s", "s",
     "BM_MinSize3DCrowned/40", "BM_MinSize3DCrowned/40"),
    ("line-model LCR sizing, ratio −90 study", "≤ 0.5 s", "s",
     "BM_LcrMinSizeStudy/0/0/1", "BM_LcrMinSizeStudy/0/0/1"),
    (YARDSTICK, "", "us", "BM_FftwPair/80", "BM_FftwPair/80"),
]

SCALE = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}


def run(build, name, cpu):
    """CPU times [s] of every repetition of one benchmark (exact name), or [] if it is absent."""
    exe = os.path.join(build, "camopt_bench")
    cmd = [exe, "--benchmark_filter=^" + name + "(/|$)", "--benchmark_format=json"]
    if shutil.which("taskset"):
        cmd = ["taskset", "-c", str(cpu)] + cmd
    out = subprocess.run(cmd, capture_output=True, text=True, check=False).stdout
    try:
        runs = json.loads(out)["benchmarks"]
    except (ValueError, KeyError):
        return []
    return [r["cpu_time"] * SCALE[r["time_unit"]] for r in runs
            if r.get("run_type", "iteration") == "iteration" and bare(r["name"]) == name]


def bare(name):
    """A benchmark's name without the suffixes Google Benchmark adds (iterations:1, process_time)."""
    return "/".join(p for p in name.split("/") if ":" not in p and p not in ("process_time", "real_time"))


def main():
    argv = sys.argv[1:]
    rounds, cpu = 3, 0
    if "--rounds" in argv:
        i = argv.index("--rounds")
        rounds = int(argv[i + 1])
        del argv[i:i + 2]
    if "--cpu" in argv:
        i = argv.index("--cpu")
        cpu = int(argv[i + 1])
        del argv[i:i + 2]
    if not argv or len(argv) > 2:
        sys.exit(__doc__)
    builds = [os.path.realpath(b) for b in argv]
    times = {(b, t[0]): [] for b in builds for t in TARGETS}
    for r in range(rounds):
        order = builds if r % 2 == 0 else builds[::-1]
        for b in order:
            for t in TARGETS:
                name = t[3] if b == builds[0] else t[4]
                if name:
                    times[(b, t[0])] += run(b, name, cpu)
        print(f"round {r + 1} of {rounds} done", file=sys.stderr)
    load = os.getloadavg()[0]
    labels = [os.path.basename(os.path.dirname(b.rstrip("/"))) + "/" + os.path.basename(b) for b in builds]
    print(f"CPU time on one core (taskset -c {cpu}), {rounds} rounds alternated, load average at the end {load:.1f}")
    print()
    head = "| target | line |" + "".join(f" {l}: min / median |" for l in labels)
    if len(builds) == 2:
        head += " new / old (min) |"
    stick = times[(builds[0], YARDSTICK)]
    scale = ISSUE_FFT_PAIR_US * 1e-6 / min(stick) if stick else None
    if scale:
        head += f" {labels[0]} min × {scale:.3f} (at a {ISSUE_FFT_PAIR_US:g} µs FFT pair) |"
    print(head)
    print("|---|---|" + "---|" * (len(builds) + (len(builds) == 2) + (scale is not None)))
    for t in TARGETS:
        unit = SCALE[t[2]]
        row = f"| {t[0]} | {t[1]} |"
        mins = []
        for b in builds:
            v = times[(b, t[0])]
            if v:
                row += f" {min(v) / unit:.4g} / {statistics.median(v) / unit:.4g} {t[2]} |"
                mins.append(min(v))
            else:
                row += " — |"
                mins.append(None)
        if len(builds) == 2:
            row += f" {mins[0] / mins[1]:.3f} |" if all(mins) else " — |"
        if scale:
            row += f" {mins[0] * scale / unit:.4g} {t[2]} |" if mins[0] else " — |"
        print(row)
    # The gradient's ratio to the value within each build (medians).
    for b, l in zip(builds, labels):
        for value, grad in ((TARGETS[1][0], TARGETS[2][0]), (TARGETS[3][0], TARGETS[4][0])):
            v, g = times[(b, value)], times[(b, grad)]
            if v and g:
                print(f"\n{l}: ({grad}) / ({value}) = {statistics.median(g) / statistics.median(v):.3f} (medians)")


if __name__ == "__main__":
    main()
