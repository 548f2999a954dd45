"""Writes the Gmsh-made fixtures of this directory with Gmsh's own Python API (Debian's
python3-gmsh 4.8): a unit square of two straight triangles of order k, with a $NodeData view "f"
holding the polynomial f(x, y) below (degree <= k, so the triangles represent it exactly),
appended with gmsh.view.write as users do. Run with the system Python: python3 make_gmsh_fixtures.py
(the unit tests read the files; they do not need Gmsh).

The second group holds the other sections Gmsh writes: $ElementNodeData (as GetDP and many
solvers write, with Gmsh's $InterpolationScheme), $ElementData, binary MSH 2.2 and views with
several time steps (the value of step s is f + 10 s, at time 0.1 s)."""
import os

import gmsh


def f(x, y):
    # Must match the function in tests/unit/test_msh_reader.cpp.
    return 1.0 + x - 2.0 * y + 3.0 * x * y - x * x * y + 0.5 * y * y


def square(order):
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("square")
    gmsh.model.occ.addRectangle(0, 0, 0, 1, 1)
    gmsh.model.occ.synchronize()
    for _, curve in gmsh.model.getEntities(1):
        gmsh.model.mesh.setTransfiniteCurve(curve, 2)
    gmsh.model.mesh.setTransfiniteSurface(1)
    gmsh.model.mesh.generate(2)
    gmsh.model.mesh.setOrder(order)


def write(name, order, version, binary, parametric):
    square(order)
    gmsh.option.setNumber("Mesh.MshFileVersion", version)
    gmsh.option.setNumber("Mesh.Binary", binary)
    gmsh.option.setNumber("Mesh.SaveParametric", parametric)
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), name)
    gmsh.write(path)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    view = gmsh.view.add("f")
    gmsh.view.addModelData(view, 0, "square", "NodeData", tags,
                           [[f(coords[3 * i], coords[3 * i + 1])] for i in range(len(tags))])
    gmsh.view.write(view, path, append=True)
    gmsh.finalize()


write("gmsh_square_p3_binary.msh", 3, 4.1, 1, 1)
write("gmsh_square_p4_ascii.msh", 4, 4.1, 0, 0)
write("gmsh_square_p3_msh22.msh", 3, 2.2, 0, 0)


def element_values(g):
    """The triangles' tags and, per triangle, g at its nodes (in Gmsh's order of them)."""
    types, elements, element_nodes = gmsh.model.mesh.getElements(2)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    at = {int(t): (coords[3 * i], coords[3 * i + 1]) for i, t in enumerate(tags)}
    n = len(element_nodes[0]) // len(elements[0])
    data = []
    for k, e in enumerate(elements[0]):
        data.append([g(int(e), *at[int(t)]) for t in element_nodes[0][n * k:n * k + n]])
    return list(elements[0]), data


def write_views(name, order, version, binary, views):
    """views: (name, kind, [(time, g)]) with g(element, x, y)."""
    square(order)
    gmsh.option.setNumber("Mesh.MshFileVersion", version)
    gmsh.option.setNumber("Mesh.Binary", binary)
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), name)
    gmsh.write(path)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    for view_name, kind, steps in views:
        view = gmsh.view.add(view_name)
        for step, (time, g) in enumerate(steps):
            if kind == "NodeData":
                data = [[g(0, coords[3 * i], coords[3 * i + 1])] for i in range(len(tags))]
                gmsh.view.addModelData(view, step, "square", kind, tags, data, time=time)
            else:
                elements, data = element_values(g)
                if kind == "ElementData":
                    data = [[float(e)] for e in elements]
                gmsh.view.addModelData(view, step, "square", kind, elements, data, time=time)
        gmsh.view.write(view, path, append=True)
    gmsh.finalize()


def continuous(e, x, y):
    return f(x, y)


def jump(e, x, y):
    # Discontinuous: the triangle with the larger tag is 0.25 higher.
    return f(x, y) + (0.25 if e % 2 == 0 else 0.0)


def step(s):
    return lambda e, x, y: f(x, y) + 10 * s


write("gmsh_square_p3_msh22_binary.msh", 3, 2.2, 1, 0)
write_views("gmsh_elementnode_p3_ascii.msh", 3, 4.1, 0,
            [("area", "ElementData", [(0, continuous)]),
             ("f", "ElementNodeData", [(0, continuous)]),
             ("jump", "ElementNodeData", [(0, jump)])])
write_views("gmsh_elementnode_p3_binary.msh", 3, 4.1, 1,
            [("f", "ElementNodeData", [(0, continuous)]),
             ("jump", "ElementNodeData", [(0, jump)])])
write_views("gmsh_elementnode_p3_msh22_binary.msh", 3, 2.2, 1,
            [("f", "ElementNodeData", [(0, continuous)]),
             ("jump", "ElementNodeData", [(0, jump)])])
write_views("gmsh_elementnode_p2_msh22.msh", 2, 2.2, 0,
            [("f", "ElementNodeData", [(0.1 * s, step(s)) for s in range(3)]),
             ("area", "ElementData", [(0, continuous)])])
write_views("gmsh_steps_p2.msh", 2, 4.1, 0,
            [("T", "NodeData", [(0.1 * s, step(s)) for s in range(3)]),
             ("f", "NodeData", [(0, continuous)])])
write_views("gmsh_steps_p2_binary.msh", 2, 4.1, 1,
            [("T", "NodeData", [(0.1 * s, step(s)) for s in range(3)])])


def write_pos():
    """.pos views of the square: P1 by Gmsh (gmsh.view.addListData "ST", two steps: f, then
    f + 10), and ST2 in Gmsh's parsed syntax (Gmsh has no list type of degree 2 in its API)."""
    here = os.path.dirname(os.path.abspath(__file__))
    for order in (1, 2):
        square(order)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        at = {int(t): coords[3 * i:3 * i + 3] for i, t in enumerate(tags)}
        types, elements, element_nodes = gmsh.model.mesh.getElements(2)
        n = len(element_nodes[0]) // len(elements[0])
        triangles = [[int(t) for t in element_nodes[0][n * k:n * k + n]]
                     for k in range(len(elements[0]))]
        if order == 1:
            data = []
            for nodes in triangles:
                for k in range(3):
                    data += [at[t][k] for t in nodes]
                data += [f(*at[t][:2]) for t in nodes] + [f(*at[t][:2]) + 10 for t in nodes]
            view = gmsh.view.add("f")
            gmsh.view.addListData(view, "ST", len(triangles), data)
            gmsh.view.write(view, os.path.join(here, "gmsh_square_p1.pos"))
        else:
            with open(os.path.join(here, "square_p2.pos"), "w") as out:
                out.write('// The square of two quadratic triangles, f at the nodes.\n')
                out.write('View "f" {\nTIME{0.5};\n')
                for nodes in triangles:
                    xyz = ",".join(repr(float(c)) for t in nodes for c in at[t])
                    values = ",".join(repr(f(*at[t][:2])) for t in nodes)
                    out.write(f"ST2({xyz}){{{values}}};\n")
                out.write('T2(10, 10, 0){"a text annotation"};\n};\n')
        gmsh.finalize()


write_pos()
