"""MSH files written by Gmsh itself (python3-gmsh) and read by hoct: MSH 4.1 ascii and binary and
MSH 2.2 ascii and binary, triangles of orders 1 to 10, with $NodeData views appended by gmsh.view.write.

Checked through the hoct CLI (HOCT_BIN), against Gmsh's own data:
 - the number of triangles and their degree;
 - node order: for every triangle, at the reference coordinates Gmsh gives its i-th node
   (getElementProperties), `hoct eval` returns that node's coordinates and value;
 - on the straight-sided square, at random points of every triangle, the position is the affine
   map of the triangle's corners and the value is the polynomial the view holds (degree <= order,
   so the triangle represents it exactly); on the disk, whose boundary triangles are curved, only
   the nodes are checked;
 - several views, time steps (the last one is read), parametric nodes (Mesh.SaveParametric);
 - recombined quadrangles of orders 1 to 10, complete and incomplete: hoct eval against Gmsh's
   own basis functions (getBasisFunctions) inside every cell;
 - what hoct must refuse: serendipity triangles, tetrahedra, and every other element type Gmsh
   defines, with the type and Gmsh's name for it; points and lines are skipped.
"""
import json
import os
import random

import gmsh

from hoct_testing import Results, evaluate, run, tempdir

R = Results()
rng = random.Random(7)


def poly(order):
    """A polynomial of total degree `order` in (x, y) with fixed, unequal coefficients."""
    terms = [(i, j, ((3 * i + 5 * j) % 7 - 3) / 4 + 0.1 * (i + 1))
             for i in range(order + 1) for j in range(order + 1 - i)]
    return lambda x, y: sum(c * x ** i * y ** j for i, j, c in terms)


def close(a, b, tol=1e-9):
    return abs(a - b) <= tol * max(1.0, abs(b))


GMSH_OPEN = [False]


def start(name):
    gmsh.initialize()
    GMSH_OPEN[0] = True
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add(name)


def stop():
    if GMSH_OPEN[0]:
        gmsh.finalize()
        GMSH_OPEN[0] = False


def mesh_square(order, size=0.3):
    gmsh.model.occ.addRectangle(0, 0, 0, 1, 1)
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", size)
    gmsh.model.mesh.generate(2)
    gmsh.model.mesh.setOrder(order)


def mesh_disk(order, size=0.5):
    gmsh.model.occ.addDisk(0, 0, 0, 1, 1)
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", size)
    gmsh.model.mesh.generate(2)
    gmsh.model.mesh.setOrder(order)


def write(path, version, binary, views, parametric=0):
    """Writes the current model, then appends each view (name, [(step, function)]) with
    gmsh.view.write. Returns what the checks need from Gmsh: node coordinates by tag, and the
    triangles: (number of nodes, reference coordinates of the nodes), element tags, node tags
    in Gmsh order."""
    gmsh.option.setNumber("Mesh.MshFileVersion", version)
    gmsh.option.setNumber("Mesh.Binary", binary)
    gmsh.option.setNumber("Mesh.SaveParametric", parametric)
    gmsh.write(path)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    xyz = {int(t): tuple(coords[3 * i:3 * i + 3]) for i, t in enumerate(tags)}
    model = gmsh.model.getCurrent()
    for name, steps in views:
        v = gmsh.view.add(name)
        for step, g in steps:
            gmsh.view.addModelData(v, step, model, "NodeData", tags,
                                   [[g(*xyz[int(t)][:2])] for t in tags], time=float(step))
        gmsh.view.write(v, path, append=True)
    types = gmsh.model.mesh.getElementTypes(2)
    assert len(types) == 1, types
    etags, enodes = gmsh.model.mesh.getElementsByType(types[0])
    _, _, _, nn, local, _ = gmsh.model.mesh.getElementProperties(types[0])
    return xyz, (nn, list(local)), [int(t) for t in etags], [int(n) for n in enodes]


def check_nodes(label, path, scalar, g, xyz, element, etags, enodes, tol=1e-9):
    """At Gmsh's reference coordinates of each node of each triangle, hoct gives that node."""
    nn, local = element
    queries = [(c, local[2 * i], local[2 * i + 1]) for c in range(len(etags)) for i in range(nn)]
    rows = evaluate(path, queries, scalar)
    bad = 0
    for k, row in enumerate(rows):
        c, i = divmod(k, nn)
        x, y, z = xyz[enodes[c * nn + i]]
        if not (abs(row[0] - x) < 1e-12 and abs(row[1] - y) < 1e-12 and abs(row[2] - z) < 1e-12
                and close(row[3], g(x, y), tol)):
            bad += 1
            if bad <= 3:
                print(f"  {label}: cell {c} node {i}: hoct {row}, gmsh {(x, y, z, g(x, y))}")
    R.check(len(rows) == len(queries) and bad == 0,
            f"{label}: {bad} of {len(queries)} nodes differ from Gmsh's")


def check_interior(label, path, scalar, g, xyz, etags, enodes, nn):
    """Straight triangles: affine position, polynomial value, at random points of each cell."""
    queries = []
    for c in range(len(etags)):
        for _ in range(3):
            u, v = rng.random(), rng.random()
            if u + v > 1:
                u, v = 1 - u, 1 - v
            queries.append((c, u, v))
    rows = evaluate(path, queries, scalar)
    bad = 0
    for (c, u, v), row in zip(queries, rows):
        p = [xyz[enodes[c * nn + k]] for k in range(3)]
        x = [p[0][d] + u * (p[1][d] - p[0][d]) + v * (p[2][d] - p[0][d]) for d in range(3)]
        if not (all(abs(row[d] - x[d]) < 1e-12 for d in range(3)) and close(row[3], g(x[0], x[1]))):
            bad += 1
            if bad <= 3:
                print(f"  {label}: cell {c} at {u},{v}: hoct {row}, expected {x} {g(x[0], x[1])}")
    R.check(len(rows) == len(queries) and bad == 0,
            f"{label}: {bad} of {len(queries)} points differ")


def info(path, *args):
    return json.loads(run("info", path, "--json", *args).stdout)


def fails(path, phrase, label):
    r = run("info", path, check=False)
    R.check(r.returncode != 0 and path in r.stderr and phrase in r.stderr,
            f"{label}: expected failure with '{phrase}', got {r.returncode}: {r.stderr.strip()}")


def guarded(label, check, *args):
    """Runs one case; an exception (e.g. hoct failing where it should not) is a failed check."""
    try:
        check(*args)
    except Exception as e:  # noqa: BLE001 - every error is a test failure, reported and counted
        R.check(False, f"{label}: {type(e).__name__}: {str(e).strip()}")
    finally:
        stop()


FORMATS = [(4.1, 0), (4.1, 1), (2.2, 0), (2.2, 1)]


def square(tmp, order, version, binary):
    """Straight triangles: node order, cell count, and the field inside every cell."""
    label = f"square order {order} msh {version} binary={binary}"
    path = os.path.join(tmp, f"sq{order}_{version}_{binary}.msh")
    f = poly(order)
    start("square")
    mesh_square(order)
    xyz, element, etags, enodes = write(path, version, binary, [("f", [(0, f)])])
    stop()
    j = info(path)
    R.check(j["cells"] == len(etags) and j["degrees"] == {str(order): len(etags)},
            f"{label}: hoct {j['cells']} cells {j['degrees']}, gmsh {len(etags)} of order {order}")
    # One disk: shared nodes are shared (also where the mesh is repeated before the view).
    R.check((j["components"], j["euler_characteristic"], j["boundary_loops"]) == (1, 1, 1),
            f"{label}: components, Euler characteristic, boundary loops "
            f"{j['components']} {j['euler_characteristic']} {j['boundary_loops']}")
    check_nodes(label, path, None, f, xyz, element, etags, enodes)
    check_interior(label, path, None, f, xyz, etags, enodes, element[0])
    if order == 3:
        # The tree of the .msh file is the tree of the same mesh converted to .vtu: its recorded
        # input fingerprint is of the data, not the file (issue 27 item 13).
        tree, vtu = path + ".json", path + ".vtu"
        run("tree", path, "-q", "--json", tree)
        run("convert", path, "-o", vtu)
        r = run("render", vtu, "--tree", tree, "-o", path + ".png", check=False)
        R.check(r.returncode == 0 and "warning" not in r.stderr,
                f"{label}: render of the converted .vtu with the .msh's tree: {r.stderr.strip()}")


def disk(tmp, order, version, binary):
    """Curved boundary triangles: nodes only; parametric coordinates in the 4.1 files."""
    parametric = 1 if version == 4.1 else 0
    label = f"disk order {order} msh {version} binary={binary} parametric={parametric}"
    path = os.path.join(tmp, f"disk{order}_{version}_{binary}.msh")
    f = poly(order)
    start("disk")
    mesh_disk(order)
    xyz, element, etags, enodes = write(path, version, binary, [("f", [(0, f)])], parametric)
    stop()
    j = info(path)
    R.check(j["cells"] == len(etags) and j["degrees"] == {str(order): len(etags)},
            f"{label}: hoct {j['cells']} cells {j['degrees']}, gmsh {len(etags)}")
    check_nodes(label, path, None, f, xyz, element, etags, enodes)


def views(tmp, version, binary):
    """The first view by default, --scalar picks one, the last time step of a view is read."""
    label = f"views msh {version} binary={binary}"
    path = os.path.join(tmp, f"views_{version}_{binary}.msh")
    f, g = poly(3), (lambda x, y: 7.0 - x)
    start("square")
    mesh_square(3, 0.5)
    xyz, element, etags, enodes = write(
        path, version, binary, [("pressure", [(0, g)]), ("temperature", [(0, g), (1, f)])])
    stop()
    check_nodes(label + " default view", path, None, g, xyz, element, etags, enodes)
    check_nodes(label + " last time step", path, "temperature", f, xyz, element, etags, enodes)
    r = run("info", path, "--scalar", "nope", check=False)
    R.check(r.returncode != 0
            and "no $NodeData or $ElementNodeData named 'nope' (available: pressure, temperature)" in r.stderr,
            f"{label}: unknown view: {r.stderr.strip()}")


def no_view(tmp):
    path = os.path.join(tmp, "noview.msh")
    start("square")
    mesh_square(2, 0.5)
    gmsh.write(path)
    stop()
    fails(path, "the file has no node data", "mesh without $NodeData")


def serendipity(tmp, order):
    path = os.path.join(tmp, f"serendipity{order}.msh")
    start("square")
    gmsh.option.setNumber("Mesh.SecondOrderIncomplete", 1)
    mesh_square(order, 0.5)
    write(path, 4.1, order % 2, [("f", [(0, poly(1))])])
    etype = gmsh.model.mesh.getElementType("Triangle", order, True)
    stop()
    fails(path, f"incomplete (serendipity) triangle type {etype} is not supported",
          f"serendipity order {order}")


def quadrangles(tmp, order, incomplete, version, binary):
    """Recombined quadrangles (complete, or incomplete: the 4p boundary nodes): at random points
    (s, t) of every cell, hoct eval gives what Gmsh's own basis functions (getBasisFunctions at
    xi = 2s - 1, eta = 2t - 1) give from the nodes' values and coordinates; every node at its
    reference coordinates; a tree that `hoct check` accepts."""
    kind = "incomplete" if incomplete else "complete"
    label = f"quadrangles order {order} {kind} msh {version} binary={binary}"
    path = os.path.join(tmp, f"quads{order}{kind}_{version}_{binary}.msh")
    f = poly(min(order, 3))
    start("square")
    gmsh.option.setNumber("Mesh.RecombineAll", 1)
    gmsh.option.setNumber("Mesh.SecondOrderIncomplete", 1 if incomplete else 0)
    mesh_square(order, 0.35)
    xyz, element, etags, enodes = write(path, version, binary, [("f", [(0, f)])])
    etype = gmsh.model.mesh.getElementTypes(2)[0]
    name = gmsh.model.mesh.getElementProperties(etype)[0]
    nn = element[0]
    pts = [(rng.random(), rng.random()) for _ in range(4)]
    local = []
    for s_, t_ in pts:
        local += [2 * s_ - 1, 2 * t_ - 1, 0.0]
    _, basis, _ = gmsh.model.mesh.getBasisFunctions(etype, local, "Lagrange")
    stop()
    expect_nodes = (order + 1) ** 2 if not incomplete else 4 * order
    R.check(nn == expect_nodes and name.startswith("Quadrilateral"),
            f"{label}: Gmsh wrote {name} ({nn} nodes)")
    j = info(path)
    R.check(j["cells"] == len(etags) and j["cell_kinds"] == [
        {"kind": "serendipity quadrilateral" if incomplete else "quadrilateral", "degree": order,
         "count": len(etags)}], f"{label}: hoct {j['cells']} cells {j['cell_kinds']}")
    # Nodes at their reference coordinates, (xi, eta) in [-1, 1]^2 -> (s, t) in [0, 1]^2.
    ref = element[1]
    unit = (nn, [0.5 * (c + 1) for c in ref])
    # Orders 9 and 10 are triangles of degree 18 and 20 inside hoct, whose Lagrange-to-Bernstein
    # conversion amplifies the values' rounding ~1e7-fold (docs/ALGORITHM.md 1.3).
    tol = 1e-9 if order <= 8 else 1e-7
    check_nodes(label, path, None, f, xyz, unit, etags, enodes, tol)
    queries = [(c, s_, t_) for c in range(len(etags)) for s_, t_ in pts]
    rows = evaluate(path, queries)
    worst = 0.0
    for k, row in enumerate(rows):
        c, q = divmod(k, len(pts))
        phi = basis[q * nn:(q + 1) * nn]
        nodes = [xyz[enodes[c * nn + i]] for i in range(nn)]
        value = sum(w * f(*x[:2]) for w, x in zip(phi, nodes))
        x = [sum(w * n[d] for w, n in zip(phi, nodes)) for d in range(3)]
        worst = max(worst, abs(row[3] - value) / max(1.0, abs(value)),
                    max(abs(row[d] - x[d]) for d in range(3)))
    R.check(len(rows) == len(queries) and worst < tol,
            f"{label}: eval differs from Gmsh's basis functions by {worst:.3g}")
    tree = path + ".json"
    run("tree", path, "-q", "--json", tree)
    c = run("check", tree, path, check=False)
    R.check(c.returncode == 0, f"{label}: hoct check: {c.stdout[-600:]}{c.stderr[-600:]}")


def tetrahedra(tmp):
    path = os.path.join(tmp, "box.msh")
    start("box")
    gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.5)
    gmsh.model.mesh.generate(3)
    gmsh.option.setNumber("Mesh.Binary", 1)
    gmsh.write(path)
    stop()
    fails(path, "element type 4 (Tetrahedron 4), which is not a surface cell hoct reads", "tetrahedra")


def every_element_type(tmp):
    """Every element type Gmsh defines, next to one linear triangle: points and lines are
    skipped, complete triangles are read (above), anything else is refused with Gmsh's name."""
    start("types")
    described = []
    for etype in range(1, 140):
        try:
            name, dim, order, nn, _, _ = gmsh.model.mesh.getElementProperties(etype)
        except Exception:  # noqa: BLE001 - a type number Gmsh does not define
            continue
        if nn > 0:
            described.append((etype, name, dim, order, nn))
    stop()
    R.check(len(described) > 100, f"Gmsh describes {len(described)} element types")
    checked = 0
    for etype, name, dim, order, nn in described:
        triangle = name.startswith("Triangle") and order >= 1
        if triangle and nn == (order + 1) * (order + 2) // 2:
            continue  # complete triangles: read above
        if name.startswith("Quadrilateral") and order >= 1 and (
                nn == (order + 1) ** 2 or (order >= 2 and nn == 4 * order)):
            continue  # quadrangles, complete and incomplete: read above
        n = max(nn, 8)  # the triangle uses nodes 1, 2, 8
        nodes = "".join(f"{k}\n" for k in range(1, n + 1)) + "".join(
            f"{k % 7} {k // 7} 0\n" for k in range(n))
        text = ("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
                f"$Nodes\n1 {n} 1 {n}\n2 1 0 {n}\n{nodes}$EndNodes\n"
                f"$Elements\n2 2 1 2\n2 1 2 1\n1 1 2 8\n{dim} 1 {etype} 1\n2 "
                + " ".join(str(k) for k in range(1, nn + 1)) + "\n$EndElements\n"
                "$NodeData\n1\n\"f\"\n1\n0\n3\n0\n1\n3\n1 0\n2 1\n8 2\n$EndNodeData\n")
        path = os.path.join(tmp, f"type{etype}.msh")
        with open(path, "w") as out:
            out.write(text)
        r = run("info", path, "--json", check=False)
        if dim <= 1:
            ok = r.returncode == 0 and json.loads(r.stdout)["cells"] == 1
        elif triangle:
            ok = (r.returncode != 0 and
                  f"incomplete (serendipity) triangle type {etype} is not supported" in r.stderr)
        else:
            ok = r.returncode != 0 and f"element 2 has element type {etype} ({name})" in r.stderr
        checked += 1
        R.check(ok, f"element type {etype} ({name}, dimension {dim}): "
                    f"{r.returncode} {r.stderr.strip()}")
    R.check(checked > 80, f"{checked} element types checked")


with tempdir() as tmp:
    for order in range(1, 11):
        for version, binary in FORMATS:
            guarded(f"square order {order} {version} {binary}", square, tmp, order, version, binary)
    for order in (2, 3, 5, 8):
        for version, binary in FORMATS:
            guarded(f"disk order {order} {version} {binary}", disk, tmp, order, version, binary)
    for version, binary in FORMATS:
        guarded(f"views {version} {binary}", views, tmp, version, binary)
    guarded("no view", no_view, tmp)
    for order in (3, 4, 5, 6, 10):
        guarded(f"serendipity {order}", serendipity, tmp, order)
    for order in range(1, 11):
        version, binary = FORMATS[order % len(FORMATS)]
        guarded(f"quadrangles {order}", quadrangles, tmp, order, False, version, binary)
    for order in (2, 3, 4, 6):
        version, binary = FORMATS[order % len(FORMATS)]
        guarded(f"incomplete quadrangles {order}", quadrangles, tmp, order, True, version, binary)
    guarded("tetrahedra", tetrahedra, tmp)
    guarded("element types", every_element_type, tmp)

R.finish()
