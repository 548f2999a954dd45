"""What FEM users hand the Python module (issue 28, item 5): meshio meshes of Lagrange
triangles (VTK type 69, read back from .vtu), several triangle blocks, (n, 1) value arrays, id
arrays first, vector fields by component or magnitude, and merge_duplicates= in every entry
point. Each is checked against hoct.read of the same file (the CLI's reader) or its tree."""
import os
import subprocess
import tempfile

import meshio
import numpy as np
import pytest

import hoct

HOCT = os.environ.get("HOCT_BIN", "hoct")


@pytest.fixture(scope="module")
def cubic():
    """A cubic heater as .vtu (VTK_LAGRANGE_TRIANGLE cells) and its tree by hoct.read."""
    with tempfile.TemporaryDirectory(prefix="hoct-fem-") as d:
        path = os.path.join(d, "heater.vtu")
        subprocess.run([HOCT, "generate", "heater", "--cells", "800", "-o", path], check=True,
                       capture_output=True)
        yield path, hoct.contour_tree(hoct.read(path))


def same_tree(a, b):
    return list(a.values) == list(b.values) and list(a.types) == list(b.types)


def test_lagrange_triangle_blocks(cubic):
    # Was: "from_meshio: expected exactly one block of triangles, got 0".
    path, tree = cubic
    m = meshio.read(path)
    assert [b.type for b in m.cells] == ["VTK_LAGRANGE_TRIANGLE"]
    assert same_tree(hoct.contour_tree(hoct.from_meshio(m)), tree)


def test_several_triangle_blocks_and_skipped_lines(cubic):
    # A Gmsh model with two surfaces gives two blocks; line blocks (its curves) are skipped.
    path, tree = cubic
    m = meshio.read(path)
    cells = m.cells[0].data
    half = len(cells) // 2
    two = meshio.Mesh(m.points, [("VTK_LAGRANGE_TRIANGLE", cells[:half]),
                                 ("line", cells[:5, :2]),
                                 ("VTK_LAGRANGE_TRIANGLE", cells[half:])],
                      point_data=m.point_data)
    assert same_tree(hoct.contour_tree(hoct.from_meshio(two)), tree)
    tets = meshio.Mesh(m.points, [("tetra", cells[:3, :4])], point_data=m.point_data)
    with pytest.raises(hoct.HoctError, match="cell block 0 is of type 'tetra': hoct reads triangles"):
        hoct.from_meshio(tets)
    with pytest.raises(hoct.HoctError, match="no triangle or quadrilateral blocks"):
        hoct.from_meshio(meshio.Mesh(m.points, [("line", cells[:5, :2])], point_data=m.point_data))


def test_column_values_ids_first_and_vectors(cubic):
    path, tree = cubic
    m = meshio.read(path)
    (name, values), = m.point_data.items()
    n = len(m.points)
    data = {"vtkOriginalPointIds": np.arange(n, dtype=float),  # DOLFINx writes it first
            "GlobalIds": np.arange(n),
            "velocity": np.c_[values, 2 * values, np.zeros(n)],
            name: values.reshape(-1, 1)}  # (n, 1): one component
    mesh = meshio.Mesh(m.points, m.cells, point_data=data)
    assert same_tree(hoct.contour_tree(hoct.from_meshio(mesh)), tree)
    scaled = hoct.contour_tree(hoct.from_meshio(mesh, component=1))  # velocity[1] = 2 f
    assert list(scaled.values) == [2 * v for v in tree.values]
    # |velocity| = sqrt(5) |f|: a different field; its minima are where f = 0 (at least one).
    norm = hoct.from_meshio(mesh, scalar="velocity", component="magnitude")
    assert abs(norm.value(0, 0.2, 0.2) - np.sqrt(5) * abs(hoct.from_meshio(mesh).value(0, 0.2, 0.2))) < 1e-12
    with pytest.raises(hoct.HoctError, match="'velocity' has 3 components; a scalar field needs 1"):
        hoct.from_meshio(mesh, scalar="velocity")
    with pytest.raises(hoct.HoctError, match="component 3: point data 'velocity' has 3 components"):
        hoct.from_meshio(mesh, component=3)
    only_ids = meshio.Mesh(m.points, m.cells, point_data={"GlobalIds": np.arange(n)})
    with pytest.raises(hoct.HoctError, match="but ids, ghost levels or masks"):
        hoct.from_meshio(only_ids)
    # The file route: the default skips the ids too, and picks a component.
    ids_path = path.replace(".vtu", "-ids.vtu")
    meshio.write(ids_path, mesh)
    assert same_tree(hoct.contour_tree(hoct.read(ids_path)), tree)
    assert list(hoct.contour_tree(hoct.read(ids_path, component="y")).values) == list(scaled.values)


def test_merge_duplicates_everywhere():
    # Two quadratic triangles with their own copies of the shared edge's nodes (as deal.II's
    # simplex output and DG projections write them): a crack unless merged.
    pts = np.array([[0, 0], [1, 0], [1, 1], [.5, 0], [1, .5], [.5, .5],
                    [0, 0], [1, 1], [0, 1], [.5, .5], [.5, 1], [0, .5]], float)
    cells = np.array([[0, 1, 2, 3, 4, 5], [6, 7, 8, 9, 10, 11]])
    vals = (pts[:, 0] - 0.4) ** 2 - (pts[:, 1] - 0.6) ** 2
    with pytest.raises(hoct.HoctError, match="same position"):
        hoct.contour_tree(hoct.from_arrays(pts, cells, vals))
    merged = hoct.from_arrays(pts, cells, vals, merge_duplicates=True)
    tree = hoct.contour_tree(merged)
    # The tree of the same two cells sharing their edge's nodes.
    shared = np.array([[0, 1, 2, 3, 4, 5], [0, 2, 6, 5, 7, 8]])
    whole = pts[[0, 1, 2, 3, 4, 5, 8, 10, 11]]
    unbroken = hoct.contour_tree(hoct.from_arrays(whole, shared, vals[[0, 1, 2, 3, 4, 5, 8, 10, 11]]))
    assert list(tree.values) == list(unbroken.values) and "saddle" in tree.types
    mm = meshio.Mesh(np.c_[pts, np.zeros(len(pts))], [("triangle6", cells)], point_data={"f": vals})
    assert list(hoct.contour_tree(hoct.from_meshio(mm, merge_duplicates=1e-9)).values) == list(tree.values)
    with pytest.raises(hoct.HoctError, match="merge_duplicates must be True or a tolerance"):
        hoct.from_meshio(mm, merge_duplicates=0.5)


def test_read_takes_the_field_options(cubic):
    path, _ = cubic
    with pytest.raises(hoct.HoctError, match="a .vtu file holds one time step"):
        hoct.read(path, step=2)
    with pytest.raises(hoct.HoctError, match="component must be an index"):
        hoct.read(path, component="w")
    with pytest.raises(hoct.HoctError, match="time must be a finite number"):
        hoct.read(path, time=float("nan"))


def test_read_through_vtk_and_its_warnings(tmp_path):
    """hoct.read reads what `hoct tree` reads through VTK (here a legacy .vtk written by VTK),
    to the same tree as the .vtu, and raises the reader's warnings as HoctWarning (a piece of a
    partitioned file read alone)."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkIOLegacy import vtkUnstructuredGridWriter
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter

    vtu = str(tmp_path / "heater.vtu")
    subprocess.run([HOCT, "generate", "heater", "--cells", "600", "-o", vtu], check=True,
                   capture_output=True)
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(vtu)
    reader.Update()
    grid = reader.GetOutput()
    legacy = vtkUnstructuredGridWriter()
    legacy.SetFileName(str(tmp_path / "heater.vtk"))
    legacy.SetInputData(grid)
    legacy.SetFileTypeToBinary()
    assert legacy.Write() == 1
    a = hoct.contour_tree(hoct.read(vtu))
    b = hoct.contour_tree(hoct.read(tmp_path / "heater.vtk"))
    assert sorted(a.values.tolist()) == sorted(b.values.tolist()) and len(a.values) > 2

    ghosts = np.zeros(grid.GetNumberOfCells(), dtype=np.uint8)
    ghosts[:5] = 1  # DUPLICATECELL
    g = numpy_to_vtk(ghosts, deep=True)
    g.SetName("vtkGhostType")
    grid.GetCellData().AddArray(g)
    piece = vtkXMLUnstructuredGridWriter()
    piece.SetFileName(str(tmp_path / "piece.vtu"))
    piece.SetInputData(grid)
    assert piece.Write() == 1
    with pytest.warns(hoct.HoctWarning, match="one piece of a partitioned output"):
        hoct.read(tmp_path / "piece.vtu")
