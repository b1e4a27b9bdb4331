#!/usr/bin/env python3
"""Checks that the tests which run a suite again with other settings really get those settings,
as ctest will run them. A ';' inside a gtest_discover_tests ENVIRONMENT value splits it: the
second tcp:// engine's suites once ran on the default engine unnoticed, and the OCR node's test
without its thread limit.

    check_test_environment.py CTEST BUILD_DIR [REQUIRED_PREFIX ...]

A REQUIRED_PREFIX names tests that must exist (e.g. libzmq. on the Linux port).
"""
import json
import subprocess
import sys

# Test name prefix -> variable -> value it must have.
EXPECTED = {
    "libzmq.": {"UBII_TEST_ZMQ_ENGINE": "libzmq"},
    "OcrModulesNode": {"OMP_THREAD_LIMIT": "1"},
}


def environment_of(test):
    """The variables ctest sets for a test: ENVIRONMENT, then ENVIRONMENT_MODIFICATION's set:."""
    variables = {}
    for prop in test.get("properties", []):
        if prop["name"] == "ENVIRONMENT":
            for entry in prop["value"]:
                name, _, value = entry.partition("=")
                variables[name] = value
        elif prop["name"] == "ENVIRONMENT_MODIFICATION":
            for entry in prop["value"]:
                name, _, operation = entry.partition("=")
                if operation.startswith("set:"):
                    variables[name] = operation[len("set:"):]
    return variables


def main():
    ctest, build_dir, required = sys.argv[1], sys.argv[2], sys.argv[3:]
    listing = subprocess.run([ctest, "--test-dir", build_dir, "--show-only=json-v1"],
                             check=True, capture_output=True, text=True).stdout
    tests = json.loads(listing)["tests"]
    problems = []
    checked = 0
    for prefix in required:
        if not any(test["name"].startswith(prefix) for test in tests):
            problems.append(f"no test starts with {prefix}")
    for test in tests:
        for prefix, wanted in EXPECTED.items():
            if not test["name"].startswith(prefix):
                continue
            checked += 1
            variables = environment_of(test)
            for name, value in wanted.items():
                if variables.get(name) != value:
                    problems.append(f"{test['name']}: {name}={variables.get(name)!r}, "
                                    f"expected {value!r}")
    for problem in problems:
        print(problem)
    print(f"{checked} tests checked, {len(problems)} without their settings")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
