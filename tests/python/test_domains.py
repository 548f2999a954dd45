"""Hostile domains through the command line (issue 8, item 4): an annulus, two components, a
Moebius strip, non-manifold edges and vertices, duplicate vertices and an inverted cell, each
written as .vtu with VTK. hoct computes the Reeb graph of surfaces that are not disks (holes,
handles, a twist, several pieces) by every method, must explain the rest, refuse what it cannot
compute, and with --force compute what is well defined and label it; --merge-duplicates repairs
cracks."""
import json
import math
import os

import vtk

from hoct_testing import Results, run, tempdir

R = Results()


def field(p):
    x, y, z = p
    return math.sin(2.1 * x + 0.3) * math.cos(1.7 * y - 0.2) + 0.3 * z + 0.05 * x


def write_vtu(path, points, triangles, values=None):
    pts = vtk.vtkPoints()
    for p in points:
        pts.InsertNextPoint(*p)
    grid = vtk.vtkUnstructuredGrid()
    grid.SetPoints(pts)
    for t in triangles:
        ids = vtk.vtkIdList()
        for i in t:
            ids.InsertNextId(i)
        grid.InsertNextCell(vtk.VTK_TRIANGLE, ids)
    arr = vtk.vtkDoubleArray()
    arr.SetName("f")
    for i, p in enumerate(points):
        arr.InsertNextValue(values[i] if values else field(p))
    grid.GetPointData().AddArray(arr)
    w = vtk.vtkXMLUnstructuredGridWriter()
    w.SetFileName(path)
    w.SetInputData(grid)
    w.Write()


def grid(nx, ny, x0=0.0, y0=0.0):
    """(nx+1) x (ny+1) points on [x0, x0+nx] x [y0, y0+ny] scaled by 1/4, counter-clockwise."""
    pts = [((x0 + i) / 4, (y0 + j) / 4, 0.0) for j in range(ny + 1) for i in range(nx + 1)]
    idx = lambda i, j: j * (nx + 1) + i
    tris = []
    for j in range(ny):
        for i in range(nx):
            tris += [(idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)),
                     (idx(i, j), idx(i + 1, j + 1), idx(i, j + 1))]
    return pts, tris


def annulus(n=24, rings=3):
    pts = [(r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n), 0.0)
           for r in [1 + 0.5 * q for q in range(rings)] for k in range(n)]
    tris = []
    for q in range(rings - 1):
        for k in range(n):
            a, b = q * n + k, q * n + (k + 1) % n
            c, d = a + n, b + n
            tris += [(a, b, d), (a, d, c)]
    return pts, tris


def moebius(n=24):
    pts = []
    for k in range(n):
        t = 2 * math.pi * k / n
        for s in (-0.4, 0.4):
            r = 1 + s * math.cos(t / 2)
            pts.append((r * math.cos(t), r * math.sin(t), s * math.sin(t / 2)))
    tris = []
    for k in range(n):
        a, b = 2 * k, 2 * k + 1
        if k + 1 < n:
            c, d = 2 * k + 2, 2 * k + 3
        else:
            c, d = 1, 0  # the half twist: the strip closes with its sides swapped
        tris += [(a, b, d), (a, d, c)]
    return pts, tris


def torus(n=16, m=8):
    pts = [((2 + math.cos(2 * math.pi * j / m)) * math.cos(2 * math.pi * i / n),
            (2 + math.cos(2 * math.pi * j / m)) * math.sin(2 * math.pi * i / n),
            math.sin(2 * math.pi * j / m)) for i in range(n) for j in range(m)]
    idx = lambda i, j: (i % n) * m + (j % m)
    tris = []
    for i in range(n):
        for j in range(m):
            tris += [(idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)),
                     (idx(i, j), idx(i + 1, j + 1), idx(i, j + 1))]
    return pts, tris


def tree(path, *extra, check=False):
    return run("tree", path, "-q", *extra, check=check)


def expect_refused(name, path, words, extra=()):
    r = tree(path, *extra)
    R.check(r.returncode == 1, f"{name}: exit {r.returncode}")
    for w in words:
        R.check(w in r.stderr, f"{name}: '{w}' not in: {r.stderr.strip()[:400]}")
    return r


with tempdir() as tmp:
    p = lambda name: os.path.join(tmp, name)

    # A disk first: the baseline passes everything.
    pts, tris = grid(6, 6)
    write_vtu(p("disk.vtu"), pts, tris)
    tree(p("disk.vtu"), "--json", p("disk.json"), check=True)
    R.check("forced" not in json.load(open(p("disk.json"))), "disk: not forced")
    R.check(run("check", p("disk.json"), p("disk.vtu"), check=False).returncode == 0, "disk: check")

    def reeb(name, path, loops, *extra):
        """A Reeb graph: not forced, kind and loops recorded, checked."""
        out = p(name.replace(" ", "_") + ".json")
        r = tree(path, "--json", out, *extra)
        R.check(r.returncode == 0, f"{name}: exit {r.returncode}: {r.stderr.strip()[:300]}")
        if r.returncode != 0:
            return None
        t = json.load(open(out))
        R.check("forced" not in t, f"{name}: not forced")
        R.check(t["kind"] == "Reeb graph" and t["loops"] == loops,
                f"{name}: {t['kind']} with {t['loops']} loops, expected {loops}")
        r = run("check", out, path, check=False)
        R.check(r.returncode == 0, f"{name}: check {r.stdout[-300:]}")
        return t

    def same_graph(name, a, b):
        """Two methods' graphs of one linear field: the same nodes (types, values), arcs, loops."""
        if a is None or b is None:
            return
        key = lambda t: sorted((n["type"], round(n["value"], 12)) for n in t["nodes"])
        R.check(key(a) == key(b) and len(a["arcs"]) == len(b["arcs"]) and a["loops"] == b["loops"],
                f"{name}: the piecewise-linear methods' graph differs from the exact one")

    def all_methods(name, path, loops):
        """Every method computes the Reeb graph, without --force; on these linear fields the
        piecewise-linear methods' graphs are the exact one (refined: the same, finer)."""
        exact = reeb(name, path, loops)
        same_graph(name + " --linear", exact, reeb(name + " --linear", path, loops, "--linear"))
        same_graph(name + " --refine 3", exact,
                   reeb(name + " --refine 3", path, loops, "--refine", "3"))
        return exact

    # Annulus: a hole. Every method computes the Reeb graph, with no --force.
    write_vtu(p("annulus.vtu"), *annulus())
    all_methods("annulus", p("annulus.vtu"), 1)
    # --force (and its old alias) is accepted where nothing needs forcing, and says nothing.
    for flag in ("--force", "--allow-non-simply-connected"):
        r = tree(p("annulus.vtu"), "--linear", flag, "--json", p("annulus_forced.json"))
        R.check(r.returncode == 0 and "warning" not in r.stderr and
                "forced" not in json.load(open(p("annulus_forced.json"))),
                f"annulus {flag}: exit {r.returncode}, {r.stderr.strip()[:200]}")

    # Two components: a forest, one graph per component, which the checker accepts.
    a_pts, a_tris = grid(3, 3)
    b_pts, b_tris = grid(3, 3, x0=5)
    off = len(a_pts)
    write_vtu(p("two.vtu"), a_pts + b_pts, a_tris + [(x + off, y + off, z + off) for x, y, z in b_tris])
    t = all_methods("two", p("two.vtu"), 0)
    R.check(t is not None and len(t["arcs"]) == len(t["nodes"]) - 2,
            "two components: a forest of 2 trees")

    # Moebius strip: non-orientable; its Reeb graph has a loop here (the strip goes round once).
    write_vtu(p("moebius.vtu"), *moebius())
    all_methods("moebius", p("moebius.vtu"), 1)
    info = run("info", p("moebius.vtu"), check=False).stdout
    R.check("non-orientable" in info, "info names the non-orientable surface")

    # Torus: a handle; the level sets of this field go once round it (one loop).
    write_vtu(p("torus.vtu"), *torus())
    all_methods("torus", p("torus.vtu"), 1)

    # Non-manifold: three triangles on one edge, and two disks touching at one vertex. Never
    # computed, not even with --force.
    pts = [(0, 0, 0), (1, 0, 0), (0.5, 1, 0), (0.5, -1, 0), (0.5, 0, 1)]
    write_vtu(p("fin.vtu"), pts, [(0, 1, 2), (1, 0, 3), (0, 1, 4)])
    expect_refused("three triangles on an edge", p("fin.vtu"), ["non-manifold edge", "shared by 3 cells"])
    expect_refused("fin --force", p("fin.vtu"), ["non-manifold edge", "cannot go past"], ["--force"])
    pts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (-1, 0, 0), (-1, -1, 0), (0, -1, 0)]
    write_vtu(p("bowtie.vtu"), pts, [(0, 1, 2), (0, 2, 3), (0, 4, 5), (0, 5, 6)])
    expect_refused("two disks sharing a vertex", p("bowtie.vtu"), ["non-manifold vertex", "point 0"])

    # Duplicate vertices: the right half of a grid has its own copy of the middle column.
    pts, tris = grid(6, 4)
    n_before = len(pts)
    copies = {}
    split_tris = []
    for t in tris:
        xs = [pts[i][0] for i in t]
        if min(xs) >= 3 / 4:  # right half: use copies of the seam's points
            nt = []
            for i in t:
                if abs(pts[i][0] - 3 / 4) < 1e-12:
                    if i not in copies:
                        copies[i] = len(pts)
                        pts.append(pts[i])
                    nt.append(copies[i])
                else:
                    nt.append(i)
            split_tris.append(tuple(nt))
        else:
            split_tris.append(t)
    write_vtu(p("crack.vtu"), pts, split_tris)
    r = expect_refused("duplicate vertices", p("crack.vtu"),
                       ["duplicate vertices", "same position", "--merge-duplicates"])
    r = tree(p("crack.vtu"), "--merge-duplicates", "--json", p("merged.json"))
    R.check(r.returncode == 0 and f"merged {len(copies)} duplicate point(s)" in r.stderr,
            f"--merge-duplicates: {r.returncode} {r.stderr.strip()}")
    write_vtu(p("whole.vtu"), *grid(6, 4))
    tree(p("whole.vtu"), "--json", p("whole.json"), check=True)
    m, w = json.load(open(p("merged.json"))), json.load(open(p("whole.json")))
    R.check([n["value"] for n in m["nodes"]] == [n["value"] for n in w["nodes"]] and
            m["arcs"] == w["arcs"], "merged crack gives the tree of the whole mesh")
    r = tree(p("crack.vtu"), "--merge-duplicates=1e-12")
    R.check(r.returncode == 0, "--merge-duplicates=TOL")
    # Duplicates with different values: a discontinuity, not merged.
    vals = [field(q) for q in pts]
    for i, c in copies.items():
        vals[c] = vals[i] + 0.5
    write_vtu(p("jump.vtu"), pts, split_tris, vals)
    expect_refused("discontinuous duplicates", p("jump.vtu"), ["discontinuous", "not merged"],
                   ["--merge-duplicates"])
    # info shows the duplicates too.
    info = run("info", p("crack.vtu"), check=False)
    R.check(info.returncode == 1 and "duplicate vertices" in info.stdout, "info: duplicates")
    R.check(run("info", p("crack.vtu"), "--merge-duplicates", check=False).returncode == 0,
            "info --merge-duplicates")

    # An inverted cell: the fan around a square's centre, the centre moved out through one side.
    pts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, -0.3, 0)]
    write_vtu(p("inverted.vtu"), pts, [(4, 0, 1), (4, 1, 2), (4, 2, 3), (4, 3, 0)])
    expect_refused("inverted cell", p("inverted.vtu"), ["inverted cell", "cell 0"])
    r = tree(p("inverted.vtu"), "--force", "--json", p("inv.json"))
    t = json.load(open(p("inv.json"))) if r.returncode == 0 else {}
    R.check(r.returncode == 0 and t.get("forced") and any("inverted" in x for x in t["forced_reasons"]),
            f"inverted --force: {r.stderr.strip()}")

R.finish()
