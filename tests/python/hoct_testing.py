"""Shared helpers for the Python tests that check hoct against independent tools."""
import os
import subprocess
import sys
import tempfile

HOCT = os.environ.get("HOCT_BIN", "hoct")


class Results:
    def __init__(self):
        self.passed = 0
        self.failed = 0

    def check(self, condition, message):
        if condition:
            self.passed += 1
        else:
            self.failed += 1
            print("FAIL:", message, flush=True)

    def finish(self):
        print(f"{self.passed} passed, {self.failed} failed")
        sys.exit(1 if self.failed or not self.passed else 0)


def run(*args, check=True, stdin=None):
    r = subprocess.run([HOCT, *map(str, args)], input=stdin, capture_output=True, text=True)
    if check and r.returncode != 0:
        raise RuntimeError(f"hoct {' '.join(map(str, args))} failed ({r.returncode}):\n{r.stderr}")
    return r


def evaluate(path, points, scalar=None):
    """hoct eval at (cell, u, v) triples: returns [(x, y, z, value)]."""
    text = "".join(f"{c} {u!r} {v!r}\n" for c, u, v in points)
    args = ["eval", path, "--points", "-"]
    if scalar:
        args += ["--scalar", scalar]
    out = run(*args, stdin=text).stdout.split("\n")
    rows = [list(map(float, line.split()[3:])) for line in out if line.strip()]
    return rows


def tempdir():
    return tempfile.TemporaryDirectory(prefix="hoct-test-")
