#!/usr/bin/env python3
"""Writes a ctest directory that runs a build's chosen tests with the gtest ones batched.

ctest starts the test binary once per gtest test. Under AddressSanitizer a start costs about 0.3 s
of CPU (ASan's globals and the loader's symbol lookups, docs/performance.md "The sanitized suite's
start-up"), so a suite of 1000 small tests spends minutes starting. Here the chosen gtest tests of
one gtest suite are run by one process, at most GROUP of them (`--gtest_filter=A.x:A.y:...`, the
names listed exactly); every other test (scripts, fuzzers, corpus replays) is copied as it is,
with its properties.

A group fails when any of its tests fails (gtest's exit code; the failing tests are named in the
output ctest prints). ctest's skip expression is not copied to a group: one skipped test must not
mark the others skipped. A group's COST is its size, so that ctest starts the larger ones first; its TIMEOUT is each
test's own (600 s: a group of small tests takes a minute or two under the sanitizers).

Usage: ctest_in_groups.py BUILD_DIR OUT_DIR NUMBERS [GROUP]
  NUMBERS: the tests to keep, as ctest numbers them in BUILD_DIR ("1,5,7"; "all" for every test).
  Writes OUT_DIR/CTestTestfile.cmake; run it with `ctest --test-dir OUT_DIR`.
"""
import json
import os
import subprocess
import sys


def quoted(value):
    """A CMake quoted argument."""
    text = str(value)
    for a, b in (("\\", "\\\\"), ('"', '\\"'), ("$", "\\$")):
        text = text.replace(a, b)
    return '"' + text + '"'


def property_value(value):
    if isinstance(value, list):
        return quoted(";".join(str(v) for v in value))
    if isinstance(value, bool):
        return quoted("ON" if value else "OFF")
    if isinstance(value, float) and value.is_integer():
        return quoted(int(value))
    return quoted(value)


def gtest_name(test):
    """The gtest name a ctest test runs alone, or None for a test that is not one gtest test."""
    command = test.get("command", [])
    if len(command) < 2 or not command[1].startswith("--gtest_filter="):
        return None
    name = command[1][len("--gtest_filter="):]
    if any(c in name for c in "*?:-") or "." not in name:
        return None
    return name


def main(argv):
    if len(argv) not in (4, 5):
        sys.exit(__doc__)
    build, out, numbers = argv[1], argv[2], argv[3]
    group_size = int(argv[4]) if len(argv) == 5 else 8
    listing = subprocess.run(["ctest", "--test-dir", build, "--show-only=json-v1"],
                             check=True, capture_output=True, text=True).stdout
    tests = json.loads(listing)["tests"]
    if numbers == "all":
        keep = range(1, len(tests) + 1)
    else:
        keep = [int(n) for n in numbers.split(",") if n]
    chosen = [tests[n - 1] for n in keep]

    lines = ["# Written by scripts/ctest_in_groups.py from " + build + "; do not edit."]
    groups = {}  # (binary, suite, properties but the skip expression) -> gtest names
    order = []
    for test in chosen:
        name = gtest_name(test)
        props = {p["name"]: p["value"] for p in test.get("properties", [])}
        if name is not None and "COST" not in props:
            suite = name.split(".")[0]
            kept = {k: v for k, v in props.items() if k != "SKIP_REGULAR_EXPRESSION"}
            key = (test["command"][0], tuple(test["command"][2:]), suite,
                   json.dumps(kept, sort_keys=True))
            if key not in groups:
                groups[key] = []
                order.append(key)
            groups[key].append(name)
            continue
        lines.append("add_test(" + quoted(test["name"]) + " " +
                     " ".join(quoted(a) for a in test["command"]) + ")")
        if props:
            lines.append("set_tests_properties(" + quoted(test["name"]) + " PROPERTIES " +
                         " ".join(k + " " + property_value(v) for k, v in props.items()) + ")")
    batches = 0
    for key in order:
        binary, extra, suite, props_json = key
        names = groups[key]
        props = json.loads(props_json)
        for start in range(0, len(names), group_size):
            part = names[start:start + group_size]
            batches += 1
            title = part[0] if len(part) == 1 else "%s[%d-%d of %d]" % (
                suite, start + 1, start + len(part), len(names))
            filter_arg = "--gtest_filter=" + ":".join(part)
            lines.append("add_test(" + quoted(title) + " " + quoted(binary) + " " +
                         quoted(filter_arg) + "".join(" " + quoted(a) for a in extra) + ")")
            props_here = dict(props)
            props_here["COST"] = len(part)
            lines.append("set_tests_properties(" + quoted(title) + " PROPERTIES " +
                         " ".join(k + " " + property_value(v) for k, v in props_here.items()) +
                         ")")
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, "CTestTestfile.cmake")
    with open(path + ".tmp", "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(path + ".tmp", path)
    gtests = sum(len(v) for v in groups.values())
    print("%d tests: %d gtest tests in %d processes, %d others alone" %
          (len(chosen), gtests, batches, len(chosen) - gtests))


if __name__ == "__main__":
    main(sys.argv)
