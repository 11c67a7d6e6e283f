#!/usr/bin/env python3
"""Every example study through `camopt run` as a user runs it, timed (docs/performance.md, "camopt run").

    python3 scripts/time_examples.py BUILD_DIR [--rounds N] [--only SUBSTRING] [--markdown]
                                     [--compare OLD_BUILD_DIR]

For each studies/examples/*.json (one after another, never two at once): the process's CPU time,
user and system, from the operating system (the child's rusage), the wall time, and the phase split
that `camopt run --timings` prints (read, checks, parse, solve, and for a sizing its verification and
limit costs out of the solve, files, status, report, write). With
--rounds N each example runs N times and the smallest CPU time is kept (the machine's noise only ever
adds). Each example is set against the target of its class (issue "speed as the user measures it"):
an analysis 0.3 s CPU, a line-model sizing 0.5 s, a 3D-contact or cycloid sizing 2 s. A line per
example; --markdown prints the table docs/performance.md keeps. --compare OLD_BUILD_DIR runs every
example with the old build too, the two alternated round by round (the machine's drift falls on
both alike), and prints before / after / ratio instead of the phases. Exit 0 whatever the times (a
measurement, not a test); exit 1 when an example fails to run (exit 2).
"""
import argparse
import glob
import json
import os
import re
import resource
import subprocess
import sys
import tempfile
import time

TIMINGS = re.compile(r"camopt: timings \(CPU s / wall s\): (.*); total ([0-9.]+) / ([0-9.]+)")


def target_of(kind, study):
    """(class, target seconds) of an example."""
    if kind in ("lcr_min_size",):
        contact = study.get("contact", {}).get("model", "line") if isinstance(study.get("contact"), dict) else "line"
        crowned = "crowning" in json.dumps(study.get("variables", {})) or "crowning" in json.dumps(study.get("fixed", {}))
        if contact != "line" or crowned or "robust" in study:
            return "3D sizing", 2.0
        return "line-model sizing", 0.5
    if kind in ("cycloid_min_size", "cycloid_crowning_tuning", "lcr_crowning_tuning"):
        return "3D / cycloid sizing", 2.0
    if kind in ("disc_cam_min_size",):
        return "line-model sizing", 0.5
    if kind in ("disc_cam_motion",):
        # A motion design solves the follower's ODE in its rows and verifies by CVODE: as a 3D sizing.
        return "motion design (ODE rows)", 2.0
    return "analysis", 0.3


def run_once(camopt, path, out):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    proc = subprocess.run([camopt, "run", path, "--out", out, "--quiet", "--timings"], capture_output=True, text=True)
    wall = time.monotonic() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    user, system = after.ru_utime - before.ru_utime, after.ru_stime - before.ru_stime
    phases = {}
    m = TIMINGS.search(proc.stderr)
    if m:
        for part in m.group(1).split(", "):
            name, times = part.rsplit(" ", 3)[0], part.rsplit(" ", 3)[1:]
            phases[name] = float(times[0])
    return proc.returncode, user, system, wall, phases, proc.stderr


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("build", help="the build folder with camopt")
    ap.add_argument("--rounds", type=int, default=1, help="runs per example; the smallest CPU time is kept")
    ap.add_argument("--only", default="", help="only the examples whose file name contains this")
    ap.add_argument("--markdown", action="store_true", help="print a Markdown table")
    ap.add_argument("--compare", default="", help="an older build folder, run alternately with this one")
    args = ap.parse_args()
    camopt = os.path.join(args.build, "camopt")
    old_camopt = os.path.join(args.compare, "camopt") if args.compare else ""
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    examples = sorted(glob.glob(os.path.join(root, "studies", "examples", "*.json")))
    rows, failed = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for i, path in enumerate(examples):
            name = os.path.basename(path)
            if args.only not in name:
                continue
            with open(path) as f:
                study = json.load(f)
            if not isinstance(study, dict) or "study" not in study:
                continue  # a catalogue, not a study
            kind = study["study"]
            best, old_best = None, None
            for r in range(args.rounds):
                if old_camopt:
                    code, user, system, wall, phases, err = run_once(old_camopt, path, os.path.join(tmp, "old-%s-%d" % (name, r)))
                    if code in (0, 3) and (old_best is None or user + system < old_best):
                        old_best = user + system
                out = os.path.join(tmp, "%s-%d" % (name, r))
                code, user, system, wall, phases, err = run_once(camopt, path, out)
                if code not in (0, 3):
                    failed.append((name, code, err.strip().splitlines()[-1:] or [""]))
                    break
                if best is None or user + system < best[0] + best[1]:
                    best = (user, system, wall, phases, code)
            if best is None:
                continue
            cls, target = target_of(kind, study)
            rows.append((name, kind, cls, target) + best + (old_best,))
            print("%-40s %.3f s CPU (user %.3f, system %.3f), target %.1f s, %s%s" %
                  (name, best[0] + best[1], best[0], best[1], target, cls,
                   ", before %.3f s" % old_best if old_best is not None else ""), file=sys.stderr)
    if args.markdown and old_camopt:
        met = sum(1 for r in rows if r[4] + r[5] <= r[3])
        met_before = sum(1 for r in rows if r[9] is not None and r[9] <= r[3])
        print("%d of %d examples within their targets (before: %d)\n" % (met, len(rows), met_before))
        print("| example | class ≤ target s | before s | after s | after / before | met "
              "| after: solve / verification / limit costs / files s |")
        print("|---|---|---:|---:|---:|---|---|")
        for name, kind, cls, target, user, system, wall, phases, code, old_cpu in rows:
            cpu = user + system
            split = " / ".join("%.3f" % phases[k] if k in phases else "–"
                               for k in ("solve", "verification", "limit costs", "files"))
            print("| `%s` | %s ≤ %.1f | %s | %.3f | %s | %s | %s |" %
                  (name[:-5], cls, target, "%.3f" % old_cpu if old_cpu is not None else "–", cpu,
                   "%.2f" % (cpu / old_cpu) if old_cpu else "–", "yes" if cpu <= target else "**no**", split))
    elif args.markdown:
        print("| example | kind | CPU s (user + system) | target | met | read | parse | solve | verification "
              "| limit costs | files | report | write |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for name, kind, cls, target, user, system, wall, phases, code, _ in rows:
            cpu = user + system
            # A kind with its own runner times parse, solve and files as one phase (marked †).
            ph = lambda k: ("%.3f" % phases[k]) if k in phases else (
                "%.3f †" % phases["parse+solve+files"] if k == "solve" and "parse+solve+files" in phases else "")
            print("| %s | %s | %.3f (%.3f + %.3f) | %s ≤ %.1f | %s | %s | %s | %s | %s | %s | %s | %s | %s |" %
                  (name, kind, cpu, user, system, cls, target, "yes" if cpu <= target else "**no**", ph("read"),
                   ph("parse"), ph("solve"), ph("verification"), ph("limit costs"), ph("files"), ph("report"),
                   ph("write")))
    for name, code, last in failed:
        print("failed: %s exit %d: %s" % (name, code, last[0]), file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
