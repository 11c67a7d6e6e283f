"""The wheel (build/dist/camopt-<version>-<tag>.whl, the build's `wheel` target) installs into a
fresh venv and runs a study there without PYTHONPATH, as a user would; pip show and uninstall work.

Run by ctest (Python.wheel) with CAMOPT_WHEEL, CAMOPT_VERSION, CAMOPT_BINARY, CAMOPT_SOURCE_DIR
(cmake/camopt_python.cmake); nothing is downloaded (pip --no-index, the machine's pip
configuration ignored). The venv sees the system's site-packages: the module imports NumPy, which
comes from Debian's python3-numpy (docs/api.md, "Python wheel").
"""
import base64
import hashlib
import json
import os
import pathlib
import shutil
import subprocess
import sys
import unittest
import zipfile

import helpers

WHEEL = pathlib.Path(os.environ.get("CAMOPT_WHEEL", ""))
VERSION = os.environ.get("CAMOPT_VERSION", "")
# The command docs/api.md and README.md promise, exactly.
MUST_SHOW = "import camopt; camopt.Study.load('studies/examples/lcr_ii.json').run()"
# The same run, reporting what the checks below compare.
REPORT = """
import json, camopt
r = camopt.Study.load('studies/examples/lcr_ii.json').run()
print(json.dumps({"file": camopt.__file__, "version": camopt.__version__, "verdict": r.verdict,
                  "limits_met": r.limits_met, "speed_ratio": r["speed_ratio"],
                  "fixed_turret_torque_Nm": r["fixed_turret_torque_Nm"],
                  "outer_diameter_mm": r["outer_diameter_mm"],
                  "input_stress_MPa": r.result["input_cam"]["max_contact_stress_MPa"],
                  "output_stress_MPa": r.result["output_cam"]["max_contact_stress_MPa"],
                  "efficiency_rows": int(r.tables["series"]["efficiency"].shape[0]),
                  "kinds": camopt.kinds(), "schema_fields": sorted(camopt.schema("lcr_analysis")["properties"])}))
"""


def user_env():
    """A user's environment: no PYTHONPATH, no machine pip configuration, no index."""
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "PIP_", "VIRTUAL_ENV"))}
    env.update(PIP_CONFIG_FILE=os.devnull, PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1",
               PIP_NO_CACHE_DIR="1")
    return env


def run(args, cwd=None, check=True):
    p = subprocess.run([str(a) for a in args], cwd=cwd, env=user_env(), capture_output=True, text=True,
                       timeout=120)
    if check and p.returncode != 0:
        raise AssertionError(f"{args} exited {p.returncode}\nstdout:\n{p.stdout}\nstderr:\n{p.stderr}")
    return p


class Wheel(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        if not WHEEL.is_file():
            raise AssertionError(f"no wheel at {WHEEL!s}: build the `wheel` target (part of the default build)")
        cls.tmp = helpers.temp_dir("wheel")
        cls.addClassCleanup(shutil.rmtree, cls.tmp, ignore_errors=True)  # the venv: 30 MB
        cls.venv = cls.tmp / "venv"
        # sys.executable is the python the module is built for (CAMOPT_PYTHON, ctest's interpreter).
        run([sys.executable, "-m", "venv", "--system-site-packages", cls.venv])
        cls.python = cls.venv / "bin" / "python"
        cls.pip = cls.venv / "bin" / "pip"
        cls.install = run([cls.pip, "install", "--no-index", WHEEL])
        cls.site = pathlib.Path(run([cls.python, "-c", "import sysconfig; print(sysconfig.get_path('platlib'))"])
                                .stdout.strip())
        # The command line's answer for the same study, written by the program, not by the module.
        cli_out = cls.tmp / "cli"
        run([os.environ["CAMOPT_BINARY"], "run", helpers.EXAMPLES / "lcr_ii.json", "--quiet", "--out", cli_out])
        cls.cli = json.loads((cli_out / "result.json").read_text())

    def test_1_the_wheel_is_well_formed(self):
        self.assertEqual(WHEEL.name, f"camopt-{VERSION}-{self.tag()}.whl")
        with zipfile.ZipFile(WHEEL) as z:
            names = z.namelist()
            info = f"camopt-{VERSION}.dist-info"
            record = z.read(f"{info}/RECORD").decode().splitlines()
            # Every file but RECORD itself, with its own sha256 (urlsafe base64, no padding) and size.
            listed = {}
            for line in record:
                name, digest, size = line.rsplit(",", 2)
                listed[name] = (digest, size)
            self.assertEqual(sorted(listed), sorted(names))
            for name in names:
                if name == f"{info}/RECORD":
                    self.assertEqual(listed[name], ("", ""))
                    continue
                data = z.read(name)
                want = "sha256=" + base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
                self.assertEqual(listed[name], (want, str(len(data))), name)
            wheel = z.read(f"{info}/WHEEL").decode()
            self.assertIn("Wheel-Version: 1.0", wheel)
            self.assertIn("Root-Is-Purelib: false", wheel)
            self.assertIn(f"Tag: {self.tag()}", wheel)
            meta = z.read(f"{info}/METADATA").decode()
            for line in ("Metadata-Version: 2.1", "Name: camopt", f"Version: {VERSION}",
                         f"Requires-Python: =={sys.version_info.major}.{sys.version_info.minor}.*"):
                self.assertIn(line + "\n", meta)
        ext = f"camopt.cpython-{sys.version_info.major}{sys.version_info.minor}-x86_64-linux-gnu.so"
        self.assertIn(ext, names)
        self.assertIn("camopt.pyi", names)
        self.assertTrue(any(n.startswith("camopt.libs/libcamopt.so.") for n in names), names)
        # The OpenCASCADE module the library opens from its own folder (cad/solid.cc).
        self.assertIn("camopt.libs/libcamopt_occt.so", names)

    def test_2_the_must_show_command_runs_from_the_venv_without_pythonpath(self):
        self.assertNotIn("PYTHONPATH", user_env())
        run([self.python, "-c", MUST_SHOW], cwd=helpers.SOURCE)
        got = json.loads(run([self.python, "-c", REPORT], cwd=helpers.SOURCE).stdout)
        # Loaded from the venv, not from the build tree or a system install.
        self.assertEqual(pathlib.Path(got["file"]).parent, self.site)
        self.assertEqual(got["version"], VERSION)
        # The known answers of LCR II (12 lobes / 13 rollers in, 14 / 15 out; tests/lcr_study_test.cc):
        # the ratio 1 / (1 - 13·14 / (12·15)) = -90 and the fixed turret's torque from the balance.
        self.assertAlmostEqual(got["speed_ratio"], -90.0, delta=1e-9)
        self.assertAlmostEqual(got["fixed_turret_torque_Nm"], 80.0 * 14 * 13 / (15.0 * 12), delta=1e-9)
        # The same numbers as the command line's result.json (the program, another process).
        self.assertEqual(got["speed_ratio"], self.cli["speed_ratio"])
        self.assertEqual(got["outer_diameter_mm"], self.cli["outer_diameter_mm"])
        self.assertAlmostEqual(got["input_stress_MPa"], self.cli["input_cam"]["max_contact_stress_MPa"],
                               delta=1e-9 * self.cli["input_cam"]["max_contact_stress_MPa"])
        self.assertAlmostEqual(got["output_stress_MPa"], self.cli["output_cam"]["max_contact_stress_MPa"],
                               delta=1e-9 * self.cli["output_cam"]["max_contact_stress_MPa"])
        self.assertGreater(got["input_stress_MPa"], 100.0)
        self.assertLess(got["input_stress_MPa"], 1500.0)  # the study's limit, met
        self.assertTrue(got["limits_met"])
        self.assertRegex(got["verdict"], r"^All \d+ limits met$")
        self.assertEqual(got["efficiency_rows"], 3600)  # analysis.angle_steps of the example
        # Compiled-in data works from site-packages: the kinds and their JSON Schemas.
        self.assertIn("lcr_analysis", got["kinds"])
        self.assertIn("reducer", got["schema_fields"])

    def test_2_the_module_links_the_library_from_the_wheel(self):
        module = next(self.site.glob("camopt.cpython-*.so"))
        ldd = subprocess.run(["ldd", str(module)], capture_output=True, text=True, check=True).stdout
        self.assertNotIn("not found", ldd)
        line = next(l for l in ldd.splitlines() if "libcamopt.so" in l)
        self.assertIn(str(self.site / "camopt.libs"), line)
        # No build folder in the installed files' search paths: the module's is camopt.libs alone.
        self.assertEqual(self.runpath(module), "$ORIGIN/camopt.libs")
        self.assertIsNone(self.runpath(next((self.site / "camopt.libs").glob("libcamopt.so.*"))))

    @staticmethod
    def runpath(path):
        dynamic = subprocess.run(["readelf", "-d", str(path)], capture_output=True, text=True, check=True).stdout
        found = [l.split("[", 1)[1].rstrip("]") for l in dynamic.splitlines() if "(RUNPATH)" in l or "(RPATH)" in l]
        return found[0] if found else None

    def test_2_the_result_files_are_written_from_the_venv(self):
        out = self.tmp / "py-out"
        code = ("import camopt; r = camopt.Study.load('studies/examples/lcr_ii.json').run(out=%r); "
                "print(r.out)" % str(out))
        run([self.python, "-c", code], cwd=helpers.SOURCE)
        for name in ("result.json", "report.html", "series.csv"):
            self.assertTrue((out / name).is_file(), name)
        written = json.loads((out / "result.json").read_text())
        self.assertEqual(written["outer_diameter_mm"], self.cli["outer_diameter_mm"])

    def test_2_pip_show_gives_the_metadata_and_the_files(self):
        show = run([self.pip, "show", "--files", "camopt"]).stdout
        fields = dict(l.split(": ", 1) for l in show.splitlines() if ": " in l)
        self.assertEqual(fields["Name"], "camopt")
        self.assertEqual(fields["Version"], VERSION)
        self.assertEqual(fields["Requires"], "numpy")
        self.assertEqual(pathlib.Path(fields["Location"]), self.site)
        self.assertIn("cam reducers", fields["Summary"])
        files = [l.strip() for l in show.split("Files:", 1)[1].splitlines() if l.strip()]
        self.assertIn("camopt.pyi", files)
        self.assertTrue(any(f.startswith("camopt.libs/libcamopt.so.") for f in files), files)

    def test_3_uninstall_removes_every_file(self):
        installed = [self.site / "camopt.pyi", self.site / "camopt.libs",
                     next(self.site.glob("camopt.cpython-*.so")), self.site / f"camopt-{VERSION}.dist-info"]
        for p in installed:
            self.assertTrue(p.exists(), p)
        run([self.pip, "uninstall", "--yes", "camopt"])
        for p in installed:
            self.assertFalse(p.exists(), p)
        self.assertEqual(list(self.site.glob("camopt*")), [])
        self.assertNotEqual(run([self.pip, "show", "camopt"], check=False).returncode, 0)
        # Nothing left in the venv to import (a system-wide camopt, e.g. the .deb's, may remain).
        p = run([self.python, "-c", "import camopt; print(camopt.__file__)"], cwd=helpers.SOURCE, check=False)
        if p.returncode == 0:
            self.assertFalse(pathlib.Path(p.stdout.strip()).is_relative_to(self.venv), p.stdout)
        else:
            self.assertIn("No module named 'camopt'", p.stderr)

    @staticmethod
    def tag():
        import sysconfig
        v = f"cp{sys.version_info.major}{sys.version_info.minor}"
        return f"{v}-{v}-{sysconfig.get_platform().replace('-', '_').replace('.', '_')}"


class PipInstallDot(unittest.TestCase):
    """`pip install .` from the source tree: pyproject.toml's in-tree backend hands pip the wheel of
    the existing build (CAMOPT_BUILD_DIR; its `wheel` target is up to date, nothing compiles)."""

    def test_pip_install_dot_installs_the_same_module(self):
        tmp = helpers.temp_dir("pip-dot")
        self.addCleanup(shutil.rmtree, tmp, ignore_errors=True)
        venv = tmp / "venv"
        run([sys.executable, "-m", "venv", "--system-site-packages", venv])
        run([venv / "bin" / "pip", "install", "--no-index", helpers.SOURCE], cwd=helpers.SOURCE)
        got = json.loads(run([venv / "bin" / "python", "-c", REPORT], cwd=helpers.SOURCE).stdout)
        self.assertTrue(pathlib.Path(got["file"]).is_relative_to(venv), got["file"])
        self.assertEqual(got["version"], VERSION)
        self.assertAlmostEqual(got["speed_ratio"], -90.0, delta=1e-9)
        self.assertTrue(got["limits_met"])
        # The very files of the wheel target's wheel.
        with zipfile.ZipFile(WHEEL) as z:
            want = z.read(f"camopt-{VERSION}.dist-info/RECORD").decode().splitlines()
        site = pathlib.Path(got["file"]).parent
        have = (site / f"camopt-{VERSION}.dist-info" / "RECORD").read_text().splitlines()
        for line in want:
            if line.startswith(("camopt.cpython-", "camopt.libs/", "camopt.pyi")):
                self.assertIn(line, have)
        # Nothing written into the source tree (no egg-info, no build folder of pip's).
        status = subprocess.run(["git", "-C", str(helpers.SOURCE), "status", "--porcelain", "--ignored"],
                                capture_output=True, text=True)
        if status.returncode == 0:
            self.assertNotIn("egg-info", status.stdout)


if __name__ == "__main__":
    unittest.main()
