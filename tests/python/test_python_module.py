"""The Python module: the same results as the command line, numpy input (plain arrays and
meshio), simplification, networkx export, join/split trees, arc paths, and clear errors."""
import json
import os

import meshio
import networkx as nx
import numpy as np

import hoct
from hoct_testing import Results, run, tempdir

R = Results()

with tempdir() as tmp:
    p = lambda n: os.path.join(tmp, n)
    run("generate", "sphere", "-o", p("s.vtu"))
    run("tree", p("s.vtu"), "--json", p("s.json"), "-q")
    cli = json.load(open(p("s.json")))
    mesh = hoct.read(p("s.vtu"))
    R.check(mesh.num_cells == 980 and mesh.euler_characteristic == 2, "read")
    tree = hoct.contour_tree(mesh)
    R.check(list(tree.values) == [n["value"] for n in cli["nodes"]], "values equal the CLI's")
    R.check(tree.types == [n["type"] for n in cli["nodes"]], "types equal the CLI's")
    R.check(tree.arcs.tolist() == cli["arcs"], "arcs equal the CLI's")
    R.check(sorted(tree.pairs["persistence"]) == sorted(x["persistence"] for x in cli["pairs"]), "pairs")
    R.check(json.loads(tree.to_json())["format"] == "hoct-contour-tree", "to_json")
    g = tree.to_networkx()
    R.check(nx.is_tree(g) and g.number_of_nodes() == len(tree.values), "networkx tree")
    R.check(g.nodes[0]["type"] == tree.types[0], "networkx attributes")
    # Join and split trees: every node has a parent above (below), one root each.
    jp, sp = tree.join_tree()["parent"], tree.split_tree()["parent"]
    R.check((jp < 0).sum() == 1 and all(tree.values[c] <= tree.values[q] for c, q in enumerate(jp) if q >= 0), "join tree")
    R.check((sp < 0).sum() == 1 and all(tree.values[c] >= tree.values[q] for c, q in enumerate(sp) if q >= 0), "split tree")
    # Simplification: pairs above the threshold kept.
    s = hoct.contour_tree(mesh, simplify="2%")
    rng = tree.values.max() - tree.values.min()
    kept = [x for x in tree.pairs["persistence"] if x >= 0.02 * rng]
    R.check(len(s.pairs["persistence"]) == len(kept), f"simplify: {len(s.pairs['persistence'])} vs {len(kept)}")
    R.check(len(s.branches["parent"]) == len(kept) and s.branches["parent"][0] == -1, "branches")
    # Arc paths start and end at their nodes.
    paths = tree.arc_paths()
    ok = all(np.allclose(path[0], tree.positions[a]) and np.allclose(path[-1], tree.positions[b])
             for path, (a, b) in zip(paths, tree.arcs))
    R.check(len(paths) == len(tree.arcs) and ok, "arc paths")
    # PL variants.
    pl = hoct.contour_tree(mesh, method="refine", refine=4)
    R.check(pl.method == "refine k=4" and len(pl.values) > 0, "refine method")

    # numpy input: a quadratic field on two triangles, and the same through a file and meshio.
    pts = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [.5, 0], [1, .5], [.5, .5], [.5, 1], [0, .5]], float)
    cells = np.array([[0, 1, 2, 4, 5, 6], [0, 2, 3, 6, 7, 8]])
    vals = (pts[:, 0] - 0.4) ** 2 - (pts[:, 1] - 0.6) ** 2
    m2 = hoct.from_arrays(pts, cells, vals)
    t2 = hoct.contour_tree(m2)
    R.check(m2.num_cells == 2 and "saddle" in t2.types, f"from_arrays: {t2.types}")
    R.check(abs(m2.value(0, 0.5, 0.25) - ((0.75 - 0.4) ** 2 - (0.25 - 0.6) ** 2)) < 1e-12, "field value")
    mm = meshio.Mesh(np.c_[pts, np.zeros(len(pts))], [("triangle6", cells)], point_data={"f": vals})
    meshio.write(p("q.vtu"), mm)
    t3 = hoct.contour_tree(hoct.from_meshio(mm))
    t4 = hoct.contour_tree(hoct.read(p("q.vtu")))
    R.check(list(t3.values) == list(t2.values) == list(t4.values), "from_meshio and read agree")
    # The saddle of (x-.4)^2 - (y-.6)^2 is at (0.4, 0.6), exactly.
    sad = [i for i, t in enumerate(t2.types) if t == "saddle"]
    R.check(any(np.allclose(t2.positions[i][:2], [0.4, 0.6], atol=1e-12) for i in sad), "saddle position")

    # Errors are HoctError (a ValueError) with the message of the library.
    for call, phrase in [(lambda: hoct.read(p("missing.vtu")), "cannot open"),
                         (lambda: hoct.from_arrays(pts, cells[:, :5], vals), "not a complete triangle"),
                         (lambda: hoct.from_arrays(pts, cells + 20, vals), "refers to point"),
                         (lambda: hoct.contour_tree(m2, method="magic"), "method must be")]:
        try:
            call()
            R.check(False, f"no error for {phrase}")
        except hoct.HoctError as e:
            R.check(phrase in str(e) and isinstance(e, ValueError), f"error text: {e}")

R.finish()
