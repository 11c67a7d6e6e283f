"""Shared by the Python tests (run by ctest with PYTHONPATH=build/python, see cmake/camopt_python.cmake)."""
import copy
import json
import os
import pathlib
import tempfile

SOURCE = pathlib.Path(os.environ.get("CAMOPT_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
EXAMPLES = SOURCE / "studies" / "examples"
SCHEMAS = SOURCE / "studies" / "schema"
BINARY = os.environ.get("CAMOPT_BINARY", "")


def example(name):
    return json.loads((EXAMPLES / name).read_text())


def study_examples():
    """Every example that is a study (needle_rollers.json is a roller catalogue)."""
    out = []
    for p in sorted(EXAMPLES.glob("*.json")):
        s = json.loads(p.read_text())
        if isinstance(s, dict) and "study" in s:
            out.append(p)
    return out


def temp_dir(tag):
    base = os.environ.get("CAMOPT_TEST_TMP")
    if base:
        os.makedirs(base, exist_ok=True)
    return pathlib.Path(tempfile.mkdtemp(prefix=f"camopt-{tag}-", dir=base))


def small_lcr_ii():
    s = example("lcr_ii.json")
    s["analysis"] = {"angle_steps": 360}
    return s


def with_change(study, path, value):
    """A copy of study with the value at JSON path ("/a/b/0") replaced (value None: removed)."""
    s = copy.deepcopy(study)
    keys = [int(k) if k.isdigit() else k for k in path.strip("/").split("/")]
    node = s
    for k in keys[:-1]:
        node = node[k]
    if value is None:
        del node[keys[-1]]
    else:
        node[keys[-1]] = value
    return s
