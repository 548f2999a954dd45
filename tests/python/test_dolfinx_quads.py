"""DOLFINx 0.5 on quadrilateral meshes (VTKFile, VTK_LAGRANGE_QUADRILATERAL): Q1-Q3 functions of
f = (x - 0.4)^2 (y + 0.1) - 0.6 (y - 0.55)^2 (x + 0.2), which lies in Q2 and Q3 and has one
interior critical point, a saddle at (0.4, 0.55) of value 0. Q3's nodes are at Gauss-Lobatto-
Legendre points though VTK labels them equispaced (read as equispaced, the same function gave 59
tree nodes instead of 5): hoct notes it and reads the polynomial through them, so Q2 and Q3 give
the same tree, with the analytic saddle; every tree passes `hoct check`. Q3 written by DOLFINx
on 2 ranks, read by `mpirun -np 1-3 hoct tree` piece by piece: one process's JSON. Each tree is also within
the stability bound of the PL tree of f on 400 x 400 squares (bottleneck distance <= sup |f - f_h|
+ M h^2 / 4; f_h = f for Q2 and Q3, Q1's bilinear interpolant sampled here in numpy)."""
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np  # noqa: E402
from hoct_testing import (HOCT, Results, bottleneck, compare_trees, run, tempdir,  # noqa: E402
                          tree_json, write_pl_reference)

WRITER = """
import sys
from mpi4py import MPI
import dolfinx, dolfinx.fem, dolfinx.io, dolfinx.mesh
out = sys.argv[1]
for deg in (1, 2, 3):
    mesh = dolfinx.mesh.create_unit_square(MPI.COMM_WORLD, 4, 4,
                                           dolfinx.mesh.CellType.quadrilateral)
    V = dolfinx.fem.FunctionSpace(mesh, ("Lagrange", deg))
    u = dolfinx.fem.Function(V)
    u.name = "temperature"
    u.interpolate(lambda x: (x[0] - 0.4) ** 2 * (x[1] + 0.1) - 0.6 * (x[1] - 0.55) ** 2 * (x[0] + 0.2))
    with dolfinx.io.VTKFile(MPI.COMM_WORLD, f"{out}/q{deg}.pvd", "w") as f:
        f.write_function(u)
"""

try:
    import dolfinx  # noqa: F401
except ImportError as e:
    print(f"skipped: DOLFINx is missing ({e})")
    sys.exit(77)



def f(x, y):
    return (x - 0.4) ** 2 * (y + 0.1) - 0.6 * (y - 0.55) ** 2 * (x + 0.2)


def q1_error():
    """sup |f - its bilinear interpolant on the 4 x 4 squares|, sampled at 401 x 401 points."""
    s = np.linspace(0, 1, 401)
    X, Y = np.meshgrid(s, s)
    i = np.minimum((X * 4).astype(int), 3)
    j = np.minimum((Y * 4).astype(int), 3)
    a, b = X * 4 - i, Y * 4 - j
    x0, x1, y0, y1 = i / 4, (i + 1) / 4, j / 4, (j + 1) / 4
    fh = ((1 - a) * (1 - b) * f(x0, y0) + a * (1 - b) * f(x1, y0) + (1 - a) * b * f(x0, y1) +
          a * b * f(x1, y1))
    return float(np.abs(fh - f(X, Y)).max())


r = Results()
with tempdir() as d:
    w = subprocess.run([sys.executable, "-c", WRITER, d], capture_output=True, text=True,
                       env=dict(os.environ, OMP_NUM_THREADS="1"))
    if w.returncode != 0:
        print(w.stderr[-3000:])
        sys.exit(1)
    trees = {}
    for deg in (1, 2, 3):
        path = os.path.join(d, f"q{deg}.pvd")
        j, res = tree_json(path)
        trees[deg] = j
        r.check(j["input"]["cells"] == 16, f"Q{deg}: {j['input']['cells']} cells")
        note = "quadrilateral(s)" in res.stderr and "Gauss-Lobatto-Legendre" in res.stderr
        r.check(note == (deg == 3), f"Q{deg}: GLL note {'missing' if deg == 3 else 'given'}: "
                f"{res.stderr.strip()[:300]}")
        chk = run("check", f"{path}.{abs(hash(()))}.json", path, check=False)
        r.check(chk.returncode == 0, f"Q{deg}: hoct check: {chk.stdout[-500:]}{chk.stderr[-500:]}")
    reference = os.path.join(d, "reference.vtu")
    write_pl_reference(reference, f, 0.0, 1.0, 400)
    run("tree", reference, "-q", "--json", reference + ".json")
    # |Hessian f| <= sqrt(2.2^2 + 1.44^2 + 2 x 1.86^2) < 4 on the unit square.
    reference_bound = 4.0 * (1.0 / 400) ** 2 / 4
    for deg in (1, 2, 3):
        err = q1_error() if deg == 1 else 0.0
        bound = 1.05 * err + reference_bound + 1e-12
        bn = bottleneck(f"{os.path.join(d, f'q{deg}.pvd')}.{abs(hash(()))}.json",
                        reference + ".json")
        print(f"DOLFINx Q{deg}: sup |f - f_h| ~ {err:.3g}; bottleneck to the PL reference "
              f"{bn['max']:.3g}, global {bn['global']:.3g} (bound {bound:.3g})", flush=True)
        r.check(max(bn["max"], bn["global"]) <= bound,
                f"DOLFINx Q{deg}: bottleneck {bn} to the PL reference exceeds {bound:.3g}")
    compare_trees(r, "DOLFINx Q3 (GLL nodes) vs Q2", trees[3], trees[2], tol=1e-9,
                  position_tol=1e-7)
    for deg in (2, 3):
        inside = [n for n in trees[deg]["nodes"]
                  if all(1e-6 < c < 1 - 1e-6 for c in n["position"][:2])]
        ok = len(inside) == 1 and inside[0]["type"] == "saddle" and \
            abs(inside[0]["position"][0] - 0.4) < 1e-7 and \
            abs(inside[0]["position"][1] - 0.55) < 1e-7 and abs(inside[0]["value"]) < 1e-9
        r.check(ok, f"Q{deg}: interior nodes {inside}, expected the saddle at (0.4, 0.55)")

    # Q3 written by DOLFINx on 2 ranks (a .pvtu of 2 pieces with ghosts), read by
    # `mpirun -np N hoct tree` (N = 1, 2, 3): each rank resamples its pieces' GLL cells, the JSON
    # is one process's byte for byte, and the tree is the serial file's.
    mpirun = shutil.which("mpirun")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMP_NUM_THREADS="1")
    part = os.path.join(d, "part")
    os.makedirs(part)
    w = subprocess.run([mpirun, "--oversubscribe", "-np", "2", sys.executable, "-c", WRITER,
                        part], capture_output=True, text=True, env=env) if mpirun else None
    if w is not None and w.returncode == 0:
        pvtu = os.path.join(part, "q3000000.pvtu")
        j, _ = tree_json(pvtu)
        compare_trees(r, "Q3 written on 2 ranks vs serial", j, trees[3], tol=1e-12)
        want = os.path.join(part, "plain.json")
        run("tree", pvtu, "--json", want, "--no-timings", "-q")
        for m in (1, 2, 3):
            got = os.path.join(part, f"mpi{m}.json")
            p = subprocess.run([mpirun, "--oversubscribe", "-np", str(m), HOCT, "tree", pvtu,
                                "--json", got, "--no-timings"], capture_output=True, text=True,
                               env=dict(env, HOCT_MPI="1"))
            same = p.returncode == 0 and open(got, "rb").read() == open(want, "rb").read()
            r.check(same and "reads the whole" not in p.stderr
                    and "quadrilateral(s)" in p.stderr,
                    f"Q3 on 2 pieces, hoct on {m} ranks: the plain JSON, each rank its pieces: "
                    f"{p.stdout[-400:]}{p.stderr[-800:]}")
        print("DOLFINx Q3 in 2 pieces: 1-3 ranks checked", flush=True)
    else:
        r.check(w is None or w.returncode == 0,
                f"DOLFINx on 2 ranks failed:\n{w.stderr[-2000:] if w else ''}")
r.finish()
