"""Partitioned outputs (.pvtu) and time series (.pvd) written by VTK itself, read by hoct.

A cubic mesh of `hoct generate gauss` is split into pieces by VTK's streaming pipeline
(vtkExtractUnstructuredGridPiece) and written by vtkXMLPUnstructuredGridWriter: 3 and 4 pieces,
with ghost levels 0 (the shared points duplicated) and 1 (ghost cells and points, vtkGhostType),
with global ids (the GlobalIds attribute of the point data) and without (joined by position);
also pieces cut by hand with a plain GlobalIds array and an idle rank's empty piece. Each .pvtu
gives the contour tree of the whole mesh (the same nodes, values and arcs as the .vtu VTK
writes of it unsplit, with the same float32 points) and `hoct info` its counts. One piece read
alone warns that its tree is not the whole domain's, naming the .pvtu. A .pvd of 3 steps (a
.vtu, a .pvtu, a .vtu; a different field each; listed out of time order) reads the step --step
or --time chooses (the last by default), says which in the summary and in `hoct info`, which
lists the steps; a step or time that is not there is refused, listing what there is.

Run by ctest with /usr/bin/python3 and HOCT_BIN set to the hoct executable."""
import json
import os
import sys

import vtk

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hoct_testing import Results, run, tempdir  # noqa: E402
from vtk_pieces import read_grid, write_hand_cut, write_pieces  # noqa: E402

r = Results()


def write_whole(grid, path):
    """The grid as the pieces' writer would write it in one piece (its points as float32)."""
    extract = vtk.vtkExtractUnstructuredGridPiece()
    extract.SetInputData(grid)
    w = vtk.vtkXMLUnstructuredGridWriter()
    w.SetInputConnection(extract.GetOutputPort())
    w.SetFileName(path)
    w.Write()


def tree(path, *args):
    out = path + ".json"
    res = run("tree", path, "--json", out, "--no-timings", *args)
    with open(out) as f:
        return json.load(f), res


def signature(t):
    """The tree independent of cell and point order: its nodes (type, value, position) and its
    arcs between them, rounded well above the solver's rounding."""
    def key(n):
        return (n["type"], round(n["value"], 9), *(round(x, 6) for x in n["position"]))
    nodes = [key(n) for n in t["nodes"]]
    arcs = sorted(tuple(sorted((nodes[a], nodes[b]))) for a, b in t["arcs"])
    return sorted(nodes), arcs


def info(path, *args):
    return json.loads(run("info", path, "--json", *args).stdout)


with tempdir() as d:
    src = os.path.join(d, "g.vtu")
    run("generate", "gauss", "--cells", "2000", "--degree", "3", "-o", src)
    grid = read_grid(src)
    gid = vtk.vtkIdTypeArray()
    gid.SetName("gid")
    for i in range(grid.GetNumberOfPoints()):
        gid.InsertNextValue(1000 + 7 * i)  # ids that are no point indices
    grid.GetPointData().AddArray(gid)
    whole = os.path.join(d, "whole.vtu")
    write_whole(grid, whole)
    expected, _ = tree(whole)
    expected_sig = signature(expected)
    expected_info = info(whole)
    r.check(len(expected["nodes"]) > 4, f"the whole mesh's tree has nodes: {len(expected['nodes'])}")

    cases = [("ghosts_ids", 3, 1, "gid"), ("ghosts", 3, 1, None), ("no_ghosts", 4, 0, None),
             ("no_ghosts_ids", 3, 0, "gid"), ("ghosts2", 4, 2, None)]
    for name, pieces, level, ids in cases:
        pvtu = os.path.join(d, name + ".pvtu")
        write_pieces(grid, pvtu, pieces, level, ids)
        got, res = tree(pvtu)
        r.check(signature(got) == expected_sig,
                f"{name}: the .pvtu's tree is the whole mesh's ({len(got['nodes'])} nodes, "
                f"{len(expected['nodes'])} expected)")
        r.check("warning" not in res.stderr, f"{name}: no warning: {res.stderr}")
        i = info(pvtu)
        for k in ("cells", "points", "vertices", "edges", "euler_characteristic",
                  "boundary_loops", "components"):
            r.check(i[k] == expected_info[k], f"{name}: info {k} {i[k]} != {expected_info[k]}")
        r.check(i["valid"], f"{name}: valid: {i['problems']}")

    # One piece alone, with its ghost cells: read, but a warning names the whole.
    piece = os.path.join(d, "ghosts_1.vtu")
    alone, res = tree(piece, "--force")  # a piece may have holes
    warning = [line for line in res.stderr.splitlines() if "holds one piece" in line]
    r.check(len(warning) == 1, f"one warning for a piece read alone: {res.stderr!r}")
    r.check(warning and warning[0].startswith("hoct: warning: " + piece + " holds one piece of a "
                                              "partitioned output (it has ghost cells: ")
            and warning[0].endswith("read " + os.path.join(d, "ghosts.pvtu") + " for the whole"),
            f"the warning names the piece and the .pvtu: {warning}")
    r.check(signature(alone) != expected_sig, "a piece's tree is not the whole's")
    # Without ghost arrays a piece cannot tell: no warning (and none for the whole file).
    res = run("info", os.path.join(d, "no_ghosts_1.vtu"), check=False)
    r.check("holds one piece" not in res.stderr, f"no ghost arrays, no warning: {res.stderr!r}")
    _, res = tree(whole)
    r.check("warning" not in res.stderr, f"the whole file: no warning: {res.stderr!r}")

    # Pieces cut by hand: a plain GlobalIds array (no attribute), and an empty piece.
    write_hand_cut(grid, d)
    got, _ = tree(os.path.join(d, "hand.pvtu"))
    original, _ = tree(src)
    r.check(signature(got) == signature(original),
            "pieces cut by hand (an empty one, plain GlobalIds) join to the whole")

    # A time series: 3 steps, listed out of order, a different field each.
    steps = []
    for k, (t, scale) in enumerate([(0.0, 1.0), (0.5, -1.0), (1.0, 2.0)]):
        g = read_grid(src)
        f = g.GetPointData().GetArray("f")
        v = vtk.vtkDoubleArray()
        v.SetName("T")
        for i in range(f.GetNumberOfTuples()):
            x = g.GetPoint(i)
            v.InsertNextValue(scale * f.GetValue(i) + k * x[0] * x[1])
        g.GetPointData().RemoveArray("f")
        g.GetPointData().AddArray(v)
        g.GetPointData().SetActiveScalars("T")
        if k == 1:
            file = "series_1.pvtu"
            write_pieces(g, os.path.join(d, file), 3, 1)
            reference = os.path.join(d, "series_1_whole.vtu")
            write_whole(g, reference)
        else:
            file = f"series_{k}.vtu"
            w = vtk.vtkXMLUnstructuredGridWriter()
            w.SetInputData(g)
            w.SetFileName(os.path.join(d, file))
            w.Write()
            reference = os.path.join(d, file)
        steps.append((t, file, reference))
    pvd = os.path.join(d, "series.pvd")
    with open(pvd, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n <Collection>\n'
                + "".join(f'  <DataSet timestep="{t}" part="0" file="{file}"/>\n'
                          for t, file, _ in [steps[2], steps[0], steps[1]])
                + " </Collection>\n</VTKFile>\n")
    sigs = [signature(tree(ref)[0]) for _, _, ref in steps]
    r.check(len(set(map(str, sigs))) == 3, "the steps' fields differ")
    for args, k in [(["--step", "0"], 0), (["--step", "1"], 1), (["--step", "-1"], 2), ([], 2),
                    (["--step", "-3"], 0), (["--time", "0.5"], 1), (["--time", "1"], 2),
                    (["--time", "0.5000000000001"], 1)]:
        got, res = tree(pvd, *args)
        r.check(signature(got) == sigs[k], f"pvd {args}: step {k}'s tree")
        t, file, _ = steps[k]
        want = f"(step {k} of 3, time {t:g}: {file})"
        r.check(want in res.stdout.splitlines()[0], f"pvd {args}: summary says {want}: "
                f"{res.stdout.splitlines()[0]}")
    for args, words in [(["--step", "3"], ["--step 3", "3 steps", "0 to 2"]),
                        (["--step", "-4"], ["--step -4", "3 steps"]),
                        (["--time", "0.25"], ["--time 0.25", "no step at that time", "0, 0.5, 1"])]:
        res = run("tree", pvd, *args, check=False)
        r.check(res.returncode != 0 and all(w in res.stderr for w in words) and pvd in res.stderr,
                f"pvd {args} refused with {words}: {res.stderr!r}")
    res = run("tree", os.path.join(d, "ghosts.pvtu"), "--step", "1", check=False)
    r.check(res.returncode != 0 and "one time step" in res.stderr,
            f".pvtu --step refused: {res.stderr!r}")
    i = info(pvd)
    r.check([s["time"] for s in i.get("steps", [])] == [0, 0.5, 1]
            and [s["files"] for s in i["steps"]] == [[f] for _, f, _ in steps],
            f"info --json lists the steps: {i.get('steps')}")
    r.check(i.get("field_detail") == "(step 2 of 3, time 1: series_2.vtu)",
            f"info --json: the step read: {i.get('field_detail')}")
    text = run("info", pvd, "--step", "1").stdout
    r.check("steps:       3" in text and "step 1: time 0.5, series_1.pvtu" in text
            and "(step 1 of 3, time 0.5: series_1.pvtu)" in text,
            f"info lists the steps and the one read:\n{text}")
    res = run("convert", pvd, "--time", "0.5", "-o", os.path.join(d, "step1.vtu"))
    r.check("(step 1 of 3, time 0.5" in res.stdout, f"convert says the step: {res.stdout}")
    r.check(signature(tree(os.path.join(d, "step1.vtu"))[0]) == sigs[1],
            "convert writes the chosen step whole")

r.finish()
