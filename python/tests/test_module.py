"""The Python module: run from a dict and from a file, NumPy series, StudyError, kinds, schema."""
import hashlib
import json
import unittest

import numpy as np

import camopt
import helpers


class Run(unittest.TestCase):
    def test_a_dict_gives_result_json_with_numpy_series(self):
        r = camopt.run(helpers.small_lcr_ii())
        self.assertEqual(r["study"], "lcr_analysis")
        self.assertEqual(r["camopt_version"], camopt.__version__)
        self.assertIn("series.csv", r["files"])
        efficiency = r["series"]["series"]["efficiency"]
        self.assertIsInstance(efficiency, np.ndarray)
        self.assertEqual(efficiency.shape, (360,))
        self.assertTrue(np.all((efficiency > 0) & (efficiency < 1)))
        angle = r["series"]["series"]["input_angle_deg"]
        self.assertAlmostEqual(float(angle[1] - angle[0]), 1.0)
        # The same numbers as the headline, from the series.
        stress = r["series"]["series"]["input_max_contact_stress_MPa"]
        self.assertAlmostEqual(float(stress.max()), r["input_cam"]["max_contact_stress_MPa"], delta=1e-6 * stress.max())
        self.assertEqual(r["warnings"], [])

    def test_csv_outputs_with_comment_headers_become_columns(self):
        # inspection/<part>.csv opens with '#' lines (part, frame, ISO 1101 zone) before its header row.
        s = helpers.small_lcr_ii()
        s["inspection"] = {"spacing_mm": 2.0, "tolerance_um": 20}
        r = camopt.run(s)
        table = r["series"]["inspection/input_cam"]
        self.assertIn("x_mm", table)
        self.assertIsInstance(table["x_mm"], np.ndarray)
        n = np.hypot(table["nx"], table["ny"])
        self.assertTrue(np.all(np.abs(n - 1) < 1e-9))
        self.assertTrue(np.all(table["upper_mm"] == 0.01))

    def test_a_path_gives_the_same_as_the_command_line_and_the_files_sha256(self):
        d = helpers.temp_dir("py-path")
        path = d / "s.json"
        text = json.dumps(helpers.small_lcr_ii(), indent=1)
        path.write_text(text)
        r = camopt.run(str(path), out=str(d / "out"))
        self.assertEqual(r["study_sha256"], hashlib.sha256(text.encode()).hexdigest())
        written = json.loads((d / "out" / "result.json").read_text())
        self.assertEqual(written["study_sha256"], r["study_sha256"])
        self.assertEqual(written["outer_diameter_mm"], r["outer_diameter_mm"])
        # The folder also keeps camopt's list of the files it wrote (never replaced otherwise).
        self.assertEqual(sorted(p.name for p in (d / "out").iterdir() if p.name != ".camopt_manifest"),
                         sorted(r["files"]))
        self.assertEqual((d / "out" / ".camopt_manifest").read_text().split(), sorted(r["files"]))

    def test_numbers_in_lists_become_arrays(self):
        s = helpers.example("cycloid_ltca_nnm_none.json")
        s["analysis"] = {"crank_angle_steps": 2, "grid": [12, 12], "estimate_error": False}
        r = camopt.run(s)
        self.assertIsInstance(r["grid"], np.ndarray)
        self.assertEqual(list(r["grid"]), [12, 12])

    def test_an_implausible_value_is_a_warning_in_the_result(self):
        s = helpers.with_change(helpers.small_lcr_ii(), "/material/youngs_modulus_GPa", 206000)
        r = camopt.run(s)
        self.assertEqual(len(r["warnings"]), 1, r["warnings"])
        self.assertIn("/material/youngs_modulus_GPa", r["warnings"][0])
        self.assertIn("looks like MPa", r["warnings"][0])


class BadStudy(unittest.TestCase):
    def test_study_error_carries_file_path_expected_found(self):
        s = helpers.with_change(helpers.small_lcr_ii(), "/reducer/input/lobes", "twelve")
        with self.assertRaises(camopt.StudyError) as cm:
            camopt.run(s)
        e = cm.exception
        self.assertIsInstance(e, ValueError)
        self.assertEqual(e.file, "<dict>")
        self.assertEqual(e.path, "/reducer/input/lobes")
        self.assertIn("whole number", e.expected)
        self.assertIn("twelve", e.found)
        self.assertIn("/reducer/input/lobes", str(e))

    def test_a_missing_file_and_a_missing_field(self):
        with self.assertRaises(camopt.StudyError) as cm:
            camopt.run("/nonexistent/study.json")
        self.assertEqual(cm.exception.file, "/nonexistent/study.json")
        self.assertEqual(cm.exception.path, "")  # no JSON path: the file itself
        self.assertIn("/nonexistent/study.json", str(cm.exception))
        s = helpers.with_change(helpers.small_lcr_ii(), "/load/output_torque_Nm", None)
        with self.assertRaises(camopt.StudyError) as cm:
            camopt.run(s)
        self.assertEqual(cm.exception.path, "/load/output_torque_Nm")
        self.assertEqual(cm.exception.found, "nothing")

    def test_a_non_finite_work_factor_is_refused(self):
        # NaN or infinity would switch every work cap off (a MemoryError instead of the estimate).
        for factor in (float("nan"), float("inf"), 0.0, 1e7):
            with self.assertRaises(camopt.StudyError) as cm:
                camopt.run(helpers.small_lcr_ii(), max_work_factor=factor)
            self.assertIn("max_work_factor", str(cm.exception))
        r = camopt.run(helpers.small_lcr_ii(), max_work_factor=2.0)
        self.assertEqual(r["status"], "limits_met")

    def test_an_unknown_kind(self):
        with self.assertRaises(camopt.StudyError) as cm:
            camopt.run({"study": "no_such_kind"})
        self.assertEqual(cm.exception.path, "/study")
        self.assertIn("lcr_analysis", cm.exception.expected)


class Catalogue(unittest.TestCase):
    def test_kinds_schema_version(self):
        kinds = camopt.kinds()
        self.assertIn("lcr_analysis", kinds)
        self.assertEqual(kinds, sorted(kinds))
        for k in kinds:
            s = camopt.schema(k)
            self.assertEqual(s["properties"]["study"]["const"], k)
            hand_kept = helpers.SCHEMAS / f"{k}.schema.json"  # the others are emitted from their declaration
            if hand_kept.exists():
                self.assertEqual(s, json.loads(hand_kept.read_text()))
        with self.assertRaises(camopt.StudyError):
            camopt.schema("no_such_kind")
        self.assertRegex(camopt.__version__, r"^\d+\.\d+\.\d+$")


if __name__ == "__main__":
    unittest.main()
