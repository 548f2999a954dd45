"""DOLFINx's degree >= 3 output (issue 28, item 6): nodes at Gauss-Lobatto-Legendre points of
straight cells, labelled as VTK's equispaced Lagrange nodes. The same cubic (and quartic) field
written once with equispaced nodes and once with GLL-placed nodes (edge nodes at the GLL points
of their edges) must give the same tree: the GLL file's values are samples at their true
positions. Read as equispaced nodes they are the wrong polynomial, with spurious features."""
import json
import os

import meshio
import numpy as np

from hoct_testing import Results, run, tempdir

R = Results()


def gll(d):
    """GLL points on [0, 1] (numpy's Legendre: the roots of P_d' and the ends)."""
    inner = np.polynomial.legendre.Legendre.basis(d).deriv().roots()
    return np.concatenate([[0.0], (np.sort(inner.real) + 1) / 2, [1.0]])


def vtk_lattice(d, t):
    """Reference positions of a degree-d VTK Lagrange triangle's nodes, edge nodes at t (the
    edge parameters, ascending); interior nodes equispaced (d = 3: the centroid)."""
    pts = [(0, 0), (1, 0), (0, 1)]
    pts += [(t[k], 0) for k in range(1, d)]
    pts += [(1 - t[k], t[k]) for k in range(1, d)]
    pts += [(0, 1 - t[k]) for k in range(1, d)]
    if d == 3:
        pts += [(1 / 3, 1 / 3)]
    elif d == 4:
        pts += [(0.25, 0.25), (0.5, 0.25), (0.25, 0.5)]
    return pts


def field(x, y):
    return (x - 0.3) ** 3 - 0.5 * (x - 0.3) + 0.7 * (y - 0.55) ** 2 - 0.2 * x * y


def write(path, d, t, n=6):
    corners, tris = {}, []
    for i in range(n):
        for j in range(n):
            a, b, c, e = (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)
            tris += [(a, b, c), (a, c, e)]
    index, points, cells = {}, [], []
    for tri in tris:
        p = [np.array(v, float) / n for v in tri]
        ids = []
        for (u, v) in vtk_lattice(d, t):
            q = p[0] + u * (p[1] - p[0]) + v * (p[2] - p[0])
            key = (round(q[0], 9), round(q[1], 9))
            if key not in index:
                index[key] = len(points)
                points.append((q[0], q[1], 0.0))
            ids.append(index[key])
        cells.append(ids)
    pts = np.array(points)
    meshio.write(path, meshio.Mesh(pts, [("VTK_LAGRANGE_TRIANGLE", np.array(cells))],
                                   point_data={"u": field(pts[:, 0], pts[:, 1])}))


def tree(path, d):
    out = path + ".json"
    r = run("tree", path, "--json", out, "-q")
    return json.load(open(out)), r.stderr


with tempdir() as tmp:
    for d in (3, 4):
        eq, lobatto = os.path.join(tmp, f"eq{d}.vtu"), os.path.join(tmp, f"gll{d}.vtu")
        write(eq, d, np.linspace(0, 1, d + 1))
        write(lobatto, d, gll(d))
        (te, note_e), (tg, note_g) = tree(eq, d), tree(lobatto, d)
        R.check("Gauss-Lobatto-Legendre" not in note_e, f"d={d}: a note on the equispaced file")
        R.check("72 cell(s) have" in note_g and "Gauss-Lobatto-Legendre" in note_g,
                f"d={d}: the GLL note: {note_g!r}")
        ve = sorted(nd["value"] for nd in te["nodes"])
        vg = sorted(nd["value"] for nd in tg["nodes"])
        R.check(len(ve) == len(vg) and max(abs(a - b) for a, b in zip(ve, vg)) < 1e-9,
                f"d={d}: GLL tree {len(vg)} nodes, equispaced {len(ve)}")
        pe = sorted(p["persistence"] for p in te["pairs"])
        pg = sorted(p["persistence"] for p in tg["pairs"])
        R.check(len(pe) == len(pg) and max(abs(a - b) for a, b in zip(pe, pg)) < 1e-9,
                f"d={d}: persistence {pg} against {pe}")
        R.check(len(te["arcs"]) == len(tg["arcs"]), f"d={d}: arcs")
        # hoct info shows a straight planar mesh: the GLL cells' geometry is their triangle.
        info = json.loads(run("info", lobatto, "--json").stdout)
        R.check(info["geometry"] == "planar-straight", f"d={d}: geometry {info['geometry']}")
R.finish()
