"""`mpirun -np N hoct tree FILE.pvtu`: each rank reads only its own pieces (issue 31).

Partitioned files written by VTK itself (vtkExtractUnstructuredGridPiece and
vtkXMLPUnstructuredGridWriter, as in test_collections): ghost levels 0, 1 and 2, with global ids
(the GlobalIds attribute) and without (the pieces' copies of a point joined by position), cubic
triangles, quadratic quadrilaterals, a plateau (ties ordered by the whole's ids) and a field at
+1e7 simplified, and the linear and refine methods on the quadrilaterals and the plateau (2 and
7 ranks); pieces cut by hand with a plain GlobalIds array and an empty piece, also by --linear
and with --vtp (the pieces draw the arcs: as many polylines as one process, none straight, no
jump). The
independent truth is one process reading the whole file (`hoct tree FILE.pvtu`, io/piece_join):
for 1, 2, 3, 4 and 7 ranks (more ranks than pieces: ranks without any) the JSON (--no-timings,
the input's fingerprint included) is byte-identical, the ranks read their pieces alone (no note
that rank 0 reads the whole) and check the whole mesh together. A plate with 100 holes split
into pieces, read by pieces too, gets the Reeb graph of one process, with one loop per hole (hoct
info's counts; more partitioned Reeb graphs in test_mpi_reeb). Pieces whose fields differ,
and a broken piece file, give the error of one process (rank 0 reads the whole then), once.

Skipped (exit 77) without mpirun, VTK's Python module or an MPI build of hoct."""
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hoct_testing import Results, run, tempdir  # noqa: E402
from mpi_testing import arcs_drawn_by_pieces, mpi, read, reeb_with_shape, require_mpi_hoct  # noqa: E402

try:
    import vtk
    from vtk_pieces import read_grid, with_ids, write_hand_cut, write_listing, write_pieces
except ImportError as e:
    print(f"SKIPPED: no VTK Python module ({e})")
    sys.exit(77)
r = Results()


def same_for_all_ranks(label, pvtu, *extra):
    want = pvtu + ".plain.json"
    plain = run("tree", pvtu, "--json", want, "--no-timings", "-q", *extra, check=False)
    r.check(plain.returncode == 0, f"{label}: one process: {plain.stderr[-800:]}")
    # The PL methods on 2 and 7 ranks (more ranks than pieces: ranks without any).
    ranks = (2, 7) if "--linear" in extra or "--refine" in extra else (1, 2, 3, 4, 7)
    for n in ranks:
        got = f"{pvtu}.{n}.json"
        p = mpi(n, "tree", pvtu, "--json", got, "--no-timings", *extra)
        ok = p.returncode == 0 and os.path.exists(got) and read(got) == read(want)
        r.check(ok, f"{label}, {n} ranks: the JSON of one process ({p.returncode}) "
                    f"{p.stderr[-1200:]}")
        r.check("reads the whole" not in p.stderr, f"{label}, {n} ranks: read by pieces:\n{p.stderr}")
        r.check("checks: by the pieces together" in p.stdout,
                f"{label}, {n} ranks: checked by the pieces:\n{p.stdout[-1500:]}")
        # One report line per rank, their cells adding up to the whole's.
        rows = [l.split() for l in p.stdout.splitlines() if l.startswith("    ") and "cells," in l]
        m = re.search(r"field '[^']*', (\d+) cells", p.stdout)
        r.check(m and len(rows) == n and sum(int(row[1]) for row in rows) == int(m.group(1)),
                f"{label}, {n} ranks: per-rank cells add up:\n{p.stdout[-1500:]}")
    print(f"{label}: {ranks} ranks checked", flush=True)


with tempdir() as d:
    require_mpi_hoct()

    sources = {
        "gauss": ["gauss", "--cells", "2000", "--degree", "3"],
        "quads": ["random", "--cells", "1500", "--quads", "--degree", "2"],
        "plateau": ["random", "--cells", "3000", "--plateau", "30"],
        "offset": ["random", "--cells", "2000", "--degree", "4", "--offset", "1e7"],
    }
    for name, gen in sources.items():
        run("generate", *gen, "-o", os.path.join(d, f"{name}.vtu"))
    cases = [("gauss", "ghosts_ids", 3, 1, "gid", []), ("gauss", "ghosts", 3, 1, None, []),
             ("gauss", "no_ghosts", 4, 0, None, []), ("gauss", "no_ghosts_ids", 3, 0, "gid", []),
             ("gauss", "ghosts2", 4, 2, None, []), ("quads", "ghosts", 3, 1, None, []),
             ("plateau", "ghosts", 5, 1, None, []),
             ("offset", "ghosts_ids", 3, 1, "gid", ["--simplify", "1%"]),
             # The linear method's pieces (exact/pl_piece_trees).
             ("quads", "ghosts", 3, 1, None, ["--linear"]),
             ("plateau", "ghosts", 5, 1, None, ["--linear"]),
             ("quads", "ghosts", 3, 1, None, ["--refine", "2"]),
             ("plateau", "ghosts", 5, 1, None, ["--refine", "2"])]
    for source, name, pieces, level, ids, extra in cases:
        pvtu = os.path.join(d, f"{source}_{name}.pvtu")
        grid = read_grid(os.path.join(d, f"{source}.vtu"))
        write_pieces(with_ids(grid, ids) if ids else grid, pvtu, pieces, level, ids)
        same_for_all_ranks(f"{source} {name} ({pieces} pieces) {' '.join(extra)}", pvtu, *extra)

    # Pieces cut by hand: a plain GlobalIds array (no attribute) and an empty piece.
    hand_pvtu = write_hand_cut(read_grid(os.path.join(d, "gauss.vtu")), d)
    hand = [f"hand_{k}.vtu" for k in range(3)]
    same_for_all_ranks("hand-cut, an empty piece", hand_pvtu)
    same_for_all_ranks("hand-cut, an empty piece, linear", hand_pvtu, "--linear")
    # --vtp: the pieces draw the arcs (exact/piece_arcs), an empty one too.
    run("tree", hand_pvtu, "--vtp", hand_pvtu + ".plain.vtp", "-q")
    for n in (2, 3):
        got = f"{hand_pvtu}.{n}.vtp"
        p = mpi(n, "tree", hand_pvtu, "--vtp", got)
        arcs_drawn_by_pieces(r, f"hand-cut --vtp, {n} ranks", p, got, hand_pvtu + ".plain.vtp")

    # A plate with 100 holes in pieces: its Reeb graph, with the whole's loops.
    run("generate", "plate", "--cells", "2000", "-o", os.path.join(d, "plate.vtu"))
    plate = os.path.join(d, "plate.pvtu")
    write_pieces(read_grid(os.path.join(d, "plate.vtu")), plate, 4, 1)

    reeb_with_shape(r, "plate pieces", plate, read_by_pieces=True)

    # What the ranks cannot join alone: one process's error, once.
    os.makedirs(os.path.join(d, "bad"))
    for file in hand:
        shutil.copy(os.path.join(d, file), os.path.join(d, "bad", file))
    with open(os.path.join(d, "bad", "hand_2.vtu"), "rb") as f:
        data = f.read()
    with open(os.path.join(d, "bad", "cut.vtu"), "wb") as f:
        f.write(data[:len(data) // 2])
    write_listing(os.path.join(d, "bad", "broken.pvtu"), ["hand_0.vtu", "hand_1.vtu", "cut.vtu"])
    # Another field in one piece: the renamed array.
    with open(os.path.join(d, "bad", "other.vtu"), "wb") as f:
        f.write(data.replace(b'Name="f"', b'Name="g"'))
    write_listing(os.path.join(d, "bad", "fields.pvtu"), ["hand_0.vtu", "other.vtu"])
    for name in ("broken", "fields"):
        path = os.path.join(d, "bad", f"{name}.pvtu")
        want = run("tree", path, check=False)
        first = want.stderr.strip().splitlines()[0] if want.stderr.strip() else ""
        for n in (2, 3):
            p = mpi(n, "tree", path)
            r.check(want.returncode != 0 and p.returncode != 0 and first and first in p.stderr
                    and p.stderr.count("hoct: error:") == 1,
                    f"{name}, {n} ranks: {first!r} once in\n{p.stderr[-1500:]}")
r.finish()
