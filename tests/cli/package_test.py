#!/usr/bin/env python3
"""The Debian package: `cpack -G DEB` builds
rigidlab_VERSION_amd64.deb from this build; its control file names the run-time
dependencies (the linked libraries found by dpkg-shlibdeps, and OSMesa and the
font, which are opened at run time and so must be named by hand), it holds every
lab with its man page and the bash completion, and a lab unpacked from it draws
its figures.

What this test cannot do is install the package with apt on a fresh Debian 12
(that needs a clean root and the package registry): that was done by hand in a
debootstrap chroot (docs/guide.md, "Installing").

Usage: package_test.py BUILD_DIR VERSION
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile


def control_field(deb, field):
    return subprocess.run(["dpkg-deb", "-f", deb, field], check=True, capture_output=True,
                          text=True).stdout.strip()


def every_lab_draws(work, env, labs):
    """rigidlab figures from the unpacked package (its rigidlab-draw found from /usr/bin):
    what failed, if anything."""
    every = os.path.join(work, "every")
    run = subprocess.run(["rigidlab", "figures", "--out", every, "--figure-size", "800x600"],
                         capture_output=True, text=True, env=env, cwd=work)
    if run.returncode == 0 and any(f.startswith(labs[-1] + "_") for f in os.listdir(every)):
        return []
    return [f"rigidlab figures from the package: {run.returncode} {run.stderr[-400:]!r}"]


def main():
    build, version = sys.argv[1], sys.argv[2]
    work = tempfile.mkdtemp(prefix="rigid_package_")
    failures = []
    try:
        subprocess.run(["cpack", "-G", "DEB", "--config", os.path.join(build, "CPackConfig.cmake"),
                        "-B", work], check=True, stdout=subprocess.DEVNULL)
        deb = os.path.join(work, f"rigidlab_{version}_amd64.deb")
        if not os.path.isfile(deb):
            print("FAIL no", deb, "among", os.listdir(work))
            return 1

        if control_field(deb, "Package") != "rigidlab" or control_field(deb, "Version") != version:
            failures.append(f"control: {control_field(deb, 'Package')} {control_field(deb, 'Version')}")
        depends = [d.split()[0] for d in control_field(deb, "Depends").split(", ")]
        # opened with dlopen (OSMesa) or by path (the font): shlibdeps cannot see them
        for needed in ("libosmesa6", "libcairo2", "fonts-dejavu-core", "libc6", "libstdc++6"):
            if needed not in depends:
                failures.append(f"Depends lacks {needed}: {depends}")
        recommends = control_field(deb, "Recommends")
        if "libegl1" not in recommends or "libgl1-mesa-dri" not in recommends:
            failures.append(f"Recommends lacks the EGL backend: {recommends!r}")
        # --animate opens these with dlopen: the package must bring them along
        for lib in ("libwebpmux3", "libavformat59", "libavcodec59", "libswscale6"):
            if lib not in recommends:
                failures.append(f"Recommends lacks {lib} (--animate): {recommends!r}")

        # import rigidlab: Debian's python3 (the module's ABI) and NumPy
        python = len(sys.argv) > 3 and sys.argv[3] == "--python"
        if python and ("python3 (>= 3.11)" not in recommends or "python3-numpy" not in recommends):
            failures.append(f"Recommends lacks python3 3.11 and NumPy: {recommends!r}")

        listing = subprocess.run(["dpkg-deb", "-c", deb], check=True, capture_output=True,
                                 text=True).stdout
        files = {line.split()[-1].lstrip(".") for line in listing.splitlines()}
        labs = subprocess.run([os.path.join(build, "labs", "rigidlab"), "list", "--names"],
                              check=True, capture_output=True, text=True).stdout.split()
        expected = {f"/usr/bin/{lab}" for lab in labs + ["rigidlab"]}
        expected |= {f"/usr/share/man/man1/{lab}.1" for lab in labs + ["rigidlab"]}
        expected.add("/usr/share/bash-completion/completions/rigidlab")
        expected.add("/usr/libexec/rigidlab/rigidlab-draw")  # what rigidlab figures runs
        if python:
            expected.add("/usr/lib/python3/dist-packages/rigidlab/__init__.py")
        for missing in sorted(expected - files):
            failures.append(f"the package lacks {missing}")

        # unpacked (not installed): a lab from the package runs and draws
        root = os.path.join(work, "root")
        subprocess.run(["dpkg-deb", "-x", deb, root], check=True)
        figures = os.path.join(work, "figures")
        env = {"PATH": os.path.join(root, "usr", "bin") + ":/usr/bin:/bin", "HOME": work}
        # a sanitizer build's options (its leak suppressions for the GL libraries) carried over
        env.update({k: v for k, v in os.environ.items() if k.endswith("SAN_OPTIONS")})
        run = subprocess.run(["poinsot", "--figures", figures, "--json"], capture_output=True,
                             text=True, env=env, cwd=work)
        if python:
            # and a lab from Python, the package's dist-packages alone on the path
            site = os.path.join(root, "usr", "lib", "python3", "dist-packages")
            imported = subprocess.run(
                ["/usr/bin/python3", "-c", "import rigidlab as rl; print(rl.football().answer)"],
                capture_output=True, text=True, cwd=work,
                env={**env, "PYTHONPATH": site, "PYTHONDONTWRITEBYTECODE": "1"})
            if imported.returncode != 0 or "prolate" not in imported.stdout:
                failures.append(f"import rigidlab from the package: {imported.stderr[-400:]!r}")
        failures += every_lab_draws(work, env, labs)
        if run.returncode != 0:
            failures.append(f"poinsot from the package: {run.returncode} {run.stderr!r}")
        else:
            drawn = json.loads(run.stdout)["figures"]
            on_disk = sorted(os.listdir(figures))
            if not drawn or sorted(drawn) != on_disk:
                failures.append(f"poinsot from the package drew {drawn}, on disk {on_disk}")
        print(f"package: {os.path.basename(deb)}, {os.path.getsize(deb) / 1e6:.1f} MB, "
              f"Depends: {', '.join(depends)}")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    for f in failures:
        print("FAIL", f)
    print(f"package: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
