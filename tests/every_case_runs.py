#!/usr/bin/env python3
"""Every Catch test case of the build runs under some ctest test.

Test cases reach ctest two ways: catch_discover_tests (one ctest test a case) and
add_test by name (a list in a CMakeLists.txt, a case a line). A case written but left
out of such a list never runs, and every run is green without it. This asks ctest for
its tests, asks each Catch executable which of its cases each test selects, and names
every case no test selects (exit 1).

  every_case_runs.py BUILD_DIR [--except SPEC]

SPEC: a Catch test spec of cases this build leaves out on purpose ("[no-renderer]" in
a build with the renderer).
"""
import argparse
import json
import os
import subprocess
import sys


def names(command, extra=()):
    """The test names `command` (a Catch executable and its arguments) selects."""
    out = subprocess.run(command + list(extra) + ["--list-test-names-only"],
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                         timeout=120, check=False).stdout
    return {line.strip() for line in out.splitlines() if line.strip()}


def is_catch(path, seen={}):
    if path not in seen:
        try:
            out = subprocess.run([path, "--help"], stdout=subprocess.PIPE,
                                 stderr=subprocess.DEVNULL, text=True, timeout=60).stdout
        except (OSError, subprocess.TimeoutExpired):
            out = ""
        seen[path] = "Catch" in out
    return seen[path]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--except", dest="spec", default=None)
    args = ap.parse_args()
    listing = subprocess.run(["ctest", "--test-dir", args.build, "--show-only=json-v1"],
                             stdout=subprocess.PIPE, text=True, check=True).stdout
    selected = {}
    for test in json.loads(listing)["tests"]:
        command = test.get("command") or []
        # a test may run its executable through a wrapper (xvfb-run): the first
        # argument that is a Catch executable is the test's
        for k, word in enumerate(command):
            if os.path.isabs(word) and os.access(word, os.X_OK) and is_catch(word):
                selected.setdefault(word, set()).update(names(command[k:]))
                break
    missing = []
    for exe, chosen in sorted(selected.items()):
        left_out = names([exe], [args.spec]) if args.spec else set()
        for case in sorted(names([exe]) - chosen - left_out):
            missing.append(f"{os.path.basename(exe)}: {case}")
    for line in missing:
        print(f"never run by ctest: {line}")
    print(f"{sum(len(v) for v in selected.values())} cases in {len(selected)} executables "
          f"selected, {len(missing)} never run")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
