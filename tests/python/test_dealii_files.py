"""Files written by deal.II itself (Debian's libdeal.ii-dev 9.4), read by hoct.

tests/dealii/write_fields.cpp (a standalone CMake project, configured and built here in a
temporary directory) interpolates f(x, y) = sin(3x + 0.5) cos(2y + 0.5) + 0.3x on [0, 2]^2
(8 x 8 squares) with VectorTools::interpolate and writes it with DataOut and
write_higher_order_cells = true:
- simplex_p1.vtu, simplex_p2.vtu: FE_SimplexP 1 and 2 on subdivided_hyper_rectangle_with_simplices
  (each square cut into two triangles along its (x1, y0)-(x0, y1) diagonal), MappingFE;
  VTK_LAGRANGE_TRIANGLE (69) cells with 3 and 6 nodes;
- quad_q1.vtu, quad_q2.vtu, quad_q3.vtu: FE_Q 1, 2, 3 on subdivided_hyper_rectangle;
  VTK_LAGRANGE_QUADRILATERAL (70) cells of order 1, 2, 3, the function's values at equispaced
  nodes (FE_Q's own nodes are Gauss-Lobatto points from degree 3 on).
deal.II writes every cell with its own points (a point shared by k cells is written k times) and
points and values as Float32. What hoct must make of them:
- the layout, read with VTK's own reader: those cell types, cells x nodes points, the distinct
  positions of the mesh's nodes; hoct refuses the files as they are (duplicate vertices) and
  reads them with --merge-duplicates, merging exactly the duplicates; `hoct check` accepts the
  trees;
- an independent route: the same finite-element function written here with VTK's writer, in
  doubles, on triangles that share their nodes (P1, P2: f at the nodes of the same triangles;
  Q_p: the Q_p interpolant of f at the Gauss-Lobatto (p = 3) or equispaced nodes, evaluated here,
  on two triangles of degree 2p per square, i.e. the same polynomials without hoct's
  quadrilateral reader): the same tree, within the Float32 rounding of deal.II's values;
- the analytic field: every interior critical point of f (a minimum, a maximum and two saddles,
  in closed form) found with its type near its place (degree 2 and 3; the two saddles for Q1),
  and the bottleneck distance to the persistence diagrams of a fine piecewise-linear reference of
  f (400 x 400 squares) within the interpolation error (sampled here) plus the reference's bound.

Skipped (exit 77) where deal.II is not installed (HOCT_WITH_DEALII=1 ./scripts/setup installs
libdeal.ii-dev). Run by ctest with /usr/bin/python3 and HOCT_BIN set to the hoct executable."""
import itertools
import json
import math
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hoct_testing import (Results, bottleneck, compare_trees, run, tempdir, tree_json,  # noqa: E402
                          write_pl_reference)

PROJECT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "dealii")
SKIP_HINT = "HOCT_WITH_DEALII=1 ./scripts/setup installs libdeal.ii-dev"

try:
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkLagrangeTriangle, vtkUnstructuredGrid
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter
except ImportError as e:
    print(f"SKIPPED: numpy or VTK's Python modules are missing ({e})")
    sys.exit(77)

N = 8             # squares per side, as write_fields' default
H = 2.0 / N       # their side
FLOAT32 = 2e-7    # deal.II's Float32 values: relative rounding (2^-23 = 1.2e-7) and a margin
r = Results()


def f(x, y):
    return np.sin(3 * x + 0.5) * np.cos(2 * y + 0.5) + 0.3 * x


def analytic_critical_points():
    """f's interior critical points: f_y = 0 where sin(3x + .5) = 0 or sin(2y + .5) = 0, and then
    f_x = 0 fixes the other coordinate. (type, x, y)."""
    y0 = (math.pi - 0.5) / 2          # cos(2y + .5) = -1: cos(3x + .5) = 0.1
    a = math.acos(0.1)
    out = [("minimum", (a - 0.5) / 3, y0), ("maximum", (2 * math.pi - a - 0.5) / 3, y0)]
    # sin(3x + .5) = 0: 3x + .5 = pi (cos(2y + .5) = 0.1) or 2 pi (cos(2y + .5) = -0.1).
    out.append(("saddle", (math.pi - 0.5) / 3, (a - 0.5) / 2))
    out.append(("saddle", (2 * math.pi - 0.5) / 3, (math.acos(-0.1) - 0.5) / 2))
    for _, x, y in out:
        assert 0 < x < 2 and 0 < y < 2
    return out


def build_writer(d):
    """Configures and builds tests/dealii in d; exits 77 if CMake does not find deal.II 9.4."""
    if not shutil.which("cmake"):
        print(f"SKIPPED: cmake is not installed, so deal.II cannot be located ({SKIP_HINT})")
        sys.exit(77)
    t = time.monotonic()
    c = subprocess.run(["cmake", "-S", PROJECT, "-B", d], capture_output=True, text=True)
    if c.returncode != 0:
        if "deal.II" in c.stderr and ("Could not find" in c.stderr or
                                      "compatible with requested version" in c.stderr):
            print(f"SKIPPED: deal.II 9.4 not found by CMake ({SKIP_HINT}):\n"
                  f"{c.stderr.strip()[:600]}")
            sys.exit(77)
        raise RuntimeError(f"configuring {PROJECT} failed:\n{c.stdout[-2000:]}{c.stderr[-3000:]}")
    b = subprocess.run(["cmake", "--build", d], capture_output=True, text=True)
    if b.returncode != 0:
        raise RuntimeError(f"building write_fields failed:\n{b.stdout[-4000:]}{b.stderr[-3000:]}")
    print(f"built tests/dealii/write_fields in {time.monotonic() - t:.1f} s", flush=True)
    return os.path.join(d, "write_fields")


# --- The independent route: the same functions, evaluated here ---------------------------------

def cell_coords(x, y):
    """Square (i, j) of each point and the local coordinates (s, t) in [0, 1]^2."""
    i = np.clip(np.floor(x / H), 0, N - 1)
    j = np.clip(np.floor(y / H), 0, N - 1)
    return i, j, x / H - i, y / H - j


def simplex_function(degree):
    """The FE_SimplexP function of the given degree (1, 2: nodes at the vertices and edge
    midpoints, where it equals f) on deal.II's triangles, at arrays of points."""
    def fh(x, y):
        i, j, s, t = cell_coords(x, y)
        lower = s + t <= 1
        # Lower half (0,0) (1,0) (0,1); upper half (1,1) (0,1) (1,0), by symmetry.
        a, b = np.where(lower, s, 1 - s), np.where(lower, t, 1 - t)
        ox, oy = np.where(lower, i, i + 1), np.where(lower, j, j + 1)
        sx = np.where(lower, 1.0, -1.0)
        at = lambda u, v: f(H * (ox + sx * u), H * (oy + sx * v))  # noqa: E731
        l0, l1, l2 = 1 - a - b, a, b
        if degree == 1:
            return l0 * at(0, 0) + l1 * at(1, 0) + l2 * at(0, 1)
        return (l0 * (2 * l0 - 1) * at(0, 0) + l1 * (2 * l1 - 1) * at(1, 0) +
                l2 * (2 * l2 - 1) * at(0, 1) + 4 * l0 * l1 * at(0.5, 0) +
                4 * l1 * l2 * at(0.5, 0.5) + 4 * l2 * l0 * at(0, 0.5))
    return fh


def fe_q_nodes(p):
    """FE_Q(p)'s 1D support points on [0, 1]: Gauss-Lobatto points (equispaced for p <= 2)."""
    inner = np.polynomial.legendre.Legendre.basis(p).deriv().roots() if p > 1 else []
    return np.concatenate([[0.0], (np.sort(np.real(inner)) + 1) / 2, [1.0]])


def quad_function(p):
    """The FE_Q(p) interpolant of f (values at the tensor grid of fe_q_nodes) at points."""
    g = fe_q_nodes(p)

    def basis(k, s):
        out = np.ones_like(s)
        for m in range(p + 1):
            if m != k:
                out *= (s - g[m]) / (g[k] - g[m])
        return out

    def fh(x, y):
        i, j, s, t = cell_coords(x, y)
        total = np.zeros_like(x)
        for a, b in itertools.product(range(p + 1), repeat=2):
            total += f(H * (i + g[a]), H * (j + g[b])) * basis(a, s) * basis(b, t)
        return total
    return fh


def triangle_order(d):
    """VTK position of the lattice point (a, b) (at (a/d, b/d)) of a degree-d triangle."""
    c = vtkLagrangeTriangle()
    n = (d + 1) * (d + 2) // 2
    c.GetPointIds().SetNumberOfIds(n)
    c.GetPoints().SetNumberOfPoints(n)
    c.Initialize()
    pc = c.GetParametricCoords()
    return {(round(pc[3 * k] * d), round(pc[3 * k + 1] * d)): k for k in range(n)}


def write_triangles(path, d, fh, diagonal):
    """fh on the N x N squares, each cut into two triangles of degree d sharing their nodes, along
    (1,0)-(0,1) (deal.II's diagonal, diagonal 1) or (0,0)-(1,1) (diagonal 0), with VTK's writer in
    doubles: type 5 for d = 1, 69 above."""
    m = N * d
    gid = lambda I, J: I + (m + 1) * J  # noqa: E731
    I, J = np.meshgrid(np.arange(m + 1), np.arange(m + 1))
    xs, ys = (I.ravel() * H / d), (J.ravel() * H / d)
    values = fh(xs, ys)
    order = triangle_order(d)
    g = vtkUnstructuredGrid()
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    for x, y in zip(xs, ys):
        pts.InsertNextPoint(x, y, 0.0)
    g.SetPoints(pts)
    for cj, ci in itertools.product(range(N), range(N)):
        X, Y = ci * d, cj * d
        if diagonal == 1:  # (0,0) (1,0) (0,1) and (1,1) (0,1) (1,0)
            halves = [lambda a, b: (X + a, Y + b), lambda a, b: (X + d - a, Y + d - b)]
        else:  # (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1)
            halves = [lambda a, b: (X + a + b, Y + b), lambda a, b: (X + a, Y + a + b)]
        for half in halves:
            ids = [0] * len(order)
            for (a, b), k in order.items():
                ids[k] = gid(*half(a, b))
            g.InsertNextCell(5 if d == 1 else 69, len(ids), ids)
    arr = vtkDoubleArray()
    arr.SetName("f")
    for v in values:
        arr.InsertNextValue(float(v))
    g.GetPointData().SetScalars(arr)
    w = vtkXMLUnstructuredGridWriter()
    w.SetFileName(path)
    w.SetInputData(g)
    if not w.Write():
        raise RuntimeError(f"VTK could not write {path}")


# --- Checks --------------------------------------------------------------------------------------

def read_layout(path):
    """(cell types, points per cell, number of points, distinct positions, corners of each cell)
    as VTK's own reader sees the file."""
    rd = vtkXMLUnstructuredGridReader()
    rd.SetFileName(path)
    rd.Update()
    g = rd.GetOutput()
    types = vtk_to_numpy(g.GetCellTypesArray())
    offsets = vtk_to_numpy(g.GetCells().GetOffsetsArray())
    conn = vtk_to_numpy(g.GetCells().GetConnectivityArray())
    pts = vtk_to_numpy(g.GetPoints().GetData()).astype(float)
    distinct = len(np.unique(np.round(pts / H * 120).astype(np.int64), axis=0))
    ncorner = 3 if types[0] == 69 else 4
    corners = [pts[conn[offsets[k]:offsets[k] + ncorner]] for k in range(len(offsets) - 1)]
    return (set(types.tolist()), set(np.diff(offsets).tolist()), len(pts), distinct, corners,
            g.GetPoints().GetData().GetDataTypeAsString(),
            g.GetPointData().GetArray("f").GetDataTypeAsString())


def check_layout(name, path, vtk_type, nodes, cells, distinct):
    types, per_cell, npts, ndistinct, corners, ptype, vtype = read_layout(path)
    print(f"{name}: VTK types {sorted(types)}, {len(corners)} cells of {sorted(per_cell)} points, "
          f"{npts} points at {ndistinct} distinct positions; points {ptype}, values {vtype}",
          flush=True)
    r.check(types == {vtk_type} and per_cell == {nodes} and len(corners) == cells,
            f"{name}: cells {sorted(types)} of {sorted(per_cell)} points ({len(corners)}), "
            f"expected {cells} of type {vtk_type} with {nodes}")
    r.check(npts == cells * nodes and ndistinct == distinct,
            f"{name}: {npts} points at {ndistinct} positions, expected every cell's own "
            f"({cells * nodes}) at {distinct}")
    if vtk_type == 69:
        # deal.II's cut: (x0,y0) (x1,y0) (x0,y1) and (x1,y1) (x0,y1) (x1,y0), which
        # simplex_function and write_triangles(diagonal=1) assume.
        ok = True
        for c in corners:
            lo = c.min(axis=0)
            local = {(round(u), round(v)) for u, v in (c[:, :2] - lo[:2]) / H}
            ok = ok and local in ({(0, 0), (1, 0), (0, 1)}, {(1, 1), (0, 1), (1, 0)})
        r.check(ok, f"{name}: a triangle is not half of a square cut along (x1,y0)-(x0,y1)")
    return npts - ndistinct


def check_refused_unmerged(name, path):
    res = run("tree", path, check=False)
    r.check(res.returncode == 1 and "duplicate vertices" in res.stderr and
            "--merge-duplicates" in res.stderr,
            f"{name} without --merge-duplicates: {res.returncode} {res.stderr.strip()[:300]}")


def dealii_tree(name, path, duplicates):
    """hoct tree --merge-duplicates of a deal.II file, checked by hoct check: (JSON, its path)."""
    out = f"{path}.json"
    res = run("tree", path, "--merge-duplicates", "--json", out, "--no-timings")
    with open(out) as fp:
        j = json.load(fp)
    r.check(f"merged {duplicates} duplicate point(s)" in res.stderr,
            f"{name}: expected {duplicates} merged points: {res.stderr.strip()[:300]}")
    r.check(j["input"]["field"] == "f", f"{name}: field {j['input']['field']}")
    chk = run("check", out, path, "--merge-duplicates", check=False)
    r.check(chk.returncode == 0, f"{name}: hoct check: {chk.stdout[-600:]}{chk.stderr[-300:]}")
    return j, out


def check_critical_points(name, j, kinds, tol):
    """Each analytic interior critical point of a kind in `kinds` has a node of its type within
    tol; and every node strictly inside the domain is near one of them."""
    nodes = [(n["type"], n["position"][0], n["position"][1]) for n in j["nodes"]
             if n["location"] == "interior" or (1e-9 < n["position"][0] < 2 - 1e-9 and
                                                1e-9 < n["position"][1] < 2 - 1e-9)]
    for kind, x, y in analytic_critical_points():
        if kind not in kinds:
            continue
        near = [n for n in nodes if n[0] == kind and math.hypot(n[1] - x, n[2] - y) <= tol]
        r.check(len(near) == 1, f"{name}: analytic {kind} at ({x:.6f}, {y:.6f}): hoct's nodes "
                f"of that type within {tol}: {near} (interior nodes {nodes})")


def check_against_reference(name, dealii_json, reference_json, fh, reference_bound):
    """Bottleneck distances (join, split, global) to the fine PL tree of f: at most
    |f - fh| (sampled on a fine grid) + the reference's bound + Float32 rounding."""
    s = np.linspace(0, 2, 1601)
    X, Y = np.meshgrid(s, s)
    err = float(np.abs(fh(X.ravel(), Y.ravel()) - f(X.ravel(), Y.ravel())).max())
    bound = 1.05 * err + reference_bound + 1e-6
    bn = bottleneck(dealii_json, reference_json)
    print(f"{name}: sup |f - f_h| ~ {err:.3g}; bottleneck to the PL reference join "
          f"{bn['join']:.3g}, split {bn['split']:.3g}, global {bn['global']:.3g} "
          f"(bound {bound:.3g})", flush=True)
    r.check(bn["max"] <= bound and bn["global"] <= bound,
            f"{name}: bottleneck {bn} to the fine PL reference exceeds {bound:.3g}")


def check_same_as_independent(name, j, k):
    """deal.II's file (Float32) against the independent file (doubles) of the same function."""
    compare_trees(r, f"{name} vs the independent route", j, k, tol=10 * FLOAT32,
                  position_tol=1e-5)
    a = sorted((n["type"], n["value"], n["position"]) for n in j["nodes"])
    b = sorted((n["type"], n["value"], n["position"]) for n in k["nodes"])
    if len(a) == len(b):
        dv = max(abs(x[1] - y[1]) for x, y in zip(a, b))
        dp = max(max(abs(u - v) for u, v in zip(x[2], y[2])) for x, y in zip(a, b))
        print(f"{name}: {len(a)} nodes, as the independent route's within {dv:.2g} in value, "
              f"{dp:.2g} in position", flush=True)
    else:
        print(f"{name}: {len(a)} nodes {a}\n  independent route: {len(b)} nodes {b}", flush=True)


def simplex_cases(d, reference, reference_bound):
    for degree in (1, 2):
        name = f"deal.II FE_SimplexP({degree})"
        path = os.path.join(d, f"simplex_p{degree}.vtu")
        m = N * degree
        dup = check_layout(name, path, 69, 3 * degree, 2 * N * N, (m + 1) ** 2)
        check_refused_unmerged(name, path)
        j, tree_path = dealii_tree(name, path, dup)
        r.check(j["input"]["cells"] == 2 * N * N, f"{name}: {j['input']['cells']} cells")
        fh = simplex_function(degree)
        indep = os.path.join(d, f"indep_p{degree}.vtu")
        write_triangles(indep, degree, fh, diagonal=1)
        k, _ = tree_json(indep)
        check_same_as_independent(name, j, k)
        if degree == 2:
            check_critical_points(name, j, ("minimum", "maximum", "saddle"), 0.01)
        check_against_reference(name, tree_path, reference, fh, reference_bound)


def quad_cases(d, reference, reference_bound):
    """VTK_LAGRANGE_QUADRILATERAL (type 70) files, read by hoct's quadrilateral reader."""
    for p in (1, 2, 3):
        name = f"deal.II FE_Q({p})"
        path = os.path.join(d, f"quad_q{p}.vtu")
        dup = check_layout(name, path, 70, (p + 1) ** 2, N * N, (N * p + 1) ** 2)
        check_refused_unmerged(name, path)
        j, tree_path = dealii_tree(name, path, dup)
        r.check(j["input"]["cells"] == N * N, f"{name}: {j['input']['cells']} cells")
        fh = quad_function(p)
        indep = os.path.join(d, f"indep_q{p}.vtu")
        write_triangles(indep, 2 * p, fh, diagonal=0)
        k, _ = tree_json(indep)
        check_same_as_independent(name, j, k)
        kinds = ("saddle",) if p == 1 else ("minimum", "maximum", "saddle")
        check_critical_points(name, j, kinds, 0.02 if p == 1 else 0.01)
        check_against_reference(name, tree_path, reference, fh, reference_bound)


def pl_reference(d):
    """The PL tree of f on 400 x 400 squares of [0, 2]^2 (hoct_testing.write_pl_reference), and
    its bound |f - PL| <= M h^2 / 4 (M >= |Hessian of f|: sqrt(9^2 + 4^2 + 2 x 6^2) = 13)."""
    n = 400
    h = 2.0 / n
    path = os.path.join(d, "reference.vtu")
    write_pl_reference(path, f, 0.0, 2.0, n)
    out = os.path.join(d, "reference.json")
    run("tree", path, "--json", out, "--no-timings")
    return out, 13 * h * h / 4


with tempdir() as d:
    start = time.monotonic()
    writer = build_writer(os.path.join(d, "build"))
    out = os.path.join(d, "files")
    os.mkdir(out)
    w = subprocess.run([writer, out, str(N)], capture_output=True, text=True)
    if w.returncode != 0:
        raise RuntimeError(f"write_fields failed ({w.returncode}):\n{w.stdout}{w.stderr[-3000:]}")
    reference, reference_bound = pl_reference(d)
    simplex_cases(out, reference, reference_bound)
    quad_cases(out, reference, reference_bound)
    print(f"total {time.monotonic() - start:.1f} s")

r.finish()
