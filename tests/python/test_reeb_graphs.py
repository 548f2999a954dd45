"""Exact Reeb graphs of higher-order fields on domains that are not a disk or a sphere: annuli,
planar disks with 1, 2, 3 and 5 holes, tori, a genus-2 surface (two fused tori), a box drilled
through, two components in one file and Moebius strips, as .vtu files of Lagrange triangles of
degrees 1-3 (VTK_LAGRANGE_TRIANGLE, VTK_QUADRATIC_TRIANGLE) written here with VTK, their nodes on
the true curved circle or surface: structured meshes at exact parametric positions, or Gmsh's
(python3-gmsh) high-order meshes of OpenCASCADE geometry. The field at each node is an analytic
function of its position.

For each: `hoct tree --json` succeeds; the graph's first Betti number (arcs - nodes +
components of the arc graph) is the expected one (a Morse function on a closed orientable surface
of genus g: g; a near-linear function on a planar domain with h holes: h; a near-radial one on an
annulus: 0); its components are the domain's; its leaves are minima or maxima and the sum over
nodes of (degree - 2) is 2 (loops - components); the level-set oracle of level_sets.py (the
number of contours of VTK's own PL refinement at levels between node values equals the number of
arcs crossing them) agrees; the JSON's "kind" and "loops" and `hoct check` agree (see
reeb_fields); and the PL Reeb graphs of the refinements --refine 4 and 16 converge to it
(converges). First, the VTK node order written here is checked by `hoct eval` on straight cells
(a field that is a polynomial of the cell's degree is reproduced exactly) and on curved ones
(positions on the true surface). A failing case's .vtu is kept in /tmp/reeb_failures/.
"""
import json
import math
import os
import shutil
import sys
import time
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hoct_testing import Results, evaluate, run, tempdir  # noqa: E402

try:
    import numpy as np
    import level_sets  # numpy, scipy and VTK's Python modules
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import (VTK_LAGRANGE_TRIANGLE, VTK_QUADRATIC_TRIANGLE,
                                               vtkCellArray, vtkUnstructuredGrid)
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
except ImportError as e:
    print(f"skipped: numpy, scipy or VTK's Python modules are missing ({e})")
    sys.exit(77)
try:
    import gmsh
except ImportError:
    gmsh = None  # the Gmsh cases are skipped, the structured ones still run

R = Results()
FAILURES = "/tmp/reeb_failures"
RNG = np.random.default_rng(12345)


# --- Writing Lagrange triangles -------------------------------------------------------------

def lagrange_nodes(d):
    """The barycentric coordinates (of the corners 0, 1, 2) of a degree-d (1-3) triangle's nodes
    in VTK's order: the corners, then the nodes of edge 0-1 (from 0 towards 1), of edge 1-2, of
    edge 2-0, then the interior one (degree 3)."""
    assert 1 <= d <= 3
    b = [(1, 0, 0), (0, 1, 0), (0, 0, 1)]
    for i in range(1, d):
        b.append(((d - i) / d, i / d, 0))
    for i in range(1, d):
        b.append((0, (d - i) / d, i / d))
    for i in range(1, d):
        b.append((i / d, 0, (d - i) / d))
    if d == 3:
        b.append((1 / 3, 1 / 3, 1 / 3))
    return np.array(b, dtype=np.float64)


def node_keys(corners, d, cell):
    """Keys identifying a cell's nodes across cells: a corner by its vertex id, an edge node by
    its edge (ascending vertex ids) and its place from the lower id, an interior node by its
    cell."""
    a, b, c = corners
    keys = [("v", a), ("v", b), ("v", c)]
    for p, q in [(a, b), (b, c), (c, a)]:
        for i in range(1, d):
            keys.append(("e", p, q, i) if p < q else ("e", q, p, d - i))
    if d == 3:
        keys.append(("c", cell))
    return keys


def parametric_mesh(ids, params, F, d):
    """A degree-d mesh of a parametrised surface: triangles given by their corners' vertex ids
    (T x 3) and parameters (T x 3 x 2, unwrapped across periodic seams), each node at F of the
    parameters interpolated linearly in the triangle, i.e. on the true surface. Returns
    (points N x 3, cells T x n)."""
    B = lagrange_nodes(d)
    index, points, cells = {}, [], []
    for t, (corner_ids, corner_params) in enumerate(zip(ids, params)):
        cell = []
        for key, lam in zip(node_keys([int(i) for i in corner_ids], d, t), B):
            if key not in index:
                index[key] = len(points)
                points.append(F(*(lam @ np.asarray(corner_params, dtype=np.float64))))
            cell.append(index[key])
        cells.append(cell)
    return np.array(points, dtype=np.float64), np.array(cells, dtype=np.int64)


def write_vtu(path, points, cells, values, cell_type=None):
    """Writes the triangles (VTK node order) as VTK XML: degree 2 as VTK_QUADRATIC_TRIANGLE unless
    cell_type says otherwise, degrees 1 and 3 as VTK_LAGRANGE_TRIANGLE."""
    n = cells.shape[1]
    if cell_type is None:
        cell_type = VTK_QUADRATIC_TRIANGLE if n == 6 else VTK_LAGRANGE_TRIANGLE
    pts = vtkPoints()
    pts.SetData(numpy_to_vtk(np.ascontiguousarray(points, dtype=np.float64), deep=True))
    ca = vtkCellArray()
    offsets = np.arange(0, n * len(cells) + 1, n, dtype=np.int64)
    ca.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
               numpy_to_vtkIdTypeArray(np.ascontiguousarray(cells.ravel(), dtype=np.int64),
                                       deep=True))
    grid = vtkUnstructuredGrid()
    grid.SetPoints(pts)
    grid.SetCells(cell_type, ca)
    arr = numpy_to_vtk(np.ascontiguousarray(values, dtype=np.float64), deep=True)
    arr.SetName("f")
    grid.GetPointData().AddArray(arr)
    grid.GetPointData().SetActiveScalars("f")
    w = vtkXMLUnstructuredGridWriter()
    w.SetFileName(path)
    w.SetInputData(grid)
    w.SetDataModeToBinary()
    if not w.Write():
        raise RuntimeError(f"cannot write {path}")


# --- Structured meshes -------------------------------------------------------------------------

def grid_triangles(nu, nv, vid, pu, pv):
    """Two triangles per cell of an nu x nv grid (counter-clockwise in (u, v)): vertex ids
    vid(i, j) and parameters (pu(i), pv(j)) of the unwrapped grid point (i, j)."""
    ids, params = [], []
    for i in range(nu):
        for j in range(nv):
            q = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
            for tri in ([q[0], q[1], q[2]], [q[0], q[2], q[3]]):
                ids.append([vid(a, b) for a, b in tri])
                params.append([(pu(a), pv(b)) for a, b in tri])
    return ids, params


def square(n, d):
    """[0, 1]^2 in n x n squares, straight cells (for the node-order check)."""
    ids, params = grid_triangles(n, n, lambda i, j: i * (n + 1) + j, lambda i: i / n,
                                 lambda j: j / n)
    return parametric_mesh(ids, params, lambda u, v: (u, v, 0.0), d)


def annulus(nr, nt, d, r0=0.5, r1=1.0, cx=0.0):
    """r0 <= r <= r1 in polar coordinates (u = r, v = angle: counter-clockwise in the plane)."""
    ids, params = grid_triangles(nr, nt, lambda i, j: i * nt + j % nt,
                                 lambda i: r0 + (r1 - r0) * i / nr, lambda j: 2 * math.pi * j / nt)
    return parametric_mesh(ids, params, lambda r, t: (cx + r * math.cos(t), r * math.sin(t), 0.0), d)


def torus(nu, nv, d, R=2.0, r=0.7):
    ids, params = grid_triangles(nu, nv, lambda i, j: (i % nu) * nv + j % nv,
                                 lambda i: 2 * math.pi * i / nu, lambda j: 2 * math.pi * j / nv)
    return parametric_mesh(ids, params, lambda u, v: ((R + r * math.cos(v)) * math.cos(u),
                                                      (R + r * math.cos(v)) * math.sin(u),
                                                      r * math.sin(v)), d)


def moebius(n, m, d, w=0.4):
    """The strip of test_domains.moebius, n cells along and m across: (t, s) with
    -w <= s <= w; at t = 2 pi the side s meets the side -s (the half twist)."""
    def vid(k, j):
        return (k % n) * (m + 1) + (j if k < n else m - j)

    ids, params = grid_triangles(n, m, vid, lambda k: 2 * math.pi * k / n,
                                 lambda j: -w + 2 * w * j / m)
    return parametric_mesh(ids, params, lambda t, s: ((1 + s * math.cos(t / 2)) * math.cos(t),
                                                      (1 + s * math.cos(t / 2)) * math.sin(t),
                                                      s * math.sin(t / 2)), d)


# --- Gmsh meshes ----------------------------------------------------------------------------

def flipped(cell, d):
    """The same triangle with corners (0, 2, 1): its nodes in VTK order."""
    B = lagrange_nodes(d)
    old = {tuple(np.round(b, 9)): k for k, b in enumerate(B)}
    return [cell[old[tuple(np.round(b[[0, 2, 1]], 9))]] for b in B]


def orient(points, cells, d, planar):
    """Consistent orientation across shared edges (breadth first within each component): the
    neighbour of a triangle traverses their shared edge the other way. Planar components end
    counter-clockwise (normal +z)."""
    cells = [list(c) for c in cells]
    edges = {}
    for t, c in enumerate(cells):
        for k in range(3):
            edges.setdefault(frozenset((c[k], c[(k + 1) % 3])), []).append(t)
    seen = [False] * len(cells)
    for start in range(len(cells)):
        if seen[start]:
            continue
        seen[start], queue, component = True, [start], [start]
        while queue:
            t = queue.pop()
            c = cells[t]
            for k in range(3):
                a, b = c[k], c[(k + 1) % 3]
                for u in edges[frozenset((a, b))]:
                    if seen[u]:
                        continue
                    cu = cells[u]
                    same = any(cu[j] == a and cu[(j + 1) % 3] == b for j in range(3))
                    if same:
                        cells[u] = flipped(cu, d)
                    seen[u] = True
                    queue.append(u)
                    component.append(u)
        if planar:
            p = points[[cells[start][0], cells[start][1], cells[start][2]]]
            area = np.cross(p[1] - p[0], p[2] - p[0])[2]
            if area < 0:
                for t in component:
                    cells[t] = flipped(cells[t], d)
    return np.array(cells, dtype=np.int64)


def gmsh_mesh(build, d, size, planar):
    """Gmsh's degree-d triangles of the surfaces that build() makes with gmsh.model.occ (Gmsh's
    node order for triangles of orders 1-3 is VTK's), high-order nodes on the geometry."""
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("m")
        build(gmsh.model.occ)
        gmsh.model.occ.synchronize()
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        gmsh.option.setNumber("Mesh.MeshSizeMin", size / 3)
        gmsh.model.mesh.generate(2)
        if d > 1:
            gmsh.model.mesh.setOrder(d)
        tags, nodes = gmsh.model.mesh.getElementsByType({1: 2, 2: 9, 3: 21}[d])
        ntags, xyz, _ = gmsh.model.mesh.getNodes()
    finally:
        gmsh.finalize()
    xyz = np.asarray(xyz, dtype=np.float64).reshape(-1, 3)
    n = (d + 1) * (d + 2) // 2
    cells = np.asarray(nodes, dtype=np.int64).reshape(len(tags), n)
    used = np.unique(cells)
    where = {int(t): i for i, t in enumerate(ntags)}
    points = xyz[[where[int(t)] for t in used]]
    cells = np.searchsorted(used, cells)
    return points, orient(points, cells, d, planar)


def disk_with_holes(holes):
    def build(occ):
        disk = occ.addDisk(0, 0, 0, 1, 1)
        cut = [(2, occ.addDisk(x, y, 0, r, r)) for x, y, r in holes]
        occ.cut([(2, disk)], cut)
    return build


def disk_and_annulus(occ):
    occ.addDisk(0, 0, 0, 1, 1)
    outer = occ.addDisk(3, 0, 0, 1, 1)
    occ.cut([(2, outer)], [(2, occ.addDisk(3, 0, 0, 0.5, 0.5))])


def torus_solid(occ):
    occ.addTorus(0, 0, 0, 2, 0.7)


def double_torus(occ):
    a = occ.addTorus(0, 0, 0, 1, 0.35)
    b = occ.addTorus(2.4, 0, 0, 1, 0.35)
    occ.fuse([(3, a)], [(3, b)])


def drilled_box(occ):
    box = occ.addBox(-1, -1, -0.5, 2, 2, 1)
    occ.cut([(3, box)], [(3, occ.addCylinder(0, 0, -1, 0, 0, 2, 0.5))])


# --- Checks ---------------------------------------------------------------------------------

def graph_shape(tree):
    """(degrees, components, loops) of the arc graph (parallel arcs count)."""
    n = len(tree["nodes"])
    degree = [0] * n
    parent = list(range(n))

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    for a, b in tree["arcs"]:
        degree[a] += 1
        degree[b] += 1
        parent[find(a)] = find(b)
    components = len({find(a) for a in range(n)})
    return degree, components, len(tree["arcs"]) - n + components


def reeb_fields(name, tree, json_path, vtu, loops):
    """The JSON's "kind" and "loops" fields and `hoct check` accepting the graph: written against
    the Reeb-graph output as specified ("kind": "Reeb graph", "loops": the first Betti number),
    which may lag behind the graph itself; these are the checks to tighten or relax in one
    place."""
    R.check(tree.get("kind") == "Reeb graph", f"{name}: \"kind\" is {tree.get('kind')!r}")
    R.check(tree.get("loops") == loops, f"{name}: \"loops\" is {tree.get('loops')!r}, not {loops}")
    r = run("check", json_path, vtu, check=False)
    R.check(r.returncode == 0, f"{name}: hoct check exit {r.returncode}: "
                               f"{(r.stdout + r.stderr).strip()[-600:]}")


def converges(name, vtu, exact_json, exact):
    """The PL Reeb graphs of refinements (`--refine k`) converge to the exact one: at k = 16 the
    same number of loops, a bottleneck distance of all their diagrams (ordinary and loop pairs)
    no larger than at k = 4 and within 1e-3 of the range. Returns the two distances."""
    values = [n["value"] for n in exact["nodes"]]
    span = max(values) - min(values)
    dist = {}
    for k in (4, 16):
        out = f"{vtu}.refine{k}.json"
        run("tree", vtu, "-q", "--refine", str(k), "--json", out, "--no-timings")
        with open(out) as f:
            pl = json.load(f)
        R.check(pl["kind"] == "Reeb graph" and "forced" not in pl,
                f"{name} --refine {k}: {pl['kind']}, forced {pl.get('forced')}")
        d = json.loads(run("compare", exact_json, out, "--json").stdout)["bottleneck"]
        dist[k] = (d["max"], pl["loops"])
    R.check(dist[16][1] == exact["loops"],
            f"{name}: --refine 16 has {dist[16][1]} loops, the exact graph {exact['loops']}")
    R.check(dist[16][0] <= dist[4][0] + 1e-12 * span and dist[16][0] <= 1e-3 * span,
            f"{name}: bottleneck distance to --refine 4, 16: {dist[4][0]:.3g}, {dist[16][0]:.3g} "
            f"(range {span:.3g})")
    return dist[4][0], dist[16][0]


def bridges(tree):
    """The arcs whose removal disconnects their ends (brute force, parallel arcs included)."""
    n, arcs = len(tree["nodes"]), tree["arcs"]
    out = set()
    for k in range(len(arcs)):
        parent = list(range(n))

        def find(a):
            while parent[a] != a:
                parent[a] = parent[parent[a]]
                a = parent[a]
            return a
        for j, (a, b) in enumerate(arcs):
            if j != k:
                parent[find(a)] = find(b)
        if find(arcs[k][0]) != find(arcs[k][1]):
            out.add(k)
    return out


def check_svg(name, vtu, tree):
    """`hoct tree --svg` of a graph with loops: a circle per node (and 3 in the legend), a path
    per arc, the arcs on loops (no bridge, by brute force) exactly those drawn as loops."""
    svg = vtu + ".svg"
    run("tree", vtu, "-q", "--svg", svg)
    root = ET.parse(svg).getroot()
    ns = "{http://www.w3.org/2000/svg}"
    circles = root.findall(f".//{ns}circle")
    paths = root.findall(f".//{ns}path")
    loops = sum(p.get("class") == "loop" for p in paths)
    expected = len(tree["arcs"]) - len(bridges(tree))
    R.check(len(circles) == len(tree["nodes"]) + 3 and len(paths) == len(tree["arcs"]) and
            loops == expected, f"{name}: svg has {len(circles)} circles, {len(paths)} paths, "
            f"{loops} on loops; expected {len(tree['nodes'])} + 3, {len(tree['arcs'])}, {expected}")


def keep_failure(name, vtu):
    os.makedirs(FAILURES, exist_ok=True)
    target = os.path.join(FAILURES, name.replace(" ", "_").replace(",", "") + ".vtu")
    shutil.copyfile(vtu, target)
    print(f"  kept {target}", flush=True)


def check_positions(name, vtu, cells, surface, f, tol):
    """hoct eval at random points of random cells: the position on the true surface
    (|surface(x)| <= tol) and the value f(x) within tol (the interpolation error)."""
    uv = RNG.random((30, 2))
    uv = np.where(uv.sum(axis=1, keepdims=True) > 1, 1 - uv, uv)  # into the triangle
    pts = [(int(RNG.integers(cells)), float(a), float(b)) for a, b in uv]
    rows = np.array(evaluate(vtu, pts))
    geo = max(abs(surface(*p)) for p in rows[:, :3]) if surface else 0.0
    val = max(abs(v - f(*p)) for p, v in zip(rows[:, :3], rows[:, 3]))
    R.check(geo <= tol and val <= tol,
            f"{name}: hoct eval off the surface by {geo:.3g} or off the field by {val:.3g}")
    return max(geo, val)


def case(tmp, name, mesh, f, loops, components=1, level=2, surface=None, tol=1e-2,
         cell_type=None, max_loops=None):
    """Writes the mesh with f at its nodes, computes its Reeb graph and checks it (loops None:
    not asserted, only that the graph's shape and the oracle agree, and that there are at most
    max_loops: the domain's first Betti number bounds the graph's, the quotient map being onto
    on the fundamental group)."""
    t0 = time.time()
    points, cells = mesh
    vtu = os.path.join(tmp, name.replace(" ", "_").replace(",", "") + ".vtu")
    write_vtu(vtu, points, cells, np.array([f(*p) for p in points]), cell_type)
    failed = R.failed
    try:
        info = level_sets.check(R, name, vtu, level, quiet=True)
    except RuntimeError as e:
        R.check(False, f"{name}: {e}")
        keep_failure(name, vtu)
        return
    tree = info["tree"]
    degree, comps, got = graph_shape(tree)
    if loops is not None:
        R.check(got == loops, f"{name}: {got} loop(s), expected {loops}")
    if max_loops is not None:
        R.check(got <= max_loops, f"{name}: {got} loop(s), more than the domain's {max_loops}")
    R.check(comps == components, f"{name}: {comps} component(s), expected {components}")
    types = [n["type"] for n in tree["nodes"]]
    leaves = [k for k, g in enumerate(degree) if g == 1]
    R.check(all(types[k] in ("minimum", "maximum") for k in leaves),
            f"{name}: leaves that are no extremum: "
            f"{[(k, types[k]) for k in leaves if types[k] not in ('minimum', 'maximum')][:5]}")
    R.check(0 not in degree, f"{name}: isolated nodes")
    if loops is not None:  # (against the arcs' own count it would hold by construction)
        R.check(sum(g - 2 for g in degree) == 2 * (loops - components),
                f"{name}: sum of (degree - 2) is {sum(g - 2 for g in degree)}, "
                f"not 2 (loops - components) = {2 * (loops - components)}")
    reeb_fields(name, tree, info["json"], vtu, got if loops is None else loops)
    dev = check_positions(name, vtu, len(cells), surface, f, tol)
    if got > 0:
        check_svg(name, vtu, tree)
    d4, d16 = converges(name, vtu, info["json"], tree)
    bad = info["bad"]
    print(f"{name}: degree {int(round((math.sqrt(8 * cells.shape[1] + 1) - 3) / 2))}, "
          f"{len(cells)} cells; {len(tree['nodes'])} nodes, {len(tree['arcs'])} arcs, {got} loop(s), "
          f"{comps} component(s); {len(info['levels'])} levels checked, {len(bad)} disagree "
          f"(refinement error ~{info['err']:.2g}); eval deviation {dev:.2g}; "
          f"PL --refine 4, 16 at bottleneck {d4:.2g}, {d16:.2g}; "
          f"{time.time() - t0:.1f} s", flush=True)
    for c, arcs, contours in bad[:5]:
        print(f"  level {c!r}: {arcs} arcs cross it, {contours} contours", flush=True)
    if R.failed != failed:
        keep_failure(name, vtu)


def node_order(tmp):
    """The node order written here, through hoct eval on straight cells: a polynomial of the
    cell's degree is reproduced exactly (to rounding), and the position is the affine map of the
    corners at (u, v) (corner 1 at u = 1, corner 2 at v = 1)."""
    polys = {1: lambda x, y, z: 0.3 + 1.7 * x - 0.9 * y,
             2: lambda x, y, z: 0.3 + 1.7 * x - 0.9 * y + 2.1 * x * x - 1.3 * x * y + 0.7 * y * y,
             3: lambda x, y, z: (0.3 + 1.7 * x - 0.9 * y + 2.1 * x * x - 1.3 * x * y
                                 + 0.7 * y * y + 1.9 * x ** 3 - 2.3 * x * x * y
                                 + 0.6 * x * y * y - 1.1 * y ** 3)}
    for d, cell_type in [(1, VTK_LAGRANGE_TRIANGLE), (2, VTK_QUADRATIC_TRIANGLE),
                         (2, VTK_LAGRANGE_TRIANGLE), (3, VTK_LAGRANGE_TRIANGLE)]:
        points, cells = square(3, d)
        f = polys[d]
        vtu = os.path.join(tmp, f"order{d}_{cell_type}.vtu")
        write_vtu(vtu, points, cells, np.array([f(*p) for p in points]), cell_type)
        uv = [(int(RNG.integers(len(cells))), float(a), float(b))
              for a, b in RNG.random((40, 2)) if a + b <= 1]
        rows = np.array(evaluate(vtu, uv))
        corners = points[cells[[c for c, _, _ in uv], :3]]
        u = np.array([a for _, a, _ in uv])[:, None]
        v = np.array([b for _, _, b in uv])[:, None]
        affine = (1 - u - v) * corners[:, 0] + u * corners[:, 1] + v * corners[:, 2]
        pos = float(np.abs(rows[:, :3] - affine).max())
        val = max(abs(r[3] - f(*r[:3])) for r in rows)
        # A wrong order (here: the nodes of edges 0-1 and 1-2 swapped) is refused (gaps between
        # cells, folded cells) or does not reproduce the polynomial.
        wrong_note = "-"
        if d > 1:
            e = d - 1
            wrong = cells.copy()
            wrong[:, 3:3 + e], wrong[:, 3 + e:3 + 2 * e] = cells[:, 3 + e:3 + 2 * e], cells[:, 3:3 + e]
            bad_vtu = os.path.join(tmp, f"wrong{d}_{cell_type}.vtu")
            write_vtu(bad_vtu, points, wrong, np.array([f(*p) for p in points]), cell_type)
            text = "".join(f"{c} {a!r} {b!r}\n" for c, a, b in uv)
            r = run("eval", bad_vtu, "--points", "-", stdin=text, check=False)
            if r.returncode != 0:
                wrong_note = "refused: " + r.stderr.split("\n")[1].strip()
                val_w = float("inf")
            else:
                rows_w = [list(map(float, line.split()[3:])) for line in r.stdout.split("\n")
                          if line.strip()]
                val_w = max(abs(q[3] - f(*q[:3])) for q in rows_w)
                wrong_note = f"polynomial off by {val_w:.2g}"
        else:
            val_w = float("inf")
        R.check(pos < 1e-12 and val < 1e-10 and val_w > 1e-3,
                f"node order, degree {d}, VTK type {cell_type}: position off by {pos:.3g}, value "
                f"off by {val:.3g} (wrong order: {val_w:.3g})")
        print(f"node order, degree {d}, VTK type {cell_type}: {len(uv)} points, position "
              f"{pos:.2g}, polynomial {val:.2g} (edges swapped: {wrong_note})", flush=True)


# --- The cases ------------------------------------------------------------------------------

def planar(x, y, z):
    return x + 0.37 * y + 0.05 * math.sin(3 * y)


def tilted(x, y, z):
    return x + 0.3 * y


def radial(x, y, z):
    return x * x + y * y + 0.05 * x


def torus_f1(x, y, z):
    return x + 0.1 * z + 0.05 * y


def torus_f2(x, y, z):
    return z + 0.3 * x + 0.05 * y


def surface_f(x, y, z):
    return x + 0.2 * y + 0.1 * z


def wavy_torus(x, y, z):
    return math.sin(1.3 * x + 0.2) * math.cos(1.1 * y) + 0.5 * z + 0.05 * x


def wavy_surface(x, y, z):
    return math.sin(1.5 * x) * math.cos(2.0 * y) + 0.8 * z + 0.1 * y


def wavy_planar(x, y, z):
    return math.sin(4.1 * x + 0.3) * math.cos(3.7 * y - 0.2) + 0.2 * x


def moebius_f(x, y, z):
    return math.sin(2.1 * x + 0.3) * math.cos(1.7 * y - 0.2) + 0.3 * z + 0.05 * x


def on_annulus(r0, r1, cx=0.0):
    def residual(x, y, z):
        r = math.hypot(x - cx, y)
        return max(abs(z), r0 - r, r - r1, 0.0)
    return residual


def on_torus(R_, r_):
    return lambda x, y, z: math.hypot(math.hypot(x, y) - R_, z) - r_


def in_holed_disk(holes):
    def residual(x, y, z):
        out = max(abs(z), math.hypot(x, y) - 1, 0.0)
        for hx, hy, hr in holes:
            out = max(out, hr - math.hypot(x - hx, y - hy))
        return out
    return residual


HOLES = {1: [(0.1, 0.05, 0.35)],
         2: [(-0.4, 0.1, 0.25), (0.4, -0.1, 0.25)],
         3: [(-0.4, 0.1, 0.2), (0.35, 0.3, 0.15), (0.2, -0.45, 0.18)],
         5: [(-0.5, 0.0, 0.15), (0.0, 0.5, 0.15), (0.5, 0.05, 0.15), (0.0, -0.5, 0.15),
             (0.05, 0.0, 0.12)]}

with tempdir() as tmp:
    start = time.time()
    node_order(tmp)

    for d in (1, 3):
        case(tmp, f"annulus, x + 0.3 y, degree {d}", annulus(6, 48 if d == 1 else 24, d), tilted,
             loops=1, level=2, surface=on_annulus(0.5, 1.0), tol=2e-2 if d == 1 else 1e-4)
    case(tmp, "annulus, near-radial, degree 2", annulus(4, 32, 2), radial, loops=0,
         surface=on_annulus(0.5, 1.0), tol=1e-3)

    case(tmp, "torus, x + 0.1 z + 0.05 y, degree 2", torus(32, 12, 2), torus_f1, loops=1,
         surface=on_torus(2.0, 0.7), tol=2e-3)
    case(tmp, "torus, z + 0.3 x + 0.05 y, degree 3", torus(24, 10, 3), torus_f2, loops=1,
         surface=on_torus(2.0, 0.7), tol=1e-3)
    case(tmp, "torus, wavy, degree 3", torus(24, 10, 3), wavy_torus, loops=1,
         surface=on_torus(2.0, 0.7), tol=1e-3)
    case(tmp, "annulus, wavy, degree 2", annulus(6, 48, 2), wavy_planar, loops=None, max_loops=1,
         surface=on_annulus(0.5, 1.0), tol=1e-2)
    case(tmp, "Moebius strip n=96, degree 1", moebius(96, 2, 1), moebius_f, loops=None,
         max_loops=1, level=1, tol=0.15)
    case(tmp, "Moebius strip n=96, degree 2", moebius(96, 2, 2), moebius_f, loops=None,
         max_loops=1, tol=1e-2, cell_type=VTK_LAGRANGE_TRIANGLE)

    # hoct's own plate with 10 x 10 square holes (hoct generate plate): a loop round every hole.
    plate = os.path.join(tmp, "plate.vtu")
    run("generate", "plate", "--cells", "3000", "--degree", "2", "-o", plate)
    info = level_sets.check(R, "plate, 100 holes, degree 2", plate, 2)
    R.check(info["tree"]["kind"] == "Reeb graph" and info["tree"]["loops"] == 100,
            f"plate: {info['tree']['loops']} loops, expected 100")
    r = run("check", info["json"], plate, check=False)
    R.check(r.returncode == 0, f"plate: hoct check {r.stdout[-300:]}")
    d4, d16 = converges("plate", plate, info["json"], info["tree"])
    check_svg("plate", plate, info["tree"])
    print(f"plate: PL --refine 4, 16 at bottleneck {d4:.2g}, {d16:.2g}", flush=True)

    if gmsh is None:
        print("the Gmsh cases are skipped: python3-gmsh is missing")
    else:
        for h, d in [(1, 2), (2, 3), (3, 1), (5, 2)]:
            case(tmp, f"disk with {h} hole(s), degree {d}", gmsh_mesh(disk_with_holes(HOLES[h]), d,
                                                                       0.12, True),
                 planar, loops=h, level=1 if d == 1 else 2, surface=in_holed_disk(HOLES[h]),
                 tol=2e-2 if d == 1 else 1e-3,
                 cell_type=VTK_LAGRANGE_TRIANGLE if h == 5 else None)
        case(tmp, "disk with 3 holes, wavy, degree 3", gmsh_mesh(disk_with_holes(HOLES[3]), 3,
                                                                 0.12, True),
             wavy_planar, loops=None, max_loops=3, surface=in_holed_disk(HOLES[3]), tol=1e-2)
        case(tmp, "disk and annulus, x + 0.3 y, degree 3",
             gmsh_mesh(disk_and_annulus, 3, 0.15, True), tilted, loops=1, components=2,
             surface=lambda x, y, z: min(on_annulus(0, 1)(x, y, z),
                                         on_annulus(0.5, 1, 3.0)(x, y, z)), tol=1e-3)
        case(tmp, "torus (Gmsh), x + 0.1 z + 0.05 y, degree 2", gmsh_mesh(torus_solid, 2, 0.4, False),
             torus_f1, loops=1, surface=on_torus(2.0, 0.7), tol=5e-3)
        case(tmp, "drilled box (genus 1), x + 0.2 y + 0.1 z, degree 2",
             gmsh_mesh(drilled_box, 2, 0.3, False), surface_f, loops=1, tol=1e-3)
        case(tmp, "double torus (genus 2), x + 0.2 y + 0.1 z, degree 2",
             gmsh_mesh(double_torus, 2, 0.2, False), surface_f, loops=2, tol=5e-3)
        case(tmp, "double torus (genus 2), wavy, degree 3", gmsh_mesh(double_torus, 3, 0.2, False),
             wavy_surface, loops=2, tol=5e-3)
    print(f"total {time.time() - start:.1f} s")
R.finish()
