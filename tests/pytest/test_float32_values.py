"""Float32 values carry only 24 bits: the precision hoct reports (the smallest persistence the data
resolve, Tree.precision) must count their rounding, not a double's, whichever way they come in:
a .vtu with a Float32 array (written by meshio, an independent writer), a legacy .vtk (read
through VTK), and float32 arrays given to from_arrays. A pair of persistence 2^-23 around 1.5 is
resolved by doubles and at the data's resolution in float32: flagged uncertain there only."""
import json
import os
import subprocess
import sys
import tempfile

import meshio
import numpy as np

import hoct

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from hoct_testing import square_triangles  # noqa: E402

HOCT = os.environ.get("HOCT_BIN", "hoct")
N = 8


def grid():
    """P1 triangles of the unit square (diagonals from (i, j) to (i+1, j+1)) and
    f = 1.5 + 2^-23 G, G = 100 i + 10 j (integers: exact in float32, whose unit there is 2^-23)
    except at vertex (4, 4), set one unit below its lowest neighbour (3, 3): a minimum whose
    pair with the join saddle (3, 3) has a persistence of one float32 unit."""
    pts, tris = square_triangles(0.0, 1.0, N)
    i, j = np.rint(pts[:, 0] * N), np.rint(pts[:, 1] * N)
    G = 100 * i + 10 * j
    G[4 + (N + 1) * 4] = 100 * 3 + 10 * 3 - 1
    return pts, tris, 1.5 + 2.0 ** -23 * G


def expected_precision(f, unit):
    """Field::precision for P1 data: 2 units of the largest |value| plus 1e-12 of the range."""
    return 2 * unit * np.abs(f).max() + 1e-12 * (f.max() - f.min())


def test_float32_arrays_report_their_own_precision():
    pts, tris, f = grid()
    f32 = f.astype(np.float32)
    t64 = hoct.contour_tree(hoct.from_arrays(pts, tris, f))
    t32 = hoct.contour_tree(hoct.from_arrays(pts, tris, f32))
    assert np.isclose(t64.precision, expected_precision(f, 2.0 ** -52), rtol=1e-12)
    assert np.isclose(t32.precision, expected_precision(f32.astype(np.float64), 2.0 ** -23),
                      rtol=1e-12)
    # The dip's pair: certain in doubles, at the data's resolution in float32.
    for tree, flagged in ((t64, False), (t32, True)):
        pairs = tree.pairs
        small = [i for i, p in enumerate(pairs["persistence"]) if p < 1e-6]
        assert len(small) == 1, pairs["persistence"]
        assert bool(pairs["uncertain"][small[0]]) == flagged


def test_float32_files_report_their_own_precision():
    pts, tris, f = grid()
    with tempfile.TemporaryDirectory(prefix="hoct-f32-") as d:
        for ext in ("vtu", "vtk"):
            for dtype, unit in ((np.float64, 2.0 ** -52), (np.float32, 2.0 ** -23)):
                path = os.path.join(d, f"f_{np.dtype(dtype).name}.{ext}")
                values = f.astype(dtype)
                meshio.write(path, meshio.Mesh(pts, [("triangle", tris)],
                                               point_data={"f": values}))
                out = path + ".json"
                subprocess.run([HOCT, "tree", path, "-q", "--json", out], check=True,
                               capture_output=True)
                with open(out) as j:
                    tree = json.load(j)
                want = expected_precision(values.astype(np.float64), unit)
                assert np.isclose(tree["stats"]["precision"], want, rtol=1e-12), (path, tree["stats"])
                flagged = [p for p in tree["pairs"] if p.get("uncertain")]
                assert len(flagged) == (1 if dtype == np.float32 else 0), (path, tree["pairs"])


def p2_pair(origin):
    """Two straight P2 triangles of the square origin + [0, 1]^2 (meshio's triangle6 order:
    corners, then the midpoints of edges 01, 12, 20), sharing their corners 0 and 2 but each with
    its own copy of the shared edge's midpoint (points 5 and 6, at the same position)."""
    o = np.asarray(origin, dtype=np.float64)
    pts = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0, 0], [0.5, 0.5, 0],
                    [0.5, 0.5, 0], [1, 0.5, 0], [0.5, 1, 0], [0, 0.5, 0]]) + o
    cells = np.array([[0, 1, 2, 4, 7, 5], [0, 2, 3, 6, 8, 9]])
    return pts, cells


def test_float32_values_of_a_duplicated_edge_node_may_differ_by_their_rounding():
    """The two copies of an edge node hold one unit of float32 apart (a solver's value rounded
    from two cells' doubles): continuous within the values' own precision, not a discontinuity;
    a jump of 64 units is still one."""
    pts, cells = p2_pair((0, 0, 0))
    f = (1.25 + 0.1 * pts[:, 0] + 0.05 * pts[:, 1] ** 2).astype(np.float32)
    f[6] = np.nextafter(f[5], np.float32(2))
    hoct.contour_tree(hoct.from_arrays(pts, cells, f))
    f[6] = f[5] + np.float32(64 * 2.0 ** -23)
    try:
        hoct.from_arrays(pts, cells, f)
    except hoct.HoctError as e:
        assert "discontinu" in str(e)
    else:
        raise AssertionError("a jump of 64 float32 units was accepted")


def test_float32_points_through_vtk_are_straight_within_their_rounding():
    """Straight P2 cells far from the origin, their midpoints rounded to float32 (2 of 5 move,
    by up to 6e-5): stored as Float32 in a legacy .vtk (read by VTK) they are straight within
    float32 rounding, as in a .vtu; the same rounded points stored as doubles are curved."""
    corners = (np.array([[0, 0, 0], [0.77771, 0.1113, 0], [0.9137, 0.8371, 0], [0.1219, 0.9, 0]])
               + [1000.1, -2000.3, 0]).astype(np.float32).astype(np.float64)
    edges = [(0, 1), (1, 2), (2, 0), (2, 3), (3, 0)]
    mids = np.array([(corners[a] + corners[b]) / 2 for a, b in edges])
    rounded = mids.astype(np.float32).astype(np.float64)
    assert (rounded != mids).any()
    pts = np.concatenate([corners, rounded])
    cells = np.array([[0, 1, 2, 4, 5, 6], [0, 2, 3, 6, 7, 8]])  # triangle6: corners, 01, 12, 20
    with tempfile.TemporaryDirectory(prefix="hoct-f32-") as d:
        for dtype, geometry in ((np.float32, "planar-straight"), (np.float64, "planar-curved")):
            path = os.path.join(d, f"p_{np.dtype(dtype).name}.vtk")
            meshio.write(path, meshio.Mesh(pts.astype(dtype), [("triangle6", cells)],
                                           point_data={"f": pts[:, 0] - 1000}), binary=True)
            info = json.loads(subprocess.run([HOCT, "info", path, "--json"], check=True,
                                             capture_output=True, text=True).stdout)
            assert info["geometry"] == geometry, (path, info["geometry"])
