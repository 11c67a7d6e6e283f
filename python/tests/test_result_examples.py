"""Every example's result.json validates against its kind's result schema (`camopt schema KIND
--result`, emitted from the kind's declared Result, studies/archive.h), checked by jsonschema, not
by camopt. The examples are run through the command line as a user runs them; ctest splits them
into shards (CAMOPT_EXAMPLE_SHARD="k/n": the examples whose index in sorted order is k modulo n,
cmake/camopt_python.cmake), so that no one test runs every example. Without the variable, every
example is run."""
import json
import os
import pathlib
import subprocess
import tempfile
import unittest

import jsonschema

import helpers

Validator = jsonschema.Draft202012Validator


def shard():
    spec = os.environ.get("CAMOPT_EXAMPLE_SHARD", "0/1")
    k, n = (int(x) for x in spec.split("/"))
    if not 0 <= k < n:
        raise ValueError(f"CAMOPT_EXAMPLE_SHARD={spec}: expected k/n with 0 <= k < n")
    return k, n


class ResultExamples(unittest.TestCase):
    def test_every_example_writes_a_result_its_schema_accepts(self):
        if not helpers.BINARY:
            self.skipTest("CAMOPT_BINARY not set (run through ctest)")
        k, n = shard()
        mine = [p for i, p in enumerate(helpers.study_examples()) if i % n == k]
        self.assertGreater(len(mine), 0, f"shard {k}/{n} has no example")
        schemas = {}
        with tempfile.TemporaryDirectory() as tmp:
            for path in mine:
                kind = json.loads(path.read_text())["study"]
                if kind not in schemas:
                    out = subprocess.run([helpers.BINARY, "schema", kind, "--result"], capture_output=True,
                                         text=True)
                    self.assertEqual(out.returncode, 0, f"{kind}: {out.stderr}")
                    schemas[kind] = json.loads(out.stdout)
                    Validator.check_schema(schemas[kind])
                out = pathlib.Path(tmp) / path.stem
                run = subprocess.run([helpers.BINARY, "run", "-q", str(path), "-o", str(out)],
                                     capture_output=True, text=True)
                self.assertIn(run.returncode, (0, 3), f"{path.name}: {run.stderr}")
                result = json.loads((out / "result.json").read_text())
                problems = [f"/{'/'.join(str(p) for p in e.absolute_path)}: {e.message}"
                            for e in Validator(schemas[kind]).iter_errors(result)]
                self.assertEqual(problems, [], path.name)


if __name__ == "__main__":
    unittest.main()
