"""examples/python/sweep_plot.py runs (Agg backend) and writes a plot that is not blank."""
import os
import subprocess
import sys
import unittest

import matplotlib.image

import helpers


class Example(unittest.TestCase):
    def test_the_sweep_script_writes_a_plot(self):
        out = helpers.temp_dir("py-example") / "sweep.png"
        env = dict(os.environ, MPLBACKEND="Agg")
        r = subprocess.run([sys.executable, str(helpers.SOURCE / "examples" / "python" / "sweep_plot.py"), str(out)],
                           capture_output=True, text=True, env=env)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("plot written to", r.stdout)
        self.assertEqual(r.stdout.count("MPa"), 3 * 6, r.stdout)
        image = matplotlib.image.imread(str(out))
        self.assertGreater(image.shape[0], 100)
        self.assertGreater(float(image.std()), 0.01)  # not a blank page

    def test_help_is_help_not_a_plot_named_help(self):
        d = helpers.temp_dir("py-example-help")
        r = subprocess.run([sys.executable, str(helpers.SOURCE / "examples" / "python" / "sweep_plot.py"), "--help"],
                           capture_output=True, text=True, cwd=d, env=dict(os.environ, MPLBACKEND="Agg"))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("usage:", r.stdout)
        self.assertEqual(list(d.iterdir()), [])  # no --help.png


if __name__ == "__main__":
    unittest.main()
