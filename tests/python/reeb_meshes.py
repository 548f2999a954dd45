"""The surfaces of the Reeb-graph tests (test_reeb_graphs, test_mpi_reeb) and the fields on them:
.vtu files of Lagrange triangles of degrees 1-3 (VTK_LAGRANGE_TRIANGLE, VTK_QUADRATIC_TRIANGLE)
written with VTK, their nodes on the true curved circle or surface: structured meshes at exact
parametric positions (annuli, tori, Moebius strips, a square with square holes), or Gmsh's
(python3-gmsh) high-order meshes of OpenCASCADE geometry. A mesh is (points N x 3, cells T x n),
the cells' nodes in VTK's order, their first three the corners.

Importing it has no side effects; it needs numpy and VTK's Python modules (an ImportError
otherwise, which the tests turn into exit status 77, skipped); without Gmsh's Python module
HAVE_GMSH is False and gmsh_mesh cannot be called.
"""
import math

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import (VTK_LAGRANGE_TRIANGLE, VTK_QUADRATIC_TRIANGLE,
                                           vtkCellArray, vtkUnstructuredGrid)
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter

try:
    import gmsh
except ImportError:
    gmsh = None
HAVE_GMSH = gmsh is not None


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
    write_grid(path, grid)


def write_grid(path, grid):
    """A vtkUnstructuredGrid as binary VTK XML at path."""
    w = vtkXMLUnstructuredGridWriter()
    w.SetFileName(path)
    w.SetInputData(grid)
    w.SetDataModeToBinary()
    if not w.Write():
        raise RuntimeError(f"cannot write {path}")


def graph_shape(tree):
    """(degrees, components, loops) of a tree's or graph's arc graph (JSON of hoct tree;
    parallel arcs count)."""
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
    return parametric_mesh(ids, params,
                           lambda r, t: (cx + r * math.cos(t), r * math.sin(t), 0.0), d)


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


# --- Combining and cutting structured meshes --------------------------------------------------

def combined(*meshes):
    """The meshes in one file, in the order given (each one's cells after the previous ones'):
    separate components."""
    points, cells, base = [], [], 0
    for p, c in meshes:
        points.append(p)
        cells.append(c + base)
        base += len(p)
    return np.concatenate(points), np.concatenate(cells)


def square_with_holes(n, d, holes):
    """[0, 1]^2 in n x n squares of two straight triangles each, without the squares (i, j) with
    i0 <= i < i1 and j0 <= j < j1 for each (i0, i1, j0, j1) of holes: a planar disk with
    len(holes) holes if they are apart and inside."""
    ids, params = grid_triangles(n, n, lambda i, j: i * (n + 1) + j, lambda i: i / n,
                                 lambda j: j / n)
    cut = {(i, j) for i0, i1, j0, j1 in holes for i in range(i0, i1) for j in range(j0, j1)}
    keep = [t for t in range(len(ids)) if divmod(t // 2, n) not in cut]
    return parametric_mesh([ids[t] for t in keep], [params[t] for t in keep],
                           lambda u, v: (u, v, 0.0), d)


def write_field(path, mesh, f, cell_type=None):
    """write_vtu of the mesh with f(x, y, z) at its nodes."""
    points, cells = mesh
    write_vtu(path, points, cells, np.array([f(*p) for p in points]), cell_type)


# --- Fields -----------------------------------------------------------------------------------

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



HOLES = {1: [(0.1, 0.05, 0.35)],
         2: [(-0.4, 0.1, 0.25), (0.4, -0.1, 0.25)],
         3: [(-0.4, 0.1, 0.2), (0.35, 0.3, 0.15), (0.2, -0.45, 0.18)],
         5: [(-0.5, 0.0, 0.15), (0.0, 0.5, 0.15), (0.5, 0.05, 0.15), (0.0, -0.5, 0.15),
             (0.05, 0.0, 0.12)]}
