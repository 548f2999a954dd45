"""hoct: exact contour trees of piecewise-polynomial (higher-order finite-element) fields.

    import hoct
    mesh = hoct.read("field.vtu")                 # or hoct.from_arrays / hoct.from_meshio
    tree = hoct.contour_tree(mesh, simplify="0.5%")
    tree.positions, tree.values, tree.types, tree.arcs, tree.pairs, tree.branches
    tree.to_networkx()
    tree.input == {"points": ..., "cells": ..., "field": ..., "fingerprint": mesh.fingerprint}

Under MPI (mpi4py): `contour_tree(mesh, comm=comm)` with the whole mesh on every rank, or with
each rank's own piece (`read_pieces`, `piece_from_arrays`) where no rank holds the whole.

The same library computes what the `hoct` command line prints: the results are identical.
"""
import math
import numbers

import os
import warnings

from . import _arguments as _args
from . import _hoct
from ._hoct import HoctError, Mesh, Piece, Tree

__all__ = ["read", "from_arrays", "from_meshio", "generate", "contour_tree", "read_pieces",
           "piece_from_arrays", "Mesh", "Piece", "Tree", "HoctError", "HoctWarning"]


class HoctWarning(UserWarning):
    """What a reader says about a file it read (a piece of a partitioned file read alone,
    XDMF holding vertex values only, nodes at Gauss-Lobatto-Legendre points, ...)."""


def read(path, scalar=None, max_memory=None, threads=None, merge_duplicates=None,
         component=None, step=None, time=None):
    """Read a mesh file (.vtu, .msh, ...); `scalar` names the point-data array or view (default:
    the active scalars, else the first one-component floating-point array that is no id, ghost
    or mask array), as `--scalar` does.

    `component`: of a vector array, an index (0, 1, ...), 'x', 'y', 'z' or 'magnitude', as
    `--component`. `step` / `time`: the time step of files that hold several (index from 0,
    negative from the end; default the last), as `--step` / `--time`.

    `threads`: threads that read large arrays and build the mesh (default: every hardware
    thread, as `contour_tree`); the mesh is the same for any number.

    `max_memory` is the memory budget the readers check against the file's header counts
    before allocating, as for `hoct --max-memory`: bytes (int) or text such as "8G", "512M" or
    "50%" of the physical memory; default 80% of the physical memory. A file whose counts need
    more is refused with HoctError ("needs ~X GiB, limit Y GiB") before anything is allocated.

    `merge_duplicates`: merge points at the same position before building the mesh, as
    `hoct tree --merge-duplicates[=TOL]`: True (within 1e-9 of the bounding-box diagonal) or a
    tolerance TOL between 0 and 0.1.

    `path` is a str, bytes or os.PathLike; one with a NUL character is refused (HoctError), as
    is a `scalar` with one, instead of opening or naming its prefix."""
    path = _args.path(path, "read: path")
    scalar = "" if scalar is None else _args.text(scalar, "read: scalar")
    if max_memory is None:
        budget = ""
    elif isinstance(max_memory, bool):
        raise HoctError("read: max_memory must be a number of bytes or a size such as '8G'")
    elif isinstance(max_memory, int):
        if max_memory <= 0:
            raise HoctError("read: max_memory must be positive, got %d" % max_memory)
        budget = str(max_memory)
    elif isinstance(max_memory, float):
        budget = repr(max_memory)
    else:
        budget = _args.text(max_memory, "read: max_memory")
    nthreads = _args.threads(threads, "read")
    tolerance = _args.merge_tolerance(merge_duplicates, "read")
    mesh, notes = _hoct.read(path, scalar, budget, nthreads, tolerance,
                             _args.component(component, "read"), _args.step(step, "read"),
                             _args.time(time, "read"))
    name = os.fsdecode(path)
    for note in notes:  # what `hoct tree` prints as "hoct: warning:" / "hoct: note:"
        warnings.warn(note if note.startswith(name) else f"{name}: {note}", HoctWarning,
                      stacklevel=2)
    return mesh


# VTK cell types from_arrays and from_meshio take: their node counts for a degree (or order) d.
_CELL_NODES = {
    5: lambda d: 3 if d == 1 else None, 22: lambda d: 6 if d == 2 else None,
    69: lambda d: (d + 1) * (d + 2) // 2, 76: lambda d: (d + 1) * (d + 2) // 2,
    9: lambda d: 4 if d == 1 else None, 28: lambda d: 9 if d == 2 else None,
    23: lambda d: 8 if d == 2 else None, 70: lambda d: (d + 1) ** 2, 77: lambda d: (d + 1) ** 2,
}


def _triangle_degree(n):
    d = 1
    while (d + 1) * (d + 2) // 2 < n:
        d += 1
    return d if (d + 1) * (d + 2) // 2 == n else None


def _quad_order(n):
    p = int(round(math.sqrt(n))) - 1
    return p if p >= 1 and (p + 1) ** 2 == n else None


def _cell_type(n, what):
    """The VTK type of n-node cells given without one: a complete triangle, else a
    quadrilateral ((p+1)^2 nodes; 8: the serendipity VTK_QUADRATIC_QUAD)."""
    if _triangle_degree(n):
        return 5 if n == 3 else (22 if n == 6 else 69)
    if _quad_order(n):
        return 9 if n == 4 else 70
    if n == 8:
        return 23
    raise HoctError("%s: %d nodes per cell is neither a complete triangle (3, 6, 10, 15, ...) nor "
                    "a quadrilateral (4, 8, 9, 16, 25, ...)" % (what, n))


def from_arrays(points, cells, values, degree=None, cell_types=None, merge_duplicates=None):
    """A mesh from numpy arrays: points (n, 2|3), cells (cells, nodes) in VTK node order,
    values (n,). Cells are complete Lagrange triangles (3, 6, 10, 15, ... nodes per cell) or
    quadrilaterals of order (p, p) ((p+1)^2 nodes: 4, 9, 16, ...; 8: serendipity), unless
    `cell_types` says otherwise: one VTK type for all cells or one per cell (5, 22, 69
    triangles, 76 Bezier triangles, 9, 23, 28, 70 quadrilaterals, 77 Bezier quadrilaterals;
    36 nodes are a degree-7 triangle unless typed 70). `degree`, if given, must match the node
    count (a quadrilateral's order p). The mesh is built on every hardware thread (the same mesh
    for any number).

    Cell indices follow the rules of a .vtu file's connectivity: an integer array, or floating
    point values that are all whole, finite and within int64 (1.5, nan, 1e20 are refused with
    their position). A numpy masked array with a masked entry is refused (points, cells, values
    and cell_types alike): hoct does not guess the values a mask hides.

    `merge_duplicates`: as for `read` (points at the same position merged first: deal.II's
    simplex output and DG-projected fields repeat them)."""
    return _from_arrays(points, cells, values, degree, cell_types, "from_arrays",
                        _args.merge_tolerance(merge_duplicates, "from_arrays"))


def read_pieces(path, comm, scalar=None, max_memory=None, threads=None):
    """This rank's pieces of a partitioned .pvtu, or its part of one .vtu, under mpi4py (`comm`,
    e.g. MPI.COMM_WORLD; every rank of it calls this). A .pvtu: rank r of R reads pieces
    [r P / R, (r + 1) P / R) of the P the file lists and the ranks join them together (ghost
    cells dropped, shared points merged by global ids, else by position). A .vtu of raw appended
    arrays (VTK's and hoct's default): rank r reads the cells [r n / R, (r + 1) n / R) and the
    points they use. As `mpirun -np R hoct tree FILE` does: no rank holds the whole mesh.
    Returns a Piece for `contour_tree(piece, comm=comm)`.

    Where the ranks cannot do so alone (fields that differ, copies of a point that disagree, a
    .vtu of inline arrays), every rank reads the whole file instead: `piece.whole_on_every_rank`
    says why (None otherwise). `scalar`, `max_memory`, `threads` as for `read`. Errors are
    raised on every rank alike."""
    what = "read_pieces"
    path = _args.path(path, what + ": path")
    if not os.fsdecode(path).lower().endswith((".pvtu", ".vtu")):
        raise HoctError(what + ": %s is neither a partitioned .pvtu nor a .vtu file (read other "
                        "files with hoct.read and pass comm= to contour_tree)" % os.fsdecode(path))
    scalar = "" if scalar is None else _args.text(scalar, what + ": scalar")
    budget = "" if max_memory is None else _args.text(str(max_memory), what + ": max_memory")
    return _hoct.read_pieces(os.fsdecode(path), scalar, budget, _args.threads(threads, what),
                             _comm_handle(comm, what))


def piece_from_arrays(points, cells, values, comm, global_ids=None, ghost_cells=None,
                      degree=None, cell_types=None):
    """This rank's piece of a mesh spread over the ranks of `comm` (an mpi4py communicator;
    every rank of it calls this), in situ: each rank passes its own cells as `from_arrays`
    takes them (an empty `cells` for a rank without any), and the ranks join the pieces in rank
    order without any rank holding the whole mesh. Returns a Piece for
    `contour_tree(piece, comm=comm)`.

    global_ids   one integer per point, the same for every copy of a point on several ranks
                 (VTK's GlobalIds; DOLFINx's original input indices): copies are merged by id
                 (their positions must agree). Without ids, copies are merged by position
                 (within 1e-9 of the bounding-box diagonal), as hoct joins a .pvtu's pieces.
    ghost_cells  one flag per cell, true for a copy of a cell another rank owns (VTK's
                 vtkGhostType DUPLICATECELL): dropped, with the points only they use.

    A rank's bad arrays are raised as HoctError on every rank ("rank r: ..."). Where the ranks
    cannot be sure to join the pieces alone, every rank gets every piece and joins the whole
    (`piece.whole_on_every_rank` says why); a mesh that does not join is raised on every rank.
    The piece holds this rank's arrays as given (references, not a copy: do not change them
    while it lives), to make this rank's piece again where rank 0 needs the whole mesh (a
    report on it, a Reeb graph by the linear or refine method)."""
    import numpy as np

    what = "piece_from_arrays"
    handle = _comm_handle(comm, what)
    failure = ""
    try:
        args = _cell_arrays(points, cells, values, degree, cell_types, what)
        ids = np.zeros(0, dtype=np.int64)
        if global_ids is not None:
            ids = _args.index_array(global_ids, what + ": global_ids").ravel()
        ghosts = np.zeros(0, dtype=np.int64)
        if ghost_cells is not None:
            ghosts = np.asarray(ghost_cells).astype(bool).astype(np.int64).ravel()
            if ghosts.size == 0 and len(args[1][0]) > 0:
                raise HoctError(what + ": ghost_cells must have one entry per cell")
        float32 = _float32s(points, values)
    except HoctError as e:  # raised on every rank, from the native side, with this rank's number
        failure = str(e) or what + ": bad arrays"
        args = (np.zeros((0, 3)), [np.zeros((0, 3), dtype=np.int64)],
                [np.zeros(0, dtype=np.int64)], np.zeros(0))
        ids = ghosts = np.zeros(0, dtype=np.int64)
        float32 = (False, False)
    return _hoct.piece_from_arrays(*args, "f", *float32, ids, ghosts, failure, 0, handle)


def _comm_handle(comm, what):
    if not callable(getattr(comm, "py2f", None)):
        raise HoctError(what + ": comm must be an mpi4py communicator (mpi4py.MPI.Comm)")
    return comm.py2f()


def _float32(a):
    import numpy as np

    return getattr(a, "dtype", None) == np.float32


def _from_arrays(points, cells, values, degree, cell_types, what, tolerance=-1.0, field="f"):
    return _hoct.from_arrays(*_cell_arrays(points, cells, values, degree, cell_types, what),
                             tolerance, field, *_float32s(points, values))


def _float32s(points, values):
    return _float32(points), _float32(values)


def _cell_arrays(points, cells, values, degree, cell_types, what):
    """The arrays from_arrays takes, checked: points, [cells], [types], values."""
    import numpy as np

    points = _args.real_array(points, what + ": points")
    values = _args.real_array(values, what + ": values")
    cells = _args.index_array(cells, what + ": cells")
    if cells.ndim != 2:
        raise HoctError(what + ": cells must be a 2D array (cells, nodes per cell)")
    n = cells.shape[1]
    if degree is not None:
        degree = _args.integer(degree, what + ": degree", 1, 1 << 20)
    if cell_types is None and degree is not None:
        tri, quad = (degree + 1) * (degree + 2) // 2, (degree + 1) ** 2
        if n not in (tri, quad):
            raise HoctError("%s: degree %d needs %d nodes per cell (a triangle) or %d (a "
                            "quadrilateral), cells have %d" % (what, degree, tri, quad, n))
        t = (5 if n == 3 else 69) if n == tri else (9 if n == 4 else 70)
        types = np.full(cells.shape[0], t, dtype=np.int64)
    elif cell_types is None:
        types = np.full(cells.shape[0], _cell_type(n, what), dtype=np.int64)
    else:
        types = _args.index_array(cell_types, what + ": cell_types").ravel()
        if types.size == 1:
            types = np.full(cells.shape[0], types[0], dtype=np.int64)
        elif types.size != cells.shape[0]:
            raise HoctError("%s: %d cell_types for %d cells (give one type, or one per cell)"
                            % (what, types.size, cells.shape[0]))
    for i, t in enumerate(types):
        t = int(t)
        if t not in _CELL_NODES:
            raise HoctError("%s: cell %d has VTK type %d (supported: %s)"
                            % (what, i, t, ", ".join(map(str, sorted(_CELL_NODES)))))
        d = degree
        if d is None:
            d = _triangle_degree(n) if t in (5, 22, 69, 76) else (2 if t == 23 else _quad_order(n))
        if d is None or _CELL_NODES[t](d) != n:
            raise HoctError("%s: cell %d has VTK type %d, which does not match %d-node cells%s"
                            % (what, i, t, n, "" if degree is None else " of degree %d" % degree))
    return points, [cells], [types.astype(np.int64)], values


def generate(name, degree=0, cells=0, seed=1, frequency=1.0, plateau=0.0, scale=1.0, offset=0.0,
             quads=False):
    """A synthetic dataset (hoct.dataset_names()): the same as `hoct generate`
    (frequency: `random` only, its wave numbers multiplied; plateau: `random` only, the values
    below their plateau-th percentile raised to it; every value v then becomes
    scale * v + offset; quads: `random` only, Lagrange quadrilaterals of order `degree` on the
    same grid instead of triangles); its mesh built on every hardware thread.

    As for the command line, degree and seed are integers (1.5 is refused, not truncated) and
    cells a whole number (1e6 is fine)."""
    name = _args.text(name, "generate: name")
    degree = _args.integer(degree, "generate: degree", 0, 1 << 20)
    seed = _args.integer(seed, "generate: seed", 0, (1 << 64) - 1)
    if isinstance(cells, bool) or not isinstance(cells, numbers.Real):
        raise TypeError("generate: cells must be a number, not %r" % (cells,))
    if not (0 <= cells <= 1e12) or cells != math.floor(cells):
        raise HoctError("generate: cells must be a positive whole number, got %r" % (cells,))
    quads = _args.flag(quads, "generate: quads")
    return _hoct.generate(name, degree, int(cells), seed, float(frequency), float(plateau),
                          float(scale), float(offset), quads)


dataset_names = _hoct.dataset_names


# meshio's cell types that are no part of a surface's field: skipped, as the file readers skip
# vertex and line cells.
_MESHIO_SKIPPED = ("vertex", "line", "VTK_LAGRANGE_CURVE")
# meshio's surface cell types (VTK node order) as VTK types; "triangle..." blocks: by node count.
_MESHIO_TYPES = {"VTK_LAGRANGE_TRIANGLE": 0, "quad": 9, "quad8": 23, "quad9": 28,
                 "VTK_LAGRANGE_QUADRILATERAL": 70}


def from_meshio(mesh, scalar=None, component=None, merge_duplicates=None):
    """A mesh from a meshio.Mesh: every triangle block (triangle, triangle6, triangle10, ...
    and VTK_LAGRANGE_TRIANGLE of any degree) and quadrilateral block (quad, quad8, quad9,
    VTK_LAGRANGE_QUADRILATERAL), VTK node order; several blocks, e.g. a Gmsh model's
    surfaces, together; vertex and line blocks skipped. The field is point data
    `scalar`, else the first one-component floating-point array that is no id, ghost or mask
    array (as `read`); (n, 1) arrays are one-component; `component` takes one component of a
    vector array or its 'magnitude'. `merge_duplicates` as for `read`."""
    import numpy as np

    what = "from_meshio"
    tolerance = _args.merge_tolerance(merge_duplicates, what)
    blocks = []
    types = []
    for i, block in enumerate(mesh.cells):
        kind = block.type
        vtk = _MESHIO_TYPES.get(kind, 0 if kind.startswith("triangle") else None)
        if vtk is not None:
            blocks.append(_args.index_array(block.data, "%s: cell block %d (%s)" % (what, i, kind)))
            if blocks[-1].ndim != 2:
                raise HoctError("%s: cell block %d (%s) is not a 2D array" % (what, i, kind))
            types.append(np.full(blocks[-1].shape[0], vtk, dtype=np.int64))
        elif not kind.startswith(_MESHIO_SKIPPED):
            raise HoctError("%s: cell block %d is of type '%s': hoct reads triangles (triangle, "
                            "triangle6, triangle10, ..., VTK_LAGRANGE_TRIANGLE) and "
                            "quadrilaterals (quad, quad8, quad9, VTK_LAGRANGE_QUADRILATERAL)"
                            % (what, i, kind))
    if not blocks:
        raise HoctError("%s: no triangle or quadrilateral blocks (blocks: %s)"
                        % (what, ", ".join(b.type for b in mesh.cells) or "none"))
    data = mesh.point_data
    if not data:
        raise HoctError("%s: the mesh has no point data (a field at its nodes)" % what)

    def components(a):
        a = np.asarray(a)
        return 1 if a.ndim == 1 or (a.ndim == 2 and a.shape[1] == 1) else (
            a.shape[1] if a.ndim == 2 else 0)

    listed = ", ".join("%s (%d components)" % (k, components(v)) if components(v) != 1 else k
                       for k, v in data.items())
    comp = _args.component(component, what)
    vector = comp != ""
    if scalar is not None:
        name = _args.text(scalar, what + ": scalar")
        if name not in data:
            raise HoctError("%s: no point data named '%s' (available: %s)" % (what, name, listed))
    else:
        suitable = [k for k, v in data.items() if (components(v) > 1 if vector else
                                                    components(v) == 1)
                    and not _hoct.is_bookkeeping_array(k)]
        floating = [k for k in suitable if np.issubdtype(np.asarray(data[k]).dtype, np.floating)]
        if not suitable:
            raise HoctError("%s: no %s point data but ids, ghost levels or masks (available: %s):"
                            " name one with scalar=" % (what, "vector" if vector else
                                                        "scalar (one-component)", listed))
        name = (floating or suitable)[0]
    values = np.asarray(data[name])
    values_float32 = _float32(values)
    n = components(values)
    if not vector:
        if n != 1:
            raise HoctError("%s: point data '%s' has %d components; a scalar field needs 1 "
                            "(choose one with component=N, or component='magnitude')"
                            % (what, name, n))
        values, label = values.reshape(-1), name
    else:
        if n < 2:
            raise HoctError("%s: component: point data '%s' has one component" % (what, name))
        values = _args.real_array(values, what + ": values")
        if comp == "magnitude" or comp in ("mag", "norm"):
            values, label = np.sqrt((values * values).sum(axis=1)), "|%s|" % name
        else:
            k = {"x": 0, "y": 1, "z": 2}.get(comp)
            k = int(comp) if k is None else k
            if k >= n:
                raise HoctError("%s: component %d: point data '%s' has %d components (0 to %d)"
                                % (what, k, name, n, n - 1))
            values, label = values[:, k], "%s[%d]" % (name, k)
    float32 = _float32(mesh.points), values_float32
    points = _args.real_array(mesh.points, what + ": points")
    values = _args.real_array(values, what + ": values")
    return _hoct.from_arrays(points, blocks, types, values, tolerance, label, *float32)


def contour_tree(mesh, simplify=None, threads=None, method="exact", refine=4, keep_flat=False,
                 force=False, augmented=False, comm=None, arc_paths=False):
    """The contour tree of `mesh`, as `hoct tree` computes it (the same library call); on a
    domain that is not one disk or one sphere its Reeb graph (`kind`, `loops`), by every method:

    method     "exact" (default), "linear" (PL of the Lagrange nodes, `hoct tree --linear`) or
               "refine" (PL of the exact field on k x k sub-triangles per cell, k = `refine`)
    simplify   remove leaf branches below a persistence threshold: a number, or a percentage of
               the value range like "0.5%" (`--simplify`); the simplified tree is returned
    threads    threads for every phase (default: all cores; the tree does not depend on it)
    keep_flat  keep the nodes and zero-length arcs of plateaus (`--keep-flat`)
    augmented  keep the regular nodes (`--augmented`; no simplification then)
    force      compute what is well defined past inverted or folded cells and unmerged
               duplicate vertices (`--force`); without it such a mesh raises HoctError
    arc_paths  with comm: the ranks' pieces draw the arcs on the surface together (no rank
               holds the whole graph), for Tree.arc_paths() and write_vtp (`mpirun hoct tree
               --vtp`); without comm the Tree draws them when asked

    comm       an mpi4py communicator (`from mpi4py import MPI; comm=MPI.COMM_WORLD`): the
               tree computed over its ranks, as `mpirun -np N hoct tree` does. Every rank
               calls this with the same whole mesh (each reads the file); each computes the tree
               of its share of the cells and the ranks merge their join and split trees. Rank 0
               gets the tree (the same as without comm; its arcs drawn on the surface with
               arc_paths=True, else straight in `write_vtp`); the other ranks get None. Errors are raised on
               every rank; one that only one rank meets ends the job (MPI_Abort), as the others
               would wait for it. A domain with holes or handles gets its Reeb graph (each
               rank's pieces cut into disks, glued back in the tree of ranks, by every method;
               the linear method's Bezier or serendipity cells: rank 0, from the whole mesh).
               `mesh` may also be this rank's Piece (read_pieces, piece_from_arrays): then no
               rank holds the whole mesh; comm must be the communicator the piece was made on.

    The arguments follow the flags' rules: simplify a finite number >= 0 or "N%" with N such a
    number (nan, -1, "-5%" are refused), refine an integer 1..1024, threads 1..1024, the
    switches True or False."""
    what = "contour_tree"
    if isinstance(mesh, Piece) and comm is None:
        raise HoctError(what + ": a Piece is one rank's share: pass the communicator it was "
                        "made on (comm=)")
    if comm is not None:
        handle = _comm_handle(comm, what)
        native = _hoct.contour_tree_piece if isinstance(mesh, Piece) else _hoct.contour_tree_mpi
        return native(mesh, handle, _args.text(method, what + ": method"),
                      _args.integer(refine, what + ": refine", 1, _args.MAX_REFINE),
                      _args.threads(threads, what), _args.flag(keep_flat, what + ": keep_flat"),
                      _args.flag(force, what + ": force"),
                      _args.flag(augmented, what + ": augmented"),
                      _args.threshold(simplify, what + ": simplify"),
                      _args.flag(arc_paths, what + ": arc_paths"))
    if arc_paths is not False:  # without comm the Tree draws its arcs when asked
        _args.flag(arc_paths, what + ": arc_paths")
    return _hoct.contour_tree(mesh, _args.text(method, what + ": method"),
                              _args.integer(refine, what + ": refine", 1, _args.MAX_REFINE),
                              _args.threads(threads, what), _args.flag(keep_flat, what + ": keep_flat"),
                              _args.flag(force, what + ": force"),
                              _args.flag(augmented, what + ": augmented"),
                              _args.threshold(simplify, what + ": simplify"))


def _to_networkx(tree):
    """The tree as a networkx.Graph with node attributes type, value, position, location; a
    Reeb graph as a networkx.MultiGraph (parallel arcs are its loops: nx.cycle_basis lists
    them once they are told apart, e.g. through nx.Graph(nx.line_graph(g)))."""
    import networkx as nx

    g = nx.MultiGraph() if tree.kind == "Reeb graph" else nx.Graph()
    for i, (t, v, p, loc) in enumerate(zip(tree.types, tree.values, tree.positions, tree.locations)):
        g.add_node(i, type=t, value=float(v), position=tuple(map(float, p)), location=loc)
    g.add_edges_from(map(tuple, tree.arcs.tolist()))
    return g


Tree.to_networkx = _to_networkx
_native = {name: getattr(Tree, name) for name in ("simplify", "simplify_by", "write_json",
                                                  "write_vtp", "write_svg")}


def _simplify(self, threshold, loops=False):
    """The tree simplified by an absolute persistence threshold: a finite number >= 0 (nan, inf
    and negatives are refused, as by `--simplify`). `loops=True`: a Reeb graph's loops whose
    essential pair is below the threshold are removed too (`--simplify-loops`)."""
    if isinstance(threshold, bool) or not isinstance(threshold, numbers.Real):
        raise TypeError("simplify: the threshold must be a number, not %s (%r); simplify_by "
                        "takes a text such as '0.5%%'" % (type(threshold).__name__, threshold))
    if not isinstance(loops, bool):
        raise TypeError("simplify: loops must be True or False, not %r" % (loops,))
    return _native["simplify"](self, float(threshold), loops)


def _simplify_by(self, spec, loops=False):
    """The tree simplified by a persistence threshold: a finite number >= 0, or a percentage of
    the value range such as '0.5%' (as `--simplify`); `loops` as for `simplify`."""
    if not isinstance(loops, bool):
        raise TypeError("simplify_by: loops must be True or False, not %r" % (loops,))
    return _native["simplify_by"](self, _args.threshold(spec, "simplify_by"), loops)


def _write_json(self, path, timings=True):
    """Write the tree as `hoct tree --json` does (atomically); path: str, bytes or PathLike."""
    return _native["write_json"](self, _args.path(path, "write_json: path"),
                                 _args.flag(timings, "write_json: timings"))


def _write_vtp(self, path):
    """Write critical points and arcs as `hoct tree --vtp` does (atomically)."""
    return _native["write_vtp"](self, _args.path(path, "write_vtp: path"))


def _write_svg(self, path, title=""):
    """Draw the tree as `hoct tree --svg` does (atomically)."""
    return _native["write_svg"](self, _args.path(path, "write_svg: path"),
                                _args.text(title, "write_svg: title"))


Tree.simplify = _simplify
Tree.simplify_by = _simplify_by
Tree.write_json = _write_json
Tree.write_vtp = _write_vtp
Tree.write_svg = _write_svg
