"""The Python module `hoct` (pytest): the same trees as the command line on every dataset, numpy
and meshio input, simplification, networkx, join/split trees, arc paths, errors, GIL release."""
import json
import os
import subprocess
import tempfile
import threading

import meshio
import networkx as nx
import numpy as np
import pytest

import hoct

HOCT = os.environ.get("HOCT_BIN", "hoct")
SIZES = {"heater": 1500, "conductor": 1200, "random": 2000}


@pytest.fixture(scope="module")
def tmp():
    with tempfile.TemporaryDirectory(prefix="hoct-pytest-") as d:
        yield d


def cli_tree(path, *args):
    out = path + ".json"
    subprocess.run([HOCT, "tree", path, "--json", out, "-q", *args], check=True)
    return json.load(open(out))


@pytest.mark.parametrize("name", hoct.dataset_names())
def test_same_tree_as_the_cli(tmp, name):
    path = os.path.join(tmp, name + ".vtu")
    cells = SIZES.get(name, 0)
    subprocess.run([HOCT, "generate", name, "-o", path] + (["--cells", str(cells)] if cells else []),
                   check=True, capture_output=True)
    cli = cli_tree(path)
    tree = hoct.contour_tree(hoct.read(path))
    assert list(tree.values) == [n["value"] for n in cli["nodes"]]
    assert tree.types == [n["type"] for n in cli["nodes"]]
    assert tree.locations == [n["location"] for n in cli["nodes"]]
    assert tree.arcs.tolist() == cli["arcs"]
    assert sorted(tree.pairs["persistence"]) == sorted(p["persistence"] for p in cli["pairs"])
    # hoct.generate builds the same dataset in memory.
    same = hoct.contour_tree(hoct.generate(name, cells=cells))
    assert list(same.values) == list(tree.values)


def test_tree_api(tmp):
    mesh = hoct.generate("sphere")
    assert mesh.num_cells == 980 and mesh.euler_characteristic == 2 and mesh.boundary_loops == 0
    tree = hoct.contour_tree(mesh)
    assert json.loads(tree.to_json())["format"] == "hoct-contour-tree"
    g = tree.to_networkx()
    assert nx.is_tree(g) and g.number_of_nodes() == len(tree.values)
    assert g.nodes[0]["type"] == tree.types[0]
    jp, sp = tree.join_tree()["parent"], tree.split_tree()["parent"]
    assert (jp < 0).sum() == 1 and (sp < 0).sum() == 1
    assert all(tree.values[c] <= tree.values[q] for c, q in enumerate(jp) if q >= 0)
    assert all(tree.values[c] >= tree.values[q] for c, q in enumerate(sp) if q >= 0)
    s = hoct.contour_tree(mesh, simplify="2%")
    rng = tree.values.max() - tree.values.min()
    kept = [x for x in tree.pairs["persistence"] if x >= 0.02 * rng]
    assert len(s.pairs["persistence"]) == len(kept)
    assert len(s.branches["parent"]) == len(kept) and s.branches["parent"][0] == -1
    assert len(tree.simplify(0.02 * rng).values) == len(s.values)
    paths = tree.arc_paths()
    assert len(paths) == len(tree.arcs)
    for path, (a, b) in zip(paths, tree.arcs):
        assert np.allclose(path[0], tree.positions[a]) and np.allclose(path[-1], tree.positions[b])
    pl = hoct.contour_tree(mesh, method="refine", refine=4)
    assert pl.method == "refine k=4"


def test_an_offset_field_has_the_same_tree_and_says_how_precise_it_is():
    # The heater in kelvin-like units: range ~5.7 around 1e7.
    base = hoct.contour_tree(hoct.generate("heater", cells=1500))
    hot = hoct.contour_tree(hoct.generate("heater", cells=1500, offset=1e7))
    assert base.precision < 1e-10 < hot.precision < 1e-6
    # Above the precision, the same tree (pairs below it may be lost to the rounding).
    b, h = base.simplify(3 * hot.precision), hot.simplify(3 * hot.precision)
    assert h.types == b.types and h.arcs.tolist() == b.arcs.tolist()
    assert np.allclose(h.values - 1e7, b.values, rtol=0, atol=hot.precision)
    flagged = hot.pairs["uncertain"]
    assert flagged.dtype == bool and len(flagged) == len(hot.pairs["persistence"])
    assert list(flagged) == [p <= hot.precision for p in hot.pairs["persistence"]]
    assert hot.stats["precision"] == hot.precision


def test_numpy_and_meshio_input(tmp):
    pts = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [.5, 0], [1, .5], [.5, .5], [.5, 1], [0, .5]], float)
    cells = np.array([[0, 1, 2, 4, 5, 6], [0, 2, 3, 6, 7, 8]])
    vals = (pts[:, 0] - 0.4) ** 2 - (pts[:, 1] - 0.6) ** 2
    m = hoct.from_arrays(pts, cells, vals, degree=2, cell_types=[22, 69])
    t = hoct.contour_tree(m)
    assert m.num_cells == 2 and "saddle" in t.types
    assert abs(m.value(0, 0.5, 0.25) - ((0.75 - 0.4) ** 2 - (0.25 - 0.6) ** 2)) < 1e-12
    saddles = [i for i, ty in enumerate(t.types) if ty == "saddle"]
    assert any(np.allclose(t.positions[i][:2], [0.4, 0.6], atol=1e-12) for i in saddles)
    mm = meshio.Mesh(np.c_[pts, np.zeros(len(pts))], [("triangle6", cells)], point_data={"f": vals})
    path = os.path.join(tmp, "q.vtu")
    meshio.write(path, mm)
    assert list(hoct.contour_tree(hoct.from_meshio(mm)).values) == list(t.values)
    assert list(hoct.contour_tree(hoct.read(path)).values) == list(t.values)


@pytest.mark.parametrize("call,phrase", [
    (lambda: hoct.read("/nonexistent/x.vtu"), "cannot open"),
    (lambda: hoct.from_arrays(np.zeros((3, 2)), [[0, 1]], np.zeros(3)), "neither a complete triangle"),
    (lambda: hoct.from_arrays(np.zeros((3, 2)), [[0, 1, 7]], np.zeros(3)), "refers to point 7"),
    (lambda: hoct.from_arrays(np.zeros((3, 2)), [[0, 1, 2]], np.zeros(3), degree=2), "degree 2 needs 6"),
    (lambda: hoct.from_arrays(np.zeros((3, 2)), [[0, 1, 2]], np.zeros(3), cell_types=[22]), "VTK type 22"),
    (lambda: hoct.generate("nope"), "unknown dataset"),
    (lambda: hoct.generate("random", cells=200, frequency=0), "frequency must be"),
    (lambda: hoct.generate("gauss", frequency=2), "random dataset only"),
    (lambda: hoct.generate("random", cells=200, plateau=100), "plateau must be"),
    (lambda: hoct.generate("gauss", plateau=10), "random dataset only"),
    (lambda: hoct.contour_tree(hoct.generate("gauss"), method="magic"), "method must be"),
])
def test_errors_are_value_errors_with_the_library_message(call, phrase):
    with pytest.raises(hoct.HoctError, match=phrase) as e:
        call()
    assert isinstance(e.value, ValueError)


def test_computation_releases_the_gil():
    mesh = hoct.generate("random", cells=200000)
    ticks = []
    stop = threading.Event()

    def ticker():
        while not stop.is_set():
            ticks.append(1)
            stop.wait(0.001)

    th = threading.Thread(target=ticker)
    th.start()
    before = len(ticks)
    hoct.contour_tree(mesh, threads=1)
    during = len(ticks) - before
    stop.set()
    th.join()
    assert during > 5  # the other thread kept running while the tree was computed


def test_non_simply_connected_domain_is_a_reeb_graph():
    # Two separate triangles: not one disk, so a Reeb graph (here a forest: one min and max per
    # triangle), by the linear method too.
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [3, 0, 0], [4, 0, 0], [3, 1, 0]], float)
    cells = np.array([[0, 1, 2], [3, 4, 5]])
    mesh = hoct.from_arrays(points, cells, np.array([0.0, 1.0, 2.0, 3.0, 4.0, 5.0]))
    g = hoct.contour_tree(mesh)
    assert g.kind == "Reeb graph" and g.loops == 0
    assert sorted(g.values.tolist()) == [0.0, 2.0, 3.0, 5.0]
    linear = hoct.contour_tree(mesh, method="linear")
    assert linear.kind == "Reeb graph" and linear.loops == 0
    assert sorted(linear.values.tolist()) == [0.0, 2.0, 3.0, 5.0]


def test_annulus_reeb_graph_has_its_loop_in_networkx():
    # A square annulus (an 8x8 grid without its 4x4 centre), f = x + 0.3 y: one loop around the
    # hole, between its lowest and its highest corner.
    nx = pytest.importorskip("networkx")
    n = 8
    points = np.array([[i, j, 0] for j in range(n + 1) for i in range(n + 1)], float)
    cells = []
    for j in range(n):
        for i in range(n):
            if 2 <= i < 6 and 2 <= j < 6:
                continue
            a, b, c, d = j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, \
                (j + 1) * (n + 1) + i
            cells += [[a, b, c], [a, c, d]]
    values = points[:, 0] + 0.3 * points[:, 1]
    g = hoct.contour_tree(hoct.from_arrays(points, np.array(cells), values))
    assert g.kind == "Reeb graph" and g.loops == 1
    assert np.allclose(sorted(g.values.tolist()), [0.0, 2.6, 7.8, 10.4])
    G = g.to_networkx()
    assert isinstance(G, nx.MultiGraph)
    assert G.number_of_edges() - G.number_of_nodes() + nx.number_connected_components(G) == 1
    pairs = g.pairs
    loops = [p for p, k in zip(pairs["persistence"], pairs["kind"]) if k == "loop"]
    assert len(loops) == 1 and abs(loops[0] - 5.2) < 1e-12
    # Simplified: the loop stays unless asked for; below the threshold it goes when asked.
    assert g.simplify(6).loops == 1 and g.simplify_by("60%").loops == 1
    gone = g.simplify(6, loops=True)
    assert gone.loops == 0 and gone.stats["loops_removed"] == 1
    assert g.simplify_by("60%", loops=True).loops == 0
    assert g.simplify(5, loops=True).loops == 1  # 5.2 is above 5
    with pytest.raises(TypeError, match="simplify: loops must be True or False"):
        g.simplify(6, loops="yes")


def test_read_on_threads_gives_the_same_mesh_and_tree(tmp):
    # Large enough that the reader splits its arrays into parts (4 MiB each) and streams them.
    path = os.path.join(tmp, "random.vtu")
    subprocess.run([HOCT, "generate", "random", "--cells", "120000", "--degree", "5", "-o", path],
                   check=True, capture_output=True)
    assert os.path.getsize(path) > 64 << 20
    one = hoct.read(path, threads=1)
    trees = [hoct.contour_tree(m, threads=1) for m in (one, hoct.read(path, threads=2),
                                                       hoct.read(path))]
    for t in trees[1:]:
        assert t.values.tolist() == trees[0].values.tolist()
        assert t.arcs.tolist() == trees[0].arcs.tolist()
        assert t.positions.tolist() == trees[0].positions.tolist()
    for bad in (0, -1, 1.5, True, "2"):
        with pytest.raises(hoct.HoctError, match="threads must be a positive integer"):
            hoct.read(path, threads=bad)


def test_read_checks_the_memory_budget_before_allocating(tmp):
    # The same guard as `hoct --max-memory`: the header counts against the budget, before reading.
    path = os.path.join(tmp, "gauss.vtu")
    subprocess.run([HOCT, "generate", "gauss", "--cells", "2000", "--degree", "3", "-o", path],
                   check=True, capture_output=True)
    for budget in ("1M", 1 << 20):
        with pytest.raises(hoct.HoctError, match=r"gauss\.vtu: piece 0: .*need ~.*limit 1 MiB"):
            hoct.read(path, max_memory=budget)
    for bad in ("lots", "150%", "-5G", 0, -3, True):
        with pytest.raises(hoct.HoctError, match="memory size|max_memory"):
            hoct.read(path, max_memory=bad)
    for ok in (None, "4G", "50%", 8 << 30):
        assert hoct.read(path, max_memory=ok).num_cells == hoct.read(path).num_cells
