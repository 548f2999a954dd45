"""`pip install .` in a fresh venv (made with --system-site-packages, offline: Debian's
setuptools and numpy, no index): the installed module is the venv's own copy, imports from
outside the source tree, and computes the same tree as the CLI."""
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

from hoct_testing import Results, run

ROOT = pathlib.Path(__file__).resolve().parents[2]


def source_copy(dest):
    """The project's files (tracked and untracked, not ignored) copied to dest with their times,
    so that pip's in-tree build writes nothing into the checkout and a kept CMake build
    directory recompiles only what changed."""
    files = subprocess.run(["git", "-C", str(ROOT), "ls-files", "--cached", "--others",
                            "--exclude-standard", "-z"], capture_output=True, check=True
                           ).stdout.decode().split("\0")
    for name in filter(None, files):
        src = ROOT / name
        if not src.is_file():
            continue
        target = dest / name
        target.parent.mkdir(parents=True, exist_ok=True)
        st = src.stat()
        if target.exists() and target.stat().st_mtime == st.st_mtime and target.stat().st_size == st.st_size:
            continue
        shutil.copy2(src, target)
    return dest


def main():
    res = Results()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
        # ctest passes a CMake build directory kept between runs (the first run compiles the
        # library once more, later runs only what changed); the venv is new every time.
        cache = pathlib.Path(os.environ.get("HOCT_PIP_CACHE") or tmp / "cache")
        env["HOCT_PIP_BUILD_DIR"] = str(cache / "cmake-build")
        src = source_copy(cache / "source")
        subprocess.run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", str(tmp / "venv")],
                       check=True)
        pip = subprocess.run([str(tmp / "venv/bin/pip"), "install", "--no-build-isolation",
                              "--no-index", str(src)], env=env, capture_output=True, text=True,
                             cwd=tmp)
        res.check(pip.returncode == 0, "pip install failed:\n" + pip.stdout[-3000:] + pip.stderr[-3000:])
        if pip.returncode != 0:
            res.finish()
        vtu = tmp / "sphere.vtu"
        run("generate", "sphere", "-o", vtu)
        run("tree", vtu, "--json", tmp / "cli.json", "-q")
        cli = json.loads((tmp / "cli.json").read_text())
        script = (
            "import json, sys, hoct\n"
            "t = hoct.contour_tree(hoct.read(sys.argv[1]))\n"
            "print(json.dumps({'file': hoct.__file__, 'values': [float(v) for v in t.values],"
            " 'arcs': len(t.arcs)}))\n")
        out = subprocess.run([str(tmp / "venv/bin/python"), "-c", script, str(vtu)], env=env,
                             capture_output=True, text=True, cwd=tmp)
        res.check(out.returncode == 0, "import from the venv failed: " + out.stderr[-2000:])
        if out.returncode == 0:
            got = json.loads(out.stdout)
            res.check(got["file"].startswith(str(tmp / "venv")),
                      f"hoct imported from {got['file']}, not from the venv")
            want = sorted(n["value"] for n in cli["nodes"])
            res.check(sorted(got["values"]) == want, "node values differ from the CLI's JSON")
            res.check(got["arcs"] == len(cli["arcs"]), "arc count differs from the CLI's JSON")
        # Uninstall works and leaves no module behind in the venv.
        un = subprocess.run([str(tmp / "venv/bin/pip"), "uninstall", "-y", "hoct"], env=env,
                            capture_output=True, text=True, cwd=tmp)
        res.check(un.returncode == 0, "pip uninstall failed: " + un.stderr[-2000:])
        left = list((tmp / "venv").rglob("_hoct*.so"))
        res.check(not left, f"files left after uninstall: {left}")
    res.finish()


if __name__ == "__main__":
    main()
