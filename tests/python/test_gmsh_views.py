"""Gmsh views other than one $NodeData step, written by Gmsh itself (python3-gmsh), read by the
hoct CLI (HOCT_BIN) and checked against the $NodeData route on the same mesh and field:
 - $ElementNodeData (what GetDP and many solvers write), MSH 4.1 and 2.2, ascii and binary: the
   same contour tree (`hoct tree --json --no-timings`: node count, types and values) as the
   $NodeData file; a discontinuous one is refused with the jump;
 - MSH 2.2 binary: the same tree as MSH 2.2 ascii;
 - time steps: --step (from 0, negative from the end), --time, and the errors out of range;
   `hoct info --json` lists the views with their steps and times;
 - .pos files (parsed views): "ST" lists written by gmsh.view.write, and ST2 / ST3 written here
   in Gmsh's syntax and checked to parse in Gmsh (gmsh.open): the same tree as the .msh route.
"""
import json
import math
import os

import gmsh

from hoct_testing import Results, run, tempdir

R = Results()


def f(x, y):
    # A few extrema and saddles on the unit square.
    return math.sin(3.0 * x) * math.cos(2.5 * y) + 0.3 * x * y


def mesh(order, size=0.25):
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("sq")
    gmsh.model.occ.addRectangle(0, 0, 0, 1, 1)
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", size)
    gmsh.model.mesh.generate(2)
    gmsh.model.mesh.setOrder(order)


def triangles():
    types = gmsh.model.mesh.getElementTypes(2)
    etags, enodes = gmsh.model.mesh.getElementsByType(types[0])
    n = len(enodes) // len(etags)
    return [int(t) for t in etags], [[int(v) for v in enodes[n * k:n * k + n]]
                                      for k in range(len(etags))]


def xyz():
    tags, coords, _ = gmsh.model.mesh.getNodes()
    return {int(t): tuple(coords[3 * i:3 * i + 3]) for i, t in enumerate(tags)}


def write_msh(path, version, binary, kind, steps, name="f"):
    """steps: [(time, g(element, x, y))]."""
    gmsh.option.setNumber("Mesh.MshFileVersion", version)
    gmsh.option.setNumber("Mesh.Binary", binary)
    gmsh.write(path)
    at = xyz()
    etags, enodes = triangles()
    v = gmsh.view.add(name)
    for s, (time, g) in enumerate(steps):
        if kind == "NodeData":
            tags = list(at)
            data = [[g(0, *at[t][:2])] for t in tags]
        else:
            tags = etags
            data = [[g(e, *at[n][:2]) for n in nodes] for e, nodes in zip(etags, enodes)]
        gmsh.view.addModelData(v, s, "sq", kind, tags, data, time=time)
    gmsh.view.write(v, path, append=True)


def tree(path, *args):
    out = path + ".tree.json"
    r = run("tree", path, "--json", out, "--no-timings", *args, check=False)
    if r.returncode != 0:
        return None, r
    with open(out) as fp:
        return json.load(fp), r


def nodes_of(t):
    return sorted((n["type"], round(n["value"], 9)) for n in t["nodes"])


def same_tree(label, a, b):
    ta, ra = tree(*a) if isinstance(a, tuple) else tree(a)
    tb, rb = tree(*b) if isinstance(b, tuple) else tree(b)
    if ta is None or tb is None:
        R.check(False, f"{label}: {ra.stderr.strip()} {rb.stderr.strip()}")
        return
    R.check(len(ta["nodes"]) == len(tb["nodes"]) and len(ta["nodes"]) > 2
            and nodes_of(ta) == nodes_of(tb),
            f"{label}: {len(ta['nodes'])} vs {len(tb['nodes'])} nodes")


def fails(label, path, phrase, *args):
    r = run("tree", path, *args, check=False)
    R.check(r.returncode != 0 and phrase in r.stderr, f"{label}: {r.stderr.strip()}")


def continuous(e, x, y):
    return f(x, y)


def element_node_data(tmp, order):
    mesh(order)
    ref = os.path.join(tmp, f"nodes{order}.msh")
    write_msh(ref, 4.1, 1, "NodeData", [(0, continuous)])
    paths = {}
    for version, binary in [(4.1, 0), (4.1, 1), (2.2, 0), (2.2, 1)]:
        p = os.path.join(tmp, f"elem{order}_{version}_{binary}.msh")
        write_msh(p, version, binary, "ElementNodeData", [(0, continuous)])
        paths[(version, binary)] = p
    bad = os.path.join(tmp, f"jump{order}.msh")
    write_msh(bad, 4.1, 0, "ElementNodeData",
              [(0, lambda e, x, y: f(x, y) + (0.01 if e % 2 else 0.0))])
    nodes22 = {}
    for binary in (0, 1):
        nodes22[binary] = os.path.join(tmp, f"nodes{order}_22_{binary}.msh")
        write_msh(nodes22[binary], 2.2, binary, "NodeData", [(0, continuous)])
    gmsh.finalize()
    for (version, binary), p in paths.items():
        same_tree(f"order {order}: $ElementNodeData msh {version} binary={binary} vs $NodeData",
                  p, ref)
    same_tree(f"order {order}: msh 2.2 binary vs ascii", nodes22[1], nodes22[0])
    fails(f"order {order}: discontinuous $ElementNodeData", bad,
          "the field is discontinuous there (largest jump 0.01")


def interpolation_scheme(tmp):
    """A view with interpolation matrices (its values are coefficients of the scheme's basis):
    refused, naming the scheme, though its values would pass as continuous node values; the same
    values without a scheme are read."""
    mesh(1)
    plain = os.path.join(tmp, "plain.msh")
    write_msh(plain, 4.1, 0, "ElementNodeData", [(0, continuous)])
    schemed = os.path.join(tmp, "scheme.msh")
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.option.setNumber("Mesh.Binary", 0)
    gmsh.write(schemed)
    at = xyz()
    etags, enodes = triangles()
    v = gmsh.view.add("f")
    gmsh.view.addModelData(v, 0, "sq", "ElementNodeData", etags,
                           [[continuous(e, *at[n][:2]) for n in nodes]
                            for e, nodes in zip(etags, enodes)])
    # P1 in the monomial basis 1, u, v: coefficients from the values at the corners.
    gmsh.view.setInterpolationMatrices(v, "Triangle", 3, [1, 0, 0, -1, 1, 0, -1, 0, 1],
                                       [0, 0, 0, 1, 0, 0, 0, 1, 0])
    gmsh.view.write(v, schemed, append=True)
    gmsh.finalize()
    t, r = tree(plain)
    R.check(t is not None and len(t["nodes"]) > 2, f"no scheme: {r.stderr.strip()}")
    fails("interpolation scheme", schemed, "names the interpolation scheme")


def time_steps(tmp):
    mesh(2)
    path = os.path.join(tmp, "steps.msh")
    write_msh(path, 4.1, 0, "NodeData",
              [(0.5 * s, (lambda s: lambda e, x, y: f(x, y) + s * x)(s)) for s in range(3)])
    single = {}
    for s in range(3):
        single[s] = os.path.join(tmp, f"step{s}.msh")
        write_msh(single[s], 4.1, 0, "NodeData", [(0, (lambda s: lambda e, x, y: f(x, y) + s * x)(s))])
    gmsh.finalize()
    same_tree("default: the last step", path, single[2])
    same_tree("--step 0", (path, "--step", "0"), single[0])
    same_tree("--step -2", (path, "--step", "-2"), single[1])
    same_tree("--time 0.5", (path, "--time", "0.5"), single[1])
    same_tree("--time 1", (path, "--time", "1"), single[2])
    fails("--step 3", path,
          "--step 3: $NodeData 'f' has 3 time steps (times 0, 0.5, 1): steps 0 to 2", "--step", "3")
    fails("--time 0.7", path, "--time 0.7: $NodeData 'f' has no time step at that time",
          "--time", "0.7")
    r = run("tree", path, "--step", "1")
    R.check("field 'f' (step 1 of 3, time 0.5)" in r.stdout, f"summary: {r.stdout[:200]}")
    j = json.loads(run("info", path, "--json").stdout)
    R.check(j.get("views") == [{"name": "f", "kind": "node data", "components": 1,
                                "steps": [{"tag": s, "time": 0.5 * s} for s in range(3)]}]
            and j.get("field_detail") == "(step 2 of 3, time 1)", f"info --json: {j.get('views')}")


def pos_text(name, order, steps):
    """The triangles of the current mesh as a parsed .pos view: ST / ST2 / ST3 in Gmsh's node
    order, values of each step in turn, and TIME."""
    at = xyz()
    _, enodes = triangles()
    kind = {1: "ST", 2: "ST2", 3: "ST3"}[order]
    lines = [f'View "{name}" {{']
    lines.append("TIME{" + ",".join(repr(t) for t, _ in steps) + "};")
    for nodes in enodes:
        coords = ",".join(repr(c) for n in nodes for c in at[n])
        values = ",".join(repr(g(0, *at[n][:2])) for _, g in steps for n in nodes)
        lines.append(f"{kind}({coords}){{{values}}};")
    lines.append("};")
    return "\n".join(lines) + "\n"


def pos_files(tmp):
    # P1: written by Gmsh (gmsh.view.addListData "ST", gmsh.view.write to .pos).
    mesh(1)
    ref = os.path.join(tmp, "p1.msh")
    write_msh(ref, 4.1, 0, "NodeData", [(0, continuous)])
    at = xyz()
    _, enodes = triangles()
    data = []
    for nodes in enodes:
        for k in range(3):
            data += [at[n][k] for n in nodes]
        data += [f(*at[n][:2]) for n in nodes]
    v = gmsh.view.add("f")
    gmsh.view.addListData(v, "ST", len(enodes), data)
    p1 = os.path.join(tmp, "p1.pos")
    gmsh.view.write(v, p1)
    gmsh.finalize()
    same_tree(".pos ST written by Gmsh vs .msh", p1, ref)
    for order in (2, 3):
        mesh(order)
        ref = os.path.join(tmp, f"p{order}.msh")
        write_msh(ref, 4.1, 0, "NodeData", [(0, continuous)])
        steps = [(0.0, lambda e, x, y: f(x, y) - 1), (0.25, continuous)]
        text = pos_text("u", order, steps)
        path = os.path.join(tmp, f"p{order}.pos")
        with open(path, "w") as out:
            out.write(text)
        gmsh.finalize()
        # Gmsh reads the file as a view of as many triangles, two time steps.
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(path)
        tags = gmsh.view.getTags()
        types, counts, _ = gmsh.view.getListData(tags[0])
        gmsh.finalize()
        R.check(list(types) == ["ST"] and counts[0] == len(enodes_of(ref)),
                f".pos ST{order}: Gmsh reads {list(types)} {list(counts)}")
        same_tree(f".pos ST{order} (last step) vs .msh", path, ref)
        same_tree(f".pos ST{order} --time 0.25 vs .msh", (path, "--time", "0.25"), ref)
        # A jump between two triangles: the first value of the first triangle, 0.5 higher.
        first = text.index("ST")
        head, rest = text[:first], text[first:]
        brace = rest.index("){") + 2
        comma = rest.index(",", brace)
        bad = head + rest[:brace] + repr(float(rest[brace:comma]) + 0.5) + rest[comma:]
        badpath = os.path.join(tmp, f"jump{order}.pos")
        with open(badpath, "w") as out:
            out.write(bad)
        fails(f".pos ST{order} discontinuous", badpath, "the field is discontinuous there",
              "--step", "0")
    vec = os.path.join(tmp, "vectors.pos")
    with open(vec, "w") as out:
        out.write('View "v" {\nVT(0,0,0,1,0,0,0,1,0){1,0,0,1,0,0,1,0,0};\n};\n')
    fails(".pos vectors", vec, "VT (vector triangle) is not read")


def enodes_of(path):
    j = json.loads(run("info", path, "--json").stdout)
    return range(j["cells"])


with tempdir() as tmp:
    for order in (2, 3):
        element_node_data(tmp, order)
    time_steps(tmp)
    interpolation_scheme(tmp)
    pos_files(tmp)

R.finish()
