#!/usr/bin/env python3
"""Rewrites the field tables of docs/studies.md from the study declarations.

    scripts/update_schema_tables.py BUILD/camopt

Each table that follows a line `<!-- camopt schema KIND --table -->` (or `<!-- camopt schema KIND
--result --table -->`, the keys of its result.json) is replaced by what that command prints (the
kinds declared once, studies/archive.h), with the list of rules between fields that follows an
input table. The gtest
SchemaParserAgreement.DeclaredKindsFieldTablesInTheDocsAreTheEmittedOnes fails when a table is stale.
"""
import pathlib
import re
import subprocess
import sys

docs = pathlib.Path(__file__).resolve().parent.parent / "docs" / "studies.md"
lines = docs.read_text().split("\n")
out, i = [], 0
while i < len(lines):
    out.append(lines[i])
    m = re.fullmatch(r"<!-- camopt schema (\w+)( --result)? --table -->", lines[i])
    i += 1
    if not m:
        continue
    table = subprocess.run([sys.argv[1], "schema", m.group(1)] + (["--result"] if m.group(2) else []) + ["--table"], check=True,
                           capture_output=True, text=True).stdout.rstrip("\n").split("\n")
    while i < len(lines) and lines[i].startswith("|"):
        i += 1  # the old table
    if i + 1 < len(lines) and lines[i] == "" and lines[i + 1].startswith("Rules between fields"):
        i += 3  # and its rules between fields: a blank line, the heading line, a blank line, the items
        while i < len(lines) and lines[i].startswith("- "):
            i += 1
    out.extend(table)
docs.write_text("\n".join(out))
