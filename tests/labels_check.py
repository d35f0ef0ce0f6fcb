#!/usr/bin/python3
"""Checks that every CTest test has at least one label and only labels from the documented set (CONTRIBUTING.md,
"Test"): a test without one is in no loop a contributor runs and in no group .ci/test times.

  labels_check.py CTEST BUILD_DIR LABEL...
"""
import json
import subprocess
import sys

ctest, build, allowed = sys.argv[1], sys.argv[2], set(sys.argv[3:])
listing = subprocess.run([ctest, "--test-dir", build, "--show-only=json-v1"], check=True, capture_output=True, text=True)
problems = []
tests = json.loads(listing.stdout)["tests"]
for test in tests:
    labels = next((p["value"] for p in test.get("properties", []) if p["name"] == "LABELS"), [])
    if not labels:
        problems.append("%s: no label (give it one of: %s)" % (test["name"], " ".join(sorted(allowed))))
    for label in set(labels) - allowed:
        problems.append("%s: label %r is not in tests/CMakeLists.txt's HEXC_TEST_LABELS" % (test["name"], label))
for problem in problems:
    print(problem)
print("%d tests, %d label problems" % (len(tests), len(problems)))
sys.exit(1 if problems else 0)
