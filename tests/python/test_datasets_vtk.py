"""The generated datasets, read by VTK's own reader (what ParaView uses): VTK's Lagrange cells
evaluate the same positions and values as hoct at random parametric points, and each dataset has
the topology it should (disks: Euler characteristic 1 and one boundary loop; closed surfaces: 2, 0)."""
import json
import os
import random

import vtk

from hoct_testing import Results, evaluate, run, tempdir

R = Results()
rng = random.Random(11)
EXPECT = {  # name: (args, euler, loops, geometry)
    "gauss": ([], 1, 1, "planar-straight"),
    "sphere": ([], 2, 0, "surface-curved"),
    "two-triangle": ([], 1, 1, "planar-straight"),
    "heater": (["--cells", "2000"], 2, 0, "surface-curved"),
    "conductor": (["--cells", "1200"], 1, 1, "planar-straight"),
    "random": (["--cells", "3000", "--degree", "4"], 1, 1, "planar-straight"),
}

with tempdir() as tmp:
    for name, (args, euler, loops, geometry) in EXPECT.items():
        path = os.path.join(tmp, name + ".vtu")
        run("generate", name, "-o", path, *args)
        info = json.loads(run("info", path, "--json").stdout)
        R.check(info["valid"], f"{name}: problems {info['problems']}")
        R.check(info["euler_characteristic"] == euler and info["boundary_loops"] == loops,
                f"{name}: Euler {info['euler_characteristic']} loops {info['boundary_loops']}")
        R.check(info["geometry"] == geometry, f"{name}: geometry {info['geometry']}")
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(path)
        reader.Update()
        grid = reader.GetOutput()
        R.check(grid.GetNumberOfCells() == info["cells"], f"{name}: VTK reads {grid.GetNumberOfCells()} cells")
        values = grid.GetPointData().GetArray(0)
        queries, expected = [], []
        for c in rng.sample(range(grid.GetNumberOfCells()), min(40, grid.GetNumberOfCells())):
            cell = grid.GetCell(c)
            n = cell.GetNumberOfPoints()
            for _ in range(3):
                u, v = rng.random(), rng.random()
                if u + v > 1:
                    u, v = 1 - u, 1 - v
                w = [0.0] * n
                x = [0.0, 0.0, 0.0]
                cell.EvaluateLocation(vtk.mutable(0), [u, v, 0.0], x, w)
                cell.InterpolateFunctions([u, v, 0.0], w)
                val = sum(w[k] * values.GetValue(cell.GetPointId(k)) for k in range(n))
                queries.append((c, u, v))
                expected.append((*x, val))
        rows = evaluate(path, queries)
        scale = max(1.0, abs(info["value_range"][0]), abs(info["value_range"][1]))
        worst = max(max(abs(r[i] - e[i]) for i in range(4)) for r, e in zip(rows, expected))
        R.check(len(rows) == len(queries) and worst < 1e-9 * scale, f"{name}: VTK vs hoct {worst}")
        # Deterministic: the same seed gives the same file, another seed another field.
        again = os.path.join(tmp, name + "-again.vtu")
        run("generate", name, "-o", again, *args)
        R.check(open(path, "rb").read() == open(again, "rb").read(), f"{name}: not deterministic")
        other = os.path.join(tmp, name + "-seed2.vtu")
        run("generate", name, "-o", other, "--seed", "2", *args)
        R.check(open(path, "rb").read() != open(other, "rb").read(), f"{name}: seed ignored")

R.finish()
