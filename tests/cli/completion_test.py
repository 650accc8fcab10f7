#!/usr/bin/env python3
"""The bash completion offers exactly the options each command's --help lists: a lab's
(`LAB --` and `rigidlab LAB --`), `rigidlab list --` and `rigidlab figures --`, and
`rigidlab explore LAB --` (the explorer's and the lab's), and after `rigidlab` every
command and lab. The completion reads the options from --help itself; this test reads
--help's "Options:" block its own way and asks bash, through the completion's own
functions, what it offers, so an option typed into the completion by hand, or one it
fails to read, shows as a difference.

Usage: completion_test.py COMPLETION_FILE BIN_DIR...
(the folders holding rigidlab, the labs and rigidlab-explore, put first on PATH)
"""
import os
import re
import subprocess
import sys


def help_options(env, *command):
    """The long options of COMMAND's --help, read from its "Options:" block."""
    text = subprocess.run(list(command) + ["--help"], capture_output=True, text=True,
                          env=env).stdout
    lines = text.splitlines()
    if "Options:" not in lines:
        return set()
    options = set()
    for line in lines[lines.index("Options:") + 1:]:
        if not line.strip():
            break
        match = re.match(r"\s+(?:-\w,)?(--[a-z][a-z0-9-]*)", line)
        if match:
            options.add(match.group(1))
    return options


def offered(env, completion, function, words):
    """What the completion FUNCTION offers for WORDS, the last one being completed."""
    quoted = " ".join("'" + w + "'" for w in words)
    script = (f"source '{completion}'; COMP_WORDS=({quoted}); COMP_CWORD={len(words) - 1}; "
              f"{function}; printf '%s\\n' \"${{COMPREPLY[@]}}\"")
    done = subprocess.run(["bash", "-c", script], capture_output=True, text=True, env=env)
    return set(done.stdout.split())


def main():
    completion, bin_dirs = sys.argv[1], sys.argv[2:]
    env = dict(os.environ, PATH=":".join(bin_dirs + [os.environ.get("PATH", "/usr/bin:/bin")]))
    labs = subprocess.run(["rigidlab", "list", "--names"], capture_output=True, text=True,
                          env=env, check=True).stdout.split()
    failures = []
    checked = 0

    def expect(words, function, wanted):
        nonlocal checked
        got = offered(env, completion, function, words)
        checked += 1
        if not wanted:
            failures.append(f"{' '.join(words)}: its --help lists no option")
        elif got != wanted:
            failures.append(f"{' '.join(words)}: missing {sorted(wanted - got)}, "
                            f"not in --help {sorted(got - wanted)}")

    expect(["rigidlab", ""], "_rigidlab",
           {"list", "figures", "explore", "--version", "--help"} | set(labs))
    for command in ("list", "figures"):
        expect(["rigidlab", command, "--"], "_rigidlab",
               help_options(env, "rigidlab", command))
    explorer = help_options(env, "rigidlab", "explore")
    has_explorer = bool(explorer)
    if has_explorer:
        expect(["rigidlab", "explore", ""], "_rigidlab", set(labs))
        expect(["rigidlab", "explore", "--"], "_rigidlab", explorer)
    for lab in labs:
        own = help_options(env, lab)
        expect([lab, "--"], "_rigidlab_lab", own)
        expect(["rigidlab", lab, "--"], "_rigidlab", own)
        if has_explorer:
            expect(["rigidlab", "explore", lab, "--"], "_rigidlab", explorer | own)
    for f in failures:
        print("FAIL", f)
    print(f"completion: {checked} command lines, {len(failures)} failures"
          + ("" if has_explorer else " (no explorer in this build)"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
