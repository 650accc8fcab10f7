#!/usr/bin/env python3
"""Every program in bench/ answers --help (exit 0, its usage on stdout, nothing
written) and refuses an option it does not know with an error (exit 2; the first
rule broken is named, which may be a missing required option), and runs no
benchmark for either.

Usage: bench_cli_test.py BENCH_BINARY_DIR BENCH_SOURCE_DIR"""
import os
import subprocess
import sys
import tempfile

PROGRAMS = ["bench_work_precision", "bench_heavy_top", "bench_report", "bench_figure_context",
            "bench_startup_bare", "bench_startup_cairo", "bench_startup_ffmpeg"]
# progress.py is a module the scripts import, not a program
SCRIPTS = ["explore_bench.py", "figures_bench.py", "figures_matplotlib.py", "python_bench.py",
           "scipy_heavy_top.py", "scipy_work_precision.py"]


def main():
    binary_dir, source_dir = sys.argv[1], sys.argv[2]
    commands = [[os.path.join(binary_dir, p)] for p in PROGRAMS
                if os.path.exists(os.path.join(binary_dir, p))]
    commands += [[sys.executable, os.path.join(source_dir, s)] for s in SCRIPTS]
    failures = 0
    for command in commands:
        name = os.path.basename(command[-1])
        with tempfile.TemporaryDirectory() as cwd:
            for arg, status in (("--help", 0), ("--no-such-option", 2)):
                run = subprocess.run(command + [arg], cwd=cwd, capture_output=True, text=True)
                problems = []
                if run.returncode != status:
                    problems.append(f"exit {run.returncode}, not {status}")
                if arg == "--help" and "usage" not in run.stdout.lower():
                    problems.append("no usage on stdout")
                if arg != "--help" and "error" not in run.stderr:
                    problems.append(f"no error line: {run.stderr!r}")
                if os.listdir(cwd):
                    problems.append(f"wrote {os.listdir(cwd)}")
                print(f"{name} {arg}: {'; '.join(problems) or 'ok'}")
                failures += bool(problems)
    print(f"{len(commands)} programs, {failures} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
