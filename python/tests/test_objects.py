"""The object API: camopt.Study / Result / Sweep, the progress callback, FileNotFoundError and
StudyError, the model objects (camopt.Lcr, camopt.CycloidDrive) against the study's own output, and
the stub camopt.pyi against the module."""
import ast
import json
import os
import math
import unittest

import numpy as np

import camopt
import helpers


def small_ltca():
    s = helpers.example("cycloid_ltca_nnm_none.json")
    s["analysis"] = {"crank_angle_steps": 4, "grid": [12, 12], "estimate_error": False}
    return s


class StudyObjects(unittest.TestCase):
    def test_load_run_result(self):
        d = helpers.temp_dir("py-obj")
        path = d / "s.json"
        path.write_text(json.dumps(helpers.small_lcr_ii()))
        s = camopt.Study.load(path)  # a PathLike
        self.assertEqual(s.kind, "lcr_analysis")
        self.assertEqual(s.file, str(path))
        r = s.run(out=d / "out")
        self.assertIsInstance(r, camopt.Result)
        self.assertEqual(r.kind, "lcr_analysis")
        self.assertEqual(r.out, str(d / "out"))
        self.assertTrue((d / "out" / "result.json").exists())
        self.assertEqual(json.loads((d / "out" / "result.json").read_text())["outer_diameter_mm"],
                         r.result["outer_diameter_mm"])
        self.assertEqual(r["outer_diameter_mm"], r.result["outer_diameter_mm"])
        self.assertIn("series.csv", r.files)
        self.assertEqual(r.text("result.json"), (d / "out" / "result.json").read_bytes())
        eff = r.tables["series"]["efficiency"]
        self.assertIsInstance(eff, np.ndarray)
        self.assertEqual(eff.shape, (360,))
        self.assertIsNone(r.incomplete)
        self.assertEqual(r.warnings, [])
        # The verdict and headlines are those of the command line's summary (studies/report.h).
        self.assertIsInstance(r.verdict, str)
        self.assertTrue(r.verdict)
        self.assertGreater(len(r.headlines), 0)
        stress = [h for h in r.headlines if h.get("pointer") == "/input_cam/max_contact_stress_MPa"]
        self.assertEqual(len(stress), 1, r.headlines)
        self.assertEqual(stress[0]["value"], r.result["input_cam"]["max_contact_stress_MPa"])
        self.assertEqual(stress[0]["unit"], "MPa")
        self.assertIn(stress[0]["status"], ("pass", "fail", ""))
        self.assertEqual(r.limits_met, all(h["status"] != "fail" for h in r.headlines))

    def test_a_dict_with_its_kind_and_the_same_numbers_as_run(self):
        fields = helpers.small_lcr_ii()
        del fields["study"]
        s = camopt.Study("lcr_analysis", fields)
        self.assertNotIn("study", fields)  # the caller's dict is left alone
        self.assertEqual(s.file, "<dict>")
        self.assertEqual(s.to_dict()["study"], "lcr_analysis")
        r = s.run()
        self.assertIsNone(r.out)
        self.assertEqual(r.result["input_cam"]["max_contact_stress_MPa"],
                         camopt.run(helpers.small_lcr_ii())["input_cam"]["max_contact_stress_MPa"])
        with self.assertRaises(camopt.StudyError) as cm:
            camopt.Study("cycloid_ltca", helpers.small_lcr_ii())
        self.assertEqual(cm.exception.path, "/study")

    def test_progress_callback(self):
        events = []
        s = camopt.Study("lcr_analysis", helpers.with_change(helpers.small_lcr_ii(), "/analysis/angle_steps", 3600))
        s.run(progress=events.append)
        self.assertGreater(len(events), 0)
        self.assertTrue(all(isinstance(e, camopt.ProgressEvent) for e in events))
        self.assertTrue(all(0.0 <= e.fraction <= 1.0 for e in events), [e.fraction for e in events])
        self.assertTrue(all(e.label.startswith("lcr_analysis") for e in events))
        done = [e for e in events if e.done]
        self.assertGreater(len(done), 0)
        self.assertEqual(events[-1].done, True)
        self.assertTrue(all(e.elapsed_s >= 0 for e in events))

    def test_an_exception_in_the_callback_stops_the_run_and_is_raised(self):
        class Stop(Exception):
            pass

        def callback(e):
            raise Stop(e.label)

        s = camopt.Study("lcr_analysis", helpers.small_lcr_ii())
        with self.assertRaises(Stop):
            s.run(progress=callback)
        self.assertGreater(s.run().result["outer_diameter_mm"], 0)  # the next run is not cancelled

    def test_a_run_from_the_callback_is_refused(self):
        s = camopt.Study("lcr_analysis", helpers.small_lcr_ii())

        def callback(e):
            s.run()

        with self.assertRaises(RuntimeError) as cm:
            s.run(progress=callback)
        self.assertIn("progress callback", str(cm.exception))

    def test_missing_files(self):
        for load in (camopt.Study.load, camopt.Sweep.load, camopt.Lcr.from_study):
            with self.assertRaises(FileNotFoundError) as cm:
                load("/nonexistent/study.json")
            self.assertEqual(cm.exception.filename, "/nonexistent/study.json")

    def test_study_error_attributes(self):
        d = helpers.temp_dir("py-bad")
        path = d / "bad.json"
        path.write_text(json.dumps(helpers.with_change(helpers.small_lcr_ii(), "/reducer/input/lobes", "twelve")))
        with self.assertRaises(camopt.StudyError) as cm:
            camopt.Study.load(path)
        e = cm.exception
        self.assertIsInstance(e, ValueError)
        self.assertEqual(e.file, str(path))
        self.assertEqual(e.path, "/reducer/input/lobes")
        self.assertIn("whole number", e.expected)
        self.assertIn("twelve", e.found)
        with self.assertRaises(camopt.StudyError) as cm:
            camopt.Study("lcr_analysis", helpers.with_change(helpers.small_lcr_ii(), "/load/output_torque_Nm", None))
        self.assertEqual(cm.exception.file, "<dict>")
        self.assertEqual(cm.exception.path, "/load/output_torque_Nm")
        self.assertEqual(cm.exception.found, "nothing")


class Sweeps(unittest.TestCase):
    def test_a_sweep_from_python(self):
        d = helpers.temp_dir("py-sweep")
        sweep = {
            "sweep": "torques",
            "base": str(helpers.EXAMPLES / "lcr_ii.json"),
            "set": {"/analysis": {"angle_steps": 360}},
            "vary": [{"path": "/load/output_torque_Nm", "values": [50, 100, 150]}],
            "outputs": ["/input_cam/max_contact_stress_MPa"],
        }
        (d / "sweep.json").write_text(json.dumps(sweep))
        sw = camopt.Sweep.load(d / "sweep.json")
        self.assertEqual(len(sw), 3)
        self.assertEqual(sw.cases, [{"case": 0, "/load/output_torque_Nm": 50}, {"case": 1, "/load/output_torque_Nm": 100},
                                    {"case": 2, "/load/output_torque_Nm": 150}])
        events = []
        r = sw.run(jobs=1, progress=events.append)
        self.assertIsNone(r.out)
        cases = r.tables["cases"]
        self.assertEqual(list(cases["case"]), [0, 1, 2])
        self.assertEqual(cases["status"], ["ok", "ok", "ok"])
        stress = cases["/input_cam/max_contact_stress_MPa"]
        self.assertTrue(np.all(np.diff(stress) > 0), stress)  # more torque, more stress
        one = camopt.run(helpers.with_change(helpers.small_lcr_ii(), "/load/output_torque_Nm", 100))
        self.assertAlmostEqual(stress[1], one["input_cam"]["max_contact_stress_MPa"], delta=1e-6 * stress[1])
        self.assertEqual(r.result["cases"], 3)
        self.assertEqual(r.verdict, "All 3 cases ok")
        self.assertTrue(any(e.done for e in events))
        # With out=FOLDER the folder is kept, as `camopt sweep --out` leaves it.
        r2 = sw.run(out=d / "out", jobs=1)
        self.assertEqual(r2.out, str(d / "out"))
        self.assertTrue((d / "out" / "cases.csv").exists())
        bad = dict(sweep, vary=[{"path": "no pointer", "values": [1]}])
        (d / "bad.json").write_text(json.dumps(bad))
        with self.assertRaises(camopt.StudyError) as cm:
            camopt.Sweep.load(d / "bad.json")
        self.assertEqual(cm.exception.path, "/vary/0/path")

    def test_a_sweep_from_a_dict(self):
        # camopt.Sweep({...}) as camopt.Sweep.load of the same JSON: a relative base is found from
        # the current folder, messages name "<dict>", and the cases are the table cases.csv numbers.
        d = helpers.temp_dir("py-sweep-dict")
        sweep = {
            "sweep": "eccentricity and torque",
            "base": "lcr_ii.json",
            "set": {"/analysis": {"angle_steps": 180}},
            "vary": [{"path": "/reducer/eccentricity_mm", "values": [1.9, 2.1]},
                     {"path": "/load/output_torque_Nm", "values": [60, 90]}],
            "outputs": ["/input_cam/max_contact_stress_MPa"],
        }
        here = os.getcwd()
        os.chdir(helpers.EXAMPLES)
        try:
            sw = camopt.Sweep(sweep)
            self.assertEqual(len(sw), 4)
            self.assertEqual([(c["/reducer/eccentricity_mm"], c["/load/output_torque_Nm"]) for c in sw.cases],
                             [(1.9, 60), (1.9, 90), (2.1, 60), (2.1, 90)])
            r = sw.run(jobs=1)
        finally:
            os.chdir(here)
        self.assertEqual(r.verdict, "All 4 cases ok")
        self.assertEqual(list(r.tables["cases"]["case"]), [0, 1, 2, 3])
        (d / "sweep.json").write_text(json.dumps(dict(sweep, base=str(helpers.EXAMPLES / "lcr_ii.json"))))
        from_file = camopt.Sweep.load(d / "sweep.json").run(jobs=1)
        self.assertEqual(list(r.tables["cases"]["/input_cam/max_contact_stress_MPa"]),
                         list(from_file.tables["cases"]["/input_cam/max_contact_stress_MPa"]))
        self.assertEqual(camopt.Sweep(d / "sweep.json").cases, sw.cases)  # a path works too
        with self.assertRaises(camopt.StudyError) as cm:
            camopt.Sweep(dict(sweep, base=str(helpers.EXAMPLES / "lcr_ii.json"),
                              vary=[{"path": "/load/output_torque_Nm", "values": "many"}]))
        self.assertEqual(cm.exception.path, "/vary/0/values")
        self.assertIn("<dict>", str(cm.exception))
        # Here (not the examples' folder) the relative base is not found: said at /base.
        with self.assertRaises(camopt.StudyError) as cm:
            camopt.Sweep(sweep)
        self.assertEqual(cm.exception.path, "/base")

    def test_a_users_files_in_the_output_folder_are_kept_by_run_and_sweep(self):
        # The one output-folder rule of `camopt run` and `camopt sweep` holds for the module's
        # writers too: a folder camopt did not write (no manifest, or files beyond it) is never
        # replaced; the call raises StudyError and every file stays.
        d = helpers.temp_dir("py-user-files")
        (d / "s.json").write_text(json.dumps(helpers.small_lcr_ii()))
        sweep = {"sweep": "t", "base": str(d / "s.json"),
                 "vary": [{"path": "/load/output_torque_Nm", "values": [50, 60]}],
                 "outputs": ["/input_cam/max_contact_stress_MPa"]}
        (d / "sweep.json").write_text(json.dumps(sweep))
        for tag, write in (("run", lambda out: camopt.run(str(d / "s.json"), out=str(out))),
                           ("sweep", lambda out: camopt.Sweep.load(d / "sweep.json").run(out=out, jobs=1))):
            with self.subTest(tag):
                out = d / ("out_" + tag)
                write(out)  # a first result: camopt's own folder, replaced by the same call
                write(out)
                (out / "notes.txt").write_text("mine")
                if tag == "sweep":
                    (out / "cases.csv").write_text("my own table")  # a user's file of a sweep's name
                    (out / ".camopt_manifest").unlink(missing_ok=True)
                with self.assertRaises(camopt.StudyError):
                    write(out)
                self.assertEqual((out / "notes.txt").read_text(), "mine")
                if tag == "sweep":
                    self.assertEqual((out / "cases.csv").read_text(), "my own table")


class LcrModel(unittest.TestCase):
    def test_loads_at_the_study_angles_are_series_csv(self):
        study = camopt.Study("lcr_analysis", helpers.small_lcr_ii())
        csv = study.run().tables["series"]
        lcr = camopt.Lcr.from_study(study)
        theta = lcr.angles_rad
        self.assertEqual(theta.shape, (360,))
        np.testing.assert_allclose(theta * 180 / np.pi, csv["input_angle_deg"], rtol=1e-9, atol=1e-9)
        loads = lcr.loads(theta)
        compared = 0
        for name, column in csv.items():
            if name == "input_angle_deg":
                continue
            self.assertIn(name, loads)
            # series.csv holds 10 significant digits (studies/writers.cc): the same numbers to 1e-9.
            np.testing.assert_allclose(loads[name], column, rtol=1e-9, atol=1e-9 * float(np.abs(column).max()),
                                       err_msg=name)
            compared += 1
        self.assertGreaterEqual(compared, 10)
        # Each roller's force: the largest of a row is the cam's largest roller force.
        forces = loads["input_roller_force_N"]
        self.assertEqual(forces.shape, (360, study.to_dict()["reducer"]["input"]["rollers"]))
        np.testing.assert_array_equal(forces.max(axis=1), loads["input_max_roller_force_N"])
        # Any angle, not only the study's.
        self.assertEqual(lcr.loads([0.1, 0.2])["efficiency"].shape, (2,))
        with self.assertRaises(ValueError):
            lcr.loads([math.nan])

    def test_the_profile_is_the_pitch_curve_offset_by_the_roller(self):
        s = helpers.small_lcr_ii()
        lcr = camopt.Lcr.from_study(s)
        r_roller = s["reducer"]["input"]["roller_diameter_mm"] / 2
        x, y = lcr.profile("input", points=720)
        px, py = lcr.profile("input", points=20000, offset_mm=0.0)
        # Every profile point lies a roller radius from the (densely sampled) pitch curve.
        d = np.sqrt((x[:, None] - px[None, :]) ** 2 + (y[:, None] - py[None, :]) ** 2).min(axis=1)
        np.testing.assert_allclose(d, r_roller, atol=2e-3)
        with self.assertRaises(ValueError):
            lcr.profile("middle")

    def test_another_kind_is_refused(self):
        with self.assertRaises(camopt.StudyError) as cm:
            camopt.Lcr.from_study(small_ltca())
        self.assertEqual(cm.exception.path, "/study")


class CycloidModel(unittest.TestCase):
    def test_loads_at_the_study_angles_are_per_angle_csv(self):
        s = camopt.Study("cycloid_ltca", small_ltca())
        csv = s.run().tables["per_angle"]
        drive = camopt.CycloidDrive.from_study(s)
        phi = drive.crank_angles_rad
        self.assertEqual(phi.shape, (4,))
        events = []
        loads = drive.loads(phi, progress=events.append)
        self.assertTrue(loads["converged"])
        self.assertGreater(len(events), 0)
        for name in ("crank_angle_deg", "lte_arcsec", "unloaded_te_arcsec", "gear_ratio", "max_contact_stress_MPa",
                     "pairs_in_contact"):
            np.testing.assert_allclose(loads[name], csv[name], rtol=1e-9, atol=1e-12, err_msg=name)
        for i in range(drive.rollers):
            col = csv[f"load_roller_{i + 1}_N"]
            np.testing.assert_allclose(loads["roller_load_N"][:, i], col, rtol=1e-9,
                                       atol=1e-9 * float(np.abs(col).max() or 1), err_msg=str(i))
            peak = csv[f"max_pressure_roller_{i + 1}_MPa"]
            np.testing.assert_allclose(loads["roller_max_pressure_MPa"][:, i], peak, rtol=1e-9,
                                       atol=1e-9 * float(np.abs(peak).max() or 1), err_msg=str(i))
        np.testing.assert_allclose(loads["roller_max_pressure_MPa"].max(axis=1), csv["max_contact_stress_MPa"], rtol=1e-9)
        unloaded = drive.unloaded(phi)
        np.testing.assert_allclose(unloaded["unloaded_te_arcsec"], csv["unloaded_te_arcsec"], rtol=1e-9, atol=1e-12)
        # The tooth profile: the roller circles at crank angle 0 touch it (the unmodified drive's
        # loaded flanks); every profile point is at least a roller radius from every roller centre.
        x, y = drive.profile(4000)
        cx, cy = drive.roller_centres(0.0)
        rho = small_ltca()["drive"]["roller_radius_mm"]
        dist = np.sqrt((x[:, None] - cx[None, :]) ** 2 + (y[:, None] - cy[None, :]) ** 2).min(axis=0)
        self.assertGreater(dist.min(), rho - 1e-3)
        self.assertLess(dist.min(), rho + 0.05)


class DiscCamModel(unittest.TestCase):
    def test_evaluate_at_the_study_angles_is_series_csv(self):
        for example in ("disc_cam_translating.json", "disc_cam_oscillating.json"):
            with self.subTest(example=example):
                s = helpers.example(example)
                s["analysis"] = {"angle_steps": 720, "evaluate": ["profile"]}
                s.pop("tolerances", None)
                study = camopt.Study("disc_cam", s)
                csv = study.run().tables["series"]
                cam = camopt.DiscCam.from_study(study)
                self.assertEqual(cam.oscillating, example == "disc_cam_oscillating.json")
                values = cam.evaluate(cam.angles_rad)
                compared = 0
                for name, column in values.items():
                    self.assertIn(name, csv)
                    np.testing.assert_allclose(column, csv[name], rtol=1e-9,
                                               atol=1e-9 * max(1.0, float(np.abs(csv[name]).max())), err_msg=name)
                    compared += 1
                self.assertGreaterEqual(compared, 12)
                x, y = cam.profile(720)
                np.testing.assert_array_equal(x, values["contact_x_mm"])
                np.testing.assert_array_equal(y, values["contact_y_mm"])
        flat = camopt.DiscCam.from_study(helpers.example("disc_cam_flat_faced.json"))
        with self.assertRaises(ValueError):
            flat.evaluate([0.0])


class Stub(unittest.TestCase):
    def test_every_public_name_is_in_the_stub(self):
        stub = ast.parse((helpers.SOURCE / "python" / "camopt.pyi").read_text())
        declared = {}
        for node in stub.body:
            if isinstance(node, ast.ClassDef):
                declared[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef)} | {
                    n.target.id for n in node.body if isinstance(n, ast.AnnAssign)}
            elif isinstance(node, ast.FunctionDef):
                declared[node.name] = set()
            elif isinstance(node, ast.AnnAssign):
                declared[node.target.id] = set()
        public = [n for n in dir(camopt) if not n.startswith("_")] + ["__version__"]
        self.assertEqual([n for n in public if n not in declared], [])
        for name in public:
            obj = getattr(camopt, name)
            if isinstance(obj, type) and name != "StudyError":
                members = [m for m in vars(obj) if not m.startswith("_")]
                self.assertEqual([m for m in members if m not in declared[name]], [], name)
        self.assertEqual([n for n in declared if not n.startswith("_") and n not in public], [])


if __name__ == "__main__":
    unittest.main()
