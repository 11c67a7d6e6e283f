"""Ctrl-C (SIGINT to the Python process) interrupts camopt.Study.run() within a second: the run is
cancelled (studies/study.h, RequestCancel), KeyboardInterrupt is raised, and the output folder is
left as it was (absent here, and no temporary folder beside it). The same for a sweep."""
import json
import os
import signal
import subprocess
import sys
import textwrap
import time
import unittest

import camopt
import helpers

# The child: prints "running" at the first progress report, then the monotonic time (the same clock
# in every process of the machine) at which KeyboardInterrupt reached Python, or "finished".
CHILD = textwrap.dedent("""
    import json, sys, time
    import camopt
    kind, path, out = sys.argv[1], sys.argv[2], sys.argv[3]
    started = []
    def progress(e):
        if not started:
            started.append(1)
            print("running", flush=True)
    try:
        if kind == "study":
            camopt.Study.load(path).run(out=out, progress=progress)
        else:
            camopt.Sweep.load(path).run(out=out, jobs=2, progress=progress)
        print("finished", flush=True)
    except KeyboardInterrupt:
        print("interrupted", time.monotonic(), flush=True)
""")


def run_and_interrupt(test, kind, path, out, delay_s=1.0):
    env = dict(os.environ)
    p = subprocess.Popen([sys.executable, "-c", CHILD, kind, str(path), str(out)], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, env=env)
    try:
        line = p.stdout.readline().strip()
        test.assertEqual(line, "running", p.stderr.read() if line == "" else line)
        time.sleep(delay_s)  # well inside the run
        sent = time.monotonic()
        p.send_signal(signal.SIGINT)
        stdout, stderr = p.communicate(timeout=60)
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
    test.assertEqual(p.returncode, 0, stderr)
    words = stdout.split()
    test.assertEqual(words[:1], ["interrupted"], stdout + stderr)
    latency = float(words[1]) - sent
    return latency


# Two threads whose first camopt call is camopt.run, in a fresh interpreter: both finish.
TWO_THREADS = textwrap.dedent("""
    import sys, threading
    import camopt, helpers
    done = []
    def go(i):
        r = camopt.run(helpers.small_lcr_ii(), out=sys.argv[1] + "/o" + str(i))
        done.append(r["study"])
    threads = [threading.Thread(target=go, args=(i,)) for i in range(2)]
    for t in threads: t.start()
    for t in threads: t.join()
    print(sorted(done))
""")


class FirstCalls(unittest.TestCase):
    def test_two_threads_whose_first_call_is_run_both_finish(self):
        d = helpers.temp_dir("two-threads")
        p = subprocess.run([sys.executable, "-c", TWO_THREADS, str(d)], capture_output=True, text=True,
                           timeout=120, cwd=os.path.dirname(os.path.abspath(__file__)))
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertEqual(p.stdout.strip(), "['lcr_analysis', 'lcr_analysis']", p.stderr)


class Interrupt(unittest.TestCase):
    def test_sigint_stops_study_run_within_a_second(self):
        d = helpers.temp_dir("py-int")
        s = helpers.example("cycloid_ltca_nnm_none.json")
        # 600 distinct phases of one mesh period (a full turn's angles would repeat phases, which
        # the LTCA solves once): seconds, certainly running after 1 s
        s["analysis"]["crank_angles_per_mesh_period"] = 600
        (d / "slow.json").write_text(json.dumps(s))
        out = d / "out"
        latency = run_and_interrupt(self, "study", d / "slow.json", out)
        print(f"\nStudy.run: KeyboardInterrupt {latency * 1000:.0f} ms after SIGINT", file=sys.stderr)
        self.assertGreaterEqual(latency, 0.0)
        self.assertLess(latency, 1.0)
        self.assertFalse(out.exists())
        self.assertEqual(sorted(p.name for p in d.iterdir()), ["slow.json"])  # no temporary folder left

    def test_an_existing_folder_is_left_as_it_was(self):
        d = helpers.temp_dir("py-int-old")
        s = helpers.example("cycloid_ltca_nnm_none.json")
        s["analysis"]["crank_angles_per_mesh_period"] = 600
        (d / "slow.json").write_text(json.dumps(s))
        out = d / "out"
        camopt.run(helpers.small_lcr_ii(), out=out)  # a previous result in the folder
        before = {p.name: p.read_bytes() for p in out.iterdir()}
        latency = run_and_interrupt(self, "study", d / "slow.json", out, delay_s=0.5)
        self.assertLess(latency, 1.0)
        self.assertEqual({p.name: p.read_bytes() for p in out.iterdir()}, before)
        self.assertEqual(sorted(p.name for p in d.iterdir()), ["out", "slow.json"])

    def test_sigint_stops_a_sweep_within_a_second(self):
        d = helpers.temp_dir("py-int-sweep")
        sweep = {
            "sweep": "slow",
            "base": str(helpers.EXAMPLES / "cycloid_ltca_nnm_none.json"),
            "set": {"/analysis": {"crank_angles_per_mesh_period": 100}},
            "vary": [{"path": "/load/torque_Nm", "values": [100, 200, 300, 400, 500, 600, 700, 800]}],
            "outputs": ["/max_contact_stress_MPa"],
        }
        (d / "sweep.json").write_text(json.dumps(sweep))
        out = d / "out"
        latency = run_and_interrupt(self, "sweep", d / "sweep.json", out)
        print(f"\nSweep.run: KeyboardInterrupt {latency * 1000:.0f} ms after SIGINT", file=sys.stderr)
        self.assertLess(latency, 1.0)
        self.assertFalse(out.exists())  # the merged folder is moved in only at the end


if __name__ == "__main__":
    unittest.main()
