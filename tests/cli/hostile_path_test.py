"""The front door runs its labs without a shell: installed under a directory whose
name a shell would act on, `rigidlab list` lists the labs and runs nothing else.

  hostile_path_test.py LAB_DIR   (the build's labs/: rigidlab and the labs beside it)
"""
import os
import shutil
import subprocess
import sys
import tempfile

labs = sys.argv[1]
with tempfile.TemporaryDirectory() as root:
    witness = os.path.join(root, "ran")
    # $(...), backquotes and a quote: each would run `touch` through a shell
    hostile = os.path.join(root, f"$(touch {witness}) `touch {witness}` ' x")
    os.makedirs(hostile)
    for name in os.listdir(labs):
        path = os.path.join(labs, name)
        if os.path.isfile(path) and os.access(path, os.X_OK):
            shutil.copy2(path, hostile)
    run = subprocess.run([os.path.join(hostile, "rigidlab"), "list"], capture_output=True,
                         text=True)
    assert run.returncode == 0, run.stderr
    assert not os.path.exists(witness), "a shell ran part of the install path"
    lines = run.stdout.splitlines()
    assert lines and all("not found" not in line for line in lines), run.stdout
    print(f"rigidlab list under a hostile path: {len(lines)} labs, no shell")
