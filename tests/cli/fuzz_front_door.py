#!/usr/bin/env python3
"""A deterministic adversary for `rigidlab figures`, the front door that runs every lab.

Classes (each case's class is in its report line, with counts at the end):
  out         any --out: empty, a file, a link to a folder, a dangling link, a FIFO,
              a device, a folder holding stage folders of other runs (a killed run's,
              one named with this run's PID), user files named like temporaries, a
              path through folders not there, a name with control bytes;
  signals     any signal that ends a process and can be caught, at a random moment;
  size limit  a random file-size limit (ulimit -f).
The contract: exit 0 with every lab's figures landed in --out; or exit 2 (bad input)
or 1 (a failed write) with one escaped line "rigidlab: error: ...", nothing landed
and nothing changed; or death by the signal sent, nothing landed. Always: no file
touched that the run did not create, no temporary or staging folder of its own
left, no lab left running, and bounded CPU time.
Usage: fuzz_front_door.py RIGIDLAB [--class-cases N] [--seed S] [--cpu-seconds S]
"""
import argparse
import os
import random
import resource
import signal
import stat
import subprocess
import sys
import tempfile
import time

import fuzz_lab

SIZE = ["--figure-size", "800x600"]  # the smallest: a case is about all 7 labs' drawing


def snapshot(workdir):
    """Every path under workdir with its kind and, for files, bytes: what must not change."""
    seen = {}
    for root, dirs, files in os.walk(workdir):
        for name in dirs + files:
            path = os.path.join(root, name)
            st = os.lstat(path)
            content = None
            if stat.S_ISREG(st.st_mode):
                with open(path, "rb") as f:
                    content = f.read()
            seen[os.path.relpath(path, workdir)] = (stat.S_IFMT(st.st_mode), content)
    return seen


def figures_in(out):
    try:
        return sorted(n for n in os.listdir(out) if n.endswith(".png"))
    except OSError:
        return []


def labs_alive(workdir):
    """Processes whose command line names workdir: a lab rigidlab left running."""
    alive = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                if workdir.encode() in f.read():
                    alive.append(pid)
        except OSError:
            pass
    return alive


class FrontDoor:
    def __init__(self, args):
        self.args, self.rigidlab = args, os.path.abspath(args.rigidlab)
        self.rng = random.Random(f"{args.seed}:rigidlab")
        self.tried, self.held = {}, {}
        self.start = time.monotonic()
        # every figure a run must land: what one undisturbed run draws
        with tempfile.TemporaryDirectory() as workdir:
            out = os.path.join(workdir, "out")
            subprocess.run([self.rigidlab, "figures", "--out", out] + SIZE, capture_output=True,
                           check=True)
            self.figures = figures_in(out)

    def report(self, cls, argv, problems):
        self.tried[cls] = self.tried.get(cls, 0) + 1
        self.held[cls] = self.held.get(cls, 0) + (not problems)
        if problems:
            print(f"FAIL rigidlab [{cls}]: {argv[1:]!r}"[:600] + f": {'; '.join(problems)}"[:600])

    def kept(self, workdir, before):
        """What any run must keep: no temporary or staging folder of its own left, nothing
        of before changed, no lab running."""
        problems = fuzz_lab.leftovers(
            workdir, {os.fsencode(os.path.join(workdir, p)) for p in before})
        after = snapshot(workdir)
        stages = [p for p in after if ".rigidlab-stage-" in p and p not in before]
        if stages:
            problems.append(f"left its staging folder {stages[:2]}")
        changed = sorted(p for p in before if after.get(p) != before[p])
        if changed:
            problems.append(f"changed or removed {changed[:3]}")
        if labs_alive(workdir):
            problems.append("a lab is still running")
        return problems, after

    def judge(self, proc, workdir, out, before, allowed):
        """The contract's breaches of a finished run; `allowed` exit statuses besides 0."""
        problems, after = self.kept(workdir, before)
        if proc.returncode == 0:
            if figures_in(out) != self.figures:
                problems.append(f"exit 0 with {len(figures_in(out))} of {len(self.figures)} "
                                "figures in --out")
        elif proc.returncode in allowed:
            last = proc.stderr.splitlines(True)[-1] if proc.stderr else b""
            problems += fuzz_lab.stderr_problems("rigidlab", last)
            made = sorted(p for p in after if p not in before)
            if made:
                problems.append(f"failed, yet made {made[:3]}")
        else:
            problems.append(f"exit status {proc.returncode}: {proc.stderr[-300:]!r}")
        return problems

    def out_case(self, workdir):
        """A hostile --out: its argv, and what it names."""
        rng, w = self.rng, workdir
        pick = rng.choice(["empty", "file", "link", "dangling", "fifo", "device", "stages",
                           "decoys", "deep", "bytes", "plain"])
        out = os.path.join(w, "out")
        if pick == "empty":
            out = ""
        elif pick == "file":
            with open(out, "w") as f:
                f.write("user data")
        elif pick == "link":
            os.makedirs(os.path.join(w, "real"))
            os.symlink("real", out)
        elif pick == "dangling":
            os.symlink("nowhere", out)
        elif pick == "fifo":
            os.mkfifo(out)
        elif pick == "device":
            out = "/dev/null"
        elif pick in ("stages", "decoys"):
            os.makedirs(out)
            # a killed run's stage, and one named as this run's own would be by PID alone
            for name in [".rigidlab-stage-1", f".rigidlab-stage-{os.getpid() + 1}",
                         ".rigidlab-stage-99999-abc123", "poinsot_omega.png.rigidlab-tmp-1-x",
                         "lamina_tensor_paddle.png.tmp-99999"]:
                if pick == "stages" and "stage" in name:
                    os.makedirs(os.path.join(out, name))
                    with open(os.path.join(out, name, "keep"), "w") as f:
                        f.write("keep")
                elif pick == "decoys" and "stage" not in name:
                    with open(os.path.join(out, name), "w") as f:
                        f.write("user data")
        elif pick == "deep":
            out = os.path.join(w, "a", "b", "..", "c")
        elif pick == "bytes":
            out = os.fsencode(w) + b"/" + fuzz_lab.random_bytes(rng, True)
        return [self.rigidlab, "figures", "--out", out] + SIZE, out, pick

    def out_class(self, cases):
        for _ in range(cases):
            with tempfile.TemporaryDirectory() as workdir:
                argv, out, pick = self.out_case(workdir)
                before = snapshot(workdir)
                try:
                    proc, cpu = fuzz_lab.run(argv, workdir, self.args.cpu_seconds)
                except subprocess.TimeoutExpired:
                    self.report("out", argv, ["hung"])
                    continue
                problems = self.judge(proc, workdir, out if isinstance(out, str) else
                                      os.fsdecode(out), before, (1, 2))
                if cpu > self.args.cpu_seconds:
                    problems.append(f"worked {cpu:.0f} CPU seconds")
                if pick in ("empty", "file", "fifo", "device", "dangling") and proc.returncode != 2:
                    problems.append(f"--out as {pick} not refused (exit {proc.returncode})")
                self.report("out", argv + [pick], problems)

    def signals(self, cases):
        for _ in range(cases):
            with tempfile.TemporaryDirectory() as workdir:
                out = os.path.join(workdir, "out")
                argv = [self.rigidlab, "figures", "--out", out] + SIZE
                sig = self.rng.choice(fuzz_lab.ENDING)
                before = snapshot(workdir)
                proc, err = fuzz_lab.signalled(argv, workdir, sig, self.rng.uniform(0.0, 2.0),
                                               20 * self.args.cpu_seconds)
                if proc is None:
                    self.report("signals", argv, ["did not end after the signal"])
                    continue
                proc.stderr = err
                name = fuzz_lab.signal_name(sig)
                if proc.returncode == -sig:  # ended by it: nothing landed, nothing made
                    problems, after = self.kept(workdir, before)
                    if sorted(after) != sorted(before):
                        problems.append(f"killed, yet made {sorted(set(after) - set(before))[:3]}")
                else:  # finished before the signal came: judged as any run
                    problems = self.judge(proc, workdir, out, before, ())
                self.report("signals", argv + [name], problems)

    def size_limit(self, cases):
        for _ in range(cases):
            with tempfile.TemporaryDirectory() as workdir:
                out = os.path.join(workdir, "out")
                limit = self.rng.choice([1, 16, 64, 256, 1024, 8192]) * 1024
                argv = [self.rigidlab, "figures", "--out", out] + SIZE
                before = snapshot(workdir)
                try:
                    proc, _ = fuzz_lab.run(argv, workdir, self.args.cpu_seconds,
                                           [(resource.RLIMIT_FSIZE, limit)])
                except subprocess.TimeoutExpired:
                    self.report("size limit", argv, ["hung"])
                    continue
                problems = self.judge(proc, workdir, out, before, (1,))
                self.report("size limit", argv + [f"ulimit -f {limit // 1024}"], problems)

    def summary(self):
        failures = sum(self.tried.values()) - sum(self.held.values())
        for cls in self.tried:
            print(f"rigidlab figures [{cls}]: {self.tried[cls]} tried, {self.held[cls]} held")
        print(f"rigidlab figures: {sum(self.tried.values())} cases ({len(self.figures)} figures "
              f"a run), {failures} failures, "
              f"{time.monotonic() - self.start:.1f} s")
        return 1 if failures else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("rigidlab")
    ap.add_argument("--class-cases", type=int, default=8)
    ap.add_argument("--seed", type=int, default=20261128)
    ap.add_argument("--cpu-seconds", type=float, default=60.0,
                    help="the CPU time a run (rigidlab and its labs) may spend")
    door = FrontDoor(ap.parse_args())
    door.out_class(door.args.class_cases)
    door.signals(door.args.class_cases)
    door.size_limit(door.args.class_cases)
    return door.summary()


if __name__ == "__main__":
    sys.exit(main())
