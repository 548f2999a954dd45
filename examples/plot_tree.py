"""A notebook-style walk through hoct from Python: compute the exact contour tree of a generated
field, simplify it, and plot it with matplotlib (the critical points on the domain, and the tree
with height = value). Run: /usr/bin/python3 examples/plot_tree.py [out.png]"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import hoct

# 1. A field: the thesis-like `gauss` dataset (726 quadratic cells on a disk).
mesh = hoct.generate("gauss")
print(f"{mesh.num_cells} cells, values {mesh.value_range}, Euler characteristic "
      f"{mesh.euler_characteristic}")

# 2. Its exact contour tree, and the tree without features below 2% of the value range.
tree = hoct.contour_tree(mesh)
simple = hoct.contour_tree(mesh, simplify="2%")
print(f"{len(tree.values)} nodes, {len(simple.values)} after simplification")

# 3. Pictures: the critical points and arcs (drawn on the domain) and the tree itself.
colour = {"maximum": "tab:red", "minimum": "tab:blue", "saddle": "tab:green"}
fig, (left, right) = plt.subplots(1, 2, figsize=(12, 5.5))
for path in simple.arc_paths():
    xs, ys = zip(*[(p[0], p[1]) for p in path])
    left.plot(xs, ys, color="0.3", lw=1)
pos = simple.positions
left.scatter(pos[:, 0], pos[:, 1], c=[colour[t] for t in simple.types], s=40, zorder=3,
             edgecolors="k")
left.set_aspect("equal")
left.set_title("critical points and arcs (simplified at 2%)")
for a, b in simple.arcs:
    right.plot([pos[a, 0], pos[b, 0]], [simple.values[a], simple.values[b]], color="0.3", lw=1)
right.scatter(pos[:, 0], simple.values, c=[colour[t] for t in simple.types], s=40, zorder=3,
              edgecolors="k")
right.set_xlabel("x of the node")
right.set_ylabel("value")
right.set_title("the contour tree, height = value")
out = sys.argv[1] if len(sys.argv) > 1 else "gauss-tree.png"
fig.tight_layout()
fig.savefig(out, dpi=90)
print("wrote", out)
