"""The command-line tool as a user meets it: the main job end to end (generate, info, tree with
JSON and VTP that VTK reads, compare), clear errors with a non-zero exit for bad input, and no
half-written or clobbered output when a run fails."""
import json
import os

import vtk

from hoct_testing import Results, run, tempdir

R = Results()

with tempdir() as tmp:
    p = lambda name: os.path.join(tmp, name)
    run("generate", "gauss", "-o", p("g.vtu"))
    info = json.loads(run("info", p("g.vtu"), "--json").stdout)
    R.check(info["valid"] and info["domain"] == "disk", f"info: {info['domain']}")

    # The exact tree, written as JSON and VTP.
    out = run("tree", p("g.vtu"), "--json", p("t.json"), "--vtp", p("t.vtp")).stdout
    R.check("exact tree" in out and "nodes:" in out, f"summary: {out[:200]}")
    t = json.load(open(p("t.json")))
    R.check(t["format"] == "hoct-contour-tree" and len(t["arcs"]) == len(t["nodes"]) - 1,
            "tree json: a tree")
    degree = {}
    for a, b in t["arcs"]:
        degree[a] = degree.get(a, 0) + 1
        degree[b] = degree.get(b, 0) + 1
    R.check(sum(d - 2 for d in degree.values()) == -2, "sum of (degree - 2) is -2")
    R.check(all(n["type"] in ("minimum", "maximum", "saddle") for n in t["nodes"]), "no regular nodes")
    R.check(all(n["location"] in ("vertex", "edge", "interior") for n in t["nodes"]), "locations")
    # One record per line: each node, arc, pair and branch on a line of its own.
    text = open(p("t.json")).read().splitlines()
    R.check(sum(line.startswith('  {"id":') for line in text) == len(t["nodes"]) + len(t["branches"])
            and sum(line.startswith("  [") for line in text) == len(t["arcs"]),
            "tree json: one record per line")
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(p("t.vtp"))
    reader.Update()
    poly = reader.GetOutput()
    R.check(poly.GetNumberOfVerts() == len(t["nodes"]) and poly.GetNumberOfLines() == len(t["arcs"]),
            f"vtp: {poly.GetNumberOfVerts()} vertices, {poly.GetNumberOfLines()} lines")
    values = poly.GetPointData().GetArray("value")
    R.check(values is not None and abs(values.GetValue(0) - t["nodes"][0]["value"]) < 1e-15, "vtp values")
    R.check(poly.GetPointData().GetArray("type") is not None and
            poly.GetPointData().GetArray("persistence") is not None, "vtp arrays")
    lines = poly.GetLines()
    lines.InitTraversal()
    ids = vtk.vtkIdList()
    sizes = []
    while lines.GetNextCell(ids):
        sizes.append(ids.GetNumberOfIds())
    R.check(max(sizes) > 2, f"vtp: arcs drawn through the surface (longest {max(sizes)} points)")

    # The augmented tree: its arcs join consecutive nodes of a contour-tree arc, anywhere on its
    # band, and are drawn straight (two points each).
    run("tree", p("g.vtu"), "--augmented", "--json", p("a.json"), "--vtp", p("a.vtp"))
    a = json.load(open(p("a.json")))
    R.check(any(n["type"] == "regular" for n in a["nodes"]), "augmented: regular nodes")
    reader.SetFileName(p("a.vtp"))
    reader.Update()
    poly = reader.GetOutput()
    lines = poly.GetLines()
    lines.InitTraversal()
    sizes = []
    while lines.GetNextCell(ids):
        sizes.append(ids.GetNumberOfIds())
    R.check(len(sizes) == len(a["arcs"]) and set(sizes) == {2},
            f"augmented vtp: {len(sizes)} straight lines for {len(a['arcs'])} arcs ({set(sizes)})")

    # Simplification, branches and the SVG picture.
    out = run("tree", p("g.vtu"), "--simplify", "1%", "--branches", "--json", p("s.json"),
              "--svg", p("s.svg")).stdout
    s = json.load(open(p("s.json")))
    pers = sorted(pr["persistence"] for pr in t["pairs"])
    rng_ = t["nodes"][-1]["value"] - t["nodes"][0]["value"]
    kept = [x for x in pers if x >= 0.01 * rng_]
    R.check(len(s["pairs"]) == len(kept), f"simplified pairs {len(s['pairs'])} vs {len(kept)}")
    R.check(len(s["branches"]) == len(s["pairs"]) and s["branches"][0]["parent"] == -1,
            "branches: one per pair, root first")
    R.check(s["stats"]["nodes_before_simplification"] == len(t["nodes"]), "nodes before simplification")
    R.check(out.count("persistence") >= len(s["branches"]), "--branches lists every branch")
    import xml.etree.ElementTree as ET
    svg = ET.parse(p("s.svg")).getroot()
    circles = svg.findall(".//{http://www.w3.org/2000/svg}circle")
    R.check(len(circles) == len(s["nodes"]) + 3, f"svg: {len(circles)} circles for {len(s['nodes'])} nodes")
    bad = run("tree", p("g.vtu"), "--simplify", "lots", check=False)
    R.check(bad.returncode == 1 and "is not a threshold" in bad.stderr, bad.stderr.strip())

    # A Reeb graph's loops below the threshold removed on request (the plate's 100 holes).
    run("generate", "plate", "-o", p("plate.vtu"))
    run("tree", p("plate.vtu"), "--json", p("plate.json"))
    whole = json.load(open(p("plate.json")))
    loops = sorted(pr["persistence"] for pr in whole["pairs"] if pr["kind"] == "loop")
    R.check(len(loops) == whole["loops"] > 2, f"plate: {len(loops)} loop pairs, {whole['loops']} loops")
    cut = loops[len(loops) // 2]  # about half stay
    run("tree", p("plate.vtu"), "--simplify", repr(cut), "--simplify-loops", "--json", p("pl.json"))
    run("tree", p("plate.vtu"), "--simplify", repr(cut), "--json", p("pk.json"))
    pl, pk = json.load(open(p("pl.json"))), json.load(open(p("pk.json")))
    left = [x for x in loops if x >= cut]
    R.check(pl["loops"] == len(left) and pl["stats"]["loops_removed"] == len(loops) - len(left),
            f"--simplify-loops: {pl['loops']} loops left of {len(loops)}, {len(left)} at or above {cut}")
    R.check(pk["loops"] == len(loops) and "loops_removed" not in pk["stats"],
            f"--simplify alone keeps the loops: {pk['loops']}")
    R.check(all(pr["persistence"] >= cut for pr in pl["pairs"] if pr["kind"] == "loop"),
            "loop pairs left are at or above the threshold")
    bad = run("tree", p("plate.vtu"), "--simplify-loops", check=False)
    R.check(bad.returncode == 1 and "needs --simplify" in bad.stderr, bad.stderr.strip())

    # Pictures of the field: PNG of the right size, not blank, with the glyph colours in it.
    for name in ("gauss", "sphere", "two-triangle"):
        run("generate", name, "-o", p(name + ".vtu"))
        run("render", p(name + ".vtu"), "-o", p(name + ".png"), "--size", "600x500")
        png = vtk.vtkPNGReader()
        png.SetFileName(p(name + ".png"))
        png.Update()
        img = png.GetOutput()
        dims = img.GetDimensions()
        R.check(dims[0] == 600 and dims[1] == 500, f"render {name}: size {dims}")
        from vtk.util.numpy_support import vtk_to_numpy
        pix = vtk_to_numpy(img.GetPointData().GetScalars())
        colours = {tuple(x) for x in pix[::7]}
        R.check(len(colours) > 200, f"render {name}: only {len(colours)} colours")
        red = ((pix[:, 0] > 200) & (pix[:, 1] < 60) & (pix[:, 2] < 60)).sum()
        R.check(red > 10, f"render {name}: no maximum glyphs drawn")
    r = run("render", p("g.vtu"), "-o", p("g.jpg"), check=False)
    R.check(r.returncode == 1 and "must be .png or .svg" in r.stderr, r.stderr.strip())

    # The case study: table, CSV, JSON and chart.
    out = run("study", p("sphere.vtu"), "--refine", "1,4,16", "--csv", p("st.csv"),
              "--json", p("st.json"), "--svg", p("st.svg"), "--threshold", "0.5%").stdout
    st = json.load(open(p("st.json")))
    rows = st["rows"]
    R.check([r["k"] for r in rows] == [0, 1, 4, 16], f"study rows {[r['k'] for r in rows]}")
    R.check(rows[0]["method"] == "exact" and rows[0]["bottleneck"] == 0, "exact row")
    R.check(rows[1]["bottleneck"] > rows[2]["bottleneck"] > rows[3]["bottleneck"] > 0,
            f"study: PL error does not shrink: {[r['bottleneck'] for r in rows]}")
    R.check(rows[3]["triangles"] == 256 * rows[0]["triangles"], "k=16 has 256x the triangles")
    csv_lines = open(p("st.csv")).read().strip().split("\n")
    R.check(len(csv_lines) == 5 and csv_lines[0].startswith("method,k,triangles"), "study csv")
    ET.parse(p("st.svg"))
    R.check("PL k=16" in out, "study table printed")

    # Arcs drawn on the surface: polylines from node to node, on the sphere.
    for args in ([], ["--refine", "4"]):
        run("tree", p("sphere.vtu"), "--vtp", p("arcs.vtp"), "--json", p("arcs.json"), "-q", *args)
        tj = json.load(open(p("arcs.json")))
        rd = vtk.vtkXMLPolyDataReader()
        rd.SetFileName(p("arcs.vtp"))
        rd.Update()
        pd = rd.GetOutput()
        R.check(pd.GetNumberOfLines() == len(tj["arcs"]), f"arcs {pd.GetNumberOfLines()} {args}")
        lines = pd.GetLines()
        lines.InitTraversal()
        ids = vtk.vtkIdList()
        ok_ends, curved, on_sphere, k = True, 0, True, 0
        while lines.GetNextCell(ids):
            a, b = tj["arcs"][k]
            first = pd.GetPoint(ids.GetId(0))
            last = pd.GetPoint(ids.GetId(ids.GetNumberOfIds() - 1))
            ok_ends = ok_ends and max(abs(first[i] - tj["nodes"][a]["position"][i]) for i in range(3)) < 1e-12
            ok_ends = ok_ends and max(abs(last[i] - tj["nodes"][b]["position"][i]) for i in range(3)) < 1e-12
            curved += ids.GetNumberOfIds() > 2
            for j in range(ids.GetNumberOfIds()):
                q = pd.GetPoint(ids.GetId(j))
                on_sphere = on_sphere and abs((q[0] ** 2 + q[1] ** 2 + q[2] ** 2) ** 0.5 - 1) < 1e-3
            k += 1
        R.check(ok_ends, f"arc polylines start and end at their nodes {args}")
        R.check(curved > len(tj["arcs"]) // 2, f"only {curved} of {len(tj['arcs'])} arcs are polylines {args}")
        R.check(on_sphere, f"arc polylines leave the surface {args}")
        R.check(pd.GetPointData().GetArray("value") is not None, "vtp value array")

    # PL trees and the comparison.
    run("tree", p("g.vtu"), "--refine", "8", "--json", p("pl.json"), "-q")
    run("tree", p("g.vtu"), "--linear", "--json", p("lin.json"), "-q")
    cmp = json.loads(run("compare", p("t.json"), p("pl.json"), "--json").stdout)
    R.check(cmp["bottleneck"]["max"] < 0.01, f"exact vs refine 8: {cmp['bottleneck']}")
    aug = json.loads(open(p("pl.json")).read())
    R.check(aug["method"] == "refine k=8", "method recorded")

    # Plateaus: by default each flat region is one node (no zero-persistence pairs).
    run("generate", "conductor", "-o", p("c.vtu"), "--cells", "1500")
    run("tree", p("c.vtu"), "--json", p("c.json"), "-q")
    run("tree", p("c.vtu"), "--json", p("cf.json"), "-q", "--keep-flat")
    c, cf = json.load(open(p("c.json"))), json.load(open(p("cf.json")))
    R.check(all(pr["persistence"] > 0 for pr in c["pairs"]), "zero-persistence pairs left")
    R.check(any(pr["persistence"] == 0 for pr in cf["pairs"]), "--keep-flat: plateau pairs expected")
    R.check(len(c["nodes"]) < len(cf["nodes"]) and c["stats"]["flat_nodes_merged"] > 0, "flat merge")

    # Errors: a clear message naming the file, exit status 1, nothing written.
    for args, phrase in [
        (["info", p("missing.vtu")], "missing.vtu: cannot open"),
        (["tree", p("g.vtu"), "--linear", "--refine", "2"], "exclude each other"),
        (["generate", "nope", "-o", p("x.vtu")], "unknown dataset 'nope'"),
        (["tree", p("g.vtu"), "--json", os.path.join(tmp, "no", "dir", "t.json")], "cannot open for writing"),
        (["compare", p("g.vtu"), p("t.json")], "not valid JSON"),
        (["eval", p("g.vtu"), "--points", "-"], "out of range"),
    ]:
        r = run(*args, check=False, stdin="99999 0.1 0.1\n")
        R.check(r.returncode == 1 and phrase in r.stderr, f"{args[0]}: {r.returncode} {r.stderr.strip()}")
    r = run("info", p("nothing.txt"), check=False)
    R.check(r.returncode == 1 and "unknown file type" in r.stderr, r.stderr)

    # A broken input leaves an existing output untouched and no temporary files behind.
    with open(p("keep.json"), "w") as f:
        f.write("precious")
    with open(p("broken.vtu"), "w") as f:
        f.write(open(p("g.vtu"), "rb").read()[:5000].decode("latin-1"))
    r = run("tree", p("broken.vtu"), "--json", p("keep.json"), check=False)
    R.check(r.returncode == 1 and "broken.vtu" in r.stderr, r.stderr.strip())
    R.check(open(p("keep.json")).read() == "precious", "output clobbered")
    R.check(not [f for f in os.listdir(tmp) if ".tmp-" in f], "temporary files left")

    # An annulus is not simply connected: its level-set graph is a Reeb graph with a loop.
    import numpy as np
    import meshio
    pts, cells = [], []
    n = 12
    for i in range(n):
        for r_ in (1.0, 2.0):
            a = 2 * np.pi * i / n
            pts.append((r_ * np.cos(a), r_ * np.sin(a), 0.0))
    for i in range(n):
        j = (i + 1) % n
        cells += [(2 * i, 2 * j, 2 * j + 1), (2 * i, 2 * j + 1, 2 * i + 1)]
    pts = np.array(pts)
    meshio.write(p("annulus.vtu"), meshio.Mesh(pts, [("triangle", np.array(cells))],
                                               point_data={"f": pts[:, 0]}))
    # Every method computes its Reeb graph (one loop around the hole), without --force.
    r = run("tree", p("annulus.vtu"), check=False)
    R.check(r.returncode == 0 and "exact Reeb graph (1 loop)" in r.stdout, r.stdout + r.stderr)
    r = run("tree", p("annulus.vtu"), "--linear", check=False)
    R.check(r.returncode == 0 and "linear Reeb graph (1 loop)" in r.stdout, r.stdout + r.stderr)
    info = json.loads(run("info", p("annulus.vtu"), "--json").stdout)
    R.check(info["euler_characteristic"] == 0 and info["boundary_loops"] == 2, "annulus topology")

R.finish()
