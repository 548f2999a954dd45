"""Writes the Gmsh-made fixtures of this directory with Gmsh's own Python API (Debian's
python3-gmsh 4.8): a unit square of two straight triangles of order k, with a $NodeData view "f"
holding the polynomial f(x, y) below (degree <= k, so the triangles represent it exactly),
appended with gmsh.view.write as users do. Run with the system Python: python3 make_gmsh_fixtures.py
(the unit tests read the files; they do not need Gmsh)."""
import os

import gmsh


def f(x, y):
    # Must match the function in tests/unit/test_msh_reader.cpp.
    return 1.0 + x - 2.0 * y + 3.0 * x * y - x * x * y + 0.5 * y * y


def write(name, order, version, binary, parametric):
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
