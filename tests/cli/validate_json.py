#!/usr/bin/env python3
"""Runs a lab and validates its --json output against a JSON Schema.

usage: validate_json.py SCHEMA LAB [ARGS...]
Exit 0 when the output is valid; otherwise one line per violation and exit 1.
"""
import json
import subprocess
import sys

import jsonschema


def main() -> int:
    schema_path, command = sys.argv[1], sys.argv[2:]
    with open(schema_path, encoding="utf-8") as f:
        schema = json.load(f)
    run = subprocess.run(command, capture_output=True, text=True, check=False)
    if run.returncode != 0:
        print(f"{' '.join(command)}: exit {run.returncode}: {run.stderr.strip()}")
        return 1
    output = json.loads(run.stdout)
    validator = jsonschema.Draft202012Validator(schema)
    errors = sorted(validator.iter_errors(output), key=lambda e: list(e.path))
    for error in errors:
        print(f"{'/'.join(map(str, error.path)) or '(root)'}: {error.message}")
    # The schema cannot tie two objects together: every result has its unit.
    missing = sorted(set(output["results"]) - set(output["units"]) -
                     {k for k, v in output["results"].items() if isinstance(v, str)})
    for key in missing:
        print(f"units: no unit for result '{key}'")
    return 1 if errors or missing else 0


if __name__ == "__main__":
    sys.exit(main())
