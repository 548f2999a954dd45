"""`hoct check TREE.json INPUT` (issue 8, item 6): passes on the exact tree of every generated
dataset (reduced, augmented and simplified), fails with the findings and exit 1 on each kind of
corrupted tree, and refuses malformed tree files, and the tree of another mesh, with a clear
message."""
import copy
import json
import os

from hoct_testing import Results, run, tempdir

R = Results()

with tempdir() as tmp:
    p = lambda name: os.path.join(tmp, name)
    names = [line.split()[0] for line in run("generate", "--list").stdout.splitlines() if line.strip()]
    R.check(len(names) == 7, f"datasets: {names}")
    for name in names:
        extra = ["--cells", "2000"] if name == "random" else []
        run("generate", name, "-o", p(name + ".vtu"), *extra)
        for variant, args in (("", []), ("-aug", ["--augmented"]), ("-simp", ["--simplify", "1%"])):
            j = p(name + variant + ".json")
            run("tree", p(name + ".vtu"), "-q", "--json", j, *args)
            r = run("check", j, p(name + ".vtu"), check=False)
            R.check(r.returncode == 0 and "OK" in r.stdout,
                    f"check {name}{variant}: exit {r.returncode}\n{r.stdout[-600:]}{r.stderr}")

    # Corruptions of the gauss tree, each caught.
    t = json.load(open(p("gauss.json")))
    nodes = t["nodes"]
    saddle = next(i for i, n in enumerate(nodes) if n["type"] == "saddle")
    maximum = next(i for i, n in enumerate(nodes) if n["type"] == "maximum")

    def corrupt(label, change, expect):
        c = copy.deepcopy(t)
        change(c)
        path = p("bad-" + label + ".json")
        json.dump(c, open(path, "w"))
        r = run("check", path, p("gauss.vtu"), check=False)
        R.check(r.returncode == 1 and expect in r.stdout,
                f"{label}: exit {r.returncode}, '{expect}' in:\n{r.stdout[-600:]}")

    def swap_values(c):
        a, b = c["nodes"][1], c["nodes"][-2]
        a["value"], b["value"] = b["value"], a["value"]

    corrupt("swapped-values", swap_values, "FAIL [value]")
    corrupt("deleted-arc", lambda c: c["arcs"].pop(3), "FAIL [tree]")
    corrupt("extra-cycle", lambda c: c["arcs"].append([0, len(c["nodes"]) - 1]), "closes a cycle")
    corrupt("wrong-type", lambda c: c["nodes"][saddle].update(type="maximum"), "FAIL [degree]")

    def move(c):
        c["nodes"][maximum]["position"][0] += 0.01

    corrupt("moved-position", move, "FAIL [position]")

    def min_max_only(c):
        lo, hi = dict(c["nodes"][0], id=0), dict(c["nodes"][-1], id=1)
        c["nodes"], c["arcs"], c["branches"] = [lo, hi], [[0, 1]], []
        c["pairs"] = [{"birth": 0, "death": 1, "persistence": hi["value"] - lo["value"],
                       "kind": "global"}]

    # The global minimum and maximum alone: a valid tree, missing the field's other extrema.
    corrupt("min-max-only", min_max_only, "FAIL [completeness]")
    corrupt("wrong-persistence", lambda c: c["pairs"][0].update(persistence=123.0),
            "records persistence 123")

    def move_uv(c):
        n = c["nodes"][maximum]
        n["uv"] = [n["uv"][0] * 0.9 + 0.1 / 3, n["uv"][1] * 0.9 + 0.1 / 3]

    corrupt("moved-uv", move_uv, "FAIL [value]")

    # Malformed files: clear errors, exit 1.
    open(p("junk.json"), "w").write("{ not json")
    r = run("check", p("junk.json"), p("gauss.vtu"), check=False)
    R.check(r.returncode == 1 and "not valid JSON" in r.stderr, f"junk: {r.stderr.strip()}")
    c = copy.deepcopy(t)
    c["arcs"].append([0, 10 ** 6])
    json.dump(c, open(p("range.json"), "w"))
    r = run("check", p("range.json"), p("gauss.vtu"), check=False)
    R.check(r.returncode == 1 and "refers to node 1000000" in r.stderr, f"range: {r.stderr.strip()}")
    # A tree checked against the wrong input: refused by its recorded input fingerprint.
    r = run("check", p("gauss.json"), p("sphere.vtu"), check=False)
    R.check(r.returncode == 1 and "is the tree of a mesh with" in r.stderr,
            f"tree against the wrong mesh refused: {r.stderr.strip()}")
    # Without the fingerprint (a file of an earlier version), the findings show it.
    c = copy.deepcopy(t)
    del c["input"]
    json.dump(c, open(p("no-input.json"), "w"))
    r = run("check", p("no-input.json"), p("sphere.vtu"), check=False)
    R.check(r.returncode == 1 and "FAIL" in r.stdout and "records no input fingerprint" in r.stderr,
            "tree without fingerprint against the wrong mesh fails")

R.finish()
