"""Quadrilaterals through the Python module (issue 29): from_arrays and from_meshio take them in
VTK node order, with or without cell types, and give the tree hoct.read gives for the same
cells written to a .vtu file by meshio (an independent writer)."""
import os
import tempfile

import meshio
import numpy as np
import pytest

import hoct


def grid(p, n=3):
    """An n x n grid of order-p quadrilaterals of the unit square (VTK node order), and the
    field x^2 y - 0.7 x y^2 + 0.3 sin-free cubic terms (in the space of every order p >= 2)."""
    m = n * p
    pts = np.array([[i / m, j / m, 0.0] for j in range(m + 1) for i in range(m + 1)])
    gid = lambda i, j: i + (m + 1) * j  # noqa: E731
    order = []  # VTK's order of the tensor nodes (i, j)
    order += [(0, 0), (p, 0), (p, p), (0, p)]
    order += [(i, 0) for i in range(1, p)] + [(p, j) for j in range(1, p)]
    order += [(i, p) for i in range(1, p)] + [(0, j) for j in range(1, p)]
    order += [(i, j) for j in range(1, p) for i in range(1, p)]
    cells = np.array([[gid(ci * p + i, cj * p + j) for i, j in order]
                      for cj in range(n) for ci in range(n)], dtype=np.int64)
    x, y = pts[:, 0], pts[:, 1]
    f = (x - 0.43) ** 2 * (y + 0.2) - 0.7 * (y - 0.61) ** 2 * (x + 0.1) + 0.05 * x
    return pts, cells, f


def same_tree(a, b):
    return np.allclose(sorted(a.values), sorted(b.values), rtol=1e-12, atol=1e-14) and \
        sorted(a.types) == sorted(b.types)


@pytest.mark.parametrize("p,meshio_type", [(1, "quad"), (2, "quad9"), (3, "VTK_LAGRANGE_QUADRILATERAL")])
def test_quadrilaterals_match_the_file_route(p, meshio_type):
    pts, cells, f = grid(p)
    with tempfile.TemporaryDirectory(prefix="hoct-quad-") as d:
        path = os.path.join(d, "q.vtu")
        meshio.write(path, meshio.Mesh(pts, [(meshio_type, cells)], point_data={"f": f}))
        ref = hoct.contour_tree(hoct.read(path))
    assert same_tree(hoct.contour_tree(hoct.from_arrays(pts, cells, f)), ref)
    typed = 9 if p == 1 else 70
    assert same_tree(hoct.contour_tree(hoct.from_arrays(pts, cells, f, cell_types=typed)), ref)
    assert same_tree(hoct.contour_tree(hoct.from_arrays(pts, cells, f, degree=p)), ref)
    m = meshio.Mesh(pts, [(meshio_type, cells)], point_data={"f": f})
    assert same_tree(hoct.contour_tree(hoct.from_meshio(m)), ref)
    assert len(ref.values) >= 3


def test_serendipity_and_mixed_blocks():
    pts, cells, f = grid(2)
    # quad8 (serendipity): the field x^2 y ... lies in its space, so the tree of quad9.
    ref = hoct.contour_tree(hoct.from_arrays(pts, cells, f))
    assert same_tree(hoct.contour_tree(hoct.from_arrays(pts, cells[:, :8], f)), ref)
    m = meshio.Mesh(pts, [("quad8", cells[:4, :8]), ("line", cells[:2, :2]),
                          ("quad9", cells[4:])], point_data={"f": f})
    assert same_tree(hoct.contour_tree(hoct.from_meshio(m)), ref)


def test_bad_quadrilateral_input_is_refused():
    pts, cells, f = grid(2)
    with pytest.raises(hoct.HoctError, match="neither a complete triangle"):
        hoct.from_arrays(pts, cells[:, :5], f)
    with pytest.raises(hoct.HoctError, match="cell 0 has VTK type 70, which does not match 9-node "
                                             "cells of degree 3"):
        hoct.from_arrays(pts, cells, f, degree=3, cell_types=70)
    with pytest.raises(hoct.HoctError, match="cell 0 has VTK type 10"):
        hoct.from_arrays(pts, cells[:, :4], f, cell_types=10)
    with pytest.raises(hoct.HoctError, match="2 cell_types for 9 cells"):
        hoct.from_arrays(pts, cells, f, cell_types=[70, 70])
    bad = cells.copy()
    bad[4, 3] = len(pts)
    with pytest.raises(hoct.HoctError, match="cell 4 refers to point"):
        hoct.from_arrays(pts, bad, f)


def test_generate_quadrilaterals_is_the_command_lines():
    """hoct.generate(..., quads=True) gives the mesh `hoct generate random --quads` writes: the
    same tree (independent route: the command line's file read back)."""
    import subprocess
    mesh = hoct.generate("random", degree=2, cells=400, seed=3, quads=True)
    with tempfile.TemporaryDirectory(prefix="hoct-quad-") as d:
        path = os.path.join(d, "q.vtu")
        subprocess.run([os.environ.get("HOCT_BIN", "hoct"), "generate", "random", "--quads",
                        "--degree", "2", "--cells", "400", "--seed", "3", "-o", path],
                       check=True, capture_output=True)
        from_file = hoct.read(path)
        cells = meshio.read(path).cells
    assert [c.type for c in cells] == ["VTK_LAGRANGE_QUADRILATERAL"] or \
        all(c.type in ("quad9", "VTK_LAGRANGE_QUADRILATERAL") for c in cells)
    assert sum(len(c.data) for c in cells) == 400
    a, b = hoct.contour_tree(mesh), hoct.contour_tree(from_file)
    assert len(a.values) > 2 and same_tree(a, b)
    with pytest.raises(hoct.HoctError, match="random"):
        hoct.generate("heater", quads=True)
    with pytest.raises(TypeError, match="generate: quads must be True or False"):
        hoct.generate("random", quads="yes")
