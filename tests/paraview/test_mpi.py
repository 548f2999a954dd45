"""The ParaView plugin under MPI: `mpirun -np 2 pvbatch tests/paraview/test_mpi.py`.

pvbatch runs this script on rank 0; every rank executes the pipeline. A single-piece .vtu read on
two processes puts the whole mesh on rank 0 and nothing on rank 1: rank 1's filter must produce
empty outputs without an error (ctest fails on an "ERR|" line, see tests/CMakeLists.txt), and
rank 0's output must equal `hoct tree --json`. The filter names no scalar (the default). Then the
mesh redistributed over both ranks: the filter warns, once, that the tree is computed per piece.
"""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import test_plugin as tp  # noqa: E402  (its helpers: hoct, cli_tree, compare_nodes, ...)
from paraview import servermanager as sm  # noqa: E402
from paraview import simple as pv  # noqa: E402
from vtkmodules.numpy_interface import dataset_adapter as dsa  # noqa: E402
from vtkmodules.util.misc import calldata_type  # noqa: E402
from vtkmodules.util.vtkConstants import VTK_STRING  # noqa: E402
from vtkmodules.vtkCommonCore import vtkCommand  # noqa: E402


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

    # The mesh over both ranks: one warning that the tree is per piece (Force: a piece need not
    # be a disk).
    spread = pv.RedistributeDataSet(Input=reader)
    f = pv.HigherOrderContourTree(Input=spread, Force=1)
    warnings = catch(f, vtkCommand.WarningEvent)
    f.UpdatePipeline()
    per_piece = [w for w in warnings if "computes the tree of its own piece" in w]
    tp.check(len(per_piece) == 1, f"two pieces: one per-piece warning, got {warnings}")
    f.Threads = 1
    f.UpdatePipeline()
    per_piece = [w for w in warnings if "computes the tree of its own piece" in w]
    tp.check(len(per_piece) == 1, f"two pieces: the warning is given once, got {warnings}")

    print(f"{tp.passed} passed, {tp.failed} failed", flush=True)
    # Success: the script ends normally (no sys.exit, no os._exit as in test_plugin.py), so
    # that pvbatch's rank 0 releases the other ranks and all exit 0. Failure: exit 1 at once.
    if tp.failed or not tp.passed:
        sys.stdout.flush()
        os._exit(1)


if __name__ == "__main__":
    main()
