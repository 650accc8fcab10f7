#!/usr/bin/python3
"""A deterministic random-input driver for one lab.

Reads the lab's options from its --help (so a new lab is covered without new
code), then runs it many times with random values for one to three of them:
numbers across the whole double range and beyond it, NaN and infinities,
malformed numbers, strings with control characters, vectors of the wrong
length, option combinations, and --csv paths. Every run must keep the lab
contract:
  - exit 0 with strict JSON on stdout (no NaN, no Infinity), or exit 2 with one
    line on stderr of the form "LAB: error: --option: rule", without raw
    control characters;
  - finish within the time limit;
  - leave no temporary file behind.
Usage: fuzz_lab.py LAB_EXECUTABLE [--cases N] [--seed S] [--timeout SECONDS]
Exit status 0 when every case keeps the contract, 1 otherwise.
"""
import argparse
import json
import os
import random
import re
import subprocess
import sys
import tempfile
import time

OPTION = re.compile(r"^\s+(?:-\w,)?(--[\w-]+)(?:\s+(\S+?))?(?:=(\S+))?(?:\s+x\s+(\d))?\s{2,}(.*)$")


def options_of(lab):
    """(name, kind, count, choices, defaults) for every option in --help."""
    text = subprocess.run([lab, "--help"], capture_output=True, text=True, timeout=30).stdout
    found = []
    for line in text.splitlines():
        m = OPTION.match(line)
        if not m:
            continue
        name, kind, default, count, rest = (m.group(1), m.group(2) or "", m.group(3), m.group(4),
                                            m.group(5))
        if name in ("--help", "--version", "--figures", "--figure-size", "--figure-prefix", "--timing",
                    "--animate"):
            continue  # drawing is covered by the figure and animation tests; here only the contract
        if kind.startswith("NUMBER") or kind.startswith("WORD") or kind.startswith("FILE"):
            kind = kind.split("=")[0]
        choices = []
        c = re.search(r"\(([\w|.-]+)\)\s*$", rest)
        if kind.startswith("WORD") and c:
            choices = c.group(1).split("|")
        defaults = []
        for part in (default or "").split(","):
            try:
                defaults.append(float(part))
            except ValueError:
                pass
        found.append((name, kind, int(count) if count else 1, choices, defaults))
    return found


def number(rng, default=None):
    """A number as a user might type it, or mistype it: near the default (so most
    runs compute), across the whole double range, or malformed."""
    pick = rng.random()
    if pick < 0.4 and default:  # the default scaled by up to 1e3 either way
        return repr(default * 10.0 ** rng.uniform(-3, 3))
    if pick < 0.6:  # across the whole double range, both signs
        exp = rng.uniform(-330, 330)
        value = rng.choice([1, -1]) * 10.0 ** exp if abs(exp) < 308 else rng.choice(["1e400", "1e-400", "-1e400"])
        return value if isinstance(value, str) else repr(value)
    if pick < 0.75:  # ordinary values
        return repr(rng.choice([1, -1, 0.5, 2]) * rng.uniform(0.01, 100))
    return rng.choice([
        "0", "-0", "1", "-1", "nan", "NaN", "-nan", "inf", "-inf", "infinity", "1e", "abc", "",
        "0x10", "1,2", "1e-60", "1e60", "1e-61", "1e61", "4.9e-324", "1.7976931348623157e308",
        "1\n2", "2\x1b[31m", "--json", " 3", "3 ", "1e+308", "-1e-308", "1" * 400,
    ])


def value_for(rng, kind, count, choices, defaults):
    if kind == "FILE":
        return None  # --csv is handled by the caller
    if choices:
        return rng.choice(choices) if rng.random() < 0.85 else rng.choice(["", "RK4", "x\ny", "exact,rk4"])
    if count > 1 or "," in kind:
        n = count if rng.random() < 0.85 else rng.choice([0, 1, 2, 4])
        return ",".join(number(rng, defaults[i] if i < len(defaults) else None)
                        for i in range(max(n, 1))) if n else ""
    if kind == "":
        return ""  # a flag
    return number(rng, defaults[0] if defaults else None)


def check(lab_name, proc, elapsed, limit, workdir):
    """The contract's breaches for one run, as strings."""
    problems = []
    if elapsed > limit:
        problems.append(f"took {elapsed:.1f} s")
    if proc.returncode == 0:
        def reject(token):
            raise ValueError(f"non-strict JSON constant {token}")
        try:
            out = json.loads(proc.stdout, parse_constant=reject)
            if not isinstance(out.get("results"), dict):
                problems.append("JSON without results")
        except ValueError as e:
            problems.append(f"stdout is not strict JSON: {e}")
    elif proc.returncode == 2:
        err = proc.stderr
        if err.count("\n") != 1 or not err.endswith("\n"):
            problems.append(f"not one error line: {err!r}")
        elif not err.startswith(f"{lab_name}: error: --"):
            problems.append(f"error line names no option: {err!r}")
        elif any(ord(ch) < 32 for ch in err[:-1]):
            problems.append(f"raw control character in: {err!r}")
        if proc.stdout:
            problems.append("printed to stdout as well as refusing")
    else:
        problems.append(f"exit status {proc.returncode}: {proc.stderr[-300:]!r}")
    for name in os.listdir(workdir):
        if ".tmp" in name:
            problems.append(f"left {name} behind")
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("lab")
    ap.add_argument("--cases", type=int, default=60)
    ap.add_argument("--seed", type=int, default=20261124)
    ap.add_argument("--timeout", type=float, default=10.0)
    args = ap.parse_args()
    args.lab = os.path.abspath(args.lab)
    lab_name = os.path.basename(args.lab)
    rng = random.Random(f"{args.seed}:{lab_name}")
    options = options_of(args.lab)
    physical = [o for o in options if o[0] not in ("--json", "--quiet", "--csv")]
    start = time.monotonic()
    failures = 0
    computed = 0  # runs that exited 0 (the rest refused their input)
    for case in range(args.cases):
        with tempfile.TemporaryDirectory() as workdir:
            argv = [args.lab, "--json"]
            for name, kind, count, choices, defaults in rng.sample(
                    physical, min(len(physical), rng.randint(1, 3))):
                value = value_for(rng, kind, count, choices, defaults)
                argv += [name] if kind == "" else [name, value]
            if any(o[0] == "--csv" for o in options) and rng.random() < 0.3:
                target = rng.choice(["out.csv", "sub/out.csv", ".", "x" * 300 + ".csv"])
                argv += ["--csv", os.path.join(workdir, target)]
            t0 = time.monotonic()
            try:
                proc = subprocess.run(argv, capture_output=True, text=True, errors="replace",
                                      timeout=args.timeout * 3, cwd=workdir)
            except subprocess.TimeoutExpired:
                print(f"FAIL {lab_name}: hung (> {args.timeout * 3:.0f} s): {argv[1:]!r}")
                failures += 1
                continue
            problems = check(lab_name, proc, time.monotonic() - t0, args.timeout, workdir)
            computed += proc.returncode == 0
            if problems:
                failures += 1
                print(f"FAIL {lab_name}: {argv[1:]!r}: {'; '.join(problems)}")
    print(f"{lab_name}: {args.cases} cases ({computed} computed, {args.cases - computed} refused), "
          f"{failures} failures, {time.monotonic() - start:.1f} s")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
