"""VTU files written by VTK (every encoding) and meshio, read by hoct: positions and values at
the Lagrange nodes and at random parametric points must match what the writers were given."""
import json
import os
import random

import meshio
import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray

from hoct_testing import Results, evaluate, run, tempdir

R = Results()
rng = random.Random(5)


def lattice(d):
    """VTK order of a degree-d triangle: parametric (a, b) lattice points."""
    cell = vtk.vtkLagrangeTriangle()
    n = (d + 1) * (d + 2) // 2
    cell.GetPointIds().SetNumberOfIds(n)
    cell.GetPoints().SetNumberOfPoints(n)
    cell.Initialize()
    pc = cell.GetParametricCoords()
    return [(pc[3 * i], pc[3 * i + 1]) for i in range(n)]


def field(x, y, d):
    # A polynomial of degree <= d in x, y: exact on straight cells of degree d.
    return sum((0.3 + 0.1 * k) * x ** k - 0.2 * (x * y) ** (k // 2) + 0.05 * y ** k for k in range(d + 1))


def mesh(d):
    """Two straight triangles (a square) of degree d with shared edge nodes, VTK order."""
    corners = [((0.0, 0.0), (1.0, 0.0), (1.0, 1.0)), ((0.0, 0.0), (1.0, 1.0), (0.0, 1.0))]
    lat = lattice(d)
    points, index, cells = [], {}, []
    for c in corners:
        ids = []
        for (a, b) in lat:
            x = (1 - a - b) * c[0][0] + a * c[1][0] + b * c[2][0]
            y = (1 - a - b) * c[0][1] + a * c[1][1] + b * c[2][1]
            key = (round(x, 12), round(y, 12))
            if key not in index:
                index[key] = len(points)
                points.append((x, y, 0.0))
            ids.append(index[key])
        cells.append(ids)
    values = [field(p[0], p[1], d) for p in points]
    return np.array(points), cells, np.array(values), corners, lat


def write_vtk(path, pts, cells, values, d, mode, compress, header64, float32):
    grid = vtk.vtkUnstructuredGrid()
    p = vtk.vtkPoints()
    p.SetData(numpy_to_vtk(pts.astype(np.float32 if float32 else np.float64), deep=True))
    grid.SetPoints(p)
    ctype = vtk.VTK_TRIANGLE if d == 1 else (vtk.VTK_QUADRATIC_TRIANGLE if d == 2 and mode == "ascii" else vtk.VTK_LAGRANGE_TRIANGLE)
    for c in cells:
        ids = vtk.vtkIdList()
        for i in c:
            ids.InsertNextId(i)
        grid.InsertNextCell(ctype, ids)
    arr = numpy_to_vtk(values.astype(np.float32 if float32 else np.float64), deep=True)
    arr.SetName("temperature")
    other = numpy_to_vtk(np.zeros(len(values)), deep=True)
    other.SetName("zero")
    grid.GetPointData().AddArray(arr)
    grid.GetPointData().AddArray(other)
    w = vtk.vtkXMLUnstructuredGridWriter()
    w.SetFileName(path)
    w.SetInputData(grid)
    {"ascii": w.SetDataModeToAscii, "binary": w.SetDataModeToBinary, "appended": w.SetDataModeToAppended}[mode]()
    if mode == "appended":
        w.SetEncodeAppendedData(0 if compress == "raw" else 1)
    if compress == "zlib":
        w.SetCompressorTypeToZLib()
    else:
        w.SetCompressorTypeToNone()
    w.SetHeaderTypeToUInt64() if header64 else w.SetHeaderTypeToUInt32()
    assert w.Write() == 1


def check_file(path, pts, cells, values, corners, lat, d, label, tol, scalar="temperature"):
    info = json.loads(run("info", path, "--json", "--scalar", scalar).stdout)
    R.check(info["cells"] == len(cells), f"{label}: cells {info['cells']}")
    R.check(info["degrees"] == {str(d): len(cells)}, f"{label}: degrees {info['degrees']}")
    # Every node of every cell, by its parametric position.
    queries = [(ci, a, b) for ci in range(len(cells)) for (a, b) in lat]
    rows = evaluate(path, queries, scalar)
    worst = 0.0
    for (ci, a, b), row, k in zip(queries, rows, range(len(queries))):
        node = cells[ci][k % len(lat)]
        worst = max(worst, abs(row[3] - values[node]), *(abs(row[i] - pts[node][i]) for i in range(3)))
    R.check(len(rows) == len(queries) and worst < tol, f"{label}: node mismatch {worst}")
    # Random points: the field is a polynomial of degree d in x, y on straight cells.
    queries = [(ci, u, v) for ci in range(len(cells)) for u, v in
               [(rng.random() * 0.5, rng.random() * 0.5) for _ in range(5)]]
    rows = evaluate(path, queries, scalar)
    worst = max(abs(r[3] - field(r[0], r[1], d)) for r in rows)
    R.check(worst < tol * 10, f"{label}: interior mismatch {worst}")


with tempdir() as tmp:
    for d in (1, 2, 3, 5):
        pts, cells, values, corners, lat = mesh(d)
        for mode, compress in [("ascii", None), ("binary", None), ("binary", "zlib"),
                               ("appended", "raw"), ("appended", "base64"), ("appended", "zlib")]:
            for header64 in (False, True):
                for float32 in (False, True):
                    label = f"vtk d={d} {mode}/{compress} header64={header64} f32={float32}"
                    path = os.path.join(tmp, "v.vtu")
                    write_vtk(path, pts, cells, values, d, mode, compress, header64, float32)
                    check_file(path, pts, cells, values, corners, lat, d, label,
                               2e-5 if float32 else 1e-9)
        # meshio: triangle / triangle6 only (it has no Lagrange triangles of higher degree).
        if d in (1, 2):
            ctype = "triangle" if d == 1 else "triangle6"
            for binary, compression in [(False, None), (True, None), (True, "zlib")]:
                path = os.path.join(tmp, "m.vtu")
                m = meshio.Mesh(pts, [(ctype, np.array(cells))], point_data={"temperature": values, "zero": 0 * values})
                meshio.write(path, m, file_format="vtu", binary=binary, compression=compression)
                check_file(path, pts, cells, values, corners, lat, d,
                           f"meshio d={d} binary={binary} {compression}", 1e-9)
    # Float32 coordinates of straight cells far from the origin (issue 28, item 7): the edge and
    # interior nodes are rounded off the straight lines by ~1e-4 here, far above 1e-12 of the
    # extent; they are straight within the coordinates' own precision, not "curved".
    for d in (2, 3, 5):
        pts, cells, values, corners, lat = mesh(d)
        far = pts + np.array([1000.37, -2000.11, 0.0])
        path = os.path.join(tmp, "f32.vtu")
        write_vtk(path, far, cells, values, d, "binary", None, False, True)
        info = json.loads(run("info", path, "--json").stdout)
        R.check(info["geometry"] == "planar-straight" and info["curved_cells"] == 0,
                f"float32 straight d={d}: {info['geometry']}, {info['curved_cells']} curved")
        # In doubles the same rounded points are curved (by 1e-4 of 2,000: far above 1e-12),
        # from degree 3 on (a P2 midpoint of two rounded corners rounds onto their line).
        if d == 2:
            continue
        write_vtk(path, far.astype(np.float32).astype(np.float64), cells, values, d, "binary",
                  None, False, False)
        info = json.loads(run("info", path, "--json").stdout)
        R.check(info["curved_cells"] > 0, f"float64 of rounded points d={d}: {info['geometry']}")
    # Files hoct writes are read back by VTK with the same data.
    for enc in ("ascii", "base64", "zlib", "appended", "appended-base64"):
        path = os.path.join(tmp, f"g-{enc}.vtu")
        run("generate", "sphere", "-o", path, "--cells", "80", "--encoding", enc)
        r = vtk.vtkXMLUnstructuredGridReader()
        r.SetFileName(path)
        r.Update()
        g = r.GetOutput()
        info = json.loads(run("info", path, "--json").stdout)
        R.check(g.GetNumberOfCells() == info["cells"] and g.GetNumberOfPoints() == info["points"],
                f"hoct {enc}: VTK reads {g.GetNumberOfCells()} cells")
        R.check(g.GetCellType(0) == vtk.VTK_LAGRANGE_TRIANGLE, f"hoct {enc}: cell type")

R.finish()
