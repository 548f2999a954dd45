"""The level-set oracle: the number of contours at a level, counted by brute force, against a
contour tree's or Reeb graph's arcs.

For a contour tree or a Reeb graph the number of connected components of the level set {f = c}
equals the number of arcs whose end values bracket c. This module counts those components on an
independent piecewise-linear refinement of the field: VTK's own evaluation of the higher-order
cells (vtkDataSetSurfaceFilter's nonlinear subdivision, VTK's Lagrange basis, not hoct's), merged
into one mesh by vtkCleanPolyData. At a level c away from every node value (by more than the
refinement's error, estimated by how far the refinement moves when it is refined once more), the
level set is cut where an edge's end values bracket c, and its pieces are joined within each
triangle; the components of that graph are the contours.

Importing it has no side effects; it needs numpy, scipy and VTK's Python modules (an ImportError
otherwise, which the tests turn into exit status 77, skipped).
"""
import json
import os

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkTriangleFilter
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

from hoct_testing import run


def refinement(path, level):
    """VTK's PL refinement of the file's cells: (triangles, values, points) with shared points
    merged."""
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    surface = vtkDataSetSurfaceFilter()
    surface.SetInputConnection(reader.GetOutputPort())
    surface.SetNonlinearSubdivisionLevel(level)
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(surface.GetOutputPort())
    clean = vtkCleanPolyData()
    clean.SetInputConnection(triangles.GetOutputPort())
    clean.SetTolerance(1e-9)
    clean.Update()
    poly = clean.GetOutput()
    cells = vtk_to_numpy(poly.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    values = vtk_to_numpy(poly.GetPointData().GetArray(0)).astype(np.float64)
    points = vtk_to_numpy(poly.GetPoints().GetData()).astype(np.float64)
    return cells, values, points


def edge_index(cells):
    """The mesh's edges (pairs of point ids, ascending) and each cell's three edges in them."""
    e = np.concatenate([cells[:, [0, 1]], cells[:, [1, 2]], cells[:, [2, 0]]]).astype(np.int64)
    e.sort(axis=1)
    key = e[:, 0] * (int(cells.max()) + 1) + e[:, 1]
    unique, index = np.unique(key, return_inverse=True)
    first = np.zeros(len(unique), dtype=np.int64)
    first[index] = np.arange(len(key))
    return e[first], index.reshape(3, -1).T


def contours(edges, per_cell, values, c):
    """Components of {f = c} on the PL mesh (c equal to no vertex value)."""
    s = values[edges] - c
    crossing = (s[:, 0] < 0) != (s[:, 1] < 0)
    n = len(edges)
    cross = crossing[per_cell]
    # A cell with a crossing has exactly two crossing edges: join them.
    rows = cross.sum(axis=1) == 2
    pairs = per_cell[rows][cross[rows]].reshape(-1, 2)
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
    _, label = connected_components(graph, directed=False)
    return len(np.unique(label[crossing]))


def arcs_crossing(tree, c):
    """The number of the tree's (or graph's) arcs whose end values bracket c."""
    value = [n["value"] for n in tree["nodes"]]
    return sum(1 for a, b in tree["arcs"] if min(value[a], value[b]) < c < max(value[a], value[b]))


def compare(tree, path, level, max_levels=40, even_levels=25):
    """Compares the tree's (or Reeb graph's) arcs crossing each level with the contours of VTK's
    refinement of the file at `level` subdivisions. Levels: the midpoints of the gaps between node
    values wider than twice the margin, plus `even_levels` evenly spaced levels away from every
    node value by the margin; at most max_levels of them. Returns a dict: levels, results
    [(level, arcs crossing, contours)], bad (those that differ), err (the refinement's estimated
    error), margin and triangles (of the refinement)."""
    cells, values, points = refinement(path, level)
    finer, finer_values, finer_points = refinement(path, level + 1)
    # The refinement's error, estimated: at the finer refinement's point nearest to each coarse
    # edge's midpoint (the same point where the cell is straight; on curved cells one a sagitta
    # away, which only enlarges the estimate), its value against the coarse PL interpolant.
    edges, per_cell = edge_index(cells)
    mid = (points[edges[:, 0]] + points[edges[:, 1]]) / 2
    _, nearest = cKDTree(finer_points).query(mid)
    err = float(np.abs(finer_values[nearest] -
                       (values[edges[:, 0]] + values[edges[:, 1]]) / 2).max())
    node_values = np.array(sorted(n["value"] for n in tree["nodes"]))
    lo, hi = node_values[0], node_values[-1]
    margin = 4 * err + 1e-9 * (hi - lo)
    levels = [(a + b) / 2 for a, b in zip(node_values, node_values[1:]) if b - a > 2 * margin]
    levels += [c for c in np.linspace(lo, hi, even_levels)[1:-1]
               if np.abs(node_values - c).min() > margin]
    levels = sorted(set(levels))
    if len(levels) > max_levels:
        levels = [levels[i] for i in np.linspace(0, len(levels) - 1, max_levels).astype(int)]
    results = [(c, arcs_crossing(tree, c), contours(edges, per_cell, values, c)) for c in levels]
    return {"levels": levels, "results": results, "bad": [r for r in results if r[1] != r[2]],
            "err": err, "margin": margin, "triangles": len(cells)}


def check(results, name, path, level, extra=(), quiet=False):
    """`hoct tree PATH -q --json PATH.json --no-timings EXTRA $HOCT_TEST_TREE_FLAGS`, then
    compare() at `level`: records in `results` (a hoct_testing.Results) that at least 5 levels
    were checked and that none disagrees, prints one line unless quiet, and returns compare()'s
    dict with the tree's JSON ("tree") and its path ("json") added."""
    out = path + ".json"
    run("tree", path, "-q", "--json", out, "--no-timings", *extra,
        *os.environ.get("HOCT_TEST_TREE_FLAGS", "").split())
    with open(out) as f:
        tree = json.load(f)
    info = compare(tree, path, level)
    info["tree"], info["json"] = tree, out
    levels, bad = info["levels"], info["bad"]
    if not quiet:
        print(f"{name}: {len(tree['nodes'])} nodes, refinement of {info['triangles']} triangles "
              f"(error ~{info['err']:.2g}, margin {info['margin']:.2g}); {len(levels)} levels, "
              f"{len(bad)} disagree", flush=True)
    results.check(len(levels) >= 5, f"{name}: only {len(levels)} levels away from the node values")
    results.check(not bad, f"{name}: (level, arcs crossing it, contours) differ: {bad[:5]}")
    return info
