#!/usr/bin/env python3
"""Re-runs the hardening list of docs/reliability.md ("Round two: the list re-run") with the
camopt binary and measures every item: exit code, the first line of stderr, wall time, CPU time
and peak memory (the child's maximum resident set, from wait4). Prints a Markdown table and exits
1 when an item's outcome is not the expected one, when a refusal (exit 2) takes 1 s of CPU or
more, or when an item needs 500 MB or more.

    python3 scripts/hardening_list.py build/camopt [--markdown]

Items about concurrent or killed runs (two sweeps, SIGKILL, a full disk during a merge) are kept
by their tests (tests/reliability_test.cc, tests/sweep_test.cc), named in the table's last rows.
"""
import copy
import json
import os
import shutil
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLES = os.path.join(ROOT, "studies", "examples")


def example(name):
    with open(os.path.join(EXAMPLES, name)) as f:
        return json.load(f)


def run(binary, args, cwd):
    """Runs camopt with args; returns (exit code, stderr, wall s, cpu s, rss MB)."""
    err_path = os.path.join(cwd, "stderr.txt")
    t0 = time.monotonic()
    pid = os.fork()
    if pid == 0:
        fd = os.open(err_path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
        os.dup2(fd, 2)
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, 1)
        os.chdir(cwd)
        try:
            os.execv(binary, [binary] + args)
        finally:
            os._exit(127)
    _, status, ru = os.wait4(pid, 0)
    wall = time.monotonic() - t0
    code = os.waitstatus_to_exitcode(status)
    with open(err_path, errors="replace") as f:
        err = f.read()
    return code, err, wall, ru.ru_utime + ru.ru_stime, ru.ru_maxrss / 1024.0


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    binary = os.path.abspath(sys.argv[1])
    tmp = tempfile.mkdtemp(prefix="camopt-hardening-")
    # Catalogues and other files the examples name, beside the studies written here.
    for f in os.listdir(EXAMPLES):
        os.symlink(os.path.join(EXAMPLES, f), os.path.join(tmp, f))
    items = []  # (number, what, args or callable, expected exit codes, extra check)

    def study(tag, doc, text=None):
        path = os.path.join(tmp, tag + ".json")
        with open(path, "w") as f:
            f.write(text if text is not None else json.dumps(doc, indent=1))
        return path

    def add(number, what, doc=None, expect=(2,), text=None, extra=(), check=None):
        items.append((number, what, doc, text, expect, list(extra), check))

    # 1. --out naming a previous result folder that also holds the user's files.
    def user_files():
        res = os.path.join(tmp, "res1")
        code, err, *_ = run(binary, ["run", os.path.join(EXAMPLES, "rigidity_gearbox.json"), "--out", res, "--quiet"], tmp)
        shutil.copy(os.path.join(EXAMPLES, "rigidity_gearbox.json"), os.path.join(res, "my_study.json"))
        with open(os.path.join(res, "notes.txt"), "w") as f:
            f.write("x")
        return ["run", os.path.join(res, "my_study.json"), "--out", res, "--quiet"]

    items.append((1, "`--out` a previous result folder holding the user's files", None, None, (2,), user_files,
                  lambda: os.path.exists(os.path.join(tmp, "res1", "notes.txt"))
                  and os.path.exists(os.path.join(tmp, "res1", "my_study.json"))))
    for kind_file in ("cycloid_ltca_nnm_lcm.json", "cycloid_crowning_tuning_nnm.json"):
        for value in (5, {"a": 1}, [1]):
            s = example(kind_file)
            s["name"] = value
            add(4, "`%s` with `name` %s" % (s["study"], json.dumps(value)), s)
    s = example("cycloid_ltca_nnm_lcm.json")
    s["drive"]["roller_position_radius_mm"] = 2147483648
    add(5, "cycloid pin circle 2147483648 mm", s)
    s = example("disc_cam_translating.json")
    s["base_circle_radius_mm"] = 10000
    s["analysis"].pop("monte_carlo")
    add(5, "disc cam base circle 10 m (legal: runs, files of a normal part)", s, expect=(0,))
    s = example("cycloid_ltca_nnm_lcm.json")
    s["modification"]["delta_position_um"] = 1e9
    add(5, "cycloid profile modification 1e9 µm", s)
    add(6, "`--max-work-factor nan`", example("lcr_ii.json"), extra=["--max-work-factor", "nan"])
    s = example("disc_cam_translating.json")
    s["base_circle_radius_mm"] = 5000
    s["analysis"].pop("monte_carlo")
    add(7, "disc cam base circle 5 m with geometry files (legal)", s, expect=(0,))
    s = example("lcr_min_size_straight3d.json")
    s["contact"]["slices"] = 200
    add(8, "`lcr_min_size` `contact.slices` 200", s)
    s = example("lcr_min_size_robust.json")
    s["monte_carlo"]["samples"] = 100000
    add(8, "robust sizing `monte_carlo.samples` 1e5", s)
    s = example("lcr_ii.json")
    s["name"] = "line\nbreak and an apostrophe's"
    add(9, "`name` with a line break and an apostrophe (legal: escaped in DXF/STL/STEP)", s, expect=(0,))
    add(10, "a key twice (`output_torque_Nm` 50, then 5000)", text='{"study": "lcr_analysis", "load": '
        '{"output_torque_Nm": 50, "output_torque_Nm": 5000}}')
    add(10, "the `study` key twice", text='{"study": "lcr_analysis", "study": "cycloid_ltca"}')
    s = example("lcr_min_size_straight3d.json")
    s["contact"]["slices"] = 2
    add(13, "`contact.slices` 2", s)
    s = example("lcr_min_size.json")
    s["variables"]["eccentricity_mm"] = [1, 1]
    add(13, "a range with lo = hi (legal: the variable is fixed)", s, expect=(0,))
    s = example("cycloid_crowning_tuning_nnm.json")
    s["drive"]["bore_diameter_mm"] = "x"
    add(13, "`drive.bore_diameter_mm` a string", s)
    s = example("disc_cam_translating.json")
    s.pop("tolerances")
    s["analysis"].pop("monte_carlo")
    s["motion"] = [{"law": "cycloidal", "rise_mm": 24, "cam_angle_deg": 1.5}, {"law": "dwell", "cam_angle_deg": 168.5},
                   {"law": "cycloidal", "rise_mm": -24, "cam_angle_deg": 120}, {"law": "dwell", "cam_angle_deg": 70}]
    add(15, "pressure angle 88° (legal: a warning in result.json)", s, expect=(0,),
        check=lambda: "pressure angle" in open(os.path.join(tmp, "out-15-0", "result.json")).read())
    add(15, "`--out ''`", example("lcr_ii.json"), extra=["--out", ""])
    add(15, "a number `1e-400`", text='{"study": "lcr_analysis", "load": {"output_torque_Nm": 1e-400}}')
    s = example("lcr_ii.json")
    s["load"] = {"output_torque_Nm": 80, "friction_coefficient": 0.5}
    add(16, "`lcr_analysis` μ = 0.5 (legal: the result says how the turret torque treats friction)", s, expect=(0,),
        check=lambda: "fixed_turret_torque_model" in open(os.path.join(tmp, "out-16-0", "result.json")).read())

    rows, failed = [], 0
    counters = {}
    for number, what, doc, text, expect, extra, check in items:
        k = counters.get(number, 0)
        counters[number] = k + 1
        tag = "%d-%d" % (number, k)
        out = os.path.join(tmp, "out-" + tag)
        if callable(extra):
            args = extra()
        else:
            args = ["run", study(tag, doc, text), "--quiet"]
            if "--out" not in extra:
                args += ["--out", out]
            args += extra
        code, err, wall, cpu, rss = run(binary, args, tmp)
        line = err.strip().splitlines()[0] if err.strip() else ""
        ok = code in expect and (code == 0 or line.startswith("camopt:"))
        if code == 2 and cpu >= 1.0:
            ok = False
        if rss >= 500:
            ok = False
        if ok and check is not None:
            ok = bool(check())
        failed += not ok
        line = line.replace(tmp + "/", "").replace("|", "\\|")
        if len(line) > 150:
            line = line[:147] + "..."
        rows.append("| %d | %s | %d | %.2f | %.2f | %.0f | %s | %s |" %
                    (number, what, code, wall, cpu, rss, "yes" if ok else "**NO**", line))
    print("| # | item | exit | wall s | CPU s | peak MB | as expected | stderr (first line) |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(r)
    shutil.rmtree(tmp, ignore_errors=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
