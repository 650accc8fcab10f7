"""The adversary's classes for a lab's outputs (fuzz_lab.py runs them):
  same file   two outputs that name one file, or a folder inside a file, by any of
              many spellings (".", "..", through a folder not there yet, a trailing
              separator, a link to the folder, absolute or relative): refused with
              exit 2 before any work, nothing made; and two outputs that are different
              files, whatever their spellings, land both (exit 0) and make no folder
              the spelling only passed through (a --csv whose folder is named through
              one not there is refused: the system could not open it);
  size limit  --csv and --figures under a random file-size limit (ulimit -f): every
              output lands (exit 0), or a failed write exits 1 in one line and
              nothing lands; never death by SIGXFSZ, never a temporary left.
"""
import math
import os
import resource

import fuzz_lab


def tree(workdir):
    """Every path under workdir, links not followed: what a run must leave as it was."""
    found = set()
    for root, dirs, files in os.walk(workdir):
        for name in dirs + files:
            found.add(os.path.relpath(os.path.join(root, name), workdir))
    return found


def folder_spelling(rng, workdir):
    """One of many names of the folder `d` (made by the caller, with `d/sub` and the link
    `l` to it)."""
    spelling = rng.choice(["d", "d/", "./d", "d/.", "d//", "d/sub/..", "d/not-there/..",
                           "d/not-there/../", "l", "l/", "l/sub/..", "d/sub/../."])
    return os.path.join(workdir, spelling) if rng.random() < 0.5 else spelling


def same_file_case(fuzz, workdir):
    """(argv, what is expected: "one place", "refused" or "apart") for one case."""
    rng, lab = fuzz.rng, fuzz.lab_name
    one, two = folder_spelling(rng, workdir), folder_spelling(rng, workdir)
    kinds = ([("figure", "--csv")] if fuzz.has_csv and fuzz.has_figures else []) + \
        ([("inside", "--figures")] if fuzz.has_csv and fuzz.has_figures else []) + \
        ([("film", "--animate")] if fuzz.has_csv and fuzz.has_animate else []) + \
        ([("apart", None)] if fuzz.has_csv and fuzz.has_figures else [])
    if not kinds:
        return None, None
    kind, _ = rng.choice(kinds)
    argv = [fuzz.lab, "--json"]
    if kind == "figure":  # the CSV named as one of the figures (LAB_*.png in the folder)
        argv += ["--figures", one, "--csv", f"{two}/{lab}_{rng.choice(['omega', 'x', 'a_b'])}.png"]
    elif kind == "inside":  # the figures' folder inside the CSV's file
        argv += ["--csv", f"{one}/out.csv", "--figures", f"{two}/out.csv/F"]
    elif kind == "film":  # the CSV and the film one file
        argv += ["--csv", f"{one}/same.webp", "--animate", f"{two}/same.webp", "--duration",
                 "0.2", "--fps", "5", "--animation-size", "320x240"]
    else:  # different files, each spelled its own way: both land
        argv += ["--figures", one, "--csv", f"{two}/run.csv", "--figure-size", "800x600"]
        # but a file's folder must be there, as the system opens it: "not-there/.." is not
        return argv, "refused" if "not-there" in two else "apart"
    return argv, "one place"


def same_file(fuzz, cases):
    for _ in range(cases if fuzz.has_csv else 0):
        workdir = fuzz_lab.tempfile.mkdtemp()
        try:
            os.makedirs(os.path.join(workdir, "d", "sub"))
            os.symlink("d", os.path.join(workdir, "l"))
            argv, expected = same_file_case(fuzz, workdir)
            if argv is None:
                continue
            before = tree(workdir)
            result = fuzz.attempt("same file", argv, workdir)
            if not result:
                continue
            proc, problems = result
            after = tree(workdir)
            if expected != "apart":
                if proc.returncode != 2:
                    problems.append(f"{expected}, yet exit {proc.returncode}")
                if after != before:
                    problems.append(f"refused, yet changed {sorted(after ^ before)[:5]}")
            else:
                made = after - before
                if proc.returncode != 0:
                    problems.append(f"two files refused: {proc.stderr[:200]!r}")
                elif "d/run.csv" not in made or not any(m.endswith(".png") for m in made):
                    problems.append(f"exit 0 but landed {sorted(made)[:5]}")
                if "d/not-there" in after:
                    problems.append("made the folder a spelling only passed through")
            fuzz.report("same file", argv, problems)
        finally:
            fuzz_lab.shutil.rmtree(workdir, ignore_errors=True)


def size_limit(fuzz, cases):
    for _ in range(cases if fuzz.writes else 0):
        with fuzz_lab.tempfile.TemporaryDirectory() as workdir:
            # from 1 KiB (a CSV's header) to 8 MiB (more than any default figure)
            limit = int(math.exp(fuzz.rng.uniform(math.log(1024), math.log(8 << 20))))
            csv, figures = os.path.join(workdir, "out.csv"), os.path.join(workdir, "figs")
            argv = [fuzz.lab, "--json"] + fuzz_lab.output_argv(fuzz.has_csv, fuzz.has_figures,
                                                               csv, figures)
            result = fuzz.attempt("size limit", argv, workdir, allow_write_failure=True,
                                  limits=[(resource.RLIMIT_FSIZE, limit)])
            if not result:
                continue
            proc, problems = result
            landed = fuzz_lab.outputs_landed(csv, figures)
            if proc.returncode == 0 and not fuzz_lab.all_or_none(landed, fuzz.has_csv,
                                                                  fuzz.has_figures)[1]:
                problems.append(f"exit 0 but landed {landed}")
            if proc.returncode == 2:
                problems.append("a failed write exits 2 (bad input) instead of 1")
            if proc.returncode == 1 and os.listdir(workdir):
                problems.append(f"failed, yet left {os.listdir(workdir)}")
            fuzz.report("size limit", argv + [f"ulimit -f {limit // 1024}"], problems)
