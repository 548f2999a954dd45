"""`hoct.read_pieces` and `hoct.piece_from_arrays` under mpi4py: each rank holds only its own
piece of the mesh (a .pvtu's pieces it read, or its own arrays in situ), the ranks join the
pieces together, and `hoct.contour_tree(piece, comm=...)` gives rank 0 the tree of the whole.

The independent truth is the command line without MPI on the same partitioned file, which
joins the pieces in one process (`hoct tree FILE.pvtu --json --no-timings`): rank 0's JSON
must be byte-identical to it, and the other ranks get None.
- read_pieces: .pvtu files of 4 pieces written by VTK (ghost level 1 with global ids, ghost
  level 0 without ids: copies joined by position), on 1-4 and 2-3 ranks, and one .vtu read by
  parts on 1-3 ranks; no rank reads the whole (`whole_on_every_rank` is None) and the ranks'
  cells add up to the whole's; a .vtu of inline arrays is read whole on every rank, which says
  why.
- piece_from_arrays: rank r passes the arrays of piece r of a .pvtu of consecutive cells
  (points, cells in VTK order, values, with and without global ids; with ghost cells flagged):
  cubic triangles on 2 and 3 ranks, a plate with 100 holes (the Reeb graph) on 3, a plateau on 2.
- Errors: a rank's bad arrays are raised on every rank naming that rank; comm missing for a
  Piece; a piece used on another communicator; a file neither .pvtu nor .vtu; copies of a point (one
  global id) at different positions: the ranks cannot join alone, every rank joins the whole and
  raises its refusal.

Skipped (exit 77) without mpirun, mpi4py, VTK's Python module or an MPI build of hoct."""
import json
import os
import re
import subprocess
import sys
import textwrap

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hoct_testing import Results, run, tempdir  # noqa: E402
from mpi_testing import MPIRUN, PYTHON, require_modules  # noqa: E402  (skips without mpirun)

require_modules(("mpi4py.MPI", "python3-mpi4py"), ("vtk", "python3-paraview"))
from vtk_pieces import read_grid, with_ids, write_consecutive, write_pieces  # noqa: E402

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
r = Results()

SCRIPT = textwrap.dedent('''
    import json, sys
    import numpy as np
    from mpi4py import MPI
    import vtk
    from vtkmodules.util.numpy_support import vtk_to_numpy
    import hoct
    mode, options, out = sys.argv[1], json.loads(sys.argv[2]), sys.argv[3]
    world = MPI.COMM_WORLD

    def arrays(path):
        """A piece file's points, cells (VTK order), values f, ids and ghost flags."""
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(path)
        reader.Update()
        g = reader.GetOutput()
        pts = vtk_to_numpy(g.GetPoints().GetData())
        conn = vtk_to_numpy(g.GetCells().GetConnectivityArray())
        per = g.GetCell(0).GetNumberOfPoints() if g.GetNumberOfCells() else 3
        cells = conn.reshape(-1, per)
        types = vtk_to_numpy(g.GetCellTypesArray())
        pd = g.GetPointData()
        ids = pd.GetArray("GlobalIds")
        ghost = g.GetCellData().GetArray("vtkGhostType")
        return (pts, cells, vtk_to_numpy(pd.GetArray("f")), types,
                None if ids is None else vtk_to_numpy(ids),
                None if ghost is None else vtk_to_numpy(ghost) & 1)

    if mode == "read":
        piece = hoct.read_pieces(options["path"], world, threads=1)
        sizes = world.gather((piece.num_cells, piece.whole_cells,
                              piece.whole_on_every_rank), root=0)
    elif mode == "arrays":
        pts, cells, f, types, ids, ghost = arrays(options["files"][world.rank])
        piece = hoct.piece_from_arrays(pts, cells, f, world,
                                       global_ids=ids if options["ids"] else None,
                                       ghost_cells=ghost if options["ghosts"] else None,
                                       cell_types=types if len(types) else None)
        sizes = world.gather((piece.num_cells, piece.whole_cells,
                              piece.whole_on_every_rank), root=0)
    elif mode == "raises":
        try:
            if options["case"] == "bad arrays":
                pts = np.array([[0, 0], [1, 0], [0, 1]], dtype=float)
                cells = np.array([[0, 1, 2 if world.rank != 1 else 7]])
                hoct.piece_from_arrays(pts, cells, np.zeros(3), world)
            elif options["case"] == "no comm":
                pts, cells, f, types, ids, ghost = arrays(options["files"][world.rank])
                hoct.contour_tree(hoct.piece_from_arrays(pts, cells, f, world, global_ids=ids))
            elif options["case"] == "ids disagree":
                # Rank 1's points moved: its copies of the shared points (same ids) are
                # elsewhere. The ranks cannot join alone; every rank joins the whole, which
                # refuses the ids.
                pts, cells, f, types, ids, ghost = arrays(options["files"][world.rank])
                if world.rank == 1:
                    pts = pts + 0.25
                hoct.piece_from_arrays(pts, cells, f, world, global_ids=ids)
            elif options["case"] == "other comm":
                pts, cells, f, types, ids, ghost = arrays(options["files"][world.rank])
                piece = hoct.piece_from_arrays(pts, cells, f, world, global_ids=ids)
                hoct.contour_tree(piece, comm=world.Split(world.rank % 2, world.rank))
            else:
                hoct.read_pieces(options["path"], world)
        except hoct.HoctError as e:
            print(f"\\nRAISED {world.rank}: {e}", flush=True)
        else:
            print(f"\\nNOT RAISED {world.rank}", flush=True)
        sys.exit(0)
    tree = hoct.contour_tree(piece, comm=world, threads=1, **options.get("tree", {}))
    if world.rank == 0:
        tree.write_json(out, timings=False)
        with open(out + ".sizes", "w") as fh:
            json.dump(sizes, fh)
    elif tree is not None:
        print(f"rank {world.rank} got a tree", flush=True)
        sys.exit(3)
''')


def mpi(n, mode, options, out=""):
    return subprocess.run([MPIRUN, "--oversubscribe", "-np", str(n), PYTHON, script, mode,
                           json.dumps(options), out], capture_output=True, text=True, env=ENV,
                          timeout=600)


def read(path):
    with open(path, "rb") as f:
        return f.read()


def same_tree(label, n, mode, options, want, whole_cells):
    got = os.path.join(d, f"got_{abs(hash(label))}_{n}.json")
    p = mpi(n, mode, options, got)
    r.check(p.returncode == 0, f"{label}, {n} ranks: exit {p.returncode}: "
            f"{p.stdout[-500:]}{p.stderr[-1500:]}")
    if p.returncode != 0:
        return
    r.check(read(got) == read(want), f"{label}, {n} ranks: JSON differs from the CLI's")
    with open(got + ".sizes") as f:
        sizes = json.load(f)
    r.check(all(w is None for _, _, w in sizes),
            f"{label}, {n} ranks: a rank holds the whole: {[w for _, _, w in sizes]}")
    r.check(sum(c for c, _, _ in sizes) == whole_cells and
            all(t == whole_cells for _, t, _ in sizes),
            f"{label}, {n} ranks: cells per rank {sizes}, whole {whole_cells}")


def cli_tree(label, pvtu, *flags):
    want = os.path.join(d, f"want_{abs(hash((label, flags)))}.json")
    run("tree", pvtu, "--json", want, "--no-timings", "-q", *flags)
    with open(want) as f:
        return want, json.load(f)["input"]["cells"]


with tempdir() as d:
    script = os.path.join(d, "pieces.py")
    with open(script, "w") as f:
        f.write(SCRIPT)
    gauss = os.path.join(d, "gauss.vtu")
    run("generate", "gauss", "--cells", "3000", "--degree", "3", "-o", gauss)
    probe = mpi(1, "read", {"path": gauss}, os.path.join(d, "probe.json"))
    if "built without MPI" in probe.stderr:
        print("SKIPPED: this hoct was built without MPI")
        sys.exit(77)

    # 1. read_pieces: each rank reads its own pieces of a .pvtu.
    for name, level, ids, counts in [("ghosts_ids", 1, "gid", (1, 2, 3, 4)),
                                     ("no_ids", 0, None, (2, 3))]:
        pvtu = os.path.join(d, f"gauss_{name}.pvtu")
        grid = read_grid(gauss)
        write_pieces(with_ids(grid, ids) if ids else grid, pvtu, 4, level, ids)
        label = f"read_pieces, 4 pieces {name}"
        want, cells = cli_tree(label, pvtu)
        for n in counts:
            same_tree(label, n, "read", {"path": pvtu}, want, cells)
        print(f"{label}: {counts} ranks checked", flush=True)

    # read_pieces on one .vtu (raw appended arrays): each rank reads its own part.
    want, cells = cli_tree("read_pieces, one .vtu", gauss)
    for n in (1, 2, 3):
        same_tree("read_pieces, one .vtu", n, "read", {"path": gauss}, want, cells)
    # Inline arrays: every rank reads the whole file, and says why.
    inline = os.path.join(d, "gauss_inline.vtu")
    run("generate", "gauss", "--cells", "3000", "--degree", "3", "--encoding", "zlib", "-o", inline)
    got = os.path.join(d, "inline.json")
    p = mpi(2, "read", {"path": inline}, got)
    with open(got + ".sizes") as f:
        sizes = json.load(f)
    r.check(p.returncode == 0 and read(got) == read(cli_tree("inline", inline)[0])
            and all(w and "not raw appended data" in w for _, _, w in sizes),
            f"read_pieces, inline .vtu: the whole on every rank, saying why: {sizes} "
            f"{p.stderr[-800:]}")
    print("read_pieces, one .vtu: (1, 2, 3) ranks checked", flush=True)

    # 2. piece_from_arrays: rank r passes piece r's arrays.
    plate = os.path.join(d, "plate.vtu")
    run("generate", "plate", "--cells", "1500", "--degree", "2", "-o", plate)
    plateau = os.path.join(d, "plateau.vtu")
    run("generate", "random", "--cells", "2000", "--plateau", "30", "-o", plateau)
    for source, label, counts in [(gauss, "gauss, cubic", (2, 3)),
                                  (plate, "plate, 100 holes", (3,)),
                                  (plateau, "random with a plateau", (2,))]:
        for n in counts:
            base = f"{os.path.basename(source)[:-4]}_{n}"
            pvtu = write_consecutive(read_grid(source), d, base, n)
            files = [os.path.join(d, f"{base}_{k}.vtu") for k in range(n)]
            want, cells = cli_tree(label, pvtu)
            for ids in (True, False):
                same_tree(f"piece_from_arrays, {label}, ids {ids}", n, "arrays",
                          {"files": files, "ids": ids, "ghosts": False}, want, cells)
        print(f"piece_from_arrays, {label}: {counts} ranks checked", flush=True)
    # The PL methods by the pieces (exact/pl_piece_trees): the CLI's --linear and --refine trees,
    # from 3 pieces of contiguous cells.
    def pl_by_arrays(label, source, base, ids, tree, *flags):
        pvtu = write_consecutive(read_grid(source), d, base, 3)
        files = [os.path.join(d, f"{base}_{k}.vtu") for k in range(3)]
        want, cells = cli_tree(label, pvtu, *flags)
        same_tree(f"piece_from_arrays, {label}", 3, "arrays",
                  {"files": files, "ids": ids, "ghosts": False, "tree": tree}, want, cells)

    pl_by_arrays("linear, a plateau", plateau, "plateau_linear", False, {"method": "linear"},
                 "--linear")
    # The linear method's Reeb graph is rank 0's from the whole mesh: the ranks make their pieces
    # again from the arrays they were given (kept, not copied) and send them to rank 0.
    pl_by_arrays("plate, linear (the whole on rank 0)", plate, "plate_linear", True,
                 {"method": "linear"}, "--linear")
    pl_by_arrays("refine 2, a plateau", plateau, "plateau_refine", False,
                 {"method": "refine", "refine": 2}, "--refine", "2")
    # Ghost cells flagged: VTK's pieces with a ghost level, each rank its piece's arrays.
    pvtu = os.path.join(d, "gauss_ghost3.pvtu")
    write_pieces(with_ids(read_grid(gauss), "gid"), pvtu, 3, 1, "gid")
    files = [os.path.join(d, f"gauss_ghost3_{k}.vtu") for k in range(3)]
    want, cells = cli_tree("ghosts", pvtu)
    same_tree("piece_from_arrays, ghost cells flagged", 3, "arrays",
              {"files": files, "ids": True, "ghosts": True}, want, cells)
    # Unflagged, the ghost cells are cells twice: not the CLI's mesh (it drops them).
    got = os.path.join(d, "unflagged.json")
    p = mpi(3, "arrays", {"files": files, "ids": True, "ghosts": False}, got)
    r.check(p.returncode != 0 or read(got) != read(want),
            "ghost cells not flagged: the same tree as with them dropped (the flag is not read)")
    print("piece_from_arrays, ghost cells: checked", flush=True)

    # 3. Errors: raised on every rank, and the job ends normally.
    files3 = [os.path.join(d, f"gauss_3_{k}.vtu") for k in range(3)]
    for label, options, text in [
        ("bad arrays on rank 1", {"case": "bad arrays"}, "rank 1: "),
        ("no comm for a piece", {"case": "no comm", "files": files3}, "pass the communicator"),
        ("another communicator", {"case": "other comm", "files": files3},
         "not the communicator the piece was made on"),
        ("ids that disagree", {"case": "ids disagree", "files": files3},
         "the ids are not the same points"),
        ("neither a .pvtu nor a .vtu", {"case": "msh", "path": gauss[:-4] + ".msh"},
         "neither a partitioned .pvtu nor a .vtu"),
    ]:
        p = mpi(3, "raises", options)
        raised = sorted(int(x) for x in re.findall(r"RAISED (\d+): ", p.stdout))
        r.check(p.returncode == 0 and raised == [0, 1, 2] and "NOT RAISED" not in p.stdout
                and p.stdout.count(text) == 3,
                f"{label}: want HoctError ('{text}') on all 3 ranks, got exit {p.returncode}: "
                f"{p.stdout[-1500:]}{p.stderr[-1000:]}")
        print(f"{label}: raised on every rank", flush=True)

r.finish()
