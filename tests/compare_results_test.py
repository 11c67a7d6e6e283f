#!/usr/bin/env python3
"""scripts/compare_results.py on two hand-made result trees: the largest relative difference, the
work counts kept apart, a changed status reported in full with exit 1, identical files silent."""
import json
import os
import subprocess
import sys
import tempfile

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts", "compare_results.py")


def write(root, name, result):
    os.makedirs(os.path.join(root, name))
    with open(os.path.join(root, name, "result.json"), "w") as f:
        json.dump(result, f)


def main():
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        old, new = os.path.join(tmp, "old"), os.path.join(tmp, "new")
        base = {"max_stress_MPa": 1000.0, "lte": [1.0, 2.0], "optimizer": {"evaluations": 10}, "status": "ok"}
        write(old, "a_numbers", base)
        write(new, "a_numbers", dict(base, max_stress_MPa=1000.5, optimizer={"evaluations": 12}))
        write(old, "b_same", base)
        write(new, "b_same", base)
        run = subprocess.run([sys.executable, SCRIPT, old, new], capture_output=True, text=True)
        out = run.stdout
        if run.returncode != 0:
            failures.append(f"numbers only: exit {run.returncode}, expected 0\n{out}{run.stderr}")
        # 0.5 / 1000 = 5.00e-04 by hand; the evaluation count is work, not an answer.
        if "a_numbers: 1 numbers differ, largest relative 5.00e-04; 1 work counts; 0 other" not in out:
            failures.append("the relative difference or the work count is not reported:\n" + out)
        if "b_same" in out:
            failures.append("an identical result is listed:\n" + out)
        write(old, "c_status", base)
        write(new, "c_status", dict(base, status="not_converged"))
        run = subprocess.run([sys.executable, SCRIPT, old, new], capture_output=True, text=True)
        if run.returncode != 1 or 'OTHER /status: "ok" -> "not_converged"' not in run.stdout:
            failures.append(f"a changed status: exit {run.returncode} (expected 1)\n{run.stdout}")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
