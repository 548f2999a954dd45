"""Exact Reeb graphs of higher-order fields on domains that are not a disk or a sphere: annuli,
planar disks with 1, 2, 3 and 5 holes, tori, a genus-2 surface (two fused tori), a box drilled
through, two components in one file and Moebius strips, as .vtu files of Lagrange triangles of
degrees 1-3 (VTK_LAGRANGE_TRIANGLE, VTK_QUADRATIC_TRIANGLE) written here with VTK, their nodes on
the true curved circle or surface: structured meshes at exact parametric positions, or Gmsh's
(python3-gmsh) high-order meshes of OpenCASCADE geometry. The field at each node is an analytic
function of its position.

For each: `hoct tree --json` succeeds; the graph's first Betti number (arcs - nodes +
components of the arc graph) is the expected one (a Morse function on a closed orientable surface
of genus g: g; a near-linear function on a planar domain with h holes: h; a near-radial one on an
annulus: 0); its components are the domain's; its leaves are minima or maxima and the sum over
nodes of (degree - 2) is 2 (loops - components); the level-set oracle of level_sets.py (the
number of contours of VTK's own PL refinement at levels between node values equals the number of
arcs crossing them) agrees; the JSON's "kind" and "loops" and `hoct check` agree (see
reeb_fields); and the PL Reeb graphs of the refinements --refine 4 and 16 converge to it
(converges). First, the VTK node order written here is checked by `hoct eval` on straight cells
(a field that is a polynomial of the cell's degree is reproduced exactly) and on curved ones
(positions on the true surface). A failing case's .vtu is kept in /tmp/reeb_failures/. The
meshes and fields are reeb_meshes' (shared with test_mpi_reeb).
"""
import json
import math
import os
import shutil
import sys
import time
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hoct_testing import Results, evaluate, run, tempdir  # noqa: E402

try:
    import numpy as np
    import level_sets  # numpy, scipy and VTK's Python modules
    from reeb_meshes import (HAVE_GMSH, HOLES, annulus, disk_and_annulus, disk_with_holes,
                             double_torus, drilled_box, gmsh_mesh, graph_shape, moebius,
                             moebius_f, planar, radial, square, surface_f, tilted, torus,
                             torus_f1, torus_f2, torus_solid, wavy_planar, wavy_surface,
                             wavy_torus, write_vtu)
    from vtkmodules.vtkCommonDataModel import VTK_LAGRANGE_TRIANGLE, VTK_QUADRATIC_TRIANGLE
except ImportError as e:
    print(f"skipped: numpy, scipy or VTK's Python modules are missing ({e})")
    sys.exit(77)

R = Results()
FAILURES = "/tmp/reeb_failures"
RNG = np.random.default_rng(12345)


# --- Checks ---------------------------------------------------------------------------------

def reeb_fields(name, tree, json_path, vtu, loops):
    """The JSON's "kind" and "loops" fields and `hoct check` accepting the graph: written against
    the Reeb-graph output as specified ("kind": "Reeb graph", "loops": the first Betti number),
    which may lag behind the graph itself; these are the checks to tighten or relax in one
    place."""
    R.check(tree.get("kind") == "Reeb graph", f"{name}: \"kind\" is {tree.get('kind')!r}")
    R.check(tree.get("loops") == loops, f"{name}: \"loops\" is {tree.get('loops')!r}, not {loops}")
    r = run("check", json_path, vtu, check=False)
    R.check(r.returncode == 0, f"{name}: hoct check exit {r.returncode}: "
                               f"{(r.stdout + r.stderr).strip()[-600:]}")


def converges(name, vtu, exact_json, exact):
    """The PL Reeb graphs of refinements (`--refine k`) converge to the exact one: at k = 16 the
    same number of loops, a bottleneck distance of all their diagrams (ordinary and loop pairs)
    no larger than at k = 4 and within 1e-3 of the range. Returns the two distances."""
    values = [n["value"] for n in exact["nodes"]]
    span = max(values) - min(values)
    dist = {}
    for k in (4, 16):
        out = f"{vtu}.refine{k}.json"
        run("tree", vtu, "-q", "--refine", str(k), "--json", out, "--no-timings")
        with open(out) as f:
            pl = json.load(f)
        R.check(pl["kind"] == "Reeb graph" and "forced" not in pl,
                f"{name} --refine {k}: {pl['kind']}, forced {pl.get('forced')}")
        d = json.loads(run("compare", exact_json, out, "--json").stdout)["bottleneck"]
        dist[k] = (d["max"], pl["loops"])
    R.check(dist[16][1] == exact["loops"],
            f"{name}: --refine 16 has {dist[16][1]} loops, the exact graph {exact['loops']}")
    R.check(dist[16][0] <= dist[4][0] + 1e-12 * span and dist[16][0] <= 1e-3 * span,
            f"{name}: bottleneck distance to --refine 4, 16: {dist[4][0]:.3g}, {dist[16][0]:.3g} "
            f"(range {span:.3g})")
    return dist[4][0], dist[16][0]


def bridges(tree):
    """The arcs whose removal disconnects their ends (brute force, parallel arcs included): those
    without which the arc graph has one component more."""
    arcs = tree["arcs"]
    components = graph_shape(tree)[1]
    return {k for k in range(len(arcs))
            if graph_shape({"nodes": tree["nodes"], "arcs": arcs[:k] + arcs[k + 1:]})[1]
            > components}


def check_svg(name, vtu, tree):
    """`hoct tree --svg` of a graph with loops: a circle per node (and 3 in the legend), a path
    per arc, the arcs on loops (no bridge, by brute force) exactly those drawn as loops."""
    svg = vtu + ".svg"
    run("tree", vtu, "-q", "--svg", svg)
    root = ET.parse(svg).getroot()
    ns = "{http://www.w3.org/2000/svg}"
    circles = root.findall(f".//{ns}circle")
    paths = root.findall(f".//{ns}path")
    loops = sum(p.get("class") == "loop" for p in paths)
    expected = len(tree["arcs"]) - len(bridges(tree))
    R.check(len(circles) == len(tree["nodes"]) + 3 and len(paths) == len(tree["arcs"]) and
            loops == expected, f"{name}: svg has {len(circles)} circles, {len(paths)} paths, "
            f"{loops} on loops; expected {len(tree['nodes'])} + 3, {len(tree['arcs'])}, {expected}")


def keep_failure(name, vtu):
    os.makedirs(FAILURES, exist_ok=True)
    target = os.path.join(FAILURES, name.replace(" ", "_").replace(",", "") + ".vtu")
    shutil.copyfile(vtu, target)
    print(f"  kept {target}", flush=True)


def check_positions(name, vtu, cells, surface, f, tol):
    """hoct eval at random points of random cells: the position on the true surface
    (|surface(x)| <= tol) and the value f(x) within tol (the interpolation error)."""
    uv = RNG.random((30, 2))
    uv = np.where(uv.sum(axis=1, keepdims=True) > 1, 1 - uv, uv)  # into the triangle
    pts = [(int(RNG.integers(cells)), float(a), float(b)) for a, b in uv]
    rows = np.array(evaluate(vtu, pts))
    geo = max(abs(surface(*p)) for p in rows[:, :3]) if surface else 0.0
    val = max(abs(v - f(*p)) for p, v in zip(rows[:, :3], rows[:, 3]))
    R.check(geo <= tol and val <= tol,
            f"{name}: hoct eval off the surface by {geo:.3g} or off the field by {val:.3g}")
    return max(geo, val)


def case(tmp, name, mesh, f, loops, components=1, level=2, surface=None, tol=1e-2,
         cell_type=None, max_loops=None):
    """Writes the mesh with f at its nodes, computes its Reeb graph and checks it (loops None:
    not asserted, only that the graph's shape and the oracle agree, and that there are at most
    max_loops: the domain's first Betti number bounds the graph's, the quotient map being onto
    on the fundamental group)."""
    t0 = time.time()
    points, cells = mesh
    vtu = os.path.join(tmp, name.replace(" ", "_").replace(",", "") + ".vtu")
    write_vtu(vtu, points, cells, np.array([f(*p) for p in points]), cell_type)
    failed = R.failed
    try:
        info = level_sets.check(R, name, vtu, level, quiet=True)
    except RuntimeError as e:
        R.check(False, f"{name}: {e}")
        keep_failure(name, vtu)
        return
    tree = info["tree"]
    degree, comps, got = graph_shape(tree)
    if loops is not None:
        R.check(got == loops, f"{name}: {got} loop(s), expected {loops}")
    if max_loops is not None:
        R.check(got <= max_loops, f"{name}: {got} loop(s), more than the domain's {max_loops}")
    R.check(comps == components, f"{name}: {comps} component(s), expected {components}")
    types = [n["type"] for n in tree["nodes"]]
    leaves = [k for k, g in enumerate(degree) if g == 1]
    R.check(all(types[k] in ("minimum", "maximum") for k in leaves),
            f"{name}: leaves that are no extremum: "
            f"{[(k, types[k]) for k in leaves if types[k] not in ('minimum', 'maximum')][:5]}")
    R.check(0 not in degree, f"{name}: isolated nodes")
    if loops is not None:  # (against the arcs' own count it would hold by construction)
        R.check(sum(g - 2 for g in degree) == 2 * (loops - components),
                f"{name}: sum of (degree - 2) is {sum(g - 2 for g in degree)}, "
                f"not 2 (loops - components) = {2 * (loops - components)}")
    reeb_fields(name, tree, info["json"], vtu, got if loops is None else loops)
    dev = check_positions(name, vtu, len(cells), surface, f, tol)
    if got > 0:
        check_svg(name, vtu, tree)
    d4, d16 = converges(name, vtu, info["json"], tree)
    bad = info["bad"]
    print(f"{name}: degree {int(round((math.sqrt(8 * cells.shape[1] + 1) - 3) / 2))}, "
          f"{len(cells)} cells; {len(tree['nodes'])} nodes, {len(tree['arcs'])} arcs, {got} loop(s), "
          f"{comps} component(s); {len(info['levels'])} levels checked, {len(bad)} disagree "
          f"(refinement error ~{info['err']:.2g}); eval deviation {dev:.2g}; "
          f"PL --refine 4, 16 at bottleneck {d4:.2g}, {d16:.2g}; "
          f"{time.time() - t0:.1f} s", flush=True)
    for c, arcs, contours in bad[:5]:
        print(f"  level {c!r}: {arcs} arcs cross it, {contours} contours", flush=True)
    if R.failed != failed:
        keep_failure(name, vtu)


def node_order(tmp):
    """The node order written here, through hoct eval on straight cells: a polynomial of the
    cell's degree is reproduced exactly (to rounding), and the position is the affine map of the
    corners at (u, v) (corner 1 at u = 1, corner 2 at v = 1)."""
    polys = {1: lambda x, y, z: 0.3 + 1.7 * x - 0.9 * y,
             2: lambda x, y, z: 0.3 + 1.7 * x - 0.9 * y + 2.1 * x * x - 1.3 * x * y + 0.7 * y * y,
             3: lambda x, y, z: (0.3 + 1.7 * x - 0.9 * y + 2.1 * x * x - 1.3 * x * y
                                 + 0.7 * y * y + 1.9 * x ** 3 - 2.3 * x * x * y
                                 + 0.6 * x * y * y - 1.1 * y ** 3)}
    for d, cell_type in [(1, VTK_LAGRANGE_TRIANGLE), (2, VTK_QUADRATIC_TRIANGLE),
                         (2, VTK_LAGRANGE_TRIANGLE), (3, VTK_LAGRANGE_TRIANGLE)]:
        points, cells = square(3, d)
        f = polys[d]
        vtu = os.path.join(tmp, f"order{d}_{cell_type}.vtu")
        write_vtu(vtu, points, cells, np.array([f(*p) for p in points]), cell_type)
        uv = [(int(RNG.integers(len(cells))), float(a), float(b))
              for a, b in RNG.random((40, 2)) if a + b <= 1]
        rows = np.array(evaluate(vtu, uv))
        corners = points[cells[[c for c, _, _ in uv], :3]]
        u = np.array([a for _, a, _ in uv])[:, None]
        v = np.array([b for _, _, b in uv])[:, None]
        affine = (1 - u - v) * corners[:, 0] + u * corners[:, 1] + v * corners[:, 2]
        pos = float(np.abs(rows[:, :3] - affine).max())
        val = max(abs(r[3] - f(*r[:3])) for r in rows)
        # A wrong order (here: the nodes of edges 0-1 and 1-2 swapped) is refused (gaps between
        # cells, folded cells) or does not reproduce the polynomial.
        wrong_note = "-"
        if d > 1:
            e = d - 1
            wrong = cells.copy()
            wrong[:, 3:3 + e], wrong[:, 3 + e:3 + 2 * e] = cells[:, 3 + e:3 + 2 * e], cells[:, 3:3 + e]
            bad_vtu = os.path.join(tmp, f"wrong{d}_{cell_type}.vtu")
            write_vtu(bad_vtu, points, wrong, np.array([f(*p) for p in points]), cell_type)
            text = "".join(f"{c} {a!r} {b!r}\n" for c, a, b in uv)
            r = run("eval", bad_vtu, "--points", "-", stdin=text, check=False)
            if r.returncode != 0:
                wrong_note = "refused: " + r.stderr.split("\n")[1].strip()
                val_w = float("inf")
            else:
                rows_w = [list(map(float, line.split()[3:])) for line in r.stdout.split("\n")
                          if line.strip()]
                val_w = max(abs(q[3] - f(*q[:3])) for q in rows_w)
                wrong_note = f"polynomial off by {val_w:.2g}"
        else:
            val_w = float("inf")
        R.check(pos < 1e-12 and val < 1e-10 and val_w > 1e-3,
                f"node order, degree {d}, VTK type {cell_type}: position off by {pos:.3g}, value "
                f"off by {val:.3g} (wrong order: {val_w:.3g})")
        print(f"node order, degree {d}, VTK type {cell_type}: {len(uv)} points, position "
              f"{pos:.2g}, polynomial {val:.2g} (edges swapped: {wrong_note})", flush=True)


def on_annulus(r0, r1, cx=0.0):
    def residual(x, y, z):
        r = math.hypot(x - cx, y)
        return max(abs(z), r0 - r, r - r1, 0.0)
    return residual


def on_torus(R_, r_):
    return lambda x, y, z: math.hypot(math.hypot(x, y) - R_, z) - r_


def in_holed_disk(holes):
    def residual(x, y, z):
        out = max(abs(z), math.hypot(x, y) - 1, 0.0)
        for hx, hy, hr in holes:
            out = max(out, hr - math.hypot(x - hx, y - hy))
        return out
    return residual


with tempdir() as tmp:
    start = time.time()
    node_order(tmp)

    for d in (1, 3):
        case(tmp, f"annulus, x + 0.3 y, degree {d}", annulus(6, 48 if d == 1 else 24, d), tilted,
             loops=1, level=2, surface=on_annulus(0.5, 1.0), tol=2e-2 if d == 1 else 1e-4)
    case(tmp, "annulus, near-radial, degree 2", annulus(4, 32, 2), radial, loops=0,
         surface=on_annulus(0.5, 1.0), tol=1e-3)

    case(tmp, "torus, x + 0.1 z + 0.05 y, degree 2", torus(32, 12, 2), torus_f1, loops=1,
         surface=on_torus(2.0, 0.7), tol=2e-3)
    case(tmp, "torus, z + 0.3 x + 0.05 y, degree 3", torus(24, 10, 3), torus_f2, loops=1,
         surface=on_torus(2.0, 0.7), tol=1e-3)
    case(tmp, "torus, wavy, degree 3", torus(24, 10, 3), wavy_torus, loops=1,
         surface=on_torus(2.0, 0.7), tol=1e-3)
    case(tmp, "annulus, wavy, degree 2", annulus(6, 48, 2), wavy_planar, loops=None, max_loops=1,
         surface=on_annulus(0.5, 1.0), tol=1e-2)
    case(tmp, "Moebius strip n=96, degree 1", moebius(96, 2, 1), moebius_f, loops=None,
         max_loops=1, level=1, tol=0.15)
    case(tmp, "Moebius strip n=96, degree 2", moebius(96, 2, 2), moebius_f, loops=None,
         max_loops=1, tol=1e-2, cell_type=VTK_LAGRANGE_TRIANGLE)

    # hoct's own plate with 10 x 10 square holes (hoct generate plate): a loop round every hole.
    plate = os.path.join(tmp, "plate.vtu")
    run("generate", "plate", "--cells", "3000", "--degree", "2", "-o", plate)
    info = level_sets.check(R, "plate, 100 holes, degree 2", plate, 2)
    R.check(info["tree"]["kind"] == "Reeb graph" and info["tree"]["loops"] == 100,
            f"plate: {info['tree']['loops']} loops, expected 100")
    r = run("check", info["json"], plate, check=False)
    R.check(r.returncode == 0, f"plate: hoct check {r.stdout[-300:]}")
    d4, d16 = converges("plate", plate, info["json"], info["tree"])
    check_svg("plate", plate, info["tree"])
    print(f"plate: PL --refine 4, 16 at bottleneck {d4:.2g}, {d16:.2g}", flush=True)

    if not HAVE_GMSH:
        print("the Gmsh cases are skipped: python3-gmsh is missing")
    else:
        for h, d in [(1, 2), (2, 3), (3, 1), (5, 2)]:
            case(tmp, f"disk with {h} hole(s), degree {d}", gmsh_mesh(disk_with_holes(HOLES[h]), d,
                                                                       0.12, True),
                 planar, loops=h, level=1 if d == 1 else 2, surface=in_holed_disk(HOLES[h]),
                 tol=2e-2 if d == 1 else 1e-3,
                 cell_type=VTK_LAGRANGE_TRIANGLE if h == 5 else None)
        case(tmp, "disk with 3 holes, wavy, degree 3", gmsh_mesh(disk_with_holes(HOLES[3]), 3,
                                                                 0.12, True),
             wavy_planar, loops=None, max_loops=3, surface=in_holed_disk(HOLES[3]), tol=1e-2)
        case(tmp, "disk and annulus, x + 0.3 y, degree 3",
             gmsh_mesh(disk_and_annulus, 3, 0.15, True), tilted, loops=1, components=2,
             surface=lambda x, y, z: min(on_annulus(0, 1)(x, y, z),
                                         on_annulus(0.5, 1, 3.0)(x, y, z)), tol=1e-3)
        case(tmp, "torus (Gmsh), x + 0.1 z + 0.05 y, degree 2", gmsh_mesh(torus_solid, 2, 0.4, False),
             torus_f1, loops=1, surface=on_torus(2.0, 0.7), tol=5e-3)
        case(tmp, "drilled box (genus 1), x + 0.2 y + 0.1 z, degree 2",
             gmsh_mesh(drilled_box, 2, 0.3, False), surface_f, loops=1, tol=1e-3)
        case(tmp, "double torus (genus 2), x + 0.2 y + 0.1 z, degree 2",
             gmsh_mesh(double_torus, 2, 0.2, False), surface_f, loops=2, tol=5e-3)
        case(tmp, "double torus (genus 2), wavy, degree 3", gmsh_mesh(double_torus, 3, 0.2, False),
             wavy_surface, loops=2, tol=5e-3)
    print(f"total {time.time() - start:.1f} s")
R.finish()
