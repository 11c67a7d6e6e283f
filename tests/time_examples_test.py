#!/usr/bin/env python3
"""scripts/time_examples.py on one example: its row has the kind, a CPU time > 0 that is at least the
solve phase's, and every phase of `camopt run --timings` (ctest: Scripts.TimeExamples)."""
import os
import subprocess
import sys
import unittest

BUILD = sys.argv.pop(1) if len(sys.argv) > 1 else "build"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class TimeExamples(unittest.TestCase):
    def test_one_example_has_its_row_and_phases(self):
        out = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "time_examples.py"), BUILD, "--only",
                              "lcr_ii.json", "--markdown"], capture_output=True, text=True, timeout=120)
        self.assertEqual(out.returncode, 0, out.stderr)
        rows = [line for line in out.stdout.splitlines() if line.startswith("| lcr_ii.json ")]
        self.assertEqual(len(rows), 1, out.stdout)
        cells = [c.strip() for c in rows[0].strip("|").split("|")]
        self.assertEqual(cells[1], "lcr_analysis")
        cpu = float(cells[2].split()[0])
        self.assertGreater(cpu, 0.0)
        self.assertIn("analysis", cells[3])
        phases = [float(c) for c in cells[5:]]  # read, parse, solve, files, report, write
        self.assertEqual(len(phases), 6)
        self.assertGreaterEqual(cpu + 1e-3, phases[2])
        self.assertTrue(all(p >= 0 for p in phases))


if __name__ == "__main__":
    unittest.main()
