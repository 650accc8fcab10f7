#!/usr/bin/env python3
"""A deterministic adversary for one lab, case by case in classes, with counts.

Reads the lab's options from its --help (so a new lab is covered without new
code) and runs it many times. Classes (each case's class is in its report line):
  numbers     random values for one to three options: numbers across the whole
              double range and beyond it, NaN and infinities, malformed numbers,
              strings with control characters, vectors of the wrong length,
              combinations, --csv paths;
  bytes       random bytes (invalid UTF-8, C0 and C1 controls, bidi overrides) in
              a word option or the --csv name, under --json;
  file names  any name the filesystem accepts with room for the metadata's beside it
              (up to 241 bytes, any byte but '/' and NUL) as --csv, beside decoys a
              careless cleanup would delete;
  figures     the numbers class's inputs with --figures: every valid run draws;
  signals     any signal that ends a process and can be caught (ENDING: the
              real-time ones among them) at a random moment of a run writing --csv
              and --figures;
  full disk   --csv and --figures into a small tmpfs (where this user may mount);
  same file   two outputs that name one file by different spellings (fuzz_outputs.py);
  size limit  --csv and --figures under a random file-size limit (fuzz_outputs.py).
Every run must keep the lab contract:
  - exit 0 with strict JSON on stdout (no NaN, no Infinity, valid UTF-8), or exit 2
    with one line on stderr of the form "LAB: error: --option: rule", escaped (no raw
    control character, no invalid UTF-8, no bidi override); a failure to write
    (full disk) exits 1 with one line, never 2 (its paths are good ones); a signal
    ends the run by that signal;
  - finish within its work bound: the CPU seconds it may spend (a busy machine
    does not stretch them, as it does wall time); a run still alive after many
    times that on the clock is a hang (it waits without working);
  - leave no temporary file behind, land all its outputs or none, and touch no
    file it did not create.
Usage: fuzz_lab.py LAB_EXECUTABLE [--cases N] [--class-cases M] [--seed S] [--cpu-seconds S]
Exit status 0 when every case keeps the contract, 1 otherwise.
"""
import argparse
import json
import os
import random
import re
import resource
import subprocess
import sys
import shutil
import signal
import tempfile
import time
import unicodedata

OPTION = re.compile(r"^\s+(?:-\w,)?(--[\w-]+)(?:\s+(\S+?))?(?:=(\S+))?(?:\s+x\s+(\d))?\s{2,}(.*)$")


def options_of(lab):
    """(name, kind, count, choices, defaults) for every option in --help."""
    text = subprocess.run([lab, "--help"], capture_output=True, text=True).stdout
    found = []
    for line in text.splitlines():
        m = OPTION.match(line)
        if not m:
            continue
        name, kind, default, count, rest = (m.group(1), m.group(2) or "", m.group(3), m.group(4),
                                            m.group(5))
        if name in ("--help", "--version", "--figures", "--figure-size", "--figure-prefix", "--timing",
                    "--animate", "--explore"):
            # drawing is covered by the figure and animation tests, the window (--explore) by
            # the explorer's; here only the contract
            continue
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


# Every signal whose default ends a process and that a handler can catch; not the
# faults', not SIGXFSZ, which the labs ignore (support/signals.h).
ENDING = [signal.SIGHUP, signal.SIGINT, signal.SIGQUIT, signal.SIGTERM, signal.SIGALRM,
          signal.SIGUSR1, signal.SIGUSR2, signal.SIGPIPE, signal.SIGVTALRM, signal.SIGPROF,
          signal.SIGXCPU, signal.SIGPOLL, signal.SIGPWR, signal.SIGSTKFLT] + list(
              range(signal.SIGRTMIN, signal.SIGRTMAX + 1))



def signal_name(sig):
    """SIGHUP, or SIGRTMIN+3 for a real-time signal (which has no name of its own)."""
    if signal.SIGRTMIN < sig < signal.SIGRTMAX:
        return f"SIGRTMIN+{sig - signal.SIGRTMIN}"
    return signal.Signals(sig).name


BIDI = {chr(c) for c in list(range(0x202A, 0x202F)) + list(range(0x2066, 0x206A))}


def stderr_problems(lab_name, err_bytes, kind="error"):
    """What is wrong with a one-line message on stderr ("LAB: error: --option: ...")."""
    try:
        err = err_bytes.decode("utf-8")
    except UnicodeDecodeError:
        return [f"invalid UTF-8 on stderr: {err_bytes[:200]!r}"]
    if err.count("\n") != 1 or not err.endswith("\n"):
        return [f"not one {kind} line: {err[:300]!r}"]
    if not err.startswith(f"{lab_name}: error: "):
        return [f"not an error line: {err[:300]!r}"]
    if any(unicodedata.category(ch) == "Cc" or ch in BIDI for ch in err[:-1]):
        return [f"raw control character in: {err[:300]!r}"]
    return []


def check(lab_name, proc, cpu, limit, workdir, allow_write_failure=False, ours=()):
    """The contract's breaches for one run, as strings."""
    problems = []
    if cpu > limit or proc.returncode == -signal.SIGXCPU:
        return [f"worked {cpu:.1f} CPU seconds, beyond the bound of {limit:.0f}"]
    if proc.returncode == 0:
        def reject(token):
            raise ValueError(f"non-strict JSON constant {token}")
        try:
            out = json.loads(proc.stdout.decode("utf-8"), parse_constant=reject)
            if not isinstance(out.get("results"), dict):
                problems.append("JSON without results")
        except (ValueError, UnicodeDecodeError) as e:
            problems.append(f"stdout is not strict JSON: {e}")
    elif proc.returncode == 2 or (proc.returncode == 1 and allow_write_failure):
        problems += stderr_problems(lab_name, proc.stderr)
        if proc.returncode == 2 and not proc.stderr.startswith(f"{lab_name}: error: --".encode()):
            problems.append(f"error line names no option: {proc.stderr[:300]!r}")
        if proc.stdout:
            problems.append("printed to stdout as well as refusing")
    else:
        problems.append(f"exit status {proc.returncode}: {proc.stderr[-300:]!r}")
    problems += leftovers(workdir, ours)
    return problems


def leftovers(workdir, decoys=()):
    """Temporaries left in workdir, other than the decoys the case made itself."""
    found = []
    for root, _, files in os.walk(os.fsencode(workdir)):
        for name in files:
            path = os.path.join(root, name)
            if path in decoys:
                continue
            if b".rigidlab-tmp-" in name or b".rigidlab-probe-" in name:
                found.append(f"left {path!r} behind")
    return found


def random_bytes(rng, for_file_name=False):
    """1 to 40 bytes a user could pass: printable, controls, invalid UTF-8, C1 and bidi."""
    pieces = [
        lambda: bytes([rng.randint(0x20, 0x7e)]),
        lambda: bytes([rng.randint(0x01, 0x1f)]),
        lambda: bytes([rng.choice([0x7f, 0x80, 0x9b, 0xc3, 0xff, 0xfe])]),
        lambda: "\u202e".encode(), lambda: "\u009b".encode(), lambda: "\u00e9".encode(),
        lambda: "\U0001f600".encode(), lambda: b" ", lambda: b"-",
    ]
    out = b"".join(rng.choice(pieces)() for _ in range(rng.randint(1, 40)))
    if for_file_name:
        out = out.replace(b"/", b"_") or b"x"
        if out in (b".", b".."):
            out += b"x"
    return out


# --csv FILE writes FILE-metadata.json beside it: FILE's name leaves room for that suffix.
METADATA_SUFFIX = b"-metadata.json"


def file_name(rng):
    """Any name the filesystem takes with room for the CSV's metadata beside it: up to
    241 bytes, no '/' or NUL, not . or .."""
    pick = rng.random()
    if pick < 0.3:
        name = random_bytes(rng, True)
    elif pick < 0.5:
        name = b"n" * rng.randint(200, 237) + b".csv"
    else:
        name = rng.choice([b"-out.csv", b" lead", b"trail ", b"a\nb.csv", b"$(touch pwned)",
                           b"c.csv.tmp-99999", b"x.rigidlab-tmp-1-0123456789abcdef", b".hidden",
                           "\u00e9t\u00e9.csv".encode(), b"*?[]", b"'\"", b"\\"])
    return name[:255 - len(METADATA_SUFFIX)]


def decoys_for(workdir, target):
    """Files a careless cleanup would take for its own; their bytes, by name."""
    made = {}
    for suffix in (b".tmp-1", b".tmp-99999", b".tmp-2024-01-05-backup", b".rigidlab-tmp-x",
                   b".rigidlab-tmp-99999999-0123456789abcdeg"):
        name = target + suffix
        if len(name) > 255:
            continue
        path = os.path.join(os.fsencode(workdir), name)
        with open(path, "wb") as f:
            f.write(b"user data " + name)
        made[path] = b"user data " + name
    return made


def decoys_intact(made):
    problems = []
    for path, content in made.items():
        try:
            with open(path, "rb") as f:
                if f.read() != content:
                    problems.append(f"changed {path!r}")
        except OSError:
            problems.append(f"deleted {path!r}")
    return problems


def children_cpu():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def cpu_bound(seconds, limits=()):
    """A child's limit of CPU time: the kernel stops it with SIGXCPU just past it; and
    the other (resource, value) limits asked for."""
    limit = int(seconds) + 1

    def bound():
        resource.setrlimit(resource.RLIMIT_CPU, (limit, limit + 1))
        for which, value in limits:
            resource.setrlimit(which, (value, value))
    return bound


def run(argv, cwd, cpu_seconds, limits=()):
    """One run and the CPU seconds it spent; runs are one at a time, so the children's
    total grows by this run's alone. The clock only stops a run that has stopped
    working (a hang), at twenty times its work bound."""
    before = children_cpu()
    proc = subprocess.run(argv, capture_output=True, timeout=20 * cpu_seconds, cwd=cwd,
                          preexec_fn=cpu_bound(cpu_seconds, limits))
    return proc, children_cpu() - before


def random_argv(rng, lab, physical):
    argv = [lab, "--json"]
    for name, kind, count, choices, defaults in rng.sample(
            physical, min(len(physical), rng.randint(1, 3))):
        value = value_for(rng, kind, count, choices, defaults)
        argv += [name] if kind == "" else [name, value]
    return argv


def outputs_landed(csv, figures):
    """(csv landed, figures landed) of a run; an output not asked for counts as landed
    when the other did, so that "all or none" compares like with like."""
    pngs = os.path.isdir(figures) and any(n.endswith(".png") for n in os.listdir(figures))
    return os.path.exists(csv), pngs


def output_argv(has_csv, has_figures, csv, figures):
    return (["--csv", csv] if has_csv else []) + (["--figures", figures] if has_figures else [])


def all_or_none(landed, has_csv, has_figures):
    asked = [x for x, on in zip(landed, (has_csv, has_figures)) if on]
    return all(asked) or not any(asked), all(asked)


def signalled(argv, workdir, sig, delay, timeout):
    """(process, stderr) of a run sent `sig` after `delay` seconds, or (None, None) if it
    did not end within `timeout` after (then killed)."""
    # no core file (SIGQUIT's default) among the run's outputs
    proc = subprocess.Popen(argv, cwd=workdir, stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, preexec_fn=no_core_dump)
    time.sleep(delay)
    proc.send_signal(sig)
    try:
        _, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.communicate()
        return None, None
    return proc, err


def no_core_dump():
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))


def can_mount():
    if os.geteuid() != 0 or not shutil.which("mount"):
        return False
    with tempfile.TemporaryDirectory() as d:
        ok = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", d],
                            capture_output=True).returncode == 0
        if ok:
            subprocess.run(["umount", d], capture_output=True)
        return ok


class Fuzz:
    """One lab under attack: its options, the seeded random sequence every class draws
    from in turn (so a class's cases depend on those of the classes before it), and
    the cases tried and held, per class."""

    def __init__(self, args):
        self.args, self.lab = args, args.lab
        self.lab_name = os.path.basename(args.lab)
        self.rng = random.Random(f"{args.seed}:{self.lab_name}")
        options = options_of(args.lab)
        help_text = subprocess.run([args.lab, "--help"], capture_output=True, text=True).stdout
        self.has_csv, self.has_figures = "--csv" in help_text, "--figures" in help_text
        self.has_animate = "--animate" in help_text
        self.writes = self.has_csv or self.has_figures
        self.physical = [o for o in options if o[0] not in ("--json", "--quiet", "--csv")]
        self.words = [o for o in self.physical if o[3]]
        self.start = time.monotonic()
        self.tried, self.held = {}, {}

    def report(self, cls, argv, problems):
        self.tried[cls] = self.tried.get(cls, 0) + 1
        self.held[cls] = self.held.get(cls, 0) + (not problems)
        if problems:
            shown = [a if isinstance(a, str) else repr(a) for a in argv[1:]]
            print(f"FAIL {self.lab_name} [{cls}]: {shown!r}"[:600]
                  + f": {'; '.join(problems)}"[:600])

    def attempt(self, cls, argv, workdir, limits=(), **kw):
        """(process, problems) of a run, or None when it hung (reported here)."""
        limit = self.args.cpu_seconds
        try:
            proc, cpu = run(argv, workdir, limit, limits)
        except subprocess.TimeoutExpired:
            self.report(cls, argv, [f"hung (alive after {20 * limit:.0f} s on the clock)"])
            return None
        problems = check(self.lab_name, proc, cpu, limit, workdir, **kw)
        return proc, problems

    def numbers(self, cases):
        for _ in range(cases):
            with tempfile.TemporaryDirectory() as workdir:
                argv = random_argv(self.rng, self.lab, self.physical)
                if self.has_csv and self.rng.random() < 0.3:
                    target = self.rng.choice(["out.csv", "sub/out.csv", ".", "x" * 300 + ".csv"])
                    argv += ["--csv", os.path.join(workdir, target)]
                result = self.attempt("numbers", argv, workdir)
                if result:
                    self.report("numbers", argv, result[1])

    def byte_strings(self, cases):
        rng = self.rng
        for _ in range(cases):
            with tempfile.TemporaryDirectory() as workdir:
                argv = [os.fsencode(self.lab), b"--json"]
                if self.words and (not self.has_csv or rng.random() < 0.5):
                    argv += [os.fsencode(rng.choice(self.words)[0]), random_bytes(rng)]
                elif self.has_csv:
                    argv += [b"--csv", random_bytes(rng, True)]
                result = self.attempt("bytes", argv, workdir)
                if result:
                    self.report("bytes", argv, result[1])

    def file_names(self, cases):
        for _ in range(cases if self.has_csv else 0):
            with tempfile.TemporaryDirectory() as workdir:
                name = file_name(self.rng)
                made = decoys_for(workdir, name)
                argv = [os.fsencode(self.lab), b"--json", b"--csv", name]
                target = os.path.join(os.fsencode(workdir), name)
                result = self.attempt("file names", argv, workdir,
                                      ours=set(made) | {target, target + METADATA_SUFFIX})
                if result:
                    proc, problems = result
                    problems += decoys_intact(made)
                    if proc.returncode != 0:
                        problems.append("a name the filesystem accepts was refused")
                    elif not os.path.isfile(target):
                        problems.append("exit 0 but the file is not there")
                    elif not os.path.isfile(target + METADATA_SUFFIX):
                        problems.append("exit 0 but its metadata is not there")
                    self.report("file names", argv, problems)

    def figures(self, cases):
        for _ in range(cases if self.has_figures else 0):
            with tempfile.TemporaryDirectory() as workdir:
                figures = os.path.join(workdir, "figs")
                argv = random_argv(self.rng, self.lab, self.physical) + ["--figures", figures]
                result = self.attempt("figures", argv, workdir)
                if result:
                    proc, problems = result
                    drawn = os.path.isdir(figures) and any(n.endswith(".png")
                                                           for n in os.listdir(figures))
                    if proc.returncode == 0 and not drawn:
                        problems.append("exit 0 without its figures")
                    if proc.returncode != 0 and os.path.exists(figures):
                        problems.append("refused, yet made the figures folder")
                    self.report("figures", argv, problems)

    def signals(self, cases):
        for _ in range(cases if self.writes else 0):
            with tempfile.TemporaryDirectory() as workdir:
                self.signal_case(workdir)

    def signal_case(self, workdir):
        """A signal that ends a process, at a random moment: the run ends by it, or
        finishes, with all its outputs or none."""
        csv, figures = os.path.join(workdir, "out.csv"), os.path.join(workdir, "figs")
        argv = [self.lab, "--quiet"] + output_argv(self.has_csv, self.has_figures, csv, figures)
        sig = self.rng.choice(ENDING)
        proc, err = signalled(argv, workdir, sig, self.rng.uniform(0.0, 0.4),
                              20 * self.args.cpu_seconds)
        if proc is None:
            self.report("signals", argv, ["did not end after the signal"])
            return
        problems = leftovers(workdir)
        landed = outputs_landed(csv, figures)
        whole, every = all_or_none(landed, self.has_csv, self.has_figures)
        if proc.returncode == 0:
            if not every:
                problems.append(f"finished (exit 0) but landed {landed}")
        elif proc.returncode == -sig:
            if not whole:
                problems.append(f"killed by the signal with half its outputs: {landed}")
        else:
            problems.append(f"exit status {proc.returncode} after {signal_name(sig)}: "
                            f"{err[-200:]!r}")
        self.report("signals", argv + [signal_name(sig)], problems)

    def full_disk(self, cases):
        """--csv and --figures into a small tmpfs; whether it could be tried."""
        mountable = self.writes and can_mount()
        for _ in range(cases if mountable else 0):
            with tempfile.TemporaryDirectory() as workdir:
                size = self.rng.choice(["8k", "32k", "128k", "512k"])
                subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", workdir],
                               check=True, capture_output=True)
                try:
                    self.full_disk_case(workdir, size)
                finally:
                    subprocess.run(["umount", workdir], capture_output=True)
        return mountable

    def full_disk_case(self, workdir, size):
        csv, figures = os.path.join(workdir, "out.csv"), os.path.join(workdir, "figs")
        argv = [self.lab, "--json"] + output_argv(self.has_csv, self.has_figures, csv, figures)
        result = self.attempt("full disk", argv, workdir, allow_write_failure=True)
        if result:
            proc, problems = result
            landed = outputs_landed(csv, figures)
            if proc.returncode == 0 and not all_or_none(landed, self.has_csv, self.has_figures)[1]:
                problems.append(f"exit 0 but landed {landed}")
            if proc.returncode == 2:
                problems.append("a failed write exits 2 (bad input) instead of 1")
            if proc.returncode != 0 and os.listdir(workdir):
                problems.append(f"failed, yet left {os.listdir(workdir)}")
            self.report("full disk", argv + [size], problems)

    def summary(self, mountable):
        """The counts per class and in all; 1 when a case broke the contract."""
        tried, held = self.tried, self.held
        failures = sum(tried.values()) - sum(held.values())
        for cls in tried:
            print(f"{self.lab_name} [{cls}]: {tried[cls]} tried, {held[cls]} held")
        if self.writes and not mountable:
            print(f"{self.lab_name} [full disk]: not tried (this user cannot mount a tmpfs)")
        print(f"{self.lab_name}: {sum(tried.values())} cases, {failures} failures, "
              f"{time.monotonic() - self.start:.1f} s")
        return 1 if failures else 0


def main():
    import fuzz_outputs  # its classes use this module's
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("lab")
    ap.add_argument("--cases", type=int, default=60, help="cases of the numbers class")
    ap.add_argument("--class-cases", type=int, default=12, help="cases of each other class")
    ap.add_argument("--seed", type=int, default=20261124)
    ap.add_argument("--cpu-seconds", type=float, default=10.0,
                    help="the CPU time a run may spend")
    args = ap.parse_args()
    args.lab = os.path.abspath(args.lab)
    fuzz = Fuzz(args)
    fuzz.numbers(args.cases)
    fuzz.byte_strings(args.class_cases)
    fuzz.file_names(args.class_cases)
    fuzz.figures(args.class_cases)
    fuzz.signals(args.class_cases)
    mountable = fuzz.full_disk(args.class_cases)
    fuzz_outputs.same_file(fuzz, args.class_cases)
    fuzz_outputs.size_limit(fuzz, args.class_cases)
    return fuzz.summary(mountable)

if __name__ == "__main__":
    sys.exit(main())
