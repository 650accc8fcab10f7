#!/usr/bin/env python3
"""The installed tree works on its own: `cmake --install` into a
staging prefix, then from there, with nothing of the build tree on PATH:
`rigidlab --version`, `rigidlab list`, a lab run through rigidlab and directly,
and `rigidlab figures --out DIR --figure-size 1920x1080`, every figure of every
lab at that size; the man pages and the bash completion are where they belong.

Usage: install_test.py BUILD_DIR EXPECTED_FIGURE_COUNT
"""
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n", path
    return struct.unpack(">II", head[16:24])


def main():
    build, expected = sys.argv[1], int(sys.argv[2])
    stage = tempfile.mkdtemp(prefix="rigid_install_")
    failures = []
    try:
        subprocess.run(["cmake", "--install", build, "--prefix", stage], check=True,
                       stdout=subprocess.DEVNULL)
        bin_dir = os.path.join(stage, "bin")
        env = {"PATH": bin_dir + ":/usr/bin:/bin", "HOME": stage}
        # a sanitizer build's options (its leak suppressions for the GL libraries) carried over
        env.update({k: v for k, v in os.environ.items() if k.endswith("SAN_OPTIONS")})
        run = lambda *args: subprocess.run(list(args), capture_output=True, text=True, env=env,
                                           cwd=stage)
        version = run("rigidlab", "--version")
        if version.returncode != 0 or not version.stdout.startswith("rigidlab "):
            failures.append(f"rigidlab --version: {version.stdout!r} {version.stderr!r}")
        labs = run("rigidlab", "list", "--names").stdout.split()
        listed = run("rigidlab", "list").stdout.splitlines()
        if len(labs) < 6 or len(listed) != len(labs) or any("section" not in l and "eqs." not in l
                                                             for l in listed):
            failures.append(f"rigidlab list: {listed!r}")
        for lab in labs:
            if run(lab, "--version").returncode != 0:
                failures.append(f"{lab} --version from {bin_dir} failed")
            for page in (f"share/man/man1/{lab}.1",):
                if not os.path.isfile(os.path.join(stage, page)):
                    failures.append(f"no man page {page}")
        through = run("rigidlab", "tire_balancing", "--json", "--tilt-deg", "2")
        if through.returncode != 0 or json.loads(through.stdout)["inputs"]["tilt_deg"] != 2:
            failures.append(f"rigidlab tire_balancing: {through.stderr!r}")
        if not os.path.isfile(os.path.join(stage, "share/bash-completion/completions/rigidlab")):
            failures.append("no bash completion")
        out = os.path.join(stage, "figs")
        figs = run("rigidlab", "figures", "--out", out, "--figure-size", "1920x1080")
        if figs.returncode != 0:
            failures.append(f"rigidlab figures: {figs.stderr!r}")
        pngs = sorted(f for f in os.listdir(out)) if os.path.isdir(out) else []
        if len(pngs) != expected:
            failures.append(f"{len(pngs)} figures, expected {expected}: {pngs}")
        for png in pngs:
            if png_size(os.path.join(out, png)) != (1920, 1080):
                failures.append(f"{png} is {png_size(os.path.join(out, png))}")
        # bad input: exit 2, one line naming the command and the option, nothing drawn
        bad_out = os.path.join(stage, "bad")
        for args, start in [(["nosuchlab"], "rigidlab: error: nosuchlab"),
                            (["list", "--bogus"], "rigidlab: error: list: "),
                            (["list", "extra"], "rigidlab: error: list: "),
                            (["--version", "extra"], "rigidlab: error: --version: "),
                            (["figures", "--out", bad_out, "--figure-size", "10x10"],
                             "rigidlab: error: figures: --figure-size: "),
                            (["figures", "--out", bad_out, "--figure-prefix", "a/b"],
                             "rigidlab: error: figures: --figure-prefix: "),
                            (["figures", "--out", "/proc/rigidlab-cannot"],
                             "rigidlab: error: figures: --out: "),
                            (["figures", "--out", bad_out, "--out", bad_out + "2"],
                             "rigidlab: error: figures: --out: given twice")]:
            bad = run("rigidlab", *args)
            if (bad.returncode != 2 or not bad.stderr.startswith(start)
                    or bad.stderr.count("\n") != 1 or bad.stdout):
                failures.append(f"rigidlab {' '.join(args)}: {bad.returncode} {bad.stderr!r}")
        if os.path.isdir(bad_out) and os.listdir(bad_out):
            failures.append(f"rejected figures left {os.listdir(bad_out)}")
    finally:
        shutil.rmtree(stage, ignore_errors=True)
    for f in failures:
        print("FAIL", f)
    print(f"install: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
