#!/usr/bin/env python3
"""The geometry files' share of each analysis example's time (docs/performance.md, 'Geometry files').

    python3 scripts/geometry_share.py BUILD/camopt [OTHER/camopt] [--repeats N] [--instructions]
                                      [--only NAME,NAME,...]

For every example of the kinds that write DXF/STEP/STL (lcr_analysis, cycloid_ltca, disc_cam),
runs the study as it is and with "geometry_files": false, alternating the runs (and the two
programs, when two are given, so that both see the same load), and prints the smallest CPU time
(user + system of the child) of each and the files' share: (with − without) / with. CPU time, not
wall time: the machine may be shared. With --instructions, the instructions executed instead
(valgrind's callgrind, one run each: deterministic, so the small LCR and disc-cam studies, whose
CPU times scatter by more than the files cost, are compared exactly; about 30 s per cycloid run).
"""
import json
import os
import resource
import shutil
import subprocess
import sys
import tempfile

KINDS = ("lcr_analysis", "cycloid_ltca", "disc_cam")


def cpu_of(cmd):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def instructions_of(cmd):
    """Instructions executed by the command, in millions (valgrind --tool=callgrind)."""
    r = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null"] + cmd,
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, check=False)
    for line in r.stderr.splitlines():
        if "I   refs:" in line:
            return float(line.split()[-1].replace(",", "")) / 1e6
    return float("nan")


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    only = None
    if "--only" in sys.argv:
        only = set(sys.argv[sys.argv.index("--only") + 1].split(","))
        args = [a for a in args if a != sys.argv[sys.argv.index("--only") + 1]]
    count = "--instructions" in sys.argv
    repeats = 1 if count else 3
    if "--repeats" in sys.argv and not count:
        repeats = int(sys.argv[sys.argv.index("--repeats") + 1])
        args = [a for a in args if a != str(repeats)]
    programs = [os.path.realpath(a) for a in args]
    if not programs:
        sys.exit(__doc__)
    root = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "studies", "examples")
    work = tempfile.mkdtemp(prefix="camopt-geometry-share-")
    copy = os.path.join(work, "examples")
    shutil.copytree(root, copy)
    unit = "M instructions" if count else "s"
    header = "| example |" + "".join(f" {os.path.basename(os.path.dirname(p))}: with / without files [{unit}], share |" for p in programs)
    print(header)
    print("|---|" + "---|" * len(programs))
    for name in sorted(os.listdir(root)):
        if not name.endswith(".json") or (only and name[:-5] not in only):
            continue
        path = os.path.join(root, name)
        with open(path) as f:
            study = json.load(f)
        if not isinstance(study, dict) or study.get("study") not in KINDS:
            continue
        if study.get("geometry_files") is False:
            continue
        bare = dict(study)
        bare["geometry_files"] = False
        # A copy of the examples folder holds it, so that its relative paths (a catalogue) resolve
        # as from its own folder, and the source tree (whose examples the tests list) is untouched.
        bare_path = os.path.join(copy, name)
        with open(bare_path, "w") as f:
            json.dump(bare, f)
        best = {}
        try:
            for _ in range(repeats):
                for i, prog in enumerate(programs):
                    for tag, file in (("with", path), ("without", bare_path)):
                        cmd = [prog, "run", file, "--out", os.path.join(work, f"{i}-{tag}"), "--quiet"]
                        t = instructions_of(cmd) if count else cpu_of(cmd)
                        best[(i, tag)] = min(best.get((i, tag), t), t)
        finally:
            os.remove(bare_path)
        row = f"| `{name}` |"
        for i in range(len(programs)):
            w, wo = best[(i, "with")], best[(i, "without")]
            row += (f" {w:.1f} / {wo:.1f}, {100 * (w - wo) / w:.1f} % |" if count
                    else f" {w:.3f} / {wo:.3f}, {100 * (w - wo) / w:.0f} % |")
        print(row, flush=True)
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
