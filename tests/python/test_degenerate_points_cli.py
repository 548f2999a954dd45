"""Degenerate critical points through the command line and the Python module (issue 26): a
monkey saddle inside a cell and a peak exactly at a mesh vertex, written by VTK's own writer as
Lagrange triangles, give trees without fallback cells whose statistics, summary and `hoct check`
say so; a tree with the monkey saddle's type changed is rejected."""
import copy
import json
import os
import sys

from hoct_testing import Results, run, tempdir

try:
    import numpy as np
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkUnstructuredGrid
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
except ImportError as e:
    print(f"skipped: numpy or VTK's Python modules are missing ({e})")
    sys.exit(77)

R = Results()
VTK_LAGRANGE_TRIANGLE = 69


def cubic_grid(n, f):
    """[0, 1]^2 in n x n squares, two cubic triangles each, nodes in VTK's order (corners, two
    points per edge from its first corner, the centroid); f at every node."""
    index, points, cells = {}, [], []

    def node(key, xy):
        if key not in index:
            index[key] = len(points)
            points.append(xy)
        return index[key]

    for i in range(n):
        for j in range(n):
            square = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
            for tri in ([square[0], square[1], square[2]], [square[0], square[2], square[3]]):
                xy = [np.array(v, dtype=float) / n for v in tri]
                ids = [node(("v",) + v, xy[k]) for k, v in enumerate(tri)]
                for a, b in ((0, 1), (1, 2), (2, 0)):
                    for s in (1 / 3, 2 / 3):
                        lo, hi = sorted((tri[a], tri[b]))
                        t = s if tri[a] == lo else 1 - s
                        ids.append(node(("e", lo, hi, round(t, 6)), (1 - s) * xy[a] + s * xy[b]))
                ids.append(node(("c", len(cells)), sum(xy) / 3))
                cells.append(ids)
    pts = np.array(points)
    return pts, np.array(cells, dtype=np.int64), np.array([f(x, y) for x, y in pts])


def write_vtu(path, pts, cells, values):
    grid = vtkUnstructuredGrid()
    p = vtkPoints()
    p.SetData(numpy_to_vtk(np.column_stack([pts, np.zeros(len(pts))]), deep=True))
    grid.SetPoints(p)
    ca = vtkCellArray()
    ca.SetData(numpy_to_vtkIdTypeArray(np.arange(0, cells.size + 1, 10, dtype=np.int64), deep=True),
               numpy_to_vtkIdTypeArray(cells.ravel(), deep=True))
    grid.SetCells(VTK_LAGRANGE_TRIANGLE, ca)
    a = numpy_to_vtk(values, deep=True)
    a.SetName("f")
    grid.GetPointData().AddArray(a)
    w = vtkXMLUnstructuredGridWriter()
    w.SetFileName(path)
    w.SetInputData(grid)
    if not w.Write():
        raise RuntimeError(f"cannot write {path}")


def degrees(tree, i):
    down = sum(1 for a, b in tree["arcs"] if b == i)
    up = sum(1 for a, b in tree["arcs"] if a == i)
    return down, up


def monkey(x, y):
    u, w = x - 0.47, y - 0.52
    return u ** 3 - 3 * u * w ** 2


def peak(x, y):
    a, b = x - 0.5, y - 0.5
    return -a * a - b * b + 0.3 * a * a * b


with tempdir() as tmp:
    p = lambda name: os.path.join(tmp, name)
    for name, f in (("monkey", monkey), ("peak", peak)):
        write_vtu(p(name + ".vtu"), *cubic_grid(6, f))
        r = run("tree", p(name + ".vtu"), "--json", p(name + ".json"))
        t = json.load(open(p(name + ".json")))
        s = t["stats"]
        R.check(s["fallback_cells"] == 0, f"{name}: {s['fallback_cells']} fallback cells")
        R.check("degenerate critical points:" in r.stdout, f"{name}: summary\n{r.stdout}")
        c = run("check", p(name + ".json"), p(name + ".vtu"), check=False)
        R.check(c.returncode == 0, f"{name}: hoct check exit {c.returncode}\n{c.stdout[-800:]}")
        at = [i for i, n in enumerate(t["nodes"])
              if abs(n["position"][0] - (0.47 if name == "monkey" else 0.5)) < 1e-6
              and abs(n["position"][1] - (0.52 if name == "monkey" else 0.5)) < 1e-6]
        R.check(len(at) == 1, f"{name}: nodes at the critical point: {at}")
        if not at:
            continue
        node = t["nodes"][at[0]]
        R.check(abs(node["value"]) < 1e-12, f"{name}: value {node['value']}")
        if name == "monkey":
            R.check(s["degenerate_points"] == 1, f"monkey: degenerate_points {s['degenerate_points']}")
            R.check(node["type"] == "saddle" and degrees(t, at[0]) == (3, 3),
                    f"monkey: {node['type']} {degrees(t, at[0])}")
            bad = copy.deepcopy(t)
            bad["nodes"][at[0]]["type"] = "maximum"
            json.dump(bad, open(p("bad.json"), "w"))
            c = run("check", p("bad.json"), p(name + ".vtu"), check=False)
            R.check(c.returncode == 1, f"a monkey saddle typed maximum: exit {c.returncode}")
        else:
            R.check(s["critical_corners"] >= 6, f"peak: critical_corners {s['critical_corners']}")
            R.check(node["type"] == "maximum" and node["location"] == "vertex", f"peak: {node}")

    # The Python module reports the same.
    try:
        import hoct
    except ImportError:
        hoct = None
    if hoct is not None:
        pts, cells, values = cubic_grid(6, monkey)
        tree = hoct.contour_tree(hoct.from_arrays(pts, cells, values))
        R.check(tree.stats["degenerate_points"] == 1 and tree.stats["fallback_cells"] == 0,
                f"module: {tree.stats['degenerate_points']} {tree.stats['fallback_cells']}")
        R.check(not tree.pairs["uncertain"].any(), "module: no pair uncertain")

R.finish()
