"""Quadrilateral and Bezier cells (VTK types 9, 23, 28, 70, 76, 77) against independent truth.

Files are written with VTK's own writer, their nodes placed with VTK's own numbering
(vtkLagrangeQuadrilateral.PointIndexFromIJK, vtkLagrangeTriangle's parametric coordinates), so
hoct's reading of each order is checked against VTK, not against itself. The truths:
- tensor-product fields f = g(x) h(y) with known critical points (the roots of g' and h', and of
  g and h) on quadrilaterals of orders 1-8, straight and curved: every interior critical point
  found, with its type, at its position;
- the same field on triangles of degree 2p through the same vertices: the same tree;
- serendipity (23) = biquadratic (28) on a field of the serendipity space; Bezier (77, 76) =
  Lagrange (70, 69) on the same polynomials (control values computed here by a Bernstein solve);
- a mesh of quadrilaterals and triangles together = the same field on triangles alone.
"""
import itertools
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from hoct_testing import Results, compare_trees, evaluate, run, tempdir, tree_json  # noqa: E402

try:
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import (vtkLagrangeQuadrilateral, vtkLagrangeTriangle,
                                               vtkUnstructuredGrid)
    from vtkmodules.vtkIOLegacy import vtkUnstructuredGridWriter
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
except ImportError as e:
    print(f"skipped: VTK's Python modules are missing ({e})")
    sys.exit(77)

r = Results()
N = 3  # cells per side of the unit square


def quad_order(p):
    """VTK position of the node (i, j) of an order-p quadrilateral, from VTK itself."""
    return {(i, j): vtkLagrangeQuadrilateral.PointIndexFromIJK(i, j, [p, p])
            for i in range(p + 1) for j in range(p + 1)}


def triangle_order(d):
    """VTK position of the lattice point (a, b) (at (a/d, b/d)) of a degree-d triangle."""
    c = vtkLagrangeTriangle()
    n = (d + 1) * (d + 2) // 2
    c.GetPointIds().SetNumberOfIds(n)
    c.GetPoints().SetNumberOfPoints(n)
    c.Initialize()
    pc = c.GetParametricCoords()
    return {(round(pc[3 * k] * d), round(pc[3 * k + 1] * d)): k for k in range(n)}


def write(path, points, values, cells, legacy=False):
    """cells: [(vtk type, [point ids in VTK order])]."""
    g = vtkUnstructuredGrid()
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    for x in points:
        pts.InsertNextPoint(*x)
    g.SetPoints(pts)
    for t, ids in cells:
        g.InsertNextCell(t, len(ids), list(ids))
    a = vtkDoubleArray()
    a.SetName("f")
    for v in values:
        a.InsertNextValue(v)
    g.GetPointData().SetScalars(a)
    w = vtkUnstructuredGridWriter() if legacy else vtkXMLUnstructuredGridWriter()
    if legacy:
        w.SetFileTypeToBinary()
    w.SetFileName(path)
    w.SetInputData(g)
    if not w.Write():
        raise RuntimeError(f"VTK could not write {path}")


def straight(x, y):
    return (x, y, 0.0)


def curved(x, y):
    """A bilinear map onto a saddle surface: exactly a cell's own geometry at every order."""
    return (x + 0.1 * x * y, y + 0.15 * x * y, 0.3 * x * y)


def lagrange_quads(p, f, place=straight, serendipity=False):
    """Order-p quadrilaterals on an N x N grid of the unit square, nodes shared: (points, values,
    cells). Serendipity (p = 2): the 8 boundary nodes (type 23)."""
    m = N * p
    gid = lambda I, J: I + (m + 1) * J  # noqa: E731
    order = quad_order(p)
    points = [place(I / m, J / m) for J in range(m + 1) for I in range(m + 1)]
    values = [f(I / m, J / m) for J in range(m + 1) for I in range(m + 1)]
    cells = []
    for cj, ci in itertools.product(range(N), range(N)):
        ids = [0] * (p + 1) ** 2
        for (i, j), k in order.items():
            ids[k] = gid(ci * p + i, cj * p + j)
        if serendipity:
            cells.append((23, ids[:8]))
        else:
            cells.append((9 if p == 1 else 70, ids))
    return points, values, cells


def triangles(d, f, place=straight, diagonal=0):
    """Each grid square of lagrange_quads cut into two triangles of degree d (through the same
    vertices), along (0,0)-(1,1) (diagonal 0) or (1,0)-(0,1)."""
    m = N * d
    gid = lambda I, J: I + (m + 1) * J  # noqa: E731
    order = triangle_order(d)
    points = [place(I / m, J / m) for J in range(m + 1) for I in range(m + 1)]
    values = [f(I / m, J / m) for J in range(m + 1) for I in range(m + 1)]
    cells = []
    for cj, ci in itertools.product(range(N), range(N)):
        X, Y = ci * d, cj * d
        if diagonal == 0:  # corners (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1)
            halves = [lambda a, b: (X + a + b, Y + b), lambda a, b: (X + a, Y + a + b)]
        else:  # (0,0) (1,0) (0,1) and (1,1) (0,1) (1,0)
            halves = [lambda a, b: (X + a, Y + b), lambda a, b: (X + d - a, Y + d - b)]
        for h in halves:
            ids = [0] * len(order)
            for (a, b), k in order.items():
                ids[k] = gid(*h(a, b))
            cells.append((5 if d == 1 else 69, ids))
    return points, values, cells


def poly_with_roots(roots, scale):
    c = np.poly(roots)
    xs = np.linspace(0, 1, 2001)
    return np.poly1d(c / (np.abs(np.polyval(c, xs)).max() * scale))


def factors(p):
    """g, h of degree p: roots spread over (0, 1) away from the cell edges k/N (for p >= 5 some
    roots outside the square: fewer, wider features); h lifted above zero, so that the critical
    points are the grid of g' = 0 by h' = 0, at distinct values (were g and h both zero on lines
    through the square, their crossings would be saddles on one level set: one tree node)."""
    inside = min(p, 4)
    # Unevenly spaced (evenly spaced roots make g symmetric: equal values, ties again).
    rg = [0.07 + 0.86 * ((k + 0.37) / inside) ** 1.3 for k in range(inside)] + \
         [1.35 + 0.4 * k for k in range(p - inside)]
    rh = [0.05 + 0.88 * ((k + 0.61) / inside) ** 0.8 for k in range(inside)] + \
         [-0.4 - 0.5 * k for k in range(p - inside)]
    return poly_with_roots(rg, 1.0), poly_with_roots(rh, 1.0) + 1.5


def real_roots_in(poly, lo=1e-6, hi=1 - 1e-6):
    out = []
    for z in np.roots(poly.coeffs) if poly.order > 0 else []:
        if abs(z.imag) < 1e-9 and lo < z.real < hi:
            out.append(float(z.real))
    return sorted(out)


def analytic_critical_points(g, h):
    """Interior critical points of g(x) h(y): [(type, x, y, value)]."""
    out = []
    for x in real_roots_in(g.deriv()):
        for y in real_roots_in(h.deriv()):
            a, b = g.deriv(2)(x) * h(y), g(x) * h.deriv(2)(y)
            kind = "maximum" if a < 0 and b < 0 else ("minimum" if a > 0 and b > 0 else "saddle")
            out.append((kind, x, y, g(x) * h(y)))
    for x in real_roots_in(g):
        for y in real_roots_in(h):
            out.append(("saddle", x, y, 0.0))
    return sorted(out)


def interior_nodes(j, place, tol=1e-6):
    """hoct's nodes strictly inside the square, as (type, x, y, value) in the unit square's
    coordinates (the inverse of `place`, found by Newton from the image)."""
    out = []
    for n in j["nodes"]:
        X = np.array(n["position"][:2])
        xy = X.copy()
        for _ in range(30):  # place is x + O(xy): Newton on its first two components
            F = np.array(place(*xy)[:2]) - X
            e = 1e-7
            J = np.array([[(place(xy[0] + e, xy[1])[k] - place(xy[0] - e, xy[1])[k]) / (2 * e),
                           (place(xy[0], xy[1] + e)[k] - place(xy[0], xy[1] - e)[k]) / (2 * e)]
                          for k in range(2)])
            xy = xy - np.linalg.solve(J, F)
        if tol < xy[0] < 1 - tol and tol < xy[1] < 1 - tol:
            out.append((n["type"], float(xy[0]), float(xy[1]), n["value"]))
    return sorted(out)


def same_points(name, got, expected, tol):
    ok = len(got) == len(expected)
    if ok:
        remaining = list(got)
        for e in expected:
            match = [g for g in remaining if g[0] == e[0] and abs(g[1] - e[1]) <= tol and
                     abs(g[2] - e[2]) <= tol and abs(g[3] - e[3]) <= tol]
            if not match:
                ok = False
                break
            remaining.remove(match[0])
    r.check(ok, f"{name}: interior critical points\n  expected {expected}\n  got      {got}")


def tree_checked(path, *extra):
    j, res = tree_json(path, *extra)
    c = run("check", f"{path}.{abs(hash(extra))}.json", path, *extra, check=False)
    r.check(c.returncode == 0, f"{path} {extra}: hoct check failed:\n{c.stdout[-1500:]}"
            f"{c.stderr[-1500:]}")
    return j, res


def bernstein_matrix(p):
    """V[k, i] = B_i^p(k / p)."""
    from math import comb
    return np.array([[comb(p, i) * (k / p) ** i * (1 - k / p) ** (p - i) for i in range(p + 1)]
                     for k in range(p + 1)])


def to_bezier_quads(points, values, cells, p):
    """The same polynomials as Bezier quadrilaterals (77): tensor Bernstein coefficients of the
    values and of each coordinate, C = V^-1 F V^-T per cell (shared edges get the same control
    points from both cells: an edge's coefficients depend on the edge alone)."""
    Vi = np.linalg.inv(bernstein_matrix(p))
    order = quad_order(p)
    P = np.array(points, dtype=float)
    F = np.array(values, dtype=float)
    cP, cF = P.copy(), F.copy()
    out = []
    for _, ids in cells:
        grid = np.empty((p + 1, p + 1), dtype=int)  # grid[i, j] = point id
        for (i, j), k in order.items():
            grid[i, j] = ids[k]
        cf = Vi @ F[grid] @ Vi.T
        cp = [Vi @ P[grid, a] @ Vi.T for a in range(3)]
        for i, j in order:
            cF[grid[i, j]] = cf[i, j]
            cP[grid[i, j]] = [cp[a][i, j] for a in range(3)]
        out.append((77, ids))
    return [tuple(x) for x in cP], list(cF), out


def to_bezier_triangles(points, values, cells, d):
    """The same as Bezier triangles (76): Bernstein coefficients by a solve on the lattice."""
    from math import factorial
    order = triangle_order(d)
    lattice = sorted(order)
    B = np.array([[factorial(d) / (factorial(a) * factorial(b) * factorial(d - a - b)) *
                   (u / d) ** a * (v / d) ** b * (1 - u / d - v / d) ** (d - a - b)
                   for (a, b) in lattice] for (u, v) in lattice])
    Bi = np.linalg.inv(B)
    P = np.array(points, dtype=float)
    F = np.array(values, dtype=float)
    cP, cF = P.copy(), F.copy()
    out = []
    for _, ids in cells:
        at = np.array([ids[order[q]] for q in lattice])
        cf = Bi @ F[at]
        cp = Bi @ P[at]
        for q, i in enumerate(at):
            cF[i] = cf[q]
            cP[i] = cp[q]
        out.append((76, ids))
    return [tuple(x) for x in cP], list(cF), out


with tempdir() as d:
    path = lambda name: os.path.join(d, name)  # noqa: E731

    # 1. Tensor-product fields, orders 1-8, straight and curved: the analytic critical points,
    #    and the tree of the same field on triangles of degree 2p.
    for p in range(1, 9):
        g, h = factors(p)
        f = lambda x, y: float(g(x) * h(y))  # noqa: E731
        expected = analytic_critical_points(g, h)
        for place, shape in ((straight, "straight"), (curved, "curved")):
            if shape == "curved" and p in (5, 7):
                continue  # orders 5 and 7: straight only (time)
            name = f"Q{p} {shape}"
            write(path(f"q{p}{shape}.vtu"), *lagrange_quads(p, f, place))
            j, res = tree_checked(path(f"q{p}{shape}.vtu"))
            r.check(j["input"]["cells"] == N * N, f"{name}: input cells {j['input']['cells']}")
            same_points(name, interior_nodes(j, place), expected, 1e-7)
            if p <= 6 or shape == "straight":
                write(path(f"t{p}{shape}.vtu"), *triangles(2 * p, f, place))
                k, _ = tree_json(path(f"t{p}{shape}.vtu"))
                compare_trees(r, f"{name} vs P{2 * p} triangles", j, k, tol=1e-9,
                              position_tol=1e-9)

    # 2. VTK_QUAD (9), VTK_BIQUADRATIC_QUAD (28), VTK_QUADRATIC_QUAD (23, serendipity) and the
    #    legacy .vtk route (VTK's reader) on fields of their spaces.
    g, h = factors(2)
    fs = lambda x, y: float(g(x) * (0.3 + y) + 0.4 * h(y) * x + 0.2 * x * x * y)  # noqa: E731
    pts, vals, cells70 = lagrange_quads(2, fs)
    cells28 = [(28, ids) for _, ids in cells70]
    write(path("q28.vtu"), pts, vals, cells28)
    write(path("q70.vtu"), pts, vals, cells70)
    ref, _ = tree_checked(path("q70.vtu"))
    j28, _ = tree_checked(path("q28.vtu"))
    compare_trees(r, "VTK_BIQUADRATIC_QUAD vs VTK_LAGRANGE_QUADRILATERAL", ref, j28, tol=1e-12)
    pts, vals, cells23 = lagrange_quads(2, fs, serendipity=True)
    write(path("q23.vtu"), pts, vals, cells23)
    j23, _ = tree_checked(path("q23.vtu"))
    compare_trees(r, "VTK_QUADRATIC_QUAD (serendipity) vs biquadratic", ref, j23, tol=1e-9,
                  position_tol=1e-9)
    write(path("q70.vtk"), *lagrange_quads(2, fs), legacy=True)
    jl, _ = tree_json(path("q70.vtk"))
    compare_trees(r, "legacy .vtk (VTK's reader) vs .vtu", ref, jl, tol=1e-12)
    g1, h1 = factors(1)
    f1 = lambda x, y: float(g1(x) * h1(y) + 0.1 * x)  # noqa: E731
    pts, vals, cells = lagrange_quads(1, f1)
    write(path("q9.vtu"), pts, vals, cells)
    j9, _ = tree_checked(path("q9.vtu"))
    write(path("t9.vtu"), *triangles(2, f1))
    k9, _ = tree_json(path("t9.vtu"))
    compare_trees(r, "VTK_QUAD vs P2 triangles", j9, k9, tol=1e-9, position_tol=1e-9)

    # 3. Bezier cells: the same polynomials as Lagrange cells.
    for p in (2, 3, 5):
        g, h = factors(p)
        f = lambda x, y: float(g(x) * h(y) + 0.05 * x)  # noqa: E731
        lag = lagrange_quads(p, f, curved)
        write(path(f"b{p}lag.vtu"), *lag)
        write(path(f"b{p}.vtu"), *to_bezier_quads(*lag, p))
        jl, _ = tree_json(path(f"b{p}lag.vtu"))
        jb, _ = tree_checked(path(f"b{p}.vtu"))
        compare_trees(r, f"Bezier quadrilaterals Q{p} vs Lagrange", jl, jb, tol=1e-9,
                      position_tol=1e-9)
    for dgr in (2, 4):
        g, h = factors(2)
        f = lambda x, y: float(g(x) + h(y) + 0.3 * x * y * (dgr > 2))  # noqa: E731
        lag = triangles(dgr, f, curved, diagonal=1)
        write(path(f"bt{dgr}lag.vtu"), *lag)
        write(path(f"bt{dgr}.vtu"), *to_bezier_triangles(*lag, dgr))
        jl, _ = tree_json(path(f"bt{dgr}lag.vtu"))
        jb, _ = tree_checked(path(f"bt{dgr}.vtu"))
        compare_trees(r, f"Bezier triangles P{dgr} vs Lagrange", jl, jb, tol=1e-9,
                      position_tol=1e-9)

    # 4. Quadrilaterals and triangles in one mesh: the left column of squares as order-3
    #    quadrilaterals, the rest as cubic triangles sharing their nodes; the field G(x) + H(y)
    #    lies in both spaces. Against the all-triangle mesh.
    g, h = factors(3)
    f = lambda x, y: float(g(x) + 0.8 * h(y))  # noqa: E731
    pts, vals, tris = triangles(3, f)
    _, _, quads = lagrange_quads(3, f)
    mixed = [c for k, c in enumerate(tris) if (k // 2) % N != 0] + \
            [c for k, c in enumerate(quads) if k % N == 0]
    write(path("mixed.vtu"), pts, vals, mixed)
    write(path("alltri.vtu"), pts, vals, tris)
    jm, _ = tree_checked(path("mixed.vtu"))
    jt, _ = tree_json(path("alltri.vtu"))
    compare_trees(r, "quadrilaterals and triangles vs triangles", jm, jt, tol=1e-9,
                  position_tol=1e-9)
    r.check(jm["input"]["cells"] == 2 * N * N - N, f"mixed: input cells {jm['input']['cells']}")

    # 5. `hoct eval` at (cell, s, t) of a quadrilateral's unit square: the field and the map,
    #    exactly the polynomials written (order 3, curved), on both triangles of each cell.
    g, h = factors(3)
    rng = np.random.default_rng(29)
    queries = [(int(c), float(s_), float(t_)) for c, s_, t_ in zip(
        rng.integers(0, N * N, 200), rng.uniform(0, 1, 200), rng.uniform(0, 1, 200))]
    rows = evaluate(path("q3curved.vtu"), queries)
    worst = 0.0
    for (c, s_, t_), row in zip(queries, rows):
        x, y = (c % N + s_) / N, (c // N + t_) / N
        worst = max(worst, abs(row[3] - g(x) * h(y)),
                    max(abs(a - b) for a, b in zip(row[:3], curved(x, y))))
    r.check(len(rows) == len(queries) and worst < 1e-12,
            f"eval on quadrilaterals: off the polynomials by {worst:.3g}")
    bad = run("eval", path("q3curved.vtu"), "--points", "-", stdin="0 0.5 1.2\n", check=False)
    r.check(bad.returncode != 0 and "outside the unit square of quadrilateral 0" in bad.stderr,
            f"eval outside a quadrilateral: {bad.returncode} {bad.stderr.strip()[:300]}")

    # 6. The other modes read quadrilaterals too: linear (the nodes' PL field) and refine.
    for mode in (["--linear"], ["--refine", "4"]):
        j, res = tree_json(path("q3straight.vtu"), *mode)
        r.check(len(j["nodes"]) >= 2, f"Q3 {mode}: {len(j['nodes'])} nodes")

r.finish()
