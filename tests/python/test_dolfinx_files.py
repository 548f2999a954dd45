"""Files written by DOLFINx itself (python3-dolfinx 0.5), read by hoct.

dolfinx_writer.py interpolates f(x, y) = (x - A)^2 - (y - B)^2 (A = 0.4, B = 0.45) on the unit
square (8 x 8 triangles) and writes it with VTKFile (.pvd + .pvtu + .vtu, the point ids first in
every file) as P1, P2 and P3, with XDMFFile (P1 at two times) and, on a second-order Gmsh mesh of
a disk, with both. Under mpirun on 2 and 3 ranks it writes the P2 and P3 functions as partitioned .pvtu files
with ghost cells and points. What hoct must make of them:
- the field: 'temperature', never vtkOriginalPointIds (which DOLFINx writes first), named in the
  summary and in the JSON;
- P2 and P3 (exact for a quadratic): the analytic tree of f on the square, 5 nodes: the saddle
  (A, B) at 0, boundary minima (A, 0) at -B^2 and (A, 1) at -(1 - B)^2, boundary maxima (0, B) at
  A^2 and (1, B) at (1 - A)^2. DOLFINx's P3 nodes sit at Gauss-Lobatto-Legendre points: hoct says
  so and reads them at their true positions (else the tree would have spurious features);
- P1: a piecewise-linear field whose leaves are exactly the vertices that are local extrema
  among their mesh neighbours (found here by brute force from DOLFINx's in-memory arrays), every
  node a vertex with the value f there; VTKFile and XDMF give the same tree;
- the partitioned files (P2, and P3 with its GLL nodes), on 2 and 3 ranks, the tree of the
  serial file, and read by `mpirun -np N hoct tree` (N = 1, 2, 3, 4, 7) the same JSON as one
  process, the .pvd (rank 0 reads the whole and sends each rank its share) and the .pvtu (each rank reads only its pieces
  and resamples its GLL cells); one piece alone, a warning naming the .pvtu to read instead;
- XDMF steps: `hoct info` lists both, the default is the last, --step and --time choose, and a
  time that is not there is an error listing the times;
- P2 on curved cells: XDMF (Triangle_6) and VTKFile (Lagrange triangles) give the same tree, with
  the analytic saddle (the interior cells are straight).

Skipped (exit 77) where DOLFINx is not installed. Run by ctest with /usr/bin/python3 and HOCT_BIN
set to the hoct executable."""
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hoct_testing import HOCT, Results, close, compare_trees, run, tempdir, tree_json  # noqa: E402

try:
    import dolfinx  # noqa: F401
    import numpy as np
except ImportError as e:
    print(f"SKIPPED: DOLFINx is not installed ({e}); scripts/setup installs python3-dolfinx")
    sys.exit(77)

A, B = 0.4, 0.45
WRITER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "dolfinx_writer.py")
r = Results()


def f(x, y):
    return (x - A) ** 2 - (y - B) ** 2


def write_files(d):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    w = subprocess.run([sys.executable, WRITER, d], capture_output=True, text=True, env=env)
    if w.returncode != 0:
        raise RuntimeError(f"dolfinx_writer.py failed:\n{w.stderr[-3000:]}")
    mpirun = shutil.which("mpirun")
    ranks = []
    for n in (2, 3):
        if not mpirun:
            break
        w = subprocess.run([mpirun, "--oversubscribe", "-np", str(n), sys.executable, WRITER, d,
                            "--partitioned"], capture_output=True, text=True, env=env)
        r.check(w.returncode == 0, f"DOLFINx on {n} ranks failed:\n{w.stderr[-3000:]}")
        ranks.append(n)
    return ranks


def same_tree(name, j, k, tol=1e-12):
    compare_trees(r, name, j, k, tol)


def analytic_tree(name, j, tol, scale=1.0):
    expected = sorted([("saddle", 0.0, A, B), ("minimum", -B * B, A, 0.0),
                       ("minimum", -(1 - B) ** 2, A, 1.0), ("maximum", A * A, 0.0, B),
                       ("maximum", (1 - A) ** 2, 1.0, B)])
    got = sorted((n["type"], n["value"] / scale, n["position"][0], n["position"][1])
                 for n in j["nodes"])
    ok = len(got) == len(expected) and all(
        g[0] == e[0] and all(abs(u - v) <= tol for u, v in zip(g[1:], e[1:]))
        for g, e in zip(got, expected))
    r.check(ok, f"{name}: expected the analytic tree {expected}, got {got}")


def pl_extrema(npz):
    """The vertices of the P1 field that are local minima or maxima among their neighbours."""
    x, cells, values = npz["x"], npz["cells"], npz["values"]
    nbrs = [set() for _ in range(len(x))]
    for c in cells:
        for i in c:
            nbrs[i].update(int(k) for k in c if k != i)
    found = set()
    for i, nb in enumerate(nbrs):
        # Equal values are ordered by value, then index (simulation of simplicity by id).
        lower = [k for k in nb if (values[k], k) < (values[i], i)]
        if len(lower) in (0, len(nb)):
            found.add(("minimum" if not lower else "maximum", round(x[i][0], 9),
                       round(x[i][1], 9)))
    return found


with tempdir() as d:
    p = lambda name: os.path.join(d, name)  # noqa: E731
    ranks = write_files(d)

    # The default field on every DOLFINx .vtu (point ids first) is the function.
    for deg in (1, 2, 3):
        info = json.loads(run("info", p(f"p{deg}.pvd"), "--json").stdout)
        r.check(info.get("field") == "temperature", f"p{deg}.pvd: info's field {info.get('field')}")
    trees = {}
    for deg in (1, 2, 3):
        j, res = tree_json(p(f"p{deg}.pvd"))
        trees[deg] = j
        r.check(j["input"]["field"] == "temperature", f"P{deg}: JSON field {j['input']['field']}")
        r.check("field 'temperature'" in res.stdout, f"P{deg}: summary: {res.stdout[:300]}")
        gll = "Gauss-Lobatto-Legendre" in res.stderr
        r.check(gll == (deg == 3), f"P{deg}: GLL note {'missing' if deg == 3 else 'given'}: "
                f"{res.stderr.strip()[:300]}")
    analytic_tree("P2 (VTKFile)", trees[2], 1e-9)
    analytic_tree("P3 (VTKFile, GLL nodes)", trees[3], 1e-9)

    # P1: leaves are the brute-force local extrema; nodes are vertices with f's value.
    npz = np.load(p("p1_points.npz"))
    leaves = {(n["type"], round(n["position"][0], 9), round(n["position"][1], 9))
              for n in trees[1]["nodes"] if n["type"] in ("minimum", "maximum")}
    expected = pl_extrema(npz)
    r.check(leaves == expected, f"P1: leaves {sorted(leaves)} != local extrema {sorted(expected)}")
    r.check(all(close(n["value"], f(*n["position"][:2]), 1e-12) for n in trees[1]["nodes"]),
            "P1: a node's value is not f at its position")
    verts = {(round(a, 9), round(b, 9)) for a, b, _ in npz["x"]}
    r.check(all((round(n["position"][0], 9), round(n["position"][1], 9)) in verts
                for n in trees[1]["nodes"]), "P1: a node that is not a vertex")

    # XDMF, P1 at t = 0 (f) and t = 1 (2 f).
    info = run("info", p("p1.xdmf")).stdout
    r.check("2 time steps (times 0, 1)" in info, f"p1.xdmf: info does not list 2 steps:\n"
            f"{info[:600]}")
    last, res = tree_json(p("p1.xdmf"))
    r.check("step 1 of 2" in res.stdout, f"p1.xdmf: default step not stated: {res.stdout[:300]}")
    first, _ = tree_json(p("p1.xdmf"), "--step", "0")
    by_time, _ = tree_json(p("p1.xdmf"), "--time", "1")
    same_tree("XDMF P1 step 0 vs VTKFile P1", first, trees[1])
    same_tree("XDMF --time 1 vs default (last) step", by_time, last)
    r.check(len(last["nodes"]) == len(first["nodes"]) and all(
        close(a["value"], 2 * b["value"], 1e-12) for a, b in zip(
            sorted(last["nodes"], key=lambda n: n["position"]),
            sorted(first["nodes"], key=lambda n: n["position"]))),
        "XDMF step 1 is not twice step 0")
    res = run("tree", p("p1.xdmf"), "--time", "0.5", check=False)
    r.check(res.returncode == 1 and "no step at that time" in res.stderr and
            "0, 1" in res.stderr, f"XDMF --time 0.5: {res.returncode} {res.stderr.strip()[:300]}")

    # P2 on a curved mesh: XDMF (Triangle_6) and VTKFile agree; the saddle is the analytic one.
    curved_x, _ = tree_json(p("p2curved.xdmf"))
    curved_v, _ = tree_json(p("p2curved.pvd"))
    same_tree("curved P2: XDMF vs VTKFile", curved_x, curved_v, tol=1e-9)
    saddles = [n for n in curved_v["nodes"] if n["type"] == "saddle"]
    r.check(len(saddles) == 1 and abs(saddles[0]["value"]) < 1e-9 and
            abs(saddles[0]["position"][0] - A) < 1e-9 and abs(saddles[0]["position"][1] - B) < 1e-9,
            f"curved P2: saddles {saddles}")
    r.check(len(curved_v["nodes"]) == 5, f"curved P2: {len(curved_v['nodes'])} nodes, expected 5")

    # Partitioned over MPI ranks: the serial tree; one piece alone: a warning.
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               HOCT_MPI="1")
    for n in ranks:
        for deg, name in ((2, f"part{n}"), (3, f"part{n}p3")):
            label = f"P{deg} written on {n} ranks"
            j, res = tree_json(p(f"{name}.pvd"))
            same_tree(f"{label} vs serial", j, trees[deg], tol=1e-12)
            # ... and read by hoct under mpirun on 1, 2, 3, 4 and 7 ranks (rank 0 reads the whole,
            # the cells are shared out; P3: each rank resamples its GLL cells): the JSON of the
            # plain run, byte for byte.
            want = p(f"{name}.plain.json")
            run("tree", p(f"{name}.pvd"), "--json", want, "--no-timings", "-q")
            for m in (1, 2, 3, 4, 7):
                got = p(f"{name}.mpi{m}.json")
                w = subprocess.run([shutil.which("mpirun"), "--oversubscribe", "-np", str(m),
                                    HOCT, "tree", p(f"{name}.pvd"), "--json", got,
                                    "--no-timings", "-q"],
                                   capture_output=True, text=True, env=env)
                same = w.returncode == 0 and open(got, "rb").read() == open(want, "rb").read()
                r.check(same, f"{label}, hoct on {m} ranks: {w.stderr[-800:]}")
            # The step's .pvtu itself: each hoct rank reads only its pieces (no note that rank 0
            # reads the whole), the same JSON as one process.
            pvtu = p(f"{name}000000.pvtu")
            want = p(f"{name}.pvtu.plain.json")
            run("tree", pvtu, "--json", want, "--no-timings", "-q")
            for m in (1, 2, 3, 4, 7):
                got = p(f"{name}.pvtu.mpi{m}.json")
                w = subprocess.run([shutil.which("mpirun"), "--oversubscribe", "-np", str(m),
                                    HOCT, "tree", pvtu, "--json", got, "--no-timings"],
                                   capture_output=True, text=True, env=env)
                same = w.returncode == 0 and open(got, "rb").read() == open(want, "rb").read()
                r.check(same and "reads the whole" not in w.stderr
                        and "checks: by the pieces together" in w.stdout
                        and (deg < 3 or "Gauss-Lobatto-Legendre" in w.stderr),
                        f"{pvtu}, hoct on {m} ranks, each its pieces: {w.stderr[-800:]}")
        res = run("tree", p(f"part{n}_p0_000000.vtu"), check=False)
        r.check(res.returncode == 0 and f"part{n}000000.pvtu" in res.stderr,
                f"one piece of {n}: {res.returncode} {res.stderr.strip()[:400]}")
    r.check(len(ranks) == 2, "mpirun not found: the partitioned files were not written")

r.finish()
