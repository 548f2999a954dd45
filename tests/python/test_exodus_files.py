"""Exodus II files (MOOSE's format), written by VTK's own vtkExodusIIWriter and by a netCDF
writer laid out as the SEACAS library writes (exodus_writer.py: several time steps, TRI7), read
by hoct with the Exodus library (coordinates and values as doubles).

`hoct generate gauss --degree 2` (quadratic triangles) is the reference, read from its .vtu:
- written by vtkExodusIIWriter (TRI6 elements): the same tree (types, values, positions);
- written at two times (f, then 2 f): `hoct info` lists the steps, the default is the last (the
  values doubled), --step 0 and --time give the reference tree, a step that is not there is an
  error;
- written as TRI7 (P2 plus a cubic bubble per cell, read as cubic cells): with the quadratic
  field's own centroid values, the reference tree; with bubbles added, `hoct eval` equals the
  TRI7 interpolant computed here at 200 random points, and `hoct check` accepts the tree;
- truncated anywhere: exit status 1 and a message naming the file, never a crash.

Run by ctest with /usr/bin/python3 and HOCT_BIN set to the hoct executable."""
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_QUADRATIC_TRIANGLE, vtkUnstructuredGrid
from vtkmodules.vtkIOExodus import vtkExodusIIWriter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hoct_testing import Results, compare_trees, evaluate, run, tempdir, tree_json  # noqa: E402

r = Results()
WRITER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "exodus_writer.py")


def write_exodus(path, points, cells, kind, fields, times=(0.0,)):
    """exodus_writer.py in its own process (netCDF4's HDF5 and VTK's do not mix in one)."""
    (name, values), = fields.items()
    np.savez(path + ".npz", points=points, cells=cells, times=np.asarray(times, dtype=float),
             name=name, values=np.asarray(values))
    w = subprocess.run([sys.executable, WRITER, path + ".npz", path, kind], capture_output=True,
                       text=True)
    if w.returncode != 0:
        raise RuntimeError(f"exodus_writer.py failed:\n{w.stderr[-2000:]}")


def same_tree(name, j, k, value_tol, position_tol, scale=1.0):
    compare_trees(r, name, j, k, value_tol, position_tol, scale)


with tempdir() as d:
    p = lambda name: os.path.join(d, name)  # noqa: E731
    run("generate", "gauss", "--degree", "2", "-o", p("g2.vtu"))
    ref, _ = tree_json(p("g2.vtu"))
    field = ref["input"]["field"]
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(p("g2.vtu"))
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData()).astype(np.float64)
    cells = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 6)
    values = vtk_to_numpy(grid.GetPointData().GetArray(field)).astype(np.float64)
    r.check(len(ref["nodes"]) > 5, f"reference tree too small: {len(ref['nodes'])} nodes")

    # VTK's own writer, TRI6.
    tri6 = vtkUnstructuredGrid()
    pts = vtkPoints()
    pts.SetData(numpy_to_vtk(points, deep=True))
    tri6.SetPoints(pts)
    for c in cells:
        tri6.InsertNextCell(VTK_QUADRATIC_TRIANGLE, 6, [int(i) for i in c])
    arr = numpy_to_vtk(values, deep=True)
    arr.SetName(field)
    tri6.GetPointData().AddArray(arr)
    writer = vtkExodusIIWriter()
    writer.SetFileName(p("vtk.e"))
    writer.SetInputData(tri6)
    r.check(writer.Write() == 1, "vtkExodusIIWriter failed")
    j, res = tree_json(p("vtk.e"))
    r.check(f"field '{field}'" in res.stdout, f"vtk.e: summary: {res.stdout[:300]}")
    same_tree("vtkExodusIIWriter TRI6 vs .vtu", j, ref, 1e-12, 1e-12)

    # Two time steps, double coordinates.
    write_exodus(p("steps.exo"), points[:, :2], cells, "TRI6", {field: [values, 2 * values]},
                 times=[0.5, 1.5])
    info = run("info", p("steps.exo")).stdout
    r.check("2 time steps (times 0.5, 1.5)" in info, f"steps.exo: info:\n{info[:600]}")
    last, res = tree_json(p("steps.exo"))
    r.check("step 1 of 2" in res.stdout, f"steps.exo: default step: {res.stdout[:300]}")
    same_tree("Exodus last step vs 2 x .vtu", last, ref, 1e-12, 1e-12, scale=2.0)
    for args in (["--step", "0"], ["--time", "0.5"], ["--step", "-2"]):
        j, _ = tree_json(p("steps.exo"), *args)
        same_tree(f"Exodus {' '.join(args)} vs .vtu", j, ref, 1e-12, 1e-12)
    res = run("tree", p("steps.exo"), "--step", "2", check=False)
    r.check(res.returncode == 1 and "the file has 2 steps" in res.stderr,
            f"--step 2: {res.returncode} {res.stderr.strip()[:300]}")

    # TRI7 (a bubble node per cell), read as cubic cells. With the centroid values of the
    # quadratic field, the .vtu tree; with a bubble added per cell, the TRI7 interpolant
    # (evaluated here independently) at random points, and a valid tree (`hoct check`).
    tri = points[cells[:, :3]]
    centroids = tri.mean(axis=1)
    corner, mid = values[cells[:, :3]], values[cells[:, 3:]]
    p2_centre = -corner.sum(axis=1) / 9 + 4 * mid.sum(axis=1) / 9
    tri7 = np.hstack([cells, np.arange(len(points), len(points) + len(cells))[:, None]])
    xy7 = np.vstack([points, centroids])[:, :2]
    write_exodus(p("tri7.e"), xy7, tri7, "TRI7", {field: [np.concatenate([values, p2_centre])]})
    j, res = tree_json(p("tri7.e"))
    same_tree("TRI7 without bubble vs .vtu", j, ref, 1e-12, 1e-9)
    r.check("max degree 3" in res.stdout, f"TRI7: not read as cubic: {res.stdout[:200]}")
    rng = np.random.default_rng(7)
    span = values.max() - values.min()
    bubble = rng.uniform(-0.05, 0.05, len(cells)) * span
    write_exodus(p("bubble.e"), xy7, tri7, "TRI7",
                 {field: [np.concatenate([values, p2_centre + bubble])]})
    queries = [(int(c), float(u), float(v)) for c, u, v in zip(
        rng.integers(0, len(cells), 200), rng.uniform(0, 0.5, 200), rng.uniform(0, 0.5, 200))]
    got = evaluate(p("bubble.e"), queries)
    worst = 0.0
    for (c, u, v), row in zip(queries, got):
        l0, l1, l2 = 1 - u - v, u, v
        ui, uij = corner[c], mid[c]  # midpoints of edges 01, 12, 20
        q = (sum(l * (2 * l - 1) * w for l, w in zip((l0, l1, l2), ui)) +
             4 * (l0 * l1 * uij[0] + l1 * l2 * uij[1] + l2 * l0 * uij[2]))
        expected = q + bubble[c] * 27 * l0 * l1 * l2
        x = tri[c][0] * l0 + tri[c][1] * l1 + tri[c][2] * l2  # straight cells
        worst = max(worst, abs(row[3] - expected) / span,
                    np.abs(np.array(row[:2]) - x[:2]).max())
    r.check(len(got) == len(queries) and worst < 1e-12,
            f"TRI7 with bubbles: eval differs from the interpolant by {worst:.3g}")
    res = run("tree", p("bubble.e"), "--json", p("bubble.json"), check=False)
    chk = run("check", p("bubble.json"), p("bubble.e"), check=False)
    r.check(res.returncode == 0 and chk.returncode == 0,
            f"TRI7 with bubbles: tree {res.returncode}, check {chk.returncode}: "
            f"{(res.stderr + chk.stdout + chk.stderr).strip()[-400:]}")

    # Only a block of line elements (boundary markers): skipped, and then no triangles.
    edges = np.array([[int(c[0]), int(c[1])] for c in cells])
    write_exodus(p("bars.e"), points[:, :2], edges, "BAR2", {field: [values]})
    res = run("tree", p("bars.e"), check=False)
    r.check(res.returncode == 1 and
            "no triangle or quadrilateral elements in its 1 element block" in res.stderr,
            f"BAR2 only: {res.returncode} {res.stderr.strip()[:300]}")

    # Quadrilaterals (MOOSE and SEACAS write QUAD4, QUAD8, QUAD9): a 4 x 4 grid of biquadratic
    # cells of the unit square carrying a biquadratic field, against the .vtu of the same cells
    # (VTK_BIQUADRATIC_QUAD 28, written by VTK); QUAD8 of a field in its (serendipity) space
    # too; QUAD4 through vtkExodusIIWriter against VTK_QUAD in a .vtu.
    m = 8
    qp = np.array([[i / m, j / m] for j in range(m + 1) for i in range(m + 1)])
    gid = lambda i, j: i + (m + 1) * j  # noqa: E731
    q9 = np.array([[gid(a, b), gid(a + 2, b), gid(a + 2, b + 2), gid(a, b + 2), gid(a + 1, b),
                    gid(a + 2, b + 1), gid(a + 1, b + 2), gid(a, b + 1), gid(a + 1, b + 1)]
                   for b in range(0, m, 2) for a in range(0, m, 2)])
    x, y = qp[:, 0], qp[:, 1]
    fq = (x - 0.37) * (x - 0.81) * (y + 0.3) * (y - 0.58) + 0.2 * x * x * y
    fs = (x - 0.37) * (x - 0.81) * (y + 0.3) + 0.4 * (y - 0.58) ** 2 * x + 0.1 * y
    for kind, conn, vtk_type, fv in (("QUAD9", q9, 28, fq), ("QUAD8", q9[:, :8], 23, fs)):
        g = vtkUnstructuredGrid()
        pts = vtkPoints()
        pts.SetData(numpy_to_vtk(np.hstack([qp, np.zeros((len(qp), 1))]), deep=True))
        g.SetPoints(pts)
        for c in conn:
            g.InsertNextCell(vtk_type, len(c), [int(i) for i in c])
        arr = numpy_to_vtk(np.asarray(fv, dtype=np.float64), deep=True)
        arr.SetName("f")
        g.GetPointData().AddArray(arr)
        vw = vtkXMLUnstructuredGridWriter()
        vw.SetFileName(p(f"{kind}.vtu"))
        vw.SetInputData(g)
        vw.Write()
        write_exodus(p(f"{kind}.e"), qp, conn, kind, {"f": [fv]})
        jq, res = tree_json(p(f"{kind}.e"))
        kq, _ = tree_json(p(f"{kind}.vtu"))
        r.check(len(kq["nodes"]) >= 4 and jq["input"]["cells"] == len(conn),
                f"{kind}: {len(kq['nodes'])} nodes, {jq['input']['cells']} cells")
        same_tree(f"Exodus {kind} vs VTK type {vtk_type} .vtu", jq, kq, 1e-12, 1e-12)

    # Truncated files: a clear error, never a crash.
    data = open(p("steps.exo"), "rb").read()
    for frac in (0.0, 0.001, 0.01, 0.05, 0.2, 0.4, 0.6, 0.8, 0.9, 0.95, 0.99, 0.999):
        cut = p("cut.exo")
        with open(cut, "wb") as fh:
            fh.write(data[:int(len(data) * frac)])
        res = run("tree", cut, check=False)
        r.check(res.returncode == 1 and "cut.exo" in res.stderr,
                f"truncated at {frac}: exit {res.returncode}: {res.stderr.strip()[-300:]}")

r.finish()
