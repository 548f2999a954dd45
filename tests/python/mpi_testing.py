"""What the tests of hoct under mpirun share: the launcher (skip, exit 77, without one), its
environment and `mpi(n, ...)`, which runs the hoct CLI on n ranks; the Python interpreter for
scripts under mpirun and `require_modules` (skip without its modules)."""
import json
import os
import re
import shutil
import subprocess
import sys

from hoct_testing import HOCT

MPIRUN = shutil.which("mpirun")
if not MPIRUN:
    print("SKIPPED: no mpirun (Debian: openmpi-bin)")
    sys.exit(77)
# Debian's interpreter, for scripts run under mpirun (its python3-mpi4py).
PYTHON = "/usr/bin/python3"


def require_modules(*modules):
    """Skip (exit 77) unless PYTHON imports each (module, Debian package) given."""
    for module, package in modules:
        if subprocess.run([PYTHON, "-c", f"import {module}"], capture_output=True).returncode:
            print(f"SKIPPED: no {module} (Debian: {package})")
            sys.exit(77)


# The plain runs (one process, the truth) must not take the distributed code from the caller's
# environment; under mpirun, HOCT_MPI=1: `mpirun -np 1` too runs it (one piece).
os.environ.pop("HOCT_MPI", None)
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1", HOCT_MPI="1")


def mpi(n, *args):
    return subprocess.run([MPIRUN, "--oversubscribe", "-np", str(n), HOCT, *map(str, args)],
                          capture_output=True, text=True, env=ENV, timeout=600)


def require_mpi_hoct():
    """Skip (exit 77) where mpirun cannot start this hoct."""
    probe = mpi(1, "tree", "--help")
    if probe.returncode != 0:
        print(f"SKIPPED: mpirun cannot start hoct here:\n{probe.stderr[-2000:]}")
        sys.exit(77)


def read(path):
    with open(path, "rb") as f:
        return f.read()


def polylines(path):
    """The lines of a VTP file (hoct tree --vtp: one per arc), each a list of points."""
    import vtk

    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    poly = reader.GetOutput()
    lines, ids, out = poly.GetLines(), vtk.vtkIdList(), []
    lines.InitTraversal()
    while lines.GetNextCell(ids):
        out.append([poly.GetPoint(ids.GetId(k)) for k in range(ids.GetNumberOfIds())])
    return out


def longest_step(lines):
    """The longest segment of any of the lines."""
    return max(sum((a - b) ** 2 for a, b in zip(p, q)) ** 0.5
               for line in lines for p, q in zip(line, line[1:]))


def arcs_drawn_by_pieces(r, label, p, got_vtp, plain_vtp):
    """A run with --vtp whose pieces drew the arcs: no whole mesh on rank 0, none straight, as
    many lines as one process's, most of them over the surface, and no step longer than one
    process's longest (a route joined wrongly across pieces would jump)."""
    lines = polylines(got_vtp) if os.path.exists(got_vtp) else []
    plain = polylines(plain_vtp)
    r.check(p.returncode == 0 and "tree: the whole mesh" not in p.stdout
            and "arcs' paths: by the ranks" in p.stdout and " 0 straight" in p.stdout
            and len(lines) == len(plain) and sum(len(l) > 2 for l in lines) > len(lines) // 2
            and longest_step(lines) <= 1.5 * longest_step(plain),
            f"{label}: the arcs drawn by the pieces ({p.returncode}):\n"
            f"{p.stdout[-800:]}{p.stderr[-800:]}")


def shape_counts(text):
    """(Euler characteristic, boundary loops, components) as hoct info states them."""
    return tuple(int(re.search(pattern, text).group(1)) for pattern in
                 (r"Euler characteristic (-?\d+)", r"(\d+) boundary loop", r"(\d+) component"))


def reeb_with_shape(r, label, path, ranks=(2, 3, 7), read_by_pieces=False):
    """`mpirun hoct tree path` (a planar surface with holes and a height-like field, such as hoct's
    plate) on every rank count: the shape the pieces find together (rank 0 does not check the
    whole again) is no disk, so the result is the Reeb graph of one process (byte-identical
    JSON), its loops the whole's first Betti number from `hoct info`'s counts (components -
    Euler characteristic: one loop per hole); read_by_pieces: each rank reads its own pieces."""
    from hoct_testing import run
    chi, _, components = shape_counts(run("info", path).stdout)
    want = f"{path}.shape.json"
    run("tree", path, "--json", want, "--no-timings", "-q")
    for n in ranks:
        got = f"{path}.shape{n}.json"
        p = mpi(n, "tree", path, "--json", got, "--no-timings")
        r.check(p.returncode == 0 and os.path.exists(got) and read(got) == read(want),
                f"{label}, {n} ranks: the JSON of one process ({p.returncode}):\n"
                f"{p.stderr[-1500:]}")
        if p.returncode != 0 or not os.path.exists(got):
            continue
        with open(got) as f:
            graph = json.load(f)
        r.check(graph.get("kind") == "Reeb graph" and graph.get("loops") == components - chi
                and "Reeb graph" in p.stdout and "checks: by the pieces together" in p.stdout
                and (not read_by_pieces or "reads the whole" not in p.stderr),
                f"{label}, {n} ranks: a Reeb graph with the whole's {components - chi} loops "
                f"({graph.get('kind')}, {graph.get('loops')} loops), found by the pieces:\n"
                f"{p.stdout[-1500:]}{p.stderr[-800:]}")
