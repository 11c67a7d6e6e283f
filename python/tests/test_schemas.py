"""The JSON Schemas of the study kinds (`camopt schema KIND`: emitted from the kind's declaration,
studies/archive.h): every example validates against its
kind's schema, the files are what `camopt schema KIND` prints, and a set of bad studies is rejected
both by the schema and by camopt's own checks (the C++ parser, through the Python module)."""
import json
import pathlib
import subprocess
import tempfile
import unittest

import jsonschema

import camopt
import helpers

Validator = jsonschema.Draft202012Validator


def schema_of(kind):
    return camopt.schema(kind)


def errors(study, kind):
    return [f"/{'/'.join(str(p) for p in e.absolute_path)}: {e.message}"
            for e in Validator(schema_of(kind)).iter_errors(study)]


class Schemas(unittest.TestCase):
    def test_one_valid_schema_per_kind(self):
        kinds = camopt.kinds()
        on_disk = sorted(p.name.removesuffix(".schema.json") for p in helpers.SCHEMAS.glob("*.schema.json"))
        self.assertEqual([k for k in on_disk if k not in kinds], [], "a schema file of no kind")
        for k in kinds:
            with self.subTest(kind=k):
                Validator.check_schema(schema_of(k))

    def test_every_example_validates(self):
        failures = []
        for path in helpers.study_examples():
            study = json.loads(path.read_text())
            for e in errors(study, study["study"]):
                failures.append(f"{path.relative_to(helpers.SOURCE)}: {e}")
        # One line per field the schema does not accept, naming the file and the JSON path: a
        # field a parser learnt without its schema being updated shows up here.
        self.assertEqual(failures, [], "\n" + "\n".join(failures))

    def test_the_binary_prints_the_same_schemas(self):
        if not helpers.BINARY:
            self.skipTest("CAMOPT_BINARY not set (run through ctest)")
        for k in camopt.kinds():
            out = subprocess.run([helpers.BINARY, "schema", k], capture_output=True, text=True, check=True)
            self.assertEqual(json.loads(out.stdout), schema_of(k), k)
            hand_kept = helpers.SCHEMAS / f"{k}.schema.json"
            if hand_kept.exists():
                self.assertEqual(out.stdout, hand_kept.read_text(), k)
        bad = subprocess.run([helpers.BINARY, "schema", "no_such_kind"], capture_output=True, text=True)
        self.assertEqual(bad.returncode, 2)
        self.assertIn("expected a known study kind", bad.stderr)


# (example, JSON path changed, new value (None: removed), JSON path camopt names)
BAD_STUDIES = [
    ("lcr_ii.json", "/reducer/input/lobes", "twelve", "/reducer/input/lobes"),
    ("lcr_ii.json", "/material/poisson_ratio", 0.7, "/material/poisson_ratio"),
    ("lcr_ii.json", "/load/output_torque_Nm", None, "/load/output_torque_Nm"),
    ("lcr_ii.json", "/load/frictoin_coefficient", 0.05, "/load/frictoin_coefficient"),
    ("lcr_ii.json", "/analysis/evaluate", ["forces", "stres"], "/analysis/evaluate/1"),
    ("lcr_ii.json", "/reducer/eccentricity_mm", -2, "/reducer/eccentricity_mm"),
    ("lcr_ii.json", "/study", "lcr_analysys", "/study"),
    ("lcr_min_size.json", "/optimizer/backend", "snopt", "/optimizer/backend"),
    ("lcr_min_size.json", "/variables/eccentricity_mm", [0.5], "/variables/eccentricity_mm"),
    ("lcr_friction_fit.json", "/measurements/2", None, "/measurements"),
    ("cycloid_ltca_nnm_fcm.json", "/crowning/type", "parabolic", "/crowning/type"),
    ("cycloid_ltca_nnm_fcm.json", "/analysis/grid", [40, 40, 40], "/analysis/grid"),
    ("disc_cam_translating.json", "/follower/type", "flat_faced", "/follower/type"),
    ("disc_cam_translating.json", "/motion/0/law", "bezier", "/motion/0/law"),
    ("globoidal_cam_paper.json", "/cam/first_motion", "sideways", "/cam/first_motion"),
    ("globoidal_cam_paper.json", "/contact/cam_modulus_MPa", 206000, "/contact/cam_modulus_MPa"),
    ("globoidal_cam_paper.json", "/analysis/angle_steps", 10, "/analysis/angle_steps"),
    ("rigidity_gearbox.json", "/chain/0/element", "spring", "/chain/0/element"),
]


class LightStages(unittest.TestCase):
    def test_a_study_without_the_inputs_of_stages_it_skips_is_accepted_by_both(self):
        s = helpers.example("lcr_ii.json")
        del s["material"], s["load"], s["limits"]
        s["analysis"] = {"angle_steps": 360, "evaluate": ["profile", "undercut"]}
        self.assertEqual(errors(s, "lcr_analysis"), [])
        self.assertEqual(camopt.run(s)["study"], "lcr_analysis")
        s["analysis"]["evaluate"].append("stress")  # now the material is needed
        self.assertNotEqual(errors(s, "lcr_analysis"), [])
        with self.assertRaises(camopt.StudyError) as cm:
            camopt.run(s)
        self.assertIn(cm.exception.path, ("/material", "/load"))


class BadStudies(unittest.TestCase):
    def test_rejected_by_the_schema_and_by_camopt(self):
        self.assertGreaterEqual(len(BAD_STUDIES), 10)
        for name, path, value, named in BAD_STUDIES:
            with self.subTest(example=name, path=path, value=value):
                good = helpers.example(name)
                bad = helpers.with_change(good, path, value)
                kind = good["study"]
                self.assertEqual(errors(good, kind), [])
                self.assertNotEqual(errors(bad, kind), [], "the schema accepts it")
                with self.assertRaises(camopt.StudyError) as cm:
                    camopt.run(bad)
                self.assertEqual(cm.exception.path, named, str(cm.exception))


class ResultSchemas(unittest.TestCase):
    """`camopt schema KIND --result`: the schema of result.json, emitted from the kind's declared
    result (studies/archive.h): one per kind, the same from the binary and the module, and one that
    refuses a result with a member dropped, added or of another type. That every example's
    result.json validates against it is test_result_examples.py, in shards."""

    def test_every_kind_has_one_and_the_module_prints_the_same(self):
        if not helpers.BINARY:
            self.skipTest("CAMOPT_BINARY not set (run through ctest)")
        kinds = camopt.kinds()
        self.assertIn("transmission_rigidity", kinds)
        for k in kinds:
            out = subprocess.run([helpers.BINARY, "schema", k, "--result"], capture_output=True, text=True)
            self.assertEqual(out.returncode, 0, f"{k}: {out.stderr}")
            schema = json.loads(out.stdout)
            Validator.check_schema(schema)
            self.assertEqual(camopt.schema(k, result=True), schema, k)

    def test_a_result_missing_a_member_or_with_an_unknown_one_fails(self):
        if not helpers.BINARY:
            self.skipTest("CAMOPT_BINARY not set (run through ctest)")
        schema = camopt.schema("transmission_rigidity", result=True)
        with tempfile.TemporaryDirectory() as tmp:
            study = helpers.SOURCE / "studies" / "examples" / "rigidity_stepped_shaft.json"
            subprocess.run([helpers.BINARY, "run", "-q", str(study), "-o", tmp + "/o"], check=True, capture_output=True)
            result = json.loads(pathlib.Path(tmp, "o", "result.json").read_text())
        self.assertEqual(list(Validator(schema).iter_errors(result)), [])
        for change in ("drop", "add", "retype"):
            bad = json.loads(json.dumps(result))
            if change == "drop":
                del bad["elements"][0]["compliance_share"]
            elif change == "add":
                bad["dominant"]["colour"] = "red"
            else:
                bad["rigidity_Nm_per_rad"] = "stiff"
            with self.subTest(change=change):
                self.assertNotEqual(list(Validator(schema).iter_errors(bad)), [])


if __name__ == "__main__":
    unittest.main()
