"""The number of contours at a level, counted by brute force, against the tree's arcs.

For a contour tree (and, later, a Reeb graph) the number of connected components of the level set
{f = c} equals the number of arcs whose end values bracket c. This test counts those components
(the oracle of level_sets.py) on an independent piecewise-linear refinement of the field: VTK's
own evaluation of the higher-order cells (vtkDataSetSurfaceFilter's nonlinear subdivision, VTK's
Lagrange basis, not hoct's), merged into one mesh by vtkCleanPolyData. At a level c away from
every node value (by more than the refinement's error, estimated by how far the refinement moves
when it is refined once more), the level set is cut where an edge's end values bracket c, and its
pieces are joined within each triangle; the components of that graph are the contours. Every
generated dataset (triangles of degree 2-5, curved surfaces, a jittered quadrilateral mesh) is
checked at up to 40 levels; a tree that misses or invents a feature larger than the margin fails.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hoct_testing import Results, run, tempdir  # noqa: E402

try:
    import level_sets  # noqa: E402  (numpy, scipy and VTK's Python modules)
except ImportError as e:
    print(f"skipped: numpy, scipy or VTK's Python modules are missing ({e})")
    sys.exit(77)

R = Results()


def check(name, path, level):
    level_sets.check(R, name, path, level)


with tempdir() as d:
    for name, args, level in [("two-triangle", [], 5), ("gauss", [], 3), ("sphere", [], 3),
                              ("heater", ["--cells", "1500"], 3), ("conductor", [], 2),
                              ("random", ["--degree", "3", "--cells", "2000"], 3),
                              ("random", ["--quads", "--degree", "3", "--cells", "800"], 3)]:
        label = " ".join([name] + args)
        path = os.path.join(d, label.replace(" ", "_").replace("-", "") + ".vtu")
        run("generate", name, "-o", path, *args)
        check(label, path, level)
R.finish()
