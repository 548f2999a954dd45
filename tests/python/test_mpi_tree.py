"""`mpirun -np N hoct tree FILE`: the distributed tree (issue 31's first entry point).

Each rank reads its own part of a generated file (raw appended arrays: test_mpi_vtu_parts);
rank 0 alone reads meshio's files (inline arrays) and one the other ranks cannot open (they are
given a path that does not exist: the same JSON), and sends each rank its piece of contiguous
cells; each computes the tree of its piece,
and the ranks merge their kept join and split trees (exact/piece_trees, distributed/). The
independent truth is hoct's own single-process tree, computed without MPI at all: for every
generated genus-0 dataset, with plateaus and fallback cells, quadrilaterals, a field at +1e7,
--augmented and --simplify, the JSON (--no-timings) must be byte-identical to it for 1, 2, 3, 4
and 7 ranks (--oversubscribe: this machine has 2 cores); the same for the linear and the refine
method (PL trees, by pieces too; the plate's PL Reeb graphs by pieces as well, on 2-7 ranks),
whose serendipity cells (linear) rank 0 computes from the whole mesh, saying so. With --vtp
(exact, linear, refine) the pieces draw the arcs over the surface (exact/piece_arcs): the JSON
is one process's and every arc a polyline without a jump. Also checked:
a broken file is reported as without MPI, and rank 0 alone writes the outputs.
Bad meshes: inverted cells that a piece finds are named by the whole's cell numbers, as without
MPI, and --force past them gives the same JSON; a crack between pieces and a slit from the border
(duplicate points; the slit leaves a disk) are found by the pieces' duplicate check across ranks,
and reported by rank 0's check of the whole mesh as without MPI (the crack forced: two components,
the Reeb graph of one process). The pieces check a valid mesh together (rank 0 does not check it
again), and the shape they find for a plate with 100 holes is no disk: its Reeb graph is one
process's, with one loop per hole (hoct info's counts). The Reeb graphs over MPI are
test_mpi_reeb's.

Skipped (exit 77) without mpirun or an MPI build of hoct."""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hoct_testing import HOCT, Results, run, tempdir  # noqa: E402
from mpi_testing import (ENV, MPIRUN, arcs_drawn_by_pieces, mpi, read, reeb_with_shape,  # noqa: E402
                         require_mpi_hoct)

r = Results()


with tempdir() as d:
    require_mpi_hoct()
    cases = [
        ("two-triangle", [], []),
        ("gauss", ["--cells", "2000"], []),
        ("heater", ["--cells", "3000"], []),
        ("conductor", ["--cells", "2000"], []),
        ("sphere", ["--cells", "2000"], []),
        ("random", ["--cells", "4000"], []),
        ("random", ["--cells", "3000", "--plateau", "30"], []),
        ("random", ["--cells", "3000", "--plateau", "30"], ["--augmented"]),
        ("random", ["--cells", "2000", "--degree", "5", "--offset", "1e7"], ["--simplify", "1%"]),
        ("random", ["--cells", "1500", "--quads", "--degree", "3"], []),
        # The linear method (the PL tree of the nodes, exact/pl_piece_trees).
        ("sphere", ["--cells", "2000"], ["--linear"]),
        ("random", ["--cells", "3000", "--plateau", "30"], ["--linear"]),
        ("random", ["--cells", "3000", "--plateau", "30"], ["--linear", "--augmented"]),
        ("random", ["--cells", "2000", "--degree", "5", "--offset", "1e7"], ["--linear", "--simplify", "1%"]),
        ("random", ["--cells", "1500", "--quads", "--degree", "3"], ["--linear"]),
        # The refine method (the PL tree of the exact field on K x K sub-triangles).
        ("sphere", ["--cells", "1000"], ["--refine", "3"]),
        ("random", ["--cells", "1500", "--plateau", "30"], ["--refine", "2"]),
        ("random", ["--cells", "800", "--quads", "--degree", "3"], ["--refine", "3"]),
        ("random", ["--cells", "1000", "--degree", "5", "--offset", "1e7"], ["--refine", "2", "--simplify", "1%"]),
    ]
    for k, (name, gen, extra) in enumerate(cases):
        path = os.path.join(d, f"{name}{k}.vtu")
        run("generate", name, *gen, "-o", path)
        want = os.path.join(d, f"want{k}.json")
        run("tree", path, "--json", want, "--no-timings", "-q", *extra)
        label = f"{name} {' '.join(gen + extra)}"
        # The PL methods on 2 and 7 ranks (tests/unit/test_pl_piece_trees: 1-16 pieces).
        ranks = (2, 7) if "--linear" in extra or "--refine" in extra else (1, 2, 3, 4, 7)
        for n in ranks:
            got = os.path.join(d, f"got{k}_{n}.json")
            p = mpi(n, "tree", path, "--json", got, "--no-timings", "-q", *extra)
            r.check(p.returncode == 0, f"{label}, {n} ranks: exit {p.returncode}: {p.stderr[-1500:]}")
            if p.returncode == 0:
                r.check(read(got) == read(want), f"{label}, {n} ranks: JSON differs from one process")
        print(f"{label}: {ranks} ranks checked", flush=True)

    # The summary comes from rank 0 alone, and says how many ranks.
    path = os.path.join(d, "heater.vtu")
    run("generate", "heater", "-o", path)
    for n in (1, 3):
        p = mpi(n, "tree", path)
        r.check(p.returncode == 0 and p.stdout.count(f"over {n} MPI ranks") == 1
                and p.stdout.count("nodes:") == 1, f"summary on rank 0 only:\n{p.stdout}")
        # One report line per rank; their cells add up to the mesh's.
        rows = [l.split() for l in p.stdout.splitlines() if l.startswith("    ") and "cells," in l]
        cells = sum(int(row[1]) for row in rows)
        r.check(len(rows) == n and cells == 12324,
                f"{n} ranks: per-rank report ({len(rows)} rows, {cells} cells):\n{p.stdout}")

    # --vtp: the pieces draw the arcs (exact/piece_arcs): the JSON is one process's, no rank
    # holds the whole mesh, and each arc is a polyline over the surface with as many lines as
    # one process draws, none of whose steps is longer than one process's longest (a route
    # joined wrongly across pieces would jump).
    for flags, ranks in [([], (2, 3, 7)), (["--linear"], (2, 7)), (["--refine", "2"], (2, 7))]:
        plain_vtp, plain_json = os.path.join(d, "plain.vtp"), os.path.join(d, "plain.json")
        run("tree", path, *flags, "--vtp", plain_vtp, "--json", plain_json, "--no-timings", "-q")
        for n in ranks:
            got_vtp, got_json = os.path.join(d, f"x{n}.vtp"), os.path.join(d, f"x{n}.json")
            p = mpi(n, "tree", path, *flags, "--vtp", got_vtp, "--json", got_json, "--no-timings")
            label = f"--vtp {' '.join(flags)}, {n} ranks"
            r.check(read(got_json) == read(plain_json), f"{label}: the JSON")
            arcs_drawn_by_pieces(r, label, p, got_vtp, plain_vtp)
    # --refine past the memory budget: refused on every rank before refining, once, no output.
    big = os.path.join(d, "big_refine.json")
    p = mpi(2, "tree", path, "--refine", "1000", "--max-memory", "1G", "--json", big)
    r.check(p.returncode != 0 and p.stderr.count("hoct: error:") == 1
            and "(a rank's share) of 1000 x 1000 sub-triangles need" in p.stderr
            and not os.path.exists(big), f"--refine over budget ({p.returncode}):\n{p.stderr[-800:]}")
    for flags, words in [(["--linear"], "linear contour tree"), (["--refine", "2"], "refine k=2 contour tree")]:
        p = mpi(2, "tree", path, *flags)
        r.check(p.returncode == 0 and f"{words} over 2 MPI ranks" in p.stdout
                and "tree: the whole mesh" not in p.stdout, f"{flags} by the pieces:\n{p.stdout}")

    # The pieces check the whole mesh together (mesh/piece_surface, distributed_checks): a valid
    # mesh is not checked again by rank 0, and the shape they find is the whole mesh's for any
    # number of ranks: a plate with 100 holes gets the Reeb graph of one process, with the
    # loops of hoct info's counts.
    for n in (2, 3):
        p = mpi(n, "tree", path)
        r.check("checks: by the pieces together" in p.stdout, f"{n} ranks: checks:\n{p.stdout}")
    plate = os.path.join(d, "plate.vtu")
    run("generate", "plate", "--cells", "2000", "-o", plate)
    reeb_with_shape(r, "plate", plate)

    # The PL methods' Reeb graphs by pieces (each rank's PL mesh cut into disks, glued in the
    # tree of ranks): one process's JSON, no whole mesh on rank 0. What the linear method's
    # pieces do not compute (serendipity cells, whose PL mesh has points of its own): rank 0
    # computes it from the whole mesh, says so, and the JSON is one process's.
    import meshio
    import numpy as np

    quad8 = os.path.join(d, "quad8.vtu")
    n8 = 8
    grid = {}

    def node(x, y):
        return grid.setdefault((x, y), len(grid))

    cells8 = [[node(2 * i, 2 * j), node(2 * i + 2, 2 * j), node(2 * i + 2, 2 * j + 2), node(2 * i, 2 * j + 2),
               node(2 * i + 1, 2 * j), node(2 * i + 2, 2 * j + 1), node(2 * i + 1, 2 * j + 2), node(2 * i, 2 * j + 1)]
              for j in range(n8) for i in range(n8)]
    xy = np.array([(x / (2 * n8), y / (2 * n8), 0.0) for (x, y) in sorted(grid, key=grid.get)])
    meshio.write(quad8, meshio.Mesh(xy, [("quad8", np.array(cells8))],
                                    point_data={"f": np.sin(5 * xy[:, 0]) * np.cos(4 * xy[:, 1])}))
    for label, file, flags, why, ranks in [
            ("plate", plate, ["--linear"], None, (2, 3, 4, 7)),
            ("plate", plate, ["--linear", "--augmented"], None, (2, 3)),
            ("plate", plate, ["--refine", "2"], None, (2, 3, 4, 7)),
            ("serendipity quadrilaterals", quad8, ["--linear"], "Bezier or serendipity", (2, 3))]:
        want = os.path.join(d, "linear_whole.json")
        run("tree", file, *flags, "--json", want, "--no-timings", "-q")
        for n in ranks:
            got = os.path.join(d, f"linear_whole{n}.json")
            p = mpi(n, "tree", file, *flags, "--json", got, "--no-timings")
            whole = "tree: the whole mesh on rank 0 (" in p.stdout
            r.check(p.returncode == 0 and os.path.exists(got) and read(got) == read(want)
                    and (whole and why in p.stdout if why else not whole)
                    and flags[0][2:] in p.stdout.splitlines()[0],
                    f"{label} {flags}, {n} ranks: one process's JSON, "
                    f"{'from the whole on rank 0' if why else 'by pieces'} "
                    f"({p.returncode}):\n{p.stdout[-1500:]}{p.stderr[-800:]}")

    # Rank 0 alone reads a file the other ranks cannot open: with every other rank given a path
    # that does not exist (mpirun's MPMD form), the run still gives one process's JSON (with
    # --vtp too).
    gone = os.path.join(d, "not-there.vtu")
    want = os.path.join(d, "alone_want.json")
    run("tree", path, "--json", want, "--no-timings", "-q")
    for n in (2, 3):
        got, got_vtp = os.path.join(d, f"alone_{n}.json"), os.path.join(d, f"alone_{n}.vtp")
        p = subprocess.run([MPIRUN, "--oversubscribe", "-np", "1", HOCT, "tree", path, "--json", got,
                            "--vtp", got_vtp, "--no-timings", "-q", ":", "-np", str(n - 1), HOCT,
                            "tree", gone, "--json", got, "--vtp", got_vtp, "--no-timings", "-q"],
                           capture_output=True, text=True, env=ENV, timeout=600)
        r.check(p.returncode == 0 and os.path.exists(got) and read(got) == read(want),
                f"rank 0 alone reads the file, {n} ranks ({p.returncode}):\n{p.stderr[-1500:]}")

    # A broken file: the same error as without MPI, from rank 0's read.
    broken = os.path.join(d, "broken.vtu")
    with open(broken, "wb") as f:
        f.write(read(path)[:5000])
    want = run("tree", broken, check=False)
    p = mpi(2, "tree", broken)
    r.check(p.returncode != 0 and want.returncode != 0, f"broken file: exit {p.returncode}")
    first_line = want.stderr.strip().splitlines()[0] if want.stderr.strip() else ""
    r.check(first_line and first_line in p.stderr, f"broken file: {first_line!r} in {p.stderr[-1500:]!r}")
    r.check(p.stderr.count("hoct: error:") == 1, f"broken file: one message, not one per rank:\n{p.stderr}")

    # Problems only the whole mesh shows, or that a piece finds: the same message (the whole's
    # cell numbers) as without MPI, and --force past them the same JSON.

    def grid_mesh(path, move=None, crack=False):
        n = 12
        pts = [(i / n, j / n, 0.0) for j in range(n + 1) for i in range(n + 1)]
        tri = []
        for j in range(n):
            for i in range(n):
                a, b, c, e = j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i
                tri += [(a, b, c), (a, c, e)]
        if crack:  # the upper half's own copies of the middle row's points: a crack across pieces
            mid = n // 2
            copy = {}
            for k, t in enumerate(tri):
                if k >= len(tri) // 2:
                    tri[k] = tuple(copy.setdefault(v, None) or v for v in t)
            for k in range(len(tri) // 2, len(tri)):
                t = list(tri[k])
                for m, v in enumerate(t):
                    # crack="slit": the left half of the row only, a slit from the border
                    # (still a disk: only the duplicate vertices tell it)
                    if v // (n + 1) == mid and (crack is True or v % (n + 1) < n // 2):
                        if v not in copy or copy[v] is None:
                            copy[v] = len(pts)
                            pts.append(pts[v])
                        t[m] = copy[v]
                tri[k] = tuple(t)
        pts = np.array(pts)
        if move is not None:  # a point moved past its neighbours: inverted cells in the last piece
            pts[move[0], 0] += move[1]
        vals = np.sin(3 * pts[:, 0]) * np.cos(2 * pts[:, 1]) + 0.1 * pts[:, 0]
        meshio.write(path, meshio.Mesh(pts, [("triangle", np.array(tri))], point_data={"f": vals}))

    for name, kw in [("inverted", {"move": (9 * 13 + 6, 2.5 / 12)}), ("crack", {"crack": True}),
                     ("slit", {"crack": "slit"})]:
        path = os.path.join(d, f"{name}.vtu")
        grid_mesh(path, **kw)
        plain = run("tree", path, check=False)
        first = plain.stderr.strip().splitlines()[0] if plain.stderr.strip() else ""
        for n in (2, 3, 7):
            p = mpi(n, "tree", path)
            r.check(plain.returncode != 0 and p.returncode != 0 and first and first in p.stderr
                    and p.stderr.count("hoct: error:") == 1,
                    f"{name}, {n} ranks: {first!r} in\n{p.stderr[-1500:]}")
            lines = [l for l in plain.stderr.splitlines() if "cell" in l or "point" in l][:3]
            r.check(all(l in p.stderr for l in lines), f"{name}, {n} ranks: the same places {lines}")
        want = os.path.join(d, f"{name}-forced.json")
        plain = run("tree", path, "--force", "--json", want, "--no-timings", "-q", check=False)
        r.check(plain.returncode == 0, f"{name} --force: {plain.stderr[-800:]}")
        if name == "crack" and plain.returncode == 0:
            # Forced past the duplicates: two components, a Reeb graph.
            with open(want) as f:
                kind = json.load(f)["kind"]
            r.check(kind == "Reeb graph", f"crack --force: one process's {kind!r}")
        for n in (2, 3):
            got = os.path.join(d, f"{name}-forced{n}.json")
            p = mpi(n, "tree", path, "--force", "--json", got, "--no-timings", "-q")
            r.check(p.returncode == 0 and read(got) == read(want),
                    f"{name} --force, {n} ranks: same JSON ({p.returncode}) {p.stderr[-800:]}")
        print(f"{name}: checked", flush=True)
r.finish()
