"""`mpirun -np N hoct tree FILE` on a domain that is not a disk or a sphere: the distributed Reeb
graph (each rank's piece cut into disks, the pieces glued in the tree of ranks).

The independent truth is hoct's own single-process Reeb graph, computed without MPI at all
(`hoct tree FILE --json OUT --no-timings`, itself checked against VTK's level sets by
test_reeb_graphs): for 1, 2, 3, 4 and 7 ranks on hoct's plate (2, 3 and 7 with --augmented and
--simplify), 2 and 7 on the other shapes, 2 and 3 on the cell orders below (--oversubscribe:
this machine has 2 cores), the run exits 0 and its JSON is byte-identical (with --vtp on the
plate too, exact and --linear, the pieces drawing the arcs: no jump, none straight). The cases: hoct's
plate with 100 holes (degrees 2, 3 and 5, --augmented, --simplify 1%), and the surfaces of test_reeb_graphs (reeb_meshes: Lagrange
triangles of degrees 1-3 at exact parametric positions, or Gmsh's): annuli (one of 6 cells: ranks
without cells), tori, Moebius strips, a square and a disk with 3 holes, a double torus, mostly
with wavy fields (many saddles, ordinary pairs besides the loops), one of them simplified; and
an annulus of bilinear quadrilaterals, exact and by the PL methods (--linear, --refine 3: their
Reeb graphs by pieces too); several components in one file: two annuli, a disk and an annulus, two disks, two of hoct's
spheres, a sphere and a disk, a sphere and the plate. The JSON says "kind": "Reeb graph", its
arc graph has the domain's components and the expected loops (a height-like function: one per hole of a planar domain, g on
a closed surface of genus g; a wavy field: at most the domain's first Betti number).

Pieces are contiguous ranges of cells in file order (rank r of R: cells [r C / R, (r + 1) C / R),
as the per-rank report's cell counts confirm). Cell orders written on purpose make pieces the whole
mesh never is: pinched pieces (around a vertex one rank's cells form two or more fans, another
rank's cells between them): every other cell of some vertices' stars moved to the end of the file
(an annulus, the plate); the triangles of one class of a 2-colouring (no two of a class share an
edge) first (an annulus, a torus, a Moebius strip), so that with 2 ranks every piece is triangles
touching at vertices only; the cells shuffled (a torus). A rank whose piece alone is an annulus (it
holds the whole hole) while the others are disks; two components' cells interleaved. Each layout is
first checked here (fans around each vertex per rank, the Euler characteristic and boundary loops
of each piece), then the JSON for 2 and 3 ranks against one process. Partitioned input: the
plate and a torus as .pvtu of 4 pieces written by VTK (vtk_pieces, ghost levels 0 and 1): 1, 2, 3
and 4 ranks read their pieces alone and give the JSON of one process reading the whole .pvtu; the
plate with a plateau in 4 pieces of consecutive cells, where 4 ranks' pieces cannot glue a seam
and rank 0 computes the whole mesh the ranks join from their pieces (its summary says so). Rank
0 alone writes: on 3 ranks the output directory holds the JSON and the SVG only, equal to one
process's, no rank reports an error or a warning, and the summary (once) says "Reeb graph (N
loops)" and has the nodes line of the one-process run's.

Skipped (exit 77) without mpirun, numpy or VTK's Python module, or an MPI build of hoct. The Gmsh
cases are left out without python3-gmsh."""
import json
import math
import os
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hoct_testing import Results, run, tempdir  # noqa: E402
from mpi_testing import arcs_drawn_by_pieces, mpi, read, require_mpi_hoct  # noqa: E402

try:
    import numpy as np
    from reeb_meshes import (HAVE_GMSH, HOLES, annulus, combined, disk_and_annulus,
                             disk_with_holes, double_torus, gmsh_mesh, graph_shape, moebius,
                             moebius_f, square_with_holes, tilted, torus, torus_f1,
                             wavy_planar, wavy_surface, wavy_torus, write_field, write_grid)
    from vtk_pieces import read_grid, write_consecutive, write_pieces
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import (VTK_LAGRANGE_TRIANGLE, VTK_QUAD, vtkCellArray,
                                               vtkUnstructuredGrid)
    from vtkmodules.vtkCommonTransforms import vtkTransform
    from vtkmodules.vtkFiltersCore import vtkAppendFilter
    from vtkmodules.vtkFiltersGeneral import vtkTransformFilter
except ImportError as e:
    print(f"SKIPPED: numpy or VTK's Python modules are missing ({e})")
    sys.exit(77)

r = Results()
RANKS = (1, 2, 3, 4, 7)  # hoct's generated plate
SHAPE_RANKS = (2, 7)  # the other shapes: mpirun's start-up is most of a run


# --- The truth and the comparison -------------------------------------------------------------

def one_process(label, path, *extra):
    """The one-process JSON (no MPI at all): its path and the parsed graph (None if that run
    fails: no truth to compare with)."""
    want = f"{path}.{abs(hash(extra))}.want.json"
    p = run("tree", path, "--json", want, "--no-timings", "-q", *extra, check=False)
    r.check(p.returncode == 0, f"{label}: one process fails ({p.returncode}): {p.stderr[-800:]}")
    if p.returncode != 0:
        return want, None
    with open(want) as f:
        return want, json.load(f)


def failure(p):
    """What a failed run says: hoct's error lines (once each), else the end of its stderr."""
    lines = [line for line in p.stderr.splitlines() if line.startswith("hoct: error")]
    return "\n".join(dict.fromkeys(lines)) if lines else p.stderr[-1500:]


def difference(want, got):
    """Where two JSON files differ, in a few words (the first few keys or list entries)."""
    with open(want) as f, open(got) as g:
        a, b = json.load(f), json.load(g)
    out = []
    for key in sorted(set(a) | set(b), key=str):
        x, y = a.get(key), b.get(key)
        if x == y:
            continue
        if isinstance(x, dict) and isinstance(y, dict):
            for k in sorted(set(x) | set(y)):
                if x.get(k) != y.get(k):
                    out.append(f"{key}.{k}: {x.get(k, '(none)')!r} vs {y.get(k, '(none)')!r}")
        elif isinstance(x, list) and isinstance(y, list):
            first = next((i for i, (u, v) in enumerate(zip(x, y)) if u != v), min(len(x), len(y)))
            out.append(f"{key}: {len(x)} vs {len(y)} entries, first difference at {first}")
        else:
            out.append(f"{key}: {x!r} vs {y!r}")
    return "; ".join(out[:4]) or "the same data, other bytes"


def same_json(label, path, extra=(), ranks=RANKS, quiet=True):
    """The JSON from mpirun on each rank count byte-identical to one process's; returns the
    one-process graph and the runs that succeeded (rank count: the completed process)."""
    extra = tuple(extra)
    want, graph = one_process(label, path, *extra)
    done = {}
    if graph is None:
        return graph, done
    for n in ranks:
        got = f"{path}.{abs(hash(extra))}.{n}.json"
        p = mpi(n, "tree", path, "--json", got, "--no-timings", *(["-q"] if quiet else []),
                *extra)
        r.check(p.returncode == 0, f"{label}, {n} ranks: exit {p.returncode}: {failure(p)}")
        if p.returncode == 0:
            same = os.path.exists(got) and read(got) == read(want)
            r.check(same, "" if same else f"{label}, {n} ranks: JSON differs from one process "
                    f"(one process vs MPI: "
                    f"{difference(want, got) if os.path.exists(got) else 'no JSON'})")
            done[n] = p
    return graph, done


def check_graph(label, graph, loops, components=1, max_loops=None):
    """ "kind": "Reeb graph", the arc graph's components, and "loops" (its first Betti number):
    loops if given, else at most max_loops. Returns the loops."""
    if graph is None:
        return None
    _, comps, betti = graph_shape(graph)
    r.check(graph.get("kind") == "Reeb graph", f"{label}: \"kind\" is {graph.get('kind')!r}")
    r.check(comps == components, f"{label}: {comps} component(s), expected {components}")
    r.check(graph.get("loops") == betti, f"{label}: \"loops\" {graph.get('loops')}, the arc "
                                         f"graph has {betti}")
    if loops is not None:
        r.check(betti == loops, f"{label}: {betti} loop(s), expected {loops}")
    else:
        r.check(betti <= max_loops, f"{label}: {betti} loop(s), more than the domain's {max_loops}")
    return betti


# --- Cell orders and what they make of the pieces ------------------------------------------------

def piece_bounds(cells, ranks):
    """Rank r's cells [b[r], b[r + 1]) (mesh/mesh_partition's piece_cell_range)."""
    return [cells * k // ranks for k in range(ranks + 1)]


def stars(corners):
    """Vertex: the cells (indices into corners, ascending) that have it as a corner."""
    out = {}
    for c, tri in enumerate(corners):
        for v in tri:
            out.setdefault(int(v), []).append(c)
    return out


def fan_groups(v, cells, corners):
    """The cells around v (all with v as a corner) grouped into fans: joined across the edges
    from v that two of them share."""
    groups = []
    for c in cells:
        others = set(int(w) for w in corners[c]) - {v}
        touching = [g for g in groups if others & g[1]]
        merged = ([c], set(others))
        for g in touching:
            merged[0].extend(g[0])
            merged[1].update(g[1])
            groups.remove(g)
        groups.append(merged)
    return [sorted(g[0]) for g in groups]


def pinches(corners, ranks):
    """(vertices where some rank's cells form two or more fans, the most fans of one rank at one
    vertex) for pieces of ranks contiguous ranges."""
    bounds = piece_bounds(len(corners), ranks)
    rank_of = np.searchsorted(bounds, np.arange(len(corners)), side="right") - 1
    pinched, most = 0, 1
    for v, star in stars(corners).items():
        worst = max(len(fan_groups(v, [c for c in star if rank_of[c] == k], corners))
                    for k in set(rank_of[star]))
        pinched += worst > 1
        most = max(most, worst)
    return pinched, most


def piece_shape(corners):
    """(components, Euler characteristic, boundary loops) of a set of triangles (one boundary
    loop per component of the boundary edges: meant for pieces without pinches)."""
    edges = {}
    for tri in corners:
        for k in range(3):
            e = tuple(sorted((int(tri[k]), int(tri[(k + 1) % 3]))))
            edges[e] = edges.get(e, 0) + 1
    vertices = {int(v) for tri in corners for v in tri}
    parent = {v: v for v in vertices}

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    def components(pairs, among):
        for v in among:
            parent[v] = v
        for a, b in pairs:
            parent[find(a)] = find(b)
        return len({find(v) for v in among})

    boundary = [e for e, k in edges.items() if k == 1]
    loops = components(boundary, {v for e in boundary for v in e})
    return components(list(edges), vertices), len(vertices) - len(edges) + len(corners), loops


def fan_split(corners, within=0.3):
    """A cell order (a permutation) pinching the first pieces: around vertices whose whole star
    lies in the first `within` of the file (stars apart from each other), every other cell in
    the order round the vertex is moved to the end of the file, so that the first rank's cells
    there form separate fans (boundary vertices included: a chain of 3 cells leaves two)."""
    limit = within * len(corners)
    moved, used = [], set()
    for v, star in sorted(stars(corners).items()):
        if len(star) < 3 or star[-1] >= limit or used & set(star):
            continue
        # The cells in their order round v: a walk across the edges from v they share.
        neighbours = {c: [d for d in star if d != c and
                          len(set(corners[c]) & set(corners[d])) == 2] for c in star}
        ends = [c for c in star if len(neighbours[c]) < 2]
        walk, seen = [ends[0] if ends else star[0]], set()
        while True:
            seen.add(walk[-1])
            step = [d for d in neighbours[walk[-1]] if d not in seen]
            if not step:
                break
            walk.append(step[0])
        if len(walk) != len(star):
            continue
        used.update(star)
        moved += walk[1::2]
    moved_set = set(moved)
    return np.array([c for c in range(len(corners)) if c not in moved_set] + sorted(moved))


def checkerboard(corners):
    """A cell order: the cells of one class of a 2-colouring across shared edges first (neighbours
    are never of the same class), then the others. Fails where there is no 2-colouring."""
    by_edge = {}
    for c, tri in enumerate(corners):
        for k in range(3):
            by_edge.setdefault(frozenset((int(tri[k]), int(tri[(k + 1) % 3]))), []).append(c)
    colour = [-1] * len(corners)
    for start in range(len(corners)):
        if colour[start] >= 0:
            continue
        colour[start], queue = 0, [start]
        while queue:
            c = queue.pop()
            tri = corners[c]
            for k in range(3):
                for d in by_edge[frozenset((int(tri[k]), int(tri[(k + 1) % 3])))]:
                    if colour[d] < 0:
                        colour[d] = 1 - colour[c]
                        queue.append(d)
                    elif d != c and colour[d] == colour[c]:
                        raise ValueError("no 2-colouring of the cells")
    return np.argsort(colour, kind="stable")


def hole_first(nr, nt, rings):
    """For annulus(nr, nt, ...)'s cells (ring by ring from the hole, two per grid square): the
    first `rings` rings, then the other rings' cells sector by sector (angle first): with 3 ranks
    and rings = nr / 3, rank 0 holds the whole hole, ranks 1 and 2 two halves of the rest."""
    def key(t):
        i, j = divmod(t // 2, nt)
        return (0, i, j, t % 2) if i < rings else (1, j, i, t % 2)
    return np.array(sorted(range(2 * nr * nt), key=key))


def interleaved(a, b):
    """The cells of two meshes of as many cells in one file, alternating."""
    points, cells = combined(a, b)
    n = len(a[1])
    return points, cells[np.ravel(np.column_stack([np.arange(n), n + np.arange(n)]))]


def vtu_cells(grid):
    """A grid's cells (of one type) as an array, one row of nodes per cell; and that type."""
    types = np.unique(vtk_to_numpy(grid.GetCellTypesArray()))
    assert len(types) == 1, f"cells of several types {types}"
    offsets = vtk_to_numpy(grid.GetCells().GetOffsetsArray())
    nodes = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    return nodes.reshape(-1, offsets[1] - offsets[0]), int(types[0])


def reorder_vtu(src, dst, order):
    """The .vtu src (one cell type) with its cells in the given order, written to dst: the same
    points and point data. Returns the cells' corners in that order."""
    grid = read_grid(src)
    cells, cell_type = vtu_cells(grid)
    cells, n = cells[order], cells.shape[1]
    ca = vtkCellArray()
    ca.SetData(numpy_to_vtkIdTypeArray(np.arange(0, cells.size + 1, n, dtype=np.int64), deep=True),
               numpy_to_vtkIdTypeArray(np.ascontiguousarray(cells.ravel(), dtype=np.int64),
                                       deep=True))
    out = vtkUnstructuredGrid()
    out.SetPoints(grid.GetPoints())
    out.GetPointData().ShallowCopy(grid.GetPointData())
    out.SetCells(cell_type, ca)
    write_grid(dst, out)
    return cells[:, :3]


def appended(out, parts):
    """The .vtu files of parts [(path, shift in x)] in one .vtu (VTK's append filter, no points
    merged): one component each."""
    append = vtkAppendFilter()
    for path, dx in parts:
        move = vtkTransform()
        move.Translate(dx, 0.0, 0.0)
        shift = vtkTransformFilter()
        shift.SetTransform(move)
        shift.SetInputData(read_grid(path))
        append.AddInputConnection(shift.GetOutputPort())
    append.Update()
    write_grid(out, append.GetOutput())
    return out


def rank_cells(stdout):
    """The per-rank report's cell counts (rank order)."""
    return [int(m.group(2)) for m in re.finditer(r"^    (\d+): (\d+) cells,", stdout, re.M)]


def outline(graph):
    if graph is None:
        return "no one-process graph"
    return f"{len(graph['nodes'])} nodes, {graph['loops']} loop(s)"


def whole_case(label, path, loops, max_loops=None, components=1, extra=(), ranks=SHAPE_RANKS):
    """Every rank reading the whole file: the JSON of each rank count against one process."""
    t0 = time.time()
    graph, _ = same_json(label, path, extra, ranks)
    check_graph(label, graph, loops, components, max_loops)
    print(f"{label}: {outline(graph)}; {', '.join(map(str, ranks))} ranks checked "
          f"({time.time() - t0:.1f} s)", flush=True)


def quad_annulus(path, nr=6, nt=40):
    """An annulus of bilinear quadrilaterals (VTK_QUAD), wrapped around: hoct splits each into two
    triangles, and the nodes are named by the input's cells."""
    pts = vtkPoints()
    for j in range(nr + 1):
        for i in range(nt):
            rad, t = 0.5 + 0.5 * j / nr, 2 * math.pi * i / nt
            pts.InsertNextPoint(rad * math.cos(t), rad * math.sin(t), 0.0)
    grid = vtkUnstructuredGrid()
    grid.SetPoints(pts)
    for j in range(nr):
        for i in range(nt):
            a, b = j * nt + i, j * nt + (i + 1) % nt
            grid.InsertNextCell(VTK_QUAD, 4, [a, b, b + nt, a + nt])
    xy = vtk_to_numpy(pts.GetData())
    values = numpy_to_vtk(xy[:, 0] + 0.3 * xy[:, 1] + 0.2 * np.sin(3 * xy[:, 0] * xy[:, 1]),
                          deep=True)
    values.SetName("f")
    grid.GetPointData().SetScalars(values)
    write_grid(path, grid)
    return path


def ordered_case(label, path, corners, loops=None, max_loops=1, components=1, extra=()):
    """A cell order made for its pieces: the layout (fans per rank) reported, then the JSON for 2,
    3 and 7 ranks against one process, the per-rank cells those of piece_bounds. Returns the
    layout: {ranks: (pinched vertices, most fans of one rank at one vertex)} for 2 and 3 ranks."""
    layout = {n: pinches(corners, n) for n in (2, 3)}
    graph, done = same_json(label, path, extra, ranks=(2, 3), quiet=False)
    for n, p in done.items():
        bounds = piece_bounds(len(corners), n)
        want = [b - a for a, b in zip(bounds, bounds[1:])]
        r.check(rank_cells(p.stdout) == want, f"{label}, {n} ranks: the ranks' cells "
                f"{rank_cells(p.stdout)}, not {want}:\n{p.stdout[-1500:]}")
    check_graph(label, graph, loops, components, max_loops)
    print(f"{label}: {len(corners)} cells; pinched vertices (most fans of one rank) with 2 ranks "
          f"{layout[2][0]} ({layout[2][1]}), 3 ranks {layout[3][0]} ({layout[3][1]}); "
          f"{outline(graph)}; 2 and 3 ranks checked", flush=True)
    return layout


def write_ordered(path, mesh, order, f, cell_type=None):
    """The mesh with its cells in the given order and f at its nodes: the cells' corners."""
    cells = mesh[1][order]
    write_field(path, (mesh[0], cells), f, cell_type)
    return cells[:, :3]


with tempdir() as d:
    require_mpi_hoct()
    start = time.time()

    # 1 and 4. Whole files, every rank reading the whole: JSON of 1-7 ranks against one process.
    plate = os.path.join(d, "plate.vtu")
    run("generate", "plate", "--cells", "2000", "-o", plate)
    whole_case("plate 2000 cells, degree 3", plate, 100, ranks=RANKS)
    whole_case("plate, --augmented", plate, 100, extra=["--augmented"], ranks=(2, 3, 7))
    whole_case("plate, --simplify 1%", plate, 100, extra=["--simplify", "1%"], ranks=(2, 3, 7))
    for degree, cells in ((2, 2000), (5, 1500)):
        path = os.path.join(d, f"plate{degree}.vtu")
        run("generate", "plate", "--cells", str(cells), "--degree", str(degree), "-o", path)
        whole_case(f"plate {cells} cells, degree {degree}", path, 100, ranks=RANKS)
    # --vtp: the pieces draw the graph's arcs, each loop's two arcs around its hole apart (the
    # JSON one process's; every arc a polyline over the surface without a jump).
    for flags, ranks in (([], (2, 3, 7)), (["--linear"], (2, 7))):
        plain_vtp, plain_json = os.path.join(d, "plate.vtp"), os.path.join(d, "plate_vtp.json")
        run("tree", plate, *flags, "--vtp", plain_vtp, "--json", plain_json, "--no-timings", "-q")
        for n in ranks:
            got_vtp, got_json = os.path.join(d, f"plate{n}.vtp"), os.path.join(d, f"plate{n}.json")
            p = mpi(n, "tree", plate, *flags, "--vtp", got_vtp, "--json", got_json, "--no-timings")
            label = f"plate --vtp {' '.join(flags)}, {n} ranks"
            r.check(os.path.exists(got_json) and read(got_json) == read(plain_json), f"{label}: the JSON")
            arcs_drawn_by_pieces(r, label, p, got_vtp, plain_vtp)

    # (label, mesh, field, loops (None: at most max_loops), max_loops, components, VTK type,
    # extra flags)
    holes3 = [(3, 6, 3, 6), (9, 12, 4, 7), (5, 8, 10, 13)]  # squares of a 16 x 16 grid
    square = square_with_holes(8, 2, [])
    surfaces = [
        ("annulus, x + 0.3 y, degree 3", annulus(6, 24, 3), tilted, 1, 1, 1, None, []),
        ("annulus, wavy, degree 2", annulus(6, 48, 2), wavy_planar, None, 1, 1, None, []),
        ("annulus, wavy, degree 2, --simplify 2%", annulus(6, 48, 2), wavy_planar, None, 1, 1,
         None, ["--simplify", "2%"]),
        ("annulus of 6 cells (ranks without cells)", annulus(1, 3, 1), tilted, 1, 1, 1, None, []),
        ("torus, x + 0.1 z + 0.05 y, degree 2", torus(32, 12, 2), torus_f1, 1, 1, 1, None, []),
        ("torus, wavy, degree 3", torus(24, 10, 3), wavy_torus, 1, 1, 1, None, []),
        ("Moebius strip, degree 1", moebius(96, 2, 1), moebius_f, None, 1, 1, None, []),
        ("Moebius strip, degree 2", moebius(96, 2, 2), moebius_f, None, 1, 1,
         VTK_LAGRANGE_TRIANGLE, []),
        ("square with 3 holes, x + 0.3 y, degree 2", square_with_holes(16, 2, holes3), tilted, 3,
         3, 1, None, []),
        ("square with 3 holes, wavy, degree 3", square_with_holes(16, 3, holes3), wavy_planar,
         None, 3, 1, None, []),
        ("two annuli, x + 0.3 y, degree 2", combined(annulus(4, 32, 2), annulus(4, 32, 2, cx=3.0)),
         tilted, 2, 2, 2, None, []),
        ("two disks, wavy, degree 2", combined(square, (square[0] + [1.5, 0.0, 0.0], square[1])),
         wavy_planar, 0, 0, 2, None, []),
    ]
    if HAVE_GMSH:
        surfaces += [
            ("disk with 3 holes (Gmsh), wavy, degree 3",
             gmsh_mesh(disk_with_holes(HOLES[3]), 3, 0.12, True), wavy_planar, None, 3, 1, None,
             []),
            ("disk and annulus (Gmsh), x + 0.3 y, degree 3",
             gmsh_mesh(disk_and_annulus, 3, 0.15, True), tilted, 1, 1, 2, None, []),
            ("double torus (Gmsh), wavy, degree 3", gmsh_mesh(double_torus, 3, 0.2, False),
             wavy_surface, 2, 2, 1, None, []),
        ]
    else:
        print("the Gmsh cases are skipped: python3-gmsh is missing", flush=True)
    meshes = {}
    for k, (label, mesh, f, loops, most, comps, cell_type, extra) in enumerate(surfaces):
        path = os.path.join(d, f"surface{k}.vtu")
        write_field(path, mesh, f, cell_type)
        meshes[label] = path
        whole_case(f"{label} ({len(mesh[1])} cells)", path, loops, most, comps, extra)

    quads = quad_annulus(os.path.join(d, "quads.vtu"))
    whole_case("an annulus of bilinear quadrilaterals", quads, 1)
    # The PL methods' Reeb graphs by pieces too (exact/pl_reeb_pieces): each rank's PL mesh cut
    # into disks, glued in the tree of ranks.
    whole_case("the quadrilaterals' annulus, --linear", quads, 1, extra=["--linear"])
    whole_case("the quadrilaterals' annulus, --refine 3", quads, 1, extra=["--refine", "3"])

    # Closed components: hoct's sphere (genus 0) twice, and with hoct's Gaussian disk.
    sphere, gauss = os.path.join(d, "sphere.vtu"), os.path.join(d, "gauss.vtu")
    run("generate", "sphere", "--cells", "500", "-o", sphere)
    run("generate", "gauss", "--cells", "500", "-o", gauss)
    whole_case("two spheres", appended(os.path.join(d, "spheres.vtu"),
                                       [(sphere, 0.0), (sphere, 5.0)]), 0, components=2)
    whole_case("a sphere and a disk", appended(os.path.join(d, "sphere_disk.vtu"),
                                               [(sphere, 0.0), (gauss, 5.0)]), 0, components=2)
    # A sphere beside a surface that is cut: the cut leaves the sphere whole (it was refused as
    # not cut into disks, without MPI too, before).
    small_plate = os.path.join(d, "small_plate.vtu")
    run("generate", "plate", "--cells", "1500", "--degree", "2", "-o", small_plate)
    whole_case("a sphere and the plate", appended(os.path.join(d, "sphere_plate.vtu"),
                                                  [(sphere, -3.0), (small_plate, 0.0)]), 100,
               components=2)

    # 2. Pieces the whole mesh never is, from cell orders made for them (the layout checked).
    # Every other cell of vertex stars moved to the end: pinched first pieces.
    mesh = annulus(6, 24, 3)
    path = os.path.join(d, "annulus_fans.vtu")
    corners = write_ordered(path, mesh, fan_split(mesh[1][:, :3]), tilted)
    layout = ordered_case("annulus, fans split", path, corners, loops=1)
    r.check(all(layout[n][0] > 0 and layout[n][1] >= 2 for n in (2, 3)),
            f"annulus, fans split: the layout pinches no piece: {layout}")
    fans = os.path.join(d, "plate_fans.vtu")
    corners = reorder_vtu(plate, fans, fan_split(vtu_cells(read_grid(plate))[0][:, :3]))
    layout = ordered_case("plate, fans split", fans, corners, loops=100, max_loops=100)
    r.check(all(layout[n][0] > 0 and layout[n][1] >= 2 for n in (2, 3)),
            f"plate, fans split: the layout pinches no piece: {layout}")

    # One class of a 2-colouring of the triangles first: with 2 ranks, every piece is triangles
    # touching at vertices only (3 fans of one cell around a vertex inside).
    for label, mesh, f, loops, cell_type in [
            ("annulus, checkerboard, degree 1", annulus(6, 48, 1), wavy_planar, None, None),
            ("torus, checkerboard, degree 2", torus(24, 10, 2), wavy_torus, 1, None),
            ("Moebius strip, checkerboard, degree 2", moebius(96, 2, 2), moebius_f, None,
             VTK_LAGRANGE_TRIANGLE)]:
        path = os.path.join(d, label.split(",")[0].replace(" ", "_") + "_checkerboard.vtu")
        corners = write_ordered(path, mesh, checkerboard(mesh[1][:, :3]), f, cell_type)
        layout = ordered_case(label, path, corners, loops=loops)
        r.check(layout[2][1] >= 3 and layout[3][0] > 0,
                f"{label}: the layout pinches too little: {layout}")

    # Cells in a random order (seeded): every piece scattered over the surface.
    mesh = torus(24, 10, 3)
    path = os.path.join(d, "torus_shuffled.vtu")
    order = np.random.default_rng(3).permutation(len(mesh[1]))
    corners = write_ordered(path, mesh, order, wavy_torus)
    layout = ordered_case("torus, cells shuffled, degree 3", path, corners, loops=1)
    r.check(layout[2][0] > 0, f"torus, cells shuffled: no piece pinched: {layout}")

    # Rank 0's piece alone is an annulus (it holds the whole hole), the others are disks.
    mesh = annulus(6, 48, 2)
    path = os.path.join(d, "annulus_hole_first.vtu")
    corners = write_ordered(path, mesh, hole_first(6, 48, 2), wavy_planar)
    for n, want in [(3, [(1, 0, 2), (1, 1, 1), (1, 1, 1)]), (2, [(1, 0, 2), (1, 1, 1)])]:
        bounds = piece_bounds(len(corners), n)
        shapes = [piece_shape(corners[a:b]) for a, b in zip(bounds, bounds[1:])]
        r.check(shapes == want, f"annulus, the hole in rank 0: {n} ranks' pieces (components, "
                                f"Euler characteristic, boundary loops) {shapes}, not {want}")
    ordered_case("annulus, the hole in rank 0's piece", path, corners)

    # Two components' cells alternating: every piece holds parts of both.
    pair = interleaved(annulus(4, 32, 2), annulus(4, 32, 2, cx=3.0))
    path = os.path.join(d, "two_annuli_interleaved.vtu")
    write_field(path, pair, tilted)
    ordered_case("two annuli, cells interleaved", path, pair[1][:, :3], loops=2, max_loops=2,
                 components=2)

    # 3. Partitioned input: 4 pieces written by VTK, each rank reading its own.
    for name, src, loops in [("plate", plate, 100),
                             ("torus", meshes["torus, x + 0.1 z + 0.05 y, degree 2"], 1)]:
        for level in (0, 1):
            t0 = time.time()
            label = f"{name} in 4 pieces, ghost level {level}"
            pvtu = os.path.join(d, f"{name}_pieces{level}.pvtu")
            write_pieces(read_grid(src), pvtu, 4, level)
            graph, done = same_json(label, pvtu, ranks=(1, 2, 3, 4))
            for n, p in done.items():
                r.check("reads the whole" not in p.stderr,
                        f"{label}, {n} ranks: read by pieces:\n{p.stderr[-1500:]}")
            check_graph(label, graph, loops)
            print(f"{label}: 1-4 ranks checked ({time.time() - t0:.1f} s)", flush=True)

    # 4. A plateau below the median on the plate, in 4 pieces of consecutive cells: on 4 ranks a
    # seam piece between pieces ties with a fallback cell's lattice node, the pieces cannot
    # glue it, and rank 0 computes the graph of the whole mesh, which the ranks join together
    # from their pieces (no rank read the whole file).
    t0 = time.time()
    grid = read_grid(small_plate)
    f = grid.GetPointData().GetArray("f")
    values = vtk_to_numpy(f).copy()
    floor = np.sort(values)[len(values) // 2]
    for i, v in enumerate(values):
        f.SetValue(i, max(v, floor))
    label = "the plate with a plateau, 4 pieces"
    pvtu = write_consecutive(grid, d, "plateau_plate", 4)
    graph, done = same_json(label, pvtu, ranks=(2, 4), quiet=False)
    for n, p in done.items():
        r.check("reads the whole" not in p.stderr,
                f"{label}, {n} ranks: read by pieces:\n{p.stderr[-1500:]}")
    r.check(4 in done and "tree: the whole mesh on rank 0" in done[4].stdout,
            f"{label}, 4 ranks: the summary says rank 0 computed the whole mesh's graph:\n"
            f"{done[4].stdout[-1500:] if 4 in done else ''}")
    check_graph(label, graph, None, max_loops=100)  # holes within the plateau merge loops
    print(f"{label}: 2 and 4 ranks checked ({time.time() - t0:.1f} s)", flush=True)

    # 5. Rank 0 alone writes, and its summary is one process's.
    for label, path in [("plate", plate), ("Moebius strip", meshes["Moebius strip, degree 2"])]:
        plain = run("tree", path, "--json", os.path.join(d, "plain.json"), "--no-timings",
                    "--svg", os.path.join(d, "plain.svg"))
        out = os.path.join(d, f"out_{label.split()[0]}")
        os.makedirs(out)
        p = mpi(3, "tree", path, "--json", os.path.join(out, "g.json"), "--no-timings",
                "--svg", os.path.join(out, "g.svg"))
        r.check(p.returncode == 0, f"{label}, 3 ranks, summary: exit {p.returncode}: {failure(p)}")
        if p.returncode != 0:
            continue
        r.check(sorted(os.listdir(out)) == ["g.json", "g.svg"],
                f"{label}, 3 ranks: the output directory holds {sorted(os.listdir(out))}")
        for name in ("json", "svg"):
            got = os.path.join(out, f"g.{name}")
            if os.path.exists(got):
                r.check(read(got) == read(os.path.join(d, f"plain.{name}")),
                        f"{label}, 3 ranks: {name} differs from one process")
        r.check("error" not in p.stderr.lower() and "warning" not in p.stderr.lower(),
                f"{label}, 3 ranks: errors or warnings:\n{p.stderr[-1500:]}")
        first = p.stdout.splitlines()[0] if p.stdout else ""
        kind = plain.stdout.splitlines()[0].split("exact ")[-1]  # "Reeb graph (N loops)"
        nodes = [line for line in p.stdout.splitlines() if line.strip().startswith("nodes:")]
        want = [line for line in plain.stdout.splitlines() if line.strip().startswith("nodes:")]
        r.check(kind.startswith("Reeb graph") and f"exact {kind} over 3 MPI ranks" in first
                and p.stdout.count("over 3 MPI ranks") == 1,
                f"{label}, 3 ranks: the summary's first line, once: {first!r} (one process: "
                f"{kind!r})")
        r.check(len(nodes) == 1 and nodes == want,
                f"{label}, 3 ranks: nodes line {nodes}, one process {want}")
        print(f"{label}: rank 0 alone writes, summary checked", flush=True)
    print(f"total {time.time() - start:.1f} s", flush=True)
r.finish()
