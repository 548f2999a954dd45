"""The ParaView plugin under MPI: `mpirun -np 2 pvbatch tests/paraview/test_mpi.py`.

pvbatch runs this script on rank 0; every rank executes the pipeline. A single-piece .vtu read on
two processes puts the whole mesh on rank 0 and nothing on rank 1: rank 1's filter must produce
empty outputs without an error (ctest fails on an "ERR|" line, see tests/CMakeLists.txt), and
rank 0's output must equal `hoct tree --json`. The filter names no scalar (the default). Then the
mesh redistributed over both ranks: the pieces are gathered and the tree is computed over both
processes; rank 0's output must be the CLI's tree (nodes as a set: the gathered pieces number
the cells their own way), with and without simplification.
"""

import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

sys.path.insert(0, os.path.join(os.path.dirname(HERE), "python"))

import test_plugin as tp  # noqa: E402  (its helpers: hoct, cli_tree, compare_nodes, ...)
import vtk_pieces  # noqa: E402  (tests/python: .pvtu pieces written by VTK)
from paraview import servermanager as sm  # noqa: E402
from paraview import simple as pv  # noqa: E402
from vtkmodules.numpy_interface import dataset_adapter as dsa  # noqa: E402
from vtkmodules.util.misc import calldata_type  # noqa: E402
from vtkmodules.util.vtkConstants import VTK_STRING  # noqa: E402
from vtkmodules.vtkCommonCore import vtkCommand  # noqa: E402


# The field data Distribution of a run where each process keeps its piece and the pieces draw
# the arcs (Arc Paths Over Processes, the default).
OWN_PIECE = "each process its own piece; arcs: drawn by the processes' pieces (0 straight)"

def local_output(proxy, port):
    """Rank 0's own output (not gathered from the other ranks)."""
    return dsa.WrapDataObject(proxy.GetClientSideObject().GetOutputDataObject(port))


def catch(proxy, event):
    messages = []

    @calldata_type(VTK_STRING)
    def on_message(obj, ev, message):
        messages.append(message)

    proxy.GetClientSideObject().AddObserver(event, on_message)
    return messages


def compare_whole(name, nodes, arcs, tree):
    """Output 0 and 1 against the CLI's tree, as sets: the nodes' values, types and positions
    (to 1e-9), and the number of arcs."""
    n = len(tree["nodes"])
    tp.check(nodes.GetNumberOfVerts() == n,
             f"{name}: {nodes.GetNumberOfVerts()} critical points, the CLI has {n}")
    if nodes.GetNumberOfVerts() != n or nodes.GetNumberOfPoints() < n:
        return
    pd = nodes.PointData

    def key(value, code, position):
        return (round(value, 9), int(code), tuple(round(x, 9) for x in position))

    got = sorted(key(pd["Value"][i], pd["CriticalType"][i], nodes.Points[i]) for i in range(n))
    want = sorted(key(x["value"], tp.CODES[x["type"]], x["position"]) for x in tree["nodes"])
    bad = [(g, w) for g, w in zip(got, want) if g != w]
    tp.check(not bad, f"{name}: {len(bad)} nodes differ from the CLI's, first: {bad[:1]}")
    tp.check(arcs.GetNumberOfLines() == len(tree["arcs"]),
             f"{name}: {arcs.GetNumberOfLines()} arcs, the CLI has {len(tree['arcs'])}")


def distribution(proxy):
    """Rank 0's field data "Distribution": how the filter spread the mesh over the processes."""
    a = local_output(proxy, 0).GetFieldData().GetAbstractArray("Distribution")
    return a.GetValue(0) if a is not None else None


def write_pieces(path, pvtu, pieces, ghost_level):
    """vtk_pieces.write_pieces with global ids (a process's pieces are appended into one: only
    ids join their copies of a point) in a process of its own: VTK's parallel writer here would use
    pvbatch's MPI controller, whose other process does not run this script."""
    env = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_"))}
    code = ("import sys; sys.path.insert(0, sys.argv[1]); import vtk_pieces as v; "
            "v.write_pieces(v.with_ids(v.read_grid(sys.argv[2]), 'gid'), sys.argv[3], "
            "int(sys.argv[4]), int(sys.argv[5]), 'gid')")
    subprocess.run(["/usr/bin/python3", "-c", code, os.path.join(os.path.dirname(HERE), "python"),
                    path, pvtu, str(pieces), str(ghost_level)], env=env, check=True)


def slit_grid(path):
    """A square of 12 x 12 x 2 triangles whose upper half has its own copies of the left half of
    the middle row's points: a slit from the border (duplicate vertices across the halves; the
    surface stays a disk), written by VTK with a smooth field f."""
    import math

    n, mid = 12, 6
    pts = [(i / n, j / n, 0.0) for j in range(n + 1) for i in range(n + 1)]
    tri = []
    for j in range(n):
        for i in range(n):
            a, b = j * (n + 1) + i, j * (n + 1) + i + 1
            c, e = (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i
            tri += [[a, b, c], [a, c, e]]
    copy = {}
    for t in tri[len(tri) // 2:]:
        for m, v in enumerate(t):
            if v // (n + 1) == mid and v % (n + 1) < n // 2:
                if v not in copy:
                    copy[v] = len(pts)
                    pts.append(pts[v])
                t[m] = copy[v]
    grid = vtk_pieces.vtk.vtkUnstructuredGrid()
    points = vtk_pieces.vtk.vtkPoints()
    f = vtk_pieces.vtk.vtkDoubleArray()
    f.SetName("f")
    for x, y, z in pts:
        points.InsertNextPoint(x, y, z)
        f.InsertNextValue(math.sin(3 * x) * math.cos(2 * y) + 0.1 * x)
    grid.SetPoints(points)
    for t in tri:
        grid.InsertNextCell(vtk_pieces.vtk.VTK_TRIANGLE, 3, t)
    grid.GetPointData().SetScalars(f)
    w = vtk_pieces.vtk.vtkXMLUnstructuredGridWriter()
    w.SetInputData(grid)
    w.SetFileName(path)
    w.Write()


def main():
    os.makedirs(tp.OUT, exist_ok=True)
    tp.render_tree.load_plugin()
    ranks = sm.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
    tp.check(ranks == 2, f"runs on 2 processes (got {ranks})")
    path = os.path.join(tp.OUT, "mpi_gauss.vtu")
    tp.hoct("generate", "gauss", "-o", path)
    tree = tp.cli_tree(path)

    # The whole mesh on rank 0, nothing on rank 1; no scalar named, no active source.
    reader = pv.XMLUnstructuredGridReader(FileName=[path])
    pv.SetActiveSource(None)
    f = pv.HigherOrderContourTree(Input=reader)
    errors = catch(f, vtkCommand.ErrorEvent)
    warnings = catch(f, vtkCommand.WarningEvent)
    f.UpdatePipeline()
    tp.check(not errors, f"one piece: errors {errors}")
    tp.check(not warnings, f"one piece: warnings {warnings}")
    tp.compare_nodes("rank 0", local_output(f, 0), tree)
    tp.compare_arcs("rank 0", local_output(f, 1), tree)
    scalar = local_output(f, 0).GetFieldData().GetAbstractArray("Scalar")
    tp.check(scalar is not None and scalar.GetValue(0) == "f",
             "rank 0: the field data Scalar names the default array 'f'")
    # Gathered from both ranks (rank 1's part is empty): still the CLI's tree.
    tp.compare_nodes("gathered", tp.fetch(f, 0), tree)
    pv.Delete(f)

    # The mesh over both ranks: the pieces are gathered and the tree computed over both
    # processes (distributed/distributed_tree); rank 0's output is the whole mesh's tree, the
    # CLI's up to the numbering of cells (the gathered pieces number them their own way).
    spread = pv.RedistributeDataSet(Input=reader)
    for threshold in (0.0, 1.0):
        f = pv.HigherOrderContourTree(Input=spread, PersistenceThreshold=threshold,
                                      ArcPathsOverProcesses=0)
        errors = catch(f, vtkCommand.ErrorEvent)
        warnings = catch(f, vtkCommand.WarningEvent)
        f.UpdatePipeline()
        label = f"two pieces, threshold {threshold}%"
        tp.check(not errors and not warnings, f"{label}: errors {errors}, warnings {warnings}")
        compare_whole(label, local_output(f, 0), local_output(f, 1), tree)
        tp.check(distribution(f) == "each process its own piece",
                 f"{label}: each process keeps its piece, not {distribution(f)!r}")
        if threshold > 0:
            want = tp.cli_tree(path, "--simplify", "1%")
            simple = local_output(f, 2)
            tp.check(0 < simple.GetNumberOfVerts() == len(want["nodes"]) < len(tree["nodes"]),
                     f"{label}: output 2 has {simple.GetNumberOfVerts()} nodes, the CLI's "
                     f"simplified tree {len(want['nodes'])}")
        # Gathered from both ranks (rank 1's part is empty): the same tree.
        compare_whole(label + ", gathered", tp.fetch(f, 0), tp.fetch(f, 1), tree)
        straight = local_output(f, 1).GetNumberOfPoints()
        pv.Delete(f)
    # Arc Paths Over Processes (the default): the pieces draw the arcs on the surface together,
    # no process holding the whole mesh (the Distribution says so): the same tree, with curved
    # arcs (more points than straight).
    f = pv.HigherOrderContourTree(Input=spread)
    errors = catch(f, vtkCommand.ErrorEvent)
    f.UpdatePipeline()
    label = "two pieces, arc paths"
    tp.check(not errors, f"{label}: errors {errors}")
    compare_whole(label, local_output(f, 0), local_output(f, 1), tree)
    tp.check(distribution(f) == OWN_PIECE,
             f"{label}: the Distribution says {distribution(f)!r}")
    curved = local_output(f, 1).GetNumberOfPoints()
    tp.check(curved > straight, f"{label}: {curved} points on the arcs, straight ones have {straight}")
    pv.Delete(f)

    # A .pvtu of 4 pieces with a ghost level and global ids, each process reading two: the ghost
    # cells are dropped and the copies joined as `hoct tree FILE.pvtu` does; the CLI's tree.
    pvtu = os.path.join(tp.OUT, "mpi_gauss_ghosts.pvtu")
    write_pieces(path, pvtu, 4, 1)
    want = tp.cli_tree(pvtu)
    f = pv.HigherOrderContourTree(Input=pv.XMLPartitionedUnstructuredGridReader(FileName=[pvtu]))
    errors = catch(f, vtkCommand.ErrorEvent)
    warnings = catch(f, vtkCommand.WarningEvent)
    f.UpdatePipeline()
    label = "4 pieces with ghosts"
    tp.check(not errors and not warnings, f"{label}: errors {errors}, warnings {warnings}")
    compare_whole(label, local_output(f, 0), local_output(f, 1), want)
    tp.check(distribution(f) == OWN_PIECE,
             f"{label}: each process keeps its pieces, not {distribution(f)!r}")
    pv.Delete(f)
    # The linear method by the same pieces: the CLI's --linear tree.
    want = tp.cli_tree(pvtu, "--linear")
    f = pv.HigherOrderContourTree(Input=pv.XMLPartitionedUnstructuredGridReader(FileName=[pvtu]),
                                  Method="Linear (input nodes)")
    errors = catch(f, vtkCommand.ErrorEvent)
    f.UpdatePipeline()
    label = "4 pieces with ghosts, linear"
    tp.check(not errors, f"{label}: errors {errors}")
    compare_whole(label, local_output(f, 0), local_output(f, 1), want)
    places = [sorted(tuple(round(x, 9) for x in n["position"]) for n in t["nodes"])
              for t in (want, tp.cli_tree(pvtu))]
    tp.check(places[0] != places[1], f"{label}: the linear tree differs from the exact one here")
    tp.check(distribution(f) == OWN_PIECE,
             f"{label}: each process keeps its pieces, not {distribution(f)!r}")
    pv.Delete(f)
    # And the refine method, K = 2.
    want = tp.cli_tree(pvtu, "--refine", "2")
    f = pv.HigherOrderContourTree(Input=pv.XMLPartitionedUnstructuredGridReader(FileName=[pvtu]),
                                  Method="Refine (K x K per cell)", RefineLevel=2)
    errors = catch(f, vtkCommand.ErrorEvent)
    f.UpdatePipeline()
    label = "4 pieces with ghosts, refine 2"
    tp.check(not errors, f"{label}: errors {errors}")
    compare_whole(label, local_output(f, 0), local_output(f, 1), want)
    tp.check(distribution(f) == OWN_PIECE,
             f"{label}: each process keeps its pieces, not {distribution(f)!r}")
    pv.Delete(f)

    # Duplicate vertices across the pieces (a slit): process 0 checks the whole mesh, which the
    # processes join there from their pieces; forced past them, the CLI's --force tree.
    slit = os.path.join(tp.OUT, "mpi_slit.vtu")
    slit_grid(slit)
    want = tp.cli_tree(slit, "--force")
    f = pv.HigherOrderContourTree(Input=pv.RedistributeDataSet(
        Input=pv.XMLUnstructuredGridReader(FileName=[slit])), Force=1)
    errors = catch(f, vtkCommand.ErrorEvent)
    f.UpdatePipeline()
    label = "a slit over two processes, Force"
    tp.check(not errors, f"{label}: errors {errors}")
    compare_whole(label, local_output(f, 0), local_output(f, 1), want)
    got = distribution(f) or ""
    tp.check(got.startswith("each process its own piece; checks: the whole mesh on process 0"),
             f"{label}: process 0 checks the joined whole, not {got!r}")
    pv.Delete(f)

    # DOLFINx's P3 (nodes at Gauss-Lobatto-Legendre points) in 2 pieces with ghosts, one per
    # process: each resamples its piece as `hoct tree` resamples the whole; the CLI's tree, with
    # the note. (Not RedistributeDataSet: on these cells ParaView 5.11's vtkExtractCells inside
    # it crashes now and then.)
    p3 = tp.dolfinx_p3()
    if p3:
        p3 = os.path.join(os.path.dirname(p3), "p3_p0_000000.vtu")
        pieces = os.path.join(tp.OUT, "dolfinx_p3_pieces.pvtu")
        write_pieces(p3, pieces, 2, 1)
        p3 = pieces
        f = pv.HigherOrderContourTree(
            Input=pv.XMLPartitionedUnstructuredGridReader(FileName=[p3]))
        errors = catch(f, vtkCommand.ErrorEvent)
        f.UpdatePipeline()
        label = "DOLFINx P3 over two processes"
        tp.check(not errors, f"{label}: errors {errors}")
        compare_whole(label, local_output(f, 0), local_output(f, 1), tp.cli_tree(p3))
        tp.check(distribution(f) == OWN_PIECE,
                 f"{label}: each process keeps its piece, not {distribution(f)!r}")
        notes = local_output(f, 0).GetFieldData().GetAbstractArray("Notes")
        tp.check(notes is not None and "Gauss-Lobatto-Legendre" in notes.GetValue(0),
                 f"{label}: the field data Notes say the nodes were resampled")
        pv.Delete(f)
    print(f"{tp.passed} passed, {tp.failed} failed", flush=True)
    # Success: the script ends normally (no sys.exit, no os._exit as in test_plugin.py), so
    # that pvbatch's rank 0 releases the other ranks and all exit 0. Failure: exit 1 at once.
    if tp.failed or not tp.passed:
        sys.stdout.flush()
        os._exit(1)


if __name__ == "__main__":
    main()
