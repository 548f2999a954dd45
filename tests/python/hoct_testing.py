"""Shared helpers for the Python tests that check hoct against independent tools."""
import json
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


def tree_json(path, *extra):
    """`hoct tree PATH --json ... --no-timings EXTRA...`: (the JSON, the completed process)."""
    out = f"{path}.{abs(hash(extra))}.json"
    res = run("tree", path, "--json", out, "--no-timings", *extra)
    with open(out) as f:
        return json.load(f), res


def close(a, b, tol):
    return abs(a - b) <= tol * max(1.0, abs(a), abs(b))


def compare_trees(results, name, j, k, tol=1e-12, position_tol=None, scale=1.0):
    """Checks that trees j and k (JSON) have the same nodes (type, value, position) and pair
    persistences: values within tol (relative), positions within position_tol (absolute; default
    tol, relative), k's values multiplied by scale."""
    key = lambda n: (n["type"], n["value"], n["position"])  # noqa: E731
    a, b = sorted(j["nodes"], key=key), sorted(k["nodes"], key=key)

    def same_position(x, y):
        if position_tol is None:
            return all(close(u, v, tol) for u, v in zip(x, y))
        return all(abs(u - v) <= position_tol for u, v in zip(x, y))

    ok = len(a) == len(b) and all(
        x["type"] == y["type"] and close(x["value"], scale * y["value"], tol) and
        same_position(x["position"], y["position"]) for x, y in zip(a, b))
    results.check(ok, f"{name}: nodes differ ({len(a)} vs {len(b)} nodes)")
    pa = sorted(p["persistence"] for p in j["pairs"])
    pb = sorted(scale * p["persistence"] for p in k["pairs"])
    results.check(len(pa) == len(pb) and all(close(x, y, tol) for x, y in zip(pa, pb)),
                  f"{name}: persistence pairs differ")


def write_pl_reference(path, f, lo, hi, n):
    """A piecewise-linear reference of f on the square [lo, hi]^2: f at the vertices of n x n
    squares, each cut into two right triangles of legs h = (hi - lo) / n, written with meshio (an
    independent writer) as a .vtu of VTK_TRIANGLE cells. Its PL interpolant differs from f by
    at most M h^2 / 4 (M >= the Frobenius norm of f's Hessian): the caller's bound."""
    import meshio

    xyz, tris = square_triangles(lo, hi, n)
    meshio.write(path, meshio.Mesh(xyz, [("triangle", tris)],
                                   point_data={"f": f(xyz[:, 0], xyz[:, 1])}), binary=True)


def square_triangles(lo, hi, n):
    """The vertices (i + (n + 1) j at (lo + i h, lo + j h), z = 0) and triangles of n x n squares
    of [lo, hi]^2, each cut along its diagonal from (i, j) to (i + 1, j + 1)."""
    import numpy as np

    s = lo + (hi - lo) * np.arange(n + 1) / n
    X, Y = np.meshgrid(s, s)
    xyz = np.column_stack([X.ravel(), Y.ravel(), np.zeros(X.size)])
    I, J = np.meshgrid(np.arange(n), np.arange(n))
    v = (I + (n + 1) * J).ravel()
    tris = np.concatenate([np.column_stack([v, v + 1, v + n + 2]),
                           np.column_stack([v, v + n + 2, v + n + 1])])
    return xyz, tris


def bottleneck(tree_a, tree_b):
    """`hoct compare A B --json`'s bottleneck distances between two trees' persistence diagrams
    (join, split, global, max)."""
    return json.loads(run("compare", tree_a, tree_b, "--json").stdout)["bottleneck"]
