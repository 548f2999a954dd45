"""Quadrilateral meshes written by Gmsh (recombined, unstructured, orders 1-3) against a fine
piecewise-linear reference, through persistence diagrams (issue 29).

f = sin(3x + 0.5) cos(2y + 0.5) + 0.3x on [0, 2]^2 (four interior critical points) is
interpolated at the nodes of Gmsh's recombined quadrangles (python3-gmsh): the file holds a
function f_h of the Lagrange quadrilaterals (Q1-Q3 on the bilinear or curved-free maps Gmsh
builds). Its exact tree is compared with the PL tree of f on 400 x 400 squares: by the stability
of persistence diagrams the bottleneck distance (join, split, global) is at most
sup |f - f_h| + sup |f - PL|. sup |f - f_h| is computed with Gmsh's own basis functions (not
hoct's) at a grid of points in every cell; sup |f - PL| <= M h^2 / 4 with M = 13 >= |Hessian f|.
The bound shrinks with the order (Q1 ~ 1e-2, Q3 ~ 1e-4), so a missed or invented feature above it
fails; each tree must also pass `hoct check`, and its stats give the mesh build's phases
(the split among them) within time_check_s.
"""
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hoct_testing import Results, bottleneck, run, tempdir, write_pl_reference  # noqa: E402

try:
    import gmsh
except ImportError as e:
    print(f"skipped: python3-gmsh is missing ({e})")
    sys.exit(77)

R = Results()
N_REF = 400
HESSIAN = 13.0


def f(x, y):
    return np.sin(3 * x + 0.5) * np.cos(2 * y + 0.5) + 0.3 * x


def write_quadrangles(path, order, size):
    """A recombined quadrangle mesh of [0, 2]^2 of the given order, f at its nodes as a
    $NodeData view. Returns (cells, sup |f - f_h| at 9 x 9 points of every cell, Gmsh's element
    name)."""
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("square")
        gmsh.model.occ.addRectangle(0, 0, 0, 2, 2)
        gmsh.model.occ.synchronize()
        gmsh.option.setNumber("Mesh.RecombineAll", 1)
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        gmsh.model.mesh.generate(2)
        gmsh.model.mesh.setOrder(order)
        gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
        gmsh.write(path)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        xyz = np.asarray(coords).reshape(-1, 3)
        value = dict(zip((int(t) for t in tags), f(xyz[:, 0], xyz[:, 1])))
        position = {int(t): xyz[i] for i, t in enumerate(tags)}
        v = gmsh.view.add("f")
        gmsh.view.addModelData(v, 0, gmsh.model.getCurrent(), "NodeData", tags,
                               [[value[int(t)]] for t in tags])
        gmsh.view.write(v, path, append=True)
        types = gmsh.model.mesh.getElementTypes(2)
        assert len(types) == 1, types
        etype = types[0]
        name, _, _, nn, _, _ = gmsh.model.mesh.getElementProperties(etype)
        etags, enodes = gmsh.model.mesh.getElementsByType(etype)
        s = np.linspace(-1, 1, 9)
        local = np.array([[a, b, 0.0] for b in s for a in s]).ravel()
        _, basis, _ = gmsh.model.mesh.getBasisFunctions(etype, local, "Lagrange")
        B = np.asarray(basis).reshape(len(s) ** 2, nn)
        nodes = np.asarray(enodes, dtype=np.int64).reshape(-1, nn)
        err = 0.0
        for cell in nodes:
            fh = B @ np.array([value[int(t)] for t in cell])
            x = B @ np.array([position[int(t)] for t in cell])
            err = max(err, float(np.abs(fh - f(x[:, 0], x[:, 1])).max()))
        return len(etags), err, name
    finally:
        gmsh.finalize()


with tempdir() as d:
    reference = os.path.join(d, "reference.vtu")
    write_pl_reference(reference, f, 0.0, 2.0, N_REF)
    reference_json = reference + ".json"
    run("tree", reference, "-q", "--json", reference_json)
    reference_bound = HESSIAN * (2.0 / N_REF) ** 2 / 4
    for order, size in ((1, 0.1), (2, 0.2), (3, 0.25)):
        label = f"Gmsh recombined Q{order}"
        path = os.path.join(d, f"q{order}.msh")
        cells, err, name = write_quadrangles(path, order, size)
        R.check(name.startswith("Quadrilateral"), f"{label}: Gmsh wrote {name}")
        info = run("info", path, "--json").stdout
        R.check('"quadrilateral"' in info, f"{label}: hoct info does not list quadrilaterals")
        tree = path + ".json"
        run("tree", path, "-q", "--json", tree)
        with open(tree) as fp:
            stats = json.load(fp)["stats"]
        parts = ["time_cell_split_s", "time_topology_s", "time_geometry_s", "time_bernstein_s",
                 "time_geometry_checks_s"]
        R.check(all(k in stats for k in parts) and
                sum(stats[k] for k in parts) <= stats["time_check_s"] + 1e-6,
                f"{label}: the mesh build's phases {[stats.get(k) for k in parts]} against "
                f"time_check_s {stats.get('time_check_s')}")
        c = run("check", tree, path, check=False)
        R.check(c.returncode == 0, f"{label}: hoct check: {c.stdout[-600:]}{c.stderr[-600:]}")
        bound = 1.05 * err + reference_bound + 1e-12
        bn = bottleneck(tree, reference_json)
        print(f"{label}: {cells} cells ({name}), sup |f - f_h| ~ {err:.3g}; bottleneck to the PL "
              f"reference join {bn['join']:.3g}, split {bn['split']:.3g}, global "
              f"{bn['global']:.3g} (bound {bound:.3g})", flush=True)
        R.check(max(bn["join"], bn["split"], bn["global"]) <= bound,
                f"{label}: bottleneck {bn} to the fine PL reference exceeds {bound:.3g}")
        R.check(math.isfinite(err) and err < 0.1, f"{label}: interpolation error {err}")
R.finish()
