#!/usr/bin/env python3
"""scripts/time_examples.py on two examples: each row has the kind, a CPU time > 0 that is at least the
solve phase's, and every phase of `camopt run --timings`; an analysis has no verification or limit
costs, a sizing has both (ctest: Scripts.TimeExamples)."""
import os
import subprocess
import sys
import unittest

BUILD = sys.argv.pop(1) if len(sys.argv) > 1 else "build"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PHASES = ["read", "parse", "solve", "verification", "limit costs", "files", "report", "write"]


def row_of(name):
    out = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "time_examples.py"), BUILD, "--only",
                          name, "--markdown"], capture_output=True, text=True, timeout=120)
    rows = [line for line in out.stdout.splitlines() if line.startswith("| %s " % name)]
    return out, rows


class TimeExamples(unittest.TestCase):
    def check(self, name, kind, cls, sizing):
        out, rows = row_of(name)
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertEqual(len(rows), 1, out.stdout)
        cells = [c.strip() for c in rows[0].strip("|").split("|")]
        self.assertEqual(cells[1], kind)
        cpu = float(cells[2].split()[0])
        self.assertGreater(cpu, 0.0)
        self.assertIn(cls, cells[3])
        phases = dict(zip(PHASES, cells[5:]))
        self.assertEqual(len(cells[5:]), len(PHASES), rows[0])
        for p in PHASES:
            if p in ("verification", "limit costs") and not sizing:
                self.assertEqual(phases[p], "", p)  # an analysis has no such phase
            else:
                self.assertGreaterEqual(float(phases[p]), 0.0, p)
        total = sum(float(v) for v in phases.values() if v)
        self.assertGreaterEqual(cpu + 1e-3, float(phases["solve"]))
        self.assertGreaterEqual(cpu + 1e-2, total - 1e-2)  # the phases are parts of the process's CPU time
        if sizing:
            self.assertGreater(float(phases["verification"]), 0.0)
            self.assertGreater(float(phases["limit costs"]), 0.0)

    def test_an_analysis_has_its_row_and_phases(self):
        self.check("lcr_ii.json", "lcr_analysis", "analysis", False)

    def test_a_sizing_has_its_verification_and_limit_costs(self):
        self.check("lcr_min_size.json", "lcr_min_size", "line-model sizing", True)


if __name__ == "__main__":
    unittest.main()
