"""What the tests of hoct under mpirun share: the launcher (skip, exit 77, without one), its
environment and `mpi(n, ...)`, which runs the hoct CLI on n ranks."""
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


def shape_counts(text):
    """(Euler characteristic, boundary loops, components) as hoct info or a refusal states them."""
    return tuple(int(re.search(pattern, text).group(1)) for pattern in
                 (r"Euler characteristic (-?\d+)", r"(\d+) boundary loop", r"(\d+) component"))


def refused_with_shape(r, label, path, ranks=(2, 3, 7), read_by_pieces=False):
    """`mpirun hoct tree path` (a surface with holes) refused on every rank count with the
    whole's counts, those of `hoct info` in one process."""
    from hoct_testing import run
    want = shape_counts(run("info", path).stdout)
    for n in ranks:
        p = mpi(n, "tree", path)
        r.check(p.returncode != 0 and "Reeb graph is not computed over MPI" in p.stderr
                and shape_counts(p.stderr) == want
                and (not read_by_pieces or "reads the whole" not in p.stderr),
                f"{label}, {n} ranks: the whole's shape {want}:\n{p.stderr[-1500:]}")
