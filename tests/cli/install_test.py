#!/usr/bin/env python3
"""The installed tree: `cmake --install BUILD --prefix P` into a fresh user's prefix
puts every file under P (the programs in P/bin, every man page in P/share/man/man1,
the completion in P/share/bash-completion/completions), installed as a user who may
write nothing else: run as root, the install runs as `nobody` (setpriv), as a student
without root would; where that cannot be (no setpriv, a build `nobody` cannot read), it
runs with DESTDIR, so a file meant for an absolute path lands apart and is found. Every
file the install manifest names must lie under P.

With --figures N, the tree then works on its own, with nothing of the build tree on
PATH: `rigidlab --version`, `rigidlab list`, a lab run through rigidlab and directly,
and `rigidlab figures --out DIR --figure-size 1920x1080`, N figures at that size.

Usage: install_test.py BUILD_DIR [--figures N] [--man-pages NAME...]
"""
import argparse
import json
import os
import pwd
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


def as_nobody(build):
    """The command prefix that runs a command as `nobody`, where this test runs as root
    and `nobody` can read the build; None otherwise."""
    setpriv = shutil.which("setpriv")
    if os.geteuid() != 0 or setpriv is None:
        return None
    try:
        user = pwd.getpwnam("nobody")
    except KeyError:
        return None
    prefix = [setpriv, f"--reuid={user.pw_uid}", f"--regid={user.pw_gid}", "--clear-groups"]
    readable = subprocess.run(prefix + ["test", "-r", os.path.join(build, "cmake_install.cmake")])
    return (prefix, user) if readable.returncode == 0 else None


def install(build, stage, failures):
    """Installs BUILD into the prefix STAGE/prefix as a user who owns only that prefix;
    returns where the prefix's files are (beside DESTDIR, if one was needed)."""
    prefix = os.path.join(stage, "prefix")
    os.mkdir(prefix)
    command = ["cmake", "--install", build, "--prefix", prefix]
    env = dict(os.environ)
    env.pop("DESTDIR", None)
    destdir = ""
    manifest = os.path.join(build, "install_manifest.txt")
    nobody = as_nobody(build)
    if nobody is not None:
        run_as, user = nobody
        # The prefix is the user's; the install's manifest, which cmake writes into the
        # build, too (the build is root's, as a student's own build would be theirs).
        os.chown(stage, user.pw_uid, user.pw_gid)
        os.chown(prefix, user.pw_uid, user.pw_gid)
        open(manifest, "a").close()
        os.chown(manifest, user.pw_uid, user.pw_gid)
        command = run_as + command
        print("install: as nobody")
    elif os.geteuid() == 0:
        destdir = os.path.join(stage, "destdir")
        env["DESTDIR"] = destdir
        print("install: as root with DESTDIR (the run as a user was skipped: no setpriv, "
              "or nobody cannot read the build)")
    done = subprocess.run(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                          text=True)
    if done.returncode != 0:
        failures.append(f"cmake --install {build} --prefix {prefix}: {done.stderr.strip()}")
        return prefix
    # The manifest names each file as installed, DESTDIR left out.
    with open(manifest) as f:
        installed = [line for line in f.read().splitlines() if line]
    if not installed:
        failures.append("the install manifest names no file")
    for path in installed:
        if not path.startswith(prefix + "/"):
            failures.append(f"installed outside the prefix {prefix}: {path}")
    root = destdir + prefix
    for folder, _, files in os.walk(destdir or prefix):
        for name in files:
            path = os.path.join(folder, name)
            if not path.startswith(root + "/"):
                failures.append(f"installed outside the prefix {prefix}: {path}")
    return root


def check_layout(root, man_pages, failures):
    """The programs, man pages and completion where a user's shell and man look."""
    for name in man_pages:
        page = os.path.join(root, "share/man/man1", name + ".1")
        if not os.path.isfile(page):
            failures.append(f"no man page {page}")
        program = os.path.join(root, "bin", name)
        if not os.access(program, os.X_OK):
            failures.append(f"no program {program}")
    if not os.path.isfile(os.path.join(root, "share/bash-completion/completions/rigidlab")):
        failures.append("no bash completion")


def run_tree(stage, expected, failures):
    """The installed tree on its own: rigidlab, a lab, every figure, bad input."""
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
    through = run("rigidlab", "tire_balancing", "--json", "--tilt-deg", "2")
    if through.returncode != 0 or json.loads(through.stdout)["inputs"]["tilt_deg"] != 2:
        failures.append(f"rigidlab tire_balancing: {through.stderr!r}")
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


def import_installed(root, package_dir, failures):
    """import rigidlab from the installed tree alone: a lab computed, its figure saved."""
    site = os.path.join(root, package_dir)
    code = (
        "import os, sys, rigidlab as rl\n"
        "assert rl.__file__.startswith(sys.argv[1]), rl.__file__\n"
        "r = rl.tennis_racquet(perturbation=0.01)\n"
        "assert ' flips: ' in r.answer, r.answer\n"
        "if rl._rigidlab.has_renderer:\n"
        "    path = r.figures['flip'].save(os.path.join(sys.argv[2], 'flip.png'), size=(800, 600))\n"
        "    assert open(path, 'rb').read(8) == b'\\x89PNG\\r\\n\\x1a\\n'\n"
        "print(rl.labs())\n")
    env = {"PATH": "/usr/bin:/bin", "HOME": root, "PYTHONPATH": site,
           "PYTHONDONTWRITEBYTECODE": "1"}
    done = subprocess.run([sys.executable, "-c", code, site, root], capture_output=True,
                          text=True, env=env, cwd=root)
    if done.returncode != 0 or "tennis_racquet" not in done.stdout:
        failures.append(f"import rigidlab from {site}: {done.stderr[-600:]!r}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build")
    parser.add_argument("--figures", type=int, help="run the tree and expect N figures")
    parser.add_argument("--python", metavar="DIR",
                        help="import rigidlab from DIR under the prefix (lib/python3/...)")
    parser.add_argument("--man-pages", nargs="*", default=[],
                        help="the programs whose man pages the tree must hold")
    args = parser.parse_args()
    build = args.build
    stage = tempfile.mkdtemp(prefix="rigid_install_")
    failures = []
    try:
        root = install(build, stage, failures)
        check_layout(root, args.man_pages, failures)
        if args.python and not failures:
            import_installed(root, args.python, failures)
        if args.figures is not None and not failures:
            run_tree(root, args.figures, failures)
    finally:
        shutil.rmtree(stage, ignore_errors=True)
    for f in failures:
        print("FAIL", f)
    print(f"install: {len(failures)} failures")
    return 1 if failures else 0

if __name__ == "__main__":
    sys.exit(main())
