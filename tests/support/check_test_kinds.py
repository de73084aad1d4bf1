#!/usr/bin/env python3
"""Fails unless every CTest test has exactly one kind label and every GoogleTest suite that runs
the cardemo executable is of kind e2e or platform (tests/support/test_kinds.cmake).

Usage: check_test_kinds.py CTEST BUILD_DIR SOURCE_DIR
"""
import json
import pathlib
import re
import subprocess
import sys

KINDS = {"unit", "property", "golden", "e2e", "platform", "stress"}


def cmake_list(text, name):
    match = re.search(r"set\(" + name + r"\s+([^)]*)\)", text)
    return set(match.group(1).split()) if match else set()


def main():
    ctest, build, source = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3])
    listing = subprocess.run([ctest, "--test-dir", build, "--show-only=json-v1"], check=True,
                             capture_output=True, text=True).stdout
    problems = []
    tests = json.loads(listing)["tests"]
    for test in tests:
        labels = set()
        for prop in test.get("properties", []):
            if prop["name"] == "LABELS":
                labels.update(prop["value"])
        kinds = labels & KINDS
        if len(kinds) != 1:
            problems.append(f"{test['name']}: kinds {sorted(kinds)} (labels {sorted(labels)})")

    rules = (source / "tests/support/test_kinds.cmake").read_text()
    runs_binary = cmake_list(rules, "cardemo_e2e_suites") | cmake_list(rules, "cardemo_platform_suites")
    for path in sorted(source.glob("tests/**/*.cpp")) + sorted(source.glob("lab/tests/**/*.cpp")):
        text = path.read_text()
        if "runCardemo(" not in text and "CARDEMO_BINARY" not in text:
            continue
        for suite in sorted(set(re.findall(r"^TEST(?:_F|_P)?\((\w+),", text, re.M))):
            if suite not in runs_binary:
                problems.append(f"{path.relative_to(source)}: suite {suite} runs cardemo but is not "
                                "listed as e2e or platform in tests/support/test_kinds.cmake")
    for problem in problems:
        print(problem)
    counts = {}
    for test in tests:
        for prop in test.get("properties", []):
            if prop["name"] == "LABELS":
                for kind in set(prop["value"]) & KINDS:
                    counts[kind] = counts.get(kind, 0) + 1
    print(", ".join(f"{kind} {counts.get(kind, 0)}" for kind in sorted(KINDS)), f"of {len(tests)} tests")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
