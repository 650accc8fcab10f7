#!/usr/bin/env python3
"""A deterministic adversary for the explorer (rigidlab-explore), case by case in
classes, with counts; run under Xvfb (a display of its own).

Classes (each case's class is in its report line):
  commands      a script of one to six random commands with random arguments: valid
                ones (the window opens and runs them), numbers out of their spans,
                malformed, NaN, huge, negative, words too many or too few;
  bytes         control bytes, invalid UTF-8 and bidi overrides in a command's words
                and in the script's own file name;
  paths         every command that writes a file, at a FIFO, a symbolic link (to a
                file, a folder, a device, nowhere), a folder, a device, a name or path
                too long, a folder it cannot write, or a fresh name;
  late paths    a path good when the script is read, turned into a FIFO, a link or a
                folder before its command comes: refused as it is written, exit 1;
  script files  --script at a folder, a FIFO, a device, a file too large, none;
  sizes         --size of any text, the window opened at the valid ones;
  resizes       the window resized (xdotool) to any size up to 65535 a side: drawn and
                screenshot at most 8192 a side;
  recording     a recording under way when the explorer is ended by a random signal
                (SIGKILL among them): its lab ends too, and nothing lands.
Every case must keep the contract:
  - exit 0; or exit 2 with one line on stderr, "rigidlab-explore: error: --OPTION: ...",
    a script's naming its file, line and command; exit 1 only for a failed write;
    never a signal, a sanitizer's report, a raw control character or bidi override,
    or invalid UTF-8 in what it prints;
  - finish within its bound of CPU seconds (RLIMIT_CPU; a busy machine does not stretch
    them as it does wall time); a run alive after twenty times that is a hang;
  - touch no file it did not create: every FIFO, link, folder, device and file it was
    given is as it was (a regular file it was asked to write may be replaced), nothing
    comes but the files its commands name, and no temporary is left.
Usage: fuzz_explorer.py EXPLORER LAB_DIR [--scale K] [--seed S] [--cpu-seconds S]
Exit status 0 when every case keeps the contract, 1 otherwise.
"""
import argparse
import os
import random
import shutil
import signal
import stat
import subprocess
import sys
import tempfile
import time
import unicodedata

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
from fuzz_lab import (BIDI, children_cpu, cpu_bound, leftovers, no_core_dump,  # noqa: E402
                      number, options_of, random_bytes, value_for)

LABS = ["lamina_tensor", "tire_balancing", "poinsot", "tennis_racquet", "football",
        "euler_angles", "top_nutation"]
MOVING = ["poinsot", "euler_angles", "top_nutation", "tennis_racquet", "football"]
COMMANDS = ["set", "drag", "unset", "textbook", "lab", "play", "pause", "seek", "speed", "turn",
            "zoom", "reset-view", "show-scene", "show-plot", "hide", "show", "frames", "wait",
            "wait-for", "screenshot", "save-figure", "save-view", "export-json", "export-csv",
            "record", "print-command", "print-json", "quit"]
WRITERS = ["screenshot", "save-figure", "save-view", "export-json", "export-csv", "record"]
# what a script's error line may begin with after "FILE:LINE: "
SCRIPT_RULES = tuple(COMMANDS) + ("turn's", "unknown command", "a quote")


def quoted(word):
    """A script's word: in double quotes where it holds a blank."""
    return b'"' + word + b'"' if (b" " in word or b"\t" in word or not word) else word


class Case:
    """One run's workdir: its decoys (what must stay as it was) and the outputs named."""

    def __init__(self, base):
        self.dir = tempfile.mkdtemp(dir=base)
        d = os.fsencode(self.dir)
        self.fifo, self.link, self.dangling = d + b"/fifo.json", d + b"/link.csv", d + b"/gone.png"
        self.folder, self.target, self.device = d + b"/folder.png", d + b"/target.txt", b"/dev/null"
        os.mkfifo(self.fifo)
        with open(self.target, "wb") as f:
            f.write(b"user data")
        os.symlink(self.target, self.link)
        os.symlink(d + b"/nowhere", self.dangling)
        os.mkdir(self.folder)
        os.symlink(self.folder, d + b"/dirlink.png")
        if os.geteuid() == 0:  # a device of its own, so that a slip replaces only it
            os.mknod(d + b"/null.json", 0o600 | stat.S_IFCHR, os.makedev(1, 3))
            self.device = d + b"/null.json"
        os.symlink(self.device, d + b"/devlink.json")
        self.before = self.snapshot()
        self.outputs = set()

    def snapshot(self):
        seen = {}
        for name in os.listdir(os.fsencode(self.dir)):
            path = os.path.join(os.fsencode(self.dir), name)
            st = os.lstat(path)
            if stat.S_ISLNK(st.st_mode):
                seen[name] = ("link", os.readlink(path))
            elif stat.S_ISREG(st.st_mode):
                with open(path, "rb") as f:
                    seen[name] = ("file", f.read())
            elif stat.S_ISDIR(st.st_mode):
                seen[name] = ("dir", tuple(sorted(os.listdir(path))))
            else:
                seen[name] = ("other", stat.S_IFMT(st.st_mode), st.st_rdev)
        return seen

    def bad_path(self, rng):
        """A path an output must not be written to, or a fresh one (as bytes)."""
        d = os.fsencode(self.dir)
        if rng.random() < 0.25:
            return self.fresh(rng)
        return rng.choice([
            self.fifo, self.link, self.dangling, self.folder, self.device, d + b"/dirlink.png",
            d + b"/devlink.json", b"/dev/null", b"/dev/full", b"/proc/x.png",
            d + b"/" + b"n" * 256 + b".png", d + b"/" + b"/".join([b"d" * 200] * 21) + b".png",
            d + b"/missing/x.png", b"fifo.json", b"link.csv", b"folder.png", b""])

    def fresh(self, rng, ext=None):
        ext = ext or rng.choice([b".png", b".json", b".csv", b".svg", b".pdf", b".webp", b""])
        name = b"out-%d%s" % (rng.randint(0, 99), ext)
        return name

    def problems(self):
        """Decoys changed, files not asked for, temporaries left."""
        found = leftovers(self.dir)
        after = self.snapshot()
        for name, was in self.before.items():
            now = after.get(name)
            asked = name in self.outputs
            if now != was and not (asked and was[0] == "file" and now and now[0] == "file"):
                found.append(f"touched {name!r}: {was[0]} became {now[0] if now else 'nothing'}")
        for name in set(after) - set(self.before):
            if name not in self.outputs:
                found.append(f"made {name!r}, not asked for")
        for dev in (b"/dev/null", b"/dev/full"):
            if not stat.S_ISCHR(os.lstat(dev).st_mode):
                found.append(f"{dev!r} is no longer a device")
        return found

    def name_written(self, op, path):
        """Records what `op` writes given `path`: export-csv the CSV and, beside it, its
        metadata, as --csv writes them."""
        self.name_output(path)
        if op == "export-csv" and path:
            self.name_output(path + b"-metadata.json")

    def name_output(self, path):
        """Records that a script names `path` as an output (its name, if in the workdir)."""
        if path and b"/" not in path:
            self.outputs.add(path)
        elif path.startswith(os.fsencode(self.dir) + b"/") and path.count(b"/") == \
                os.fsencode(self.dir).count(b"/") + 1:
            self.outputs.add(os.path.basename(path))


def text_problems(data, where):
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        return [f"invalid UTF-8 on {where}: {data[:200]!r}"]
    if any((unicodedata.category(ch) == "Cc" and ch not in "\n\t") or ch in BIDI for ch in text):
        return [f"raw control character on {where}: {text[:300]!r}"]
    for mark in ("Sanitizer", "runtime error:", "Segmentation"):
        if mark in text:
            return [f"{mark} on {where}: {text[-600:]!r}"]
    return []


def error_line_problems(err, status):
    """The one line of a refusal (2) or a failed write (1)."""
    text = err.decode("utf-8", "replace")
    if text.count("\n") != 1 or not text.endswith("\n"):
        return [f"exit {status} without one line on stderr: {text[-400:]!r}"]
    if not text.startswith("rigidlab-explore: error: --"):
        return [f"exit {status} with a line naming no option: {text[:300]!r}"]
    if text.startswith("rigidlab-explore: error: --script: "):
        rest = text[len("rigidlab-explore: error: --script: "):]
        if "cannot be read" not in rest and rest != "needs a file name\n" and not any(
                part.startswith(SCRIPT_RULES) for part in rest.split(": ")[1:]):
            return [f"a script's line naming no command: {text[:300]!r}"]
    return []


def verdict(proc, cpu, limit, write_may_fail=False):
    if proc.returncode < 0:
        return [f"ended by signal {-proc.returncode}: {proc.stderr[-400:]!r}"]
    if cpu > limit:
        return [f"worked {cpu:.1f} CPU seconds, beyond the bound of {limit:.0f}"]
    problems = text_problems(proc.stdout, "stdout") + text_problems(proc.stderr, "stderr")
    if proc.returncode == 2 or (proc.returncode == 1 and write_may_fail):
        problems += error_line_problems(proc.stderr, proc.returncode)
    elif proc.returncode != 0:
        problems.append(f"exit status {proc.returncode}: {proc.stderr[-300:]!r}")
    return problems


class Fuzz:
    """The explorer under attack: the seeded random sequence every class draws from in
    turn, and the cases tried and held, per class."""

    def __init__(self, args, base):
        self.args, self.base = args, base
        self.rng = random.Random(f"{args.seed}:explorer")
        self.inputs = {lab: [o for o in options_of(os.path.join(args.lab_dir, lab))
                             if o[0] not in ("--json", "--quiet", "--csv")] for lab in LABS}
        self.tried, self.held, self.exits = {}, {}, {}
        self.status = None  # the last run's exit status

    def report(self, cls, what, problems):
        self.tried[cls] = self.tried.get(cls, 0) + 1
        self.held[cls] = self.held.get(cls, 0) + (not problems)
        exits = self.exits.setdefault(cls, {})
        exits[self.status] = exits.get(self.status, 0) + 1
        self.status = None
        if problems:
            print(f"FAIL [{cls}]: {what!r}"[:700] + f": {'; '.join(problems)}"[:700], flush=True)

    def run(self, argv, case, script=None, write_may_fail=False, status=None):
        """One run in the case's folder (its script written there first); its problems
        (among them an exit status other than `status`, where one is expected)."""
        if script is not None:
            with open(os.path.join(case.dir, "session.txt"), "wb") as f:
                f.write(script)
            argv = argv + ["--script", "session.txt"]
            case.before = case.snapshot()
        limit = self.args.cpu_seconds
        before = children_cpu()
        try:
            proc = subprocess.run([self.args.explorer] + argv, capture_output=True, cwd=case.dir,
                                  timeout=20 * limit, preexec_fn=cpu_bound(limit))
        except subprocess.TimeoutExpired:
            return [f"hung (alive after {20 * limit:.0f} s on the clock)"]
        self.status = proc.returncode
        problems = verdict(proc, children_cpu() - before, limit, write_may_fail)
        if status is not None and proc.returncode != status:
            problems.append(f"exit {proc.returncode}, not {status}: {proc.stderr[-300:]!r}")
        return problems + case.problems()

    # ---- a command's words
    def number_word(self, valid, lo, hi):
        if valid:
            return repr(round(self.rng.uniform(lo, hi), 3)).encode()
        word = number(self.rng)
        # A "wrong" number may still be a right one: within the command's own span, past
        # the quick one a valid case keeps to. Then it is the script's own work (play 60 s
        # is 3600 frames, more than a case's CPU bound), which the bounds' tests measure,
        # not this class: it is drawn again, within the quick span.
        try:
            if hi < float(word) <= 1e6:
                return repr(round(self.rng.uniform(lo, hi), 3)).encode()
        except ValueError:
            pass
        return word.encode("utf-8", "surrogateescape")

    def input_words(self, lab, valid):
        name, kind, count, choices, defaults = self.rng.choice(self.inputs[lab])
        value = value_for(self.rng, kind, count, choices, defaults) or ""
        if not valid and self.rng.random() < 0.3:
            return [name.encode(), quoted(random_bytes(self.rng))]
        return [name.encode(), quoted(value.encode("utf-8", "surrogateescape"))]

    def words(self, op, lab, valid, case):
        """The words after `op`: valid ones (bounded to stay quick) or any."""
        r, n = self.rng, self.number_word
        spans = {"play": (0, 0.3), "seek": (0, 5), "speed": (0.5, 10), "zoom": (0.2, 5),
                 "frames": (0, 4), "wait": (0, 0.05)}
        if op in spans:
            return [n(valid, *spans[op])]
        if op == "turn":
            return [n(valid, -90, 90), n(valid, -90, 90)]
        if op in ("set", "drag"):
            return self.input_words(lab, valid)
        if op == "unset":
            return self.input_words(lab, valid)[:1]
        if op == "lab":
            return [r.choice(LABS).encode() if valid or r.random() < 0.5 else quoted(random_bytes(r))]
        if op in ("show-scene", "show-plot", "hide", "show"):
            return [quoted(r.choice([b"motion", b"strip", b"nope", random_bytes(r)]))]
        if op == "wait-for":
            return [b"session.txt"]
        if op in WRITERS:
            return self.writer_words(op, valid, case)
        return []

    def writer_words(self, op, valid, case):
        r = self.rng
        ext = {"screenshot": b".png", "save-view": b".png", "export-json": b".json",
               "export-csv": b".csv", "record": b".webp"}.get(op)
        path = case.fresh(r, ext) if valid else case.bad_path(r)
        case.name_written(op, path)
        words = [quoted(path)]
        if op == "save-figure":
            words.insert(0, r.choice([b"omega", b"energy", b"nope"]))
        if op in ("save-figure", "save-view") and r.random() < 0.5:
            size = b"%dx%d" % (r.randint(16, 300), r.randint(16, 300)) if valid else \
                r.choice([b"0x0", b"9000x16", b"16x16", b"abc", b"-5x5", b"1e9x1e9", b"16x"])
            words.append(size)
        return words

    def script(self, lab, valid, case, count):
        lines = []
        ops = [o for o in COMMANDS if o not in ("record", "quit")] if valid else COMMANDS
        for _ in range(count):
            op = self.rng.choice(ops)
            words = self.words(op, lab, valid, case)
            if not valid and self.rng.random() < 0.1:
                words = words[:-1] if words and self.rng.random() < 0.5 else words + [b"extra"]
            lines.append(b" ".join([op.encode()] + words))
        return b"\n".join(lines) + b"\n"

    # ---- the classes
    def commands(self, cases):
        for _ in range(cases):
            case = Case(self.base)
            lab = self.rng.choice(LABS)
            valid = self.rng.random() < 0.4
            script = self.script(lab, valid, case, self.rng.randint(1, 6))
            self.report("commands", script, self.run([lab], case, script))
            shutil.rmtree(case.dir, ignore_errors=True)

    def byte_words(self, cases):
        for _ in range(cases):
            case = Case(self.base)
            r = self.rng
            words = [random_bytes(r) for _ in range(r.randint(1, 3))]
            # a `wait-for` a file that never comes is a valid wait of the script's whole
            # bound (600 s): not an attack this class can afford
            op = r.choice([c for c in COMMANDS if c != "wait-for"])
            for w in words:
                case.name_written(op, w)
            line = b" ".join([op.encode()] + [quoted(w) for w in words])
            name = random_bytes(r, for_file_name=True)[:200] + b".txt"
            with open(os.path.join(os.fsencode(case.dir), name), "wb") as f:
                f.write(b"frames 1\n" + line + b"\n")
            case.before = case.snapshot()
            self.report("bytes", (name, line), self.run([r.choice(LABS), "--script", name], case))
            shutil.rmtree(case.dir, ignore_errors=True)

    def paths(self, cases):
        for _ in range(cases):
            case = Case(self.base)
            op = self.rng.choice(WRITERS)
            words = self.writer_words(op, False, case)
            if op == "record" and words[0].endswith(b".webp") and b"out-" in words[0]:
                words[0] = words[0][:-5] + b".png"  # a whole recording is the recording class's
            script = b"frames 1\n" + b" ".join([op.encode()] + words) + b"\nprint-command\n"
            lab = self.rng.choice(MOVING if op == "record" else LABS)
            self.report("paths", script, self.run([lab], case, script))
            shutil.rmtree(case.dir, ignore_errors=True)

    def background(self, argv, case, script):
        with open(os.path.join(case.dir, "session.txt"), "wb") as f:
            f.write(script)
        case.before = case.snapshot()
        return subprocess.Popen([self.args.explorer] + argv + ["--script", "session.txt"],
                                cwd=case.dir, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                preexec_fn=lambda: (cpu_bound(self.args.cpu_seconds)(),
                                                    no_core_dump()))

    def finish(self, proc, case, write_may_fail=False, status=None):
        """The problems of a run started in the background, once it ends."""
        before = children_cpu()
        try:
            out, err = proc.communicate(timeout=20 * self.args.cpu_seconds)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.communicate()
            return ["hung"]
        self.status = proc.returncode
        done = subprocess.CompletedProcess(proc.args, proc.returncode, out, err)
        problems = verdict(done, children_cpu() - before, self.args.cpu_seconds, write_may_fail)
        if status is not None and proc.returncode != status:
            problems.append(f"exit {proc.returncode}, not {status}: {err[-300:]!r}")
        return problems + case.problems()

    def late_paths(self, cases):
        for _ in range(cases):
            case, r = Case(self.base), self.rng
            op = r.choice(WRITERS)
            words = self.writer_words(op, True, case)
            if op == "save-figure":
                words[0] = b"omega"  # a figure poinsot has
            path = os.path.join(os.fsencode(case.dir), words[1 if op == "save-figure" else 0])
            script = (b"frames 1\nexport-json ready.json\nwait-for go\n" +
                      b" ".join([op.encode()] + words) + b"\nprint-command\n")
            proc = self.background(["poinsot"], case, script)
            ready = os.path.join(case.dir, "ready.json")
            while proc.poll() is None and not os.path.exists(ready):
                time.sleep(0.01)
            kind = r.choice(["fifo", "link", "folder"])
            {"fifo": lambda: os.mkfifo(path), "link": lambda: os.symlink(case.target, path),
             "folder": lambda: os.mkdir(path)}[kind]()
            case.before = case.snapshot()
            case.outputs = {b"ready.json", b"go"}
            open(os.path.join(case.dir, "go"), "wb").close()
            self.report("late paths", (script, kind), self.finish(proc, case, True, 1))
            shutil.rmtree(case.dir, ignore_errors=True)

    def script_files(self, cases):
        for _ in range(cases):
            case = Case(self.base)
            d = os.fsencode(case.dir)
            with open(d + b"/big.txt", "wb") as f:
                f.write(b"#" * (1 << 20) + b"\nframes 1\n")
            case.before = case.snapshot()
            path = self.rng.choice([case.folder, case.fifo, case.device, b"/dev/zero", b"/dev/null",
                                    d + b"/big.txt", d + b"/none.txt", case.dangling,
                                    d + b"/dirlink.png", b"/proc/self/mem", b"", b"/"])
            problems = self.run([self.rng.choice(LABS), "--script", path], case, status=2)
            self.report("script files", path, problems)
            shutil.rmtree(case.dir, ignore_errors=True)

    def size_text(self):
        r = self.rng
        if r.random() < 0.5:  # valid, one side short so that a case stays quick
            w, h = r.randint(640, 8192), r.randint(400, 900)
            return (w, h) if r.random() < 0.7 else (h if h >= 640 else 640, w)
        return r.choice([b"0x0", b"100000x100000", b"-5x5", b"639x400", b"8193x400", b"1e3x1e3",
                         b"800x", b"x600", b"800x600x2", b"", random_bytes(r),
                         number(r).encode("utf-8", "surrogateescape") + b"x600"])

    def sizes(self, cases):
        for _ in range(cases):
            case = Case(self.base)
            size = self.size_text()
            text = b"%dx%d" % size if isinstance(size, tuple) else size
            case.outputs = {b"shot.png"}
            script = b"frames 2\nscreenshot shot.png\nquit\n"
            problems = self.run([self.rng.choice(LABS), "--size", text], case, script,
                                status=0 if isinstance(size, tuple) else None)
            if isinstance(size, tuple) and not problems:
                problems = shot_problems(case, size)
            self.report("sizes", text, problems)
            shutil.rmtree(case.dir, ignore_errors=True)

    def resizes(self, cases):
        if not shutil.which("xdotool") or not os.environ.get("DISPLAY"):
            return False
        for _ in range(cases):
            case, r = Case(self.base), self.rng
            big, small = r.choice([r.randint(1, 65535), r.randint(8000, 33000)]), r.randint(1, 900)
            size = (big, small) if r.random() < 0.5 else (small, big)
            case.outputs = {b"shot.png", b"go"}
            proc = self.background(["poinsot", "--size", "800x600"], case,
                                   b"frames 2\nwait-for go\nframes 2\nscreenshot shot.png\nquit\n")
            # xdotool waits for the window (--sync); a run that ends first ends the wait
            act = subprocess.Popen(["sh", "-c", "W=$(xdotool search --sync --name 'rigidlab explore') "
                                    "&& xdotool windowsize $W %d %d; touch go" % size], cwd=case.dir)
            while act.poll() is None and proc.poll() is None:
                time.sleep(0.01)
            if act.poll() is None:
                act.kill()
            act.wait()
            problems = self.finish(proc, case, status=0)
            if not problems:  # the X server takes a side of at most 32767
                asked = size if max(size) <= 32767 else (800, 600)
                problems = shot_problems(case, tuple(min(s, 8192) for s in asked), exact=False)
            self.report("resizes", size, problems)
            shutil.rmtree(case.dir, ignore_errors=True)
        return True

    def recording(self, cases):
        for _ in range(cases):
            case, r = Case(self.base), self.rng
            proc = self.background([r.choice(["euler_angles", "poinsot", "top_nutation"])], case,
                                   b"record out.webp\nframes 1\n")
            temporary = None
            while proc.poll() is None and temporary is None:
                temporary = next((n for n in os.listdir(case.dir) if ".rigidlab-tmp-" in n), None)
                time.sleep(0.005)
            time.sleep(r.uniform(0, 0.5))
            sig = r.choice([signal.SIGKILL, signal.SIGTERM, signal.SIGHUP, signal.SIGINT,
                            signal.SIGQUIT, signal.SIGALRM])
            if proc.poll() is None:
                proc.send_signal(sig)
            proc.communicate()
            self.status = proc.returncode
            lab = int(temporary.split(".rigidlab-tmp-")[1].split("-")[0]) if temporary else None
            while lab and ended(lab) is False:
                time.sleep(0.005)
            case.outputs = {b"out.webp"} if proc.returncode == 0 else set()
            problems = case.problems()
            if proc.returncode not in (0, -sig):
                problems.append(f"exit {proc.returncode} after {sig.name}")
            self.report("recording", sig.name, problems)
            shutil.rmtree(case.dir, ignore_errors=True)

    def summary(self, resized):
        failures = sum(self.tried.values()) - sum(self.held.values())
        for cls in self.tried:
            exits = ", ".join(f"{'signal ' + str(-k) if k is not None and k < 0 else k}: {v}"
                              for k, v in sorted(self.exits[cls].items(), key=lambda kv: str(kv[0])))
            print(f"{cls}: tried {self.tried[cls]}, held {self.held[cls]} (exit {exits})")
        if not resized:
            print("resizes: not tried (no xdotool or no display)")
        print(f"explorer: {sum(self.tried.values())} cases, {failures} failures")
        return 1 if failures else 0


def ended(pid):
    """Whether process `pid` has ended (gone, or a zombie not yet reaped by its new parent)."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            text = f.read()
    except OSError:
        return True
    return text[text.rfind(")") + 2] == "Z"


def shot_problems(case, size, exact=True):
    """The screenshot's size against the window's `size` (at most it, unless exact)."""
    with open(os.path.join(case.dir, "shot.png"), "rb") as f:
        head = f.read(24)
    w, h = int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
    if (w, h) == tuple(size) or (not exact and w <= 8192 and h <= 8192):
        return []
    return [f"a screenshot of {w}x{h} for a window of {size[0]}x{size[1]}"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("explorer")
    ap.add_argument("lab_dir")
    ap.add_argument("--scale", type=float, default=1.0, help="cases per class, times")
    ap.add_argument("--seed", default="41")
    ap.add_argument("--cpu-seconds", type=float, default=20.0)
    args = ap.parse_args()
    # the cases run in folders of their own: the programs by their absolute paths
    args.explorer, args.lab_dir = os.path.abspath(args.explorer), os.path.abspath(args.lab_dir)
    counts = {"commands": 100, "bytes": 40, "paths": 60, "late paths": 8, "script files": 16,
              "sizes": 24, "resizes": 10, "recording": 6}
    n = {k: max(1, round(v * args.scale)) for k, v in counts.items()}
    with tempfile.TemporaryDirectory(prefix="fuzz-explorer-") as base:
        fuzz = Fuzz(args, base)
        fuzz.commands(n["commands"])
        fuzz.byte_words(n["bytes"])
        fuzz.paths(n["paths"])
        fuzz.late_paths(n["late paths"])
        fuzz.script_files(n["script files"])
        fuzz.sizes(n["sizes"])
        resized = fuzz.resizes(n["resizes"])
        fuzz.recording(n["recording"])
        return fuzz.summary(resized)


if __name__ == "__main__":
    sys.exit(main())
