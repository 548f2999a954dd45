"""One pipeline behind every front end: for the same request, `hoct tree --json --no-timings`
and the Python module's `contour_tree(...).to_json(timings=False)` are the same bytes, on every
generated dataset and for every method and option (the ParaView filter is compared with the
command line in tests/paraview/test_plugin.py)."""
import os
import subprocess
import tempfile

import pytest

import hoct

HOCT = os.environ.get("HOCT_BIN", "hoct")
SIZES = {"heater": 1500, "conductor": 1200, "random": 2000, "plate": 3000}

# (CLI flags, Python keyword arguments): the same request.
REQUESTS = [
    ([], {}),
    (["--linear"], {"method": "linear"}),
    (["--refine", "2"], {"method": "refine", "refine": 2}),
    (["--simplify", "1%"], {"simplify": "1%"}),
    (["--simplify", "0.05"], {"simplify": 0.05}),
    (["--keep-flat"], {"keep_flat": True}),
    (["--augmented"], {"augmented": True}),
    (["--linear", "--simplify", "2%"], {"method": "linear", "simplify": "2%"}),
    (["--threads", "1"], {"threads": 1}),
]


@pytest.fixture(scope="module")
def data():
    with tempfile.TemporaryDirectory(prefix="hoct-front-ends-") as d:
        paths = {}
        for name in hoct.dataset_names():
            path = os.path.join(d, name + ".vtu")
            cells = SIZES.get(name, 0)
            subprocess.run([HOCT, "generate", name, "-o", path] +
                           (["--cells", str(cells)] if cells else []),
                           check=True, capture_output=True)
            paths[name] = path
        yield d, paths


def cli_json(path, flags):
    out = path + ".cli.json"
    subprocess.run([HOCT, "tree", path, "-q", "--no-timings", "--json", out, *flags], check=True)
    with open(out) as f:
        return f.read()


@pytest.mark.parametrize("flags,kwargs", REQUESTS, ids=[" ".join(r[0]) or "exact" for r in REQUESTS])
@pytest.mark.parametrize("name", hoct.dataset_names())
def test_cli_and_python_write_the_same_bytes(data, name, flags, kwargs):
    _, paths = data
    path = paths[name]
    expected = cli_json(path, flags)
    got = hoct.contour_tree(hoct.read(path), **kwargs).to_json(timings=False) + "\n"
    assert got == expected
    assert '"time_' not in got


def two_triangles(path, points, values):
    """A .vtu of two linear triangles (points 0-2 and 3-5), written with meshio."""
    import meshio
    import numpy as np

    meshio.write(path, meshio.Mesh(np.array(points, float), [("triangle", np.array([[0, 1, 2],
                                   [3, 4, 5]]))], point_data={"f": np.array(values, float)}))


def refused_by_both(path, words):
    r = subprocess.run([HOCT, "tree", path, "-q"], capture_output=True, text=True)
    assert r.returncode == 1 and words in r.stderr, r.stderr
    with pytest.raises(hoct.HoctError, match=words):
        hoct.contour_tree(hoct.read(path))


def test_reeb_graphs_and_forced_meshes_are_the_same_too(data):
    # Two separate triangles: the same Reeb graph (a forest) from both, by every method.
    d, _ = data
    path = os.path.join(d, "two.vtu")
    two_triangles(path, [[0, 0, 0], [1, 0, 0], [0, 1, 0], [3, 0, 0], [4, 0, 0], [3, 1, 0]],
                  [0, 1, 2, 3, 4, 5])
    for flags, kwargs in (([], {}), (["--linear"], {"method": "linear"})):
        expected = cli_json(path, flags)
        assert '"kind": "Reeb graph"' in expected and '"forced"' not in expected
        assert hoct.contour_tree(hoct.read(path), **kwargs).to_json(timings=False) + "\n" == expected
    # An inverted cell (a fan whose centre lies outside the square): refused by both without
    # force, the same forced tree with it.
    import meshio
    import numpy as np

    path = os.path.join(d, "inverted.vtu")
    points = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, -0.3, 0]], float)
    meshio.write(path, meshio.Mesh(points, [("triangle", np.array([[4, 0, 1], [4, 1, 2], [4, 2, 3],
                                   [4, 3, 0]]))], point_data={"f": points[:, 0] + 2 * points[:, 1]}))
    refused_by_both(path, "inverted cell")
    for flags, kwargs in ((["--force"], {"force": True}),
                          (["--linear", "--force"], {"method": "linear", "force": True})):
        expected = cli_json(path, flags)
        assert '"forced": true' in expected
        assert hoct.contour_tree(hoct.read(path), **kwargs).to_json(timings=False) + "\n" == expected


def test_bad_requests_fail_the_same_way(data):
    _, paths = data
    path = paths["sphere"]
    for flags, kwargs, words in [
        (["--simplify", "lots"], {"simplify": "lots"}, "is not a threshold"),
        (["--simplify", "1%", "--augmented"], {"simplify": "1%", "augmented": True},
         "works on the reduced tree"),
    ]:
        r = subprocess.run([HOCT, "tree", path, "-q", *flags], capture_output=True, text=True)
        assert r.returncode == 1 and words in r.stderr, r.stderr
        with pytest.raises(hoct.HoctError, match=words):
            hoct.contour_tree(hoct.read(path), **kwargs)


@pytest.mark.parametrize("name", ["sphere", "heater", "two-triangle"])
def test_written_files_are_the_same(data, name):
    # Tree.write_json / write_vtp / write_svg write what `hoct tree --json --vtp --svg` writes.
    d, paths = data
    path = paths[name]
    cli = {ext: os.path.join(d, f"{name}.cli.{ext}") for ext in ("json", "vtp", "svg")}
    subprocess.run([HOCT, "tree", path, "-q", "--no-timings", "--simplify", "1%", "--json",
                    cli["json"], "--vtp", cli["vtp"], "--svg", cli["svg"]], check=True)
    tree = hoct.contour_tree(hoct.read(path), simplify="1%")
    py = {ext: os.path.join(d, f"{name}.py.{ext}") for ext in ("json", "vtp", "svg")}
    tree.write_json(py["json"], timings=False)
    tree.write_vtp(py["vtp"])
    title = f"{name}.vtu: exact contour tree, {len(tree.values)} nodes"
    tree.write_svg(py["svg"], title=title)
    for ext in ("json", "vtp", "svg"):
        with open(cli[ext], "rb") as a, open(py[ext], "rb") as b:
            assert a.read() == b.read(), ext


def test_merge_duplicates_as_the_cli(data):
    # Two triangles of a square, each with its own copy of the shared edge's points: refused as
    # duplicate vertices, the same tree once merged.
    d, _ = data
    path = os.path.join(d, "crack.vtu")
    two_triangles(path, [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 0, 0], [1, 1, 0], [0, 1, 0]],
                  [0, 1, 3, 0, 3, 2])
    refused_by_both(path, "duplicate vertices")
    expected = cli_json(path, ["--merge-duplicates"])
    got = hoct.contour_tree(hoct.read(path, merge_duplicates=True)).to_json(timings=False)
    assert got + "\n" == expected
    for bad in (-1, 0.5, "lots"):
        with pytest.raises(hoct.HoctError, match="merge_duplicates"):
            hoct.read(path, merge_duplicates=bad)


def test_the_input_fingerprint_as_the_cli(data):
    # Mesh.fingerprint and Tree.input are what `hoct tree --json` records in "input"; the same
    # mesh from arrays (another front end, the same data) has the same fingerprint, another
    # field another one.
    import json

    import numpy as np

    d, paths = data
    path = paths["random"]
    recorded = json.loads(cli_json(path, []))["input"]
    mesh = hoct.read(path)
    assert mesh.fingerprint == recorded["fingerprint"]
    tree = hoct.contour_tree(mesh)
    assert tree.input == recorded
    assert tree.simplify_by("1%").input == recorded
    assert json.loads(tree.to_json(timings=False))["input"] == recorded
    points = np.array([[0, 0], [1, 0], [0, 1], [1, 1]], float)
    cells = np.array([[0, 1, 2], [1, 3, 2]])
    a = hoct.from_arrays(points, cells, np.array([0.0, 1.0, 2.0, 3.0]))
    b = hoct.from_arrays(points, cells, np.array([0.0, 1.0, 2.0, 3.0]))
    c = hoct.from_arrays(points, cells, np.array([0.0, 1.0, 2.0, np.nextafter(3.0, 4.0)]))
    assert a.fingerprint == b.fingerprint != c.fingerprint
    assert hoct.contour_tree(a).input == {"points": 4, "cells": 2, "field": "f",
                                          "fingerprint": a.fingerprint}
