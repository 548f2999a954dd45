"""`hoct generate` checked with VTK, the reader ParaView uses.

For every dataset: the file written by `hoct generate` is read by vtkXMLUnstructuredGridReader;
at random parametric points of a sample of cells, VTK's own Lagrange triangle
(EvaluateLocation, InterpolateFunctions) gives the same position and value as `hoct eval`
(to ~1e-9 relative), so VTK and hoct agree on the node order and the field; `hoct info --json`
reports the expected topology (disks: Euler characteristic 1, one boundary loop; closed surfaces:
2 and 0), sizes and degree; the same seed gives the same file, another seed another field.
Also: the sphere's curved cells stay on the unit sphere between their nodes, the encodings all
read back the same in VTK, and `generate --list`, `generate list` and the user errors behave.

Run by ctest with /usr/bin/python3 and HOCT_BIN set to the hoct executable."""
import json
import math
import os
import random
import subprocess
import sys
import tempfile

import vtk

HOCT = os.environ.get("HOCT_BIN", "hoct")
passed = failed = 0


def check(condition, message):
    global passed, failed
    if condition:
        passed += 1
    else:
        failed += 1
        print("FAIL:", message, flush=True)


def hoct(*args, stdin=None, expect_ok=True):
    r = subprocess.run([HOCT, *map(str, args)], input=stdin, capture_output=True, text=True)
    if expect_ok and r.returncode != 0:
        raise RuntimeError(f"hoct {' '.join(map(str, args))} failed ({r.returncode}):\n{r.stderr}")
    return r


def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def vtk_evaluate(grid, c, u, v):
    """Position and value at parametric (u, v) of cell c, by VTK's Lagrange triangle."""
    cell = grid.GetCell(c)
    n = cell.GetNumberOfPoints()
    weights = [0.0] * n
    x = [0.0, 0.0, 0.0]
    cell.EvaluateLocation(vtk.mutable(0), [u, v, 0.0], x, weights)
    cell.InterpolateFunctions([u, v, 0.0], weights)
    values = grid.GetPointData().GetArray(0)
    value = sum(weights[k] * values.GetValue(cell.GetPointId(k)) for k in range(n))
    return (*x, value)


def hoct_evaluate(path, queries):
    text = "".join(f"{c} {u!r} {v!r}\n" for c, u, v in queries)
    out = hoct("eval", path, "--points", "-", stdin=text).stdout
    return [list(map(float, line.split())) for line in out.splitlines() if line.strip()]


# name: (extra arguments, degree, planar, approximate cells)
DATASETS = {
    "gauss": ([], 2, True, 722),
    "sphere": ([], 3, False, 1056),
    "two-triangle": ([], 5, True, 2),
    "heater": (["--cells", "2000"], 3, False, 2000),
    "conductor": (["--cells", "1200"], 2, True, 1200),
    "random": (["--cells", "3000", "--degree", "4"], 4, True, 3000),
}

rng = random.Random(20240611)
with tempfile.TemporaryDirectory(prefix="hoct-datasets-") as tmp:
    for name, (args, degree, planar, approx_cells) in DATASETS.items():
        path = os.path.join(tmp, name + ".vtu")
        out = hoct("generate", name, "-o", path, *args).stdout
        check(name in out and path in out and "cells" in out, f"{name}: summary line {out!r}")

        info = json.loads(hoct("info", path, "--json").stdout)
        check(info.get("valid") is True, f"{name}: hoct info finds problems {info.get('problems')}")
        euler, loops = (1, 1) if planar else (2, 0)
        check(info["euler_characteristic"] == euler and info["boundary_loops"] == loops,
              f"{name}: Euler characteristic {info['euler_characteristic']}, "
              f"{info['boundary_loops']} boundary loops; expected {euler}, {loops}")
        check(info["degrees"] == {str(degree): info["cells"]}, f"{name}: degrees {info['degrees']}")
        check(abs(info["cells"] - approx_cells) <= 0.1 * approx_cells,
              f"{name}: {info['cells']} cells, expected about {approx_cells}")
        geometry = "planar-straight" if planar else "surface-curved"
        check(info["geometry"] == geometry, f"{name}: geometry {info['geometry']}")

        grid = read_vtu(path)
        ncells = grid.GetNumberOfCells()
        check(ncells == info["cells"] and grid.GetNumberOfPoints() == info["points"],
              f"{name}: VTK reads {ncells} cells, {grid.GetNumberOfPoints()} points; "
              f"hoct info {info['cells']}, {info['points']}")
        vtk_type = vtk.VTK_TRIANGLE if degree == 1 else vtk.VTK_LAGRANGE_TRIANGLE
        check(all(grid.GetCellType(c) == vtk_type for c in range(ncells)),
              f"{name}: cell types are not {vtk_type}")
        check(all(grid.GetCell(c).GetNumberOfPoints() == (degree + 1) * (degree + 2) // 2
                  for c in range(0, ncells, max(1, ncells // 50))),
              f"{name}: node count per cell")

        queries, expected = [], []
        for c in rng.sample(range(ncells), min(40, ncells)):
            for _ in range(4):
                u, v = rng.random(), rng.random()
                if u + v > 1:
                    u, v = 1 - u, 1 - v
                queries.append((c, u, v))
                expected.append(vtk_evaluate(grid, c, u, v))
        rows = hoct_evaluate(path, queries)
        value_scale = max(1.0, *map(abs, info["value_range"]))
        length_scale = max(1.0, *(abs(b) for corner in info["bounds"] for b in corner))
        ok = len(rows) == len(queries)
        worst_x = worst_f = 0.0
        for (c, u, v), row, e in zip(queries, rows, expected):
            ok = ok and int(row[0]) == c and abs(row[1] - u) < 1e-15 and abs(row[2] - v) < 1e-15
            worst_x = max(worst_x, *(abs(row[3 + i] - e[i]) for i in range(3)))
            worst_f = max(worst_f, abs(row[6] - e[3]))
        check(ok, f"{name}: hoct eval rows do not match the queries")
        check(worst_x < 1e-9 * length_scale and worst_f < 1e-9 * value_scale,
              f"{name}: VTK and hoct differ by {worst_x:g} in position, {worst_f:g} in value")

        if name == "sphere":
            # Curved cubic cells: between the nodes the surface stays within ~1e-5 of the sphere
            # (flat cells of this size would be ~1e-2 inside it).
            radius_error = max(abs(math.sqrt(e[0] ** 2 + e[1] ** 2 + e[2] ** 2) - 1) for e in expected)
            check(radius_error < 1e-4, f"sphere: interpolated surface {radius_error:g} off the sphere")
        if planar:
            check(all(abs(e[2]) == 0.0 for e in expected), f"{name}: not in the plane z = 0")

        # Deterministic: the same seed gives the same file, another seed another field.
        again = os.path.join(tmp, name + "-again.vtu")
        hoct("generate", name, "-o", again, *args)
        with open(path, "rb") as a, open(again, "rb") as b:
            check(a.read() == b.read(), f"{name}: the same seed gives a different file")
        other = os.path.join(tmp, name + "-seed2.vtu")
        hoct("generate", name, "-o", other, "--seed", "2", *args)
        values2 = read_vtu(other).GetPointData().GetArray(0)
        values1 = grid.GetPointData().GetArray(0)
        differ = values1.GetNumberOfTuples() != values2.GetNumberOfTuples() or any(
            values1.GetValue(i) != values2.GetValue(i) for i in range(values1.GetNumberOfTuples()))
        check(differ, f"{name}: --seed 2 gives the same field")

    # Every encoding reads back identically in VTK.
    reference = None
    for encoding in ["ascii", "base64", "zlib", "appended", "appended-base64"]:
        path = os.path.join(tmp, f"conductor-{encoding}.vtu")
        hoct("generate", "conductor", "--cells", "300", "--encoding", encoding, "-o", path)
        grid = read_vtu(path)
        arrays = (
            [grid.GetPoint(i) for i in range(grid.GetNumberOfPoints())],
            [grid.GetPointData().GetArray(0).GetValue(i) for i in range(grid.GetNumberOfPoints())],
            [tuple(grid.GetCell(c).GetPointId(k) for k in range(6))
             for c in range(grid.GetNumberOfCells())],
        )
        if reference is None:
            reference = arrays
            check(len(arrays[0]) > 0, "conductor (ascii): VTK reads no points")
        else:
            check(arrays == reference, f"conductor: --encoding {encoding} reads back differently")

    # Listing and user errors.
    listing = hoct("generate", "--list").stdout
    names = [line.split()[0] for line in listing.splitlines() if line.strip()]
    check(names == ["conductor", "gauss", "heater", "plate", "random", "sphere", "two-triangle"],
          f"generate --list: {names}")
    check(hoct("generate", "list").stdout == listing, "generate list differs from --list")
    bad = os.path.join(tmp, "bad.vtu")
    for args in (["nope", "-o", bad], ["two-triangle", "--cells", "10", "-o", bad],
                 ["random", "--degree", "11", "-o", bad], ["gauss"],
                 ["gauss", "-o", bad, "--encoding", "xml"]):
        r = hoct("generate", *args, expect_ok=False)
        check(r.returncode != 0 and r.stderr.strip() != "" and not os.path.exists(bad),
              f"generate {' '.join(args)}: exit {r.returncode}, stderr {r.stderr!r}")

print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed or not passed else 0)
