"""MSH files written by Gmsh itself (python3-gmsh): MSH 4.1 ascii and binary and MSH 2.2 ascii,
orders 1 to 8, with $NodeData views. hoct must read the same triangles, and its field must equal
the analytic polynomial the views hold, at the nodes and inside straight cells."""
import json
import os
import random

import gmsh

from hoct_testing import Results, evaluate, run, tempdir

R = Results()
rng = random.Random(3)


def f(x, y, order):
    # Degree <= order, so straight cells of that order represent it exactly.
    return sum((0.5 - 0.1 * k) * x ** k + 0.3 * (x * y) ** (k // 2) - 0.2 * y ** k for k in range(order + 1))


def write(path, order, version, binary, two_views):
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("square")
    gmsh.model.occ.addRectangle(0, 0, 0, 1, 1)
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.45)
    gmsh.option.setNumber("Mesh.ElementOrder", order)
    gmsh.option.setNumber("Mesh.HighOrderOptimize", 0)
    gmsh.model.mesh.generate(2)
    gmsh.option.setNumber("Mesh.MshFileVersion", version)
    gmsh.option.setNumber("Mesh.Binary", binary)
    gmsh.write(path)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    views = [("pressure", lambda x, y: 7.0)] if two_views else []
    views.append(("temperature", lambda x, y: f(x, y, order)))
    for name, g in views:
        v = gmsh.view.add(name)
        gmsh.view.addModelData(v, 0, "square", "NodeData", tags,
                               [[g(coords[3 * i], coords[3 * i + 1])] for i in range(len(tags))])
        gmsh.view.write(v, path, append=True)
    types, etags, _ = gmsh.model.mesh.getElements(2)
    ntri = sum(len(t) for t in etags)
    gmsh.finalize()
    return ntri


with tempdir() as tmp:
    for version, binary in [(4.1, 0), (4.1, 1), (2.2, 0)]:
        for order in range(1, 9):
            path = os.path.join(tmp, "m.msh")
            ntri = write(path, order, version, binary, two_views=(order == 2))
            label = f"gmsh {version} binary={binary} order={order}"
            info = json.loads(run("info", path, "--json", "--scalar", "temperature").stdout)
            R.check(info["cells"] == ntri, f"{label}: {info['cells']} cells, gmsh has {ntri}")
            R.check(info["degrees"] == {str(order): ntri}, f"{label}: degrees {info['degrees']}")
            R.check(info["euler_characteristic"] == 1 and info["boundary_loops"] == 1,
                    f"{label}: topology {info['euler_characteristic']} {info['boundary_loops']}")
            queries = [(c, rng.random() * 0.5, rng.random() * 0.5) for c in range(ntri) for _ in range(3)]
            queries += [(c, a / order, b / order) for c in range(0, ntri, 5)
                        for b in range(order + 1) for a in range(order + 1 - b)]
            rows = evaluate(path, queries, "temperature")
            worst = max(abs(r[3] - f(r[0], r[1], order)) for r in rows)
            R.check(len(rows) == len(queries) and worst < 1e-8, f"{label}: field error {worst}")
            if order == 2:
                # The first view is the default; --scalar picks the other.
                first = evaluate(path, [(0, 0.2, 0.2)])[0][3]
                R.check(abs(first - 7.0) < 1e-12, f"{label}: default view gives {first}")
                bad = run("info", path, "--scalar", "nope", check=False)
                R.check(bad.returncode != 0 and "available: pressure, temperature" in bad.stderr,
                        f"{label}: unknown view message: {bad.stderr.strip()}")

R.finish()
