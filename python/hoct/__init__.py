"""hoct: exact contour trees of piecewise-polynomial (higher-order finite-element) fields.

    import hoct
    mesh = hoct.read("field.vtu")                 # or hoct.from_arrays / hoct.from_meshio
    tree = hoct.contour_tree(mesh, simplify="0.5%")
    tree.positions, tree.values, tree.types, tree.arcs, tree.pairs, tree.branches
    tree.to_networkx()

The same library computes what the `hoct` command line prints: the results are identical.
"""
from . import _hoct
from ._hoct import HoctError, Mesh, Tree

__all__ = ["read", "from_arrays", "from_meshio", "generate", "contour_tree", "Mesh", "Tree",
           "HoctError"]


def read(path, scalar=None, max_memory=None, threads=None, merge_duplicates=None):
    """Read a .vtu or .msh file; `scalar` names the point-data array (default: the first).

    `threads`: threads that read large arrays and build the mesh (default: every hardware
    thread, as `contour_tree`); the mesh is the same for any number.

    `max_memory` is the memory budget the readers check against the file's header counts
    before allocating, as for `hoct --max-memory`: bytes (int) or text such as "8G", "512M" or
    "50%" of the physical memory; default 80% of the physical memory. A file whose counts need
    more is refused with HoctError ("needs ~X GiB, limit Y GiB") before anything is allocated.

    `merge_duplicates`: merge points at the same position before building the mesh, as
    `hoct tree --merge-duplicates[=TOL]`: True (within 1e-9 of the bounding-box diagonal) or a
    tolerance TOL between 0 and 0.1."""
    if max_memory is None:
        budget = ""
    elif isinstance(max_memory, bool):
        raise HoctError("read: max_memory must be a number of bytes or a size such as '8G'")
    elif isinstance(max_memory, int):
        if max_memory <= 0:
            raise HoctError("read: max_memory must be positive, got %d" % max_memory)
        budget = str(max_memory)
    else:
        budget = str(max_memory)
    if threads is not None and (isinstance(threads, bool) or not isinstance(threads, int)
                                or threads < 1):
        raise HoctError("read: threads must be a positive integer, got %r" % (threads,))
    if merge_duplicates is None or merge_duplicates is False:
        tolerance = -1.0
    elif merge_duplicates is True:
        tolerance = 1e-9
    elif isinstance(merge_duplicates, (int, float)) and 0 <= merge_duplicates <= 0.1:
        tolerance = float(merge_duplicates)
    else:
        raise HoctError("read: merge_duplicates must be True or a tolerance between 0 and 0.1, "
                        "got %r" % (merge_duplicates,))
    return _hoct.read(str(path), scalar or "", budget, int(threads or 0), tolerance)


_TRIANGLE_TYPES = {5: 1, 22: 2}  # VTK_TRIANGLE, VTK_QUADRATIC_TRIANGLE; 69 = any degree


def from_arrays(points, cells, values, degree=None, cell_types=None):
    """A mesh from numpy arrays: points (n, 2|3), cells (cells, nodes) of complete Lagrange
    triangles in VTK node order (3, 6, 10, 15, ... nodes per cell), values (n,). `degree`, if
    given, must match the node count; `cell_types` (VTK codes 5, 22 or 69 per cell), if given,
    are checked against it. The mesh is built on every hardware thread (the same mesh for any
    number)."""
    import numpy as np

    cells = np.asarray(cells)
    if cells.ndim != 2:
        raise HoctError("from_arrays: cells must be a 2D array (cells, nodes per cell)")
    n = cells.shape[1]
    if degree is not None and (degree + 1) * (degree + 2) // 2 != n:
        raise HoctError("from_arrays: degree %d needs %d nodes per cell, cells have %d"
                        % (degree, (degree + 1) * (degree + 2) // 2, n))
    if cell_types is not None:
        for i, t in enumerate(np.asarray(cell_types).ravel()):
            if t not in (5, 22, 69) or (t in _TRIANGLE_TYPES and
                                        (_TRIANGLE_TYPES[t] + 1) * (_TRIANGLE_TYPES[t] + 2) // 2 != n):
                raise HoctError("from_arrays: cell %d has VTK type %d, which does not match %d-node "
                                "triangles" % (i, t, n))
    return _hoct.from_arrays(points, cells, values)


def generate(name, degree=0, cells=0, seed=1, frequency=1.0, plateau=0.0, scale=1.0, offset=0.0):
    """A synthetic dataset (hoct.dataset_names()): the same as `hoct generate`
    (frequency: `random` only, its wave numbers multiplied; plateau: `random` only, the values
    below their plateau-th percentile raised to it; every value v then becomes
    scale * v + offset); its mesh built on every hardware thread."""
    return _hoct.generate(name, int(degree), int(cells), int(seed), float(frequency),
                          float(plateau), float(scale), float(offset))


dataset_names = _hoct.dataset_names


def from_meshio(mesh, scalar=None):
    """A mesh from a meshio.Mesh (its triangle blocks, VTK node order; point data `scalar` or the
    first)."""
    import numpy as np

    blocks = [b for b in mesh.cells if b.type.startswith("triangle")]
    if len(blocks) != 1:
        raise HoctError("from_meshio: expected exactly one block of triangles, got %d" % len(blocks))
    name = scalar or next(iter(mesh.point_data))
    return _hoct.from_arrays(np.asarray(mesh.points, dtype=float), np.asarray(blocks[0].data),
                             np.asarray(mesh.point_data[name], dtype=float))


def _spec(simplify):
    """A threshold as the library parses it: a number (absolute) or a text such as "0.5%"."""
    if simplify is None:
        return ""
    if isinstance(simplify, bool):
        raise HoctError("contour_tree: simplify must be a number or a text such as '0.5%'")
    return simplify if isinstance(simplify, str) else repr(float(simplify))


def contour_tree(mesh, simplify=None, threads=None, method="exact", refine=4, keep_flat=False,
                 force=False, augmented=False):
    """The contour tree of `mesh`, as `hoct tree` computes it (the same library call):

    method     "exact" (default), "linear" (PL of the Lagrange nodes, `hoct tree --linear`) or
               "refine" (PL of the exact field on k x k sub-triangles per cell, k = `refine`)
    simplify   remove leaf branches below a persistence threshold: a number, or a percentage of
               the value range like "0.5%" (`--simplify`); the simplified tree is returned
    threads    threads for every phase (default: all cores; the tree does not depend on it)
    keep_flat  keep the nodes and zero-length arcs of plateaus (`--keep-flat`)
    augmented  keep the regular nodes (`--augmented`; no simplification then)
    force      compute what is well defined on a domain that is not one disk or one sphere
               (`--force`); without it such a domain raises HoctError"""
    if threads is not None and (isinstance(threads, bool) or not isinstance(threads, int)
                                or threads < 1):
        raise HoctError("contour_tree: threads must be a positive integer, got %r" % (threads,))
    return _hoct.contour_tree(mesh, method, int(refine), int(threads or 0), bool(keep_flat),
                              bool(force), bool(augmented), _spec(simplify))


def _to_networkx(tree):
    """The tree as a networkx.Graph with node attributes type, value, position, location."""
    import networkx as nx

    g = nx.Graph()
    for i, (t, v, p, loc) in enumerate(zip(tree.types, tree.values, tree.positions, tree.locations)):
        g.add_node(i, type=t, value=float(v), position=tuple(map(float, p)), location=loc)
    g.add_edges_from(map(tuple, tree.arcs.tolist()))
    return g


Tree.to_networkx = _to_networkx
_native_simplify_by = Tree.simplify_by
Tree.simplify_by = lambda self, spec: _native_simplify_by(self, _spec(spec))
Tree.simplify_by.__doc__ = ("The tree simplified by a persistence threshold: a number, or a "
                            "percentage of the value range such as '0.5%'.")
