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
