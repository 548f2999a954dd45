"""A tree JSON records the input it was computed from ("input": points, cells, field and a
fingerprint of the data, issue 27 item 13), and the commands that read a tree with a mesh
(`render --tree`, `check`) refuse the tree of another mesh: exit 1, a message naming both,
nothing written. The same mesh in another encoding is the same input; a tree file of an
earlier version (no "input") is accepted with a warning that it cannot be checked."""
import json
import os

from hoct_testing import Results, run, tempdir

R = Results()

with tempdir() as tmp:
    p = lambda name: os.path.join(tmp, name)
    # Two fields of the same sizes (the random dataset's mesh is the same for every seed).
    run("generate", "random", "--cells", "2000", "-o", p("a.vtu"))
    run("generate", "random", "--cells", "2000", "--seed", "2", "-o", p("b.vtu"))
    for enc in ("ascii", "zlib", "base64"):
        run("generate", "random", "--cells", "2000", "--encoding", enc, "-o", p(f"a-{enc}.vtu"))
    run("tree", p("a.vtu"), "-q", "--no-timings", "--json", p("a.json"))
    run("tree", p("b.vtu"), "-q", "--no-timings", "--json", p("b.json"))
    a, b = json.load(open(p("a.json"))), json.load(open(p("b.json")))
    R.check(list(a)[:5] == ["format", "version", "method", "augmented", "input"],
            f"'input' after the header: {list(a)[:6]}")
    ia, ib = a["input"], b["input"]
    R.check(set(ia) == {"points", "cells", "field", "fingerprint"}, f"input keys: {ia}")
    R.check(ia["points"] == ib["points"] and ia["cells"] == ib["cells"] and ia["field"] == "f",
            f"the same sizes: {ia} {ib}")
    R.check(len(ia["fingerprint"]) == 16 and int(ia["fingerprint"], 16) >= 0
            and ia["fingerprint"] != ib["fingerprint"], f"fingerprints: {ia} {ib}")

    # The same mesh in other encodings: the same input, so the same bytes (--no-timings), on any
    # number of threads.
    for enc in ("ascii", "zlib", "base64"):
        for threads in ("1", "2"):
            run("tree", p(f"a-{enc}.vtu"), "-q", "--no-timings", "--threads", threads,
                "--json", p("enc.json"))
            R.check(open(p("enc.json")).read() == open(p("a.json")).read(),
                    f"{enc}, {threads} thread(s): the same tree JSON, byte for byte")
    run("convert", p("a-ascii.vtu"), "-o", p("converted.vtu"))

    # render --tree with its own tree, or the same mesh in another file: drawn.
    for mesh in ("a.vtu", "a-ascii.vtu", "a-zlib.vtu", "converted.vtu"):
        out = p("own.png")
        if os.path.exists(out):
            os.remove(out)
        r = run("render", p(mesh), "--tree", p("a.json"), "-o", out, check=False)
        R.check(r.returncode == 0 and os.path.getsize(out) > 0 and "warning" not in r.stderr,
                f"render {mesh} --tree a.json: exit {r.returncode}, {r.stderr.strip()}")

    # The tree of another mesh of the same sizes: refused, nothing written, an existing picture
    # kept.
    r = run("render", p("b.vtu"), "--tree", p("a.json"), "-o", p("new.png"), check=False)
    R.check(r.returncode == 1 and not os.path.exists(p("new.png")),
            f"render b.vtu --tree a.json: exit {r.returncode}, new.png written: "
            f"{os.path.exists(p('new.png'))}")
    expect = (f"{p('a.json')} is the tree of a mesh with 9,409 points and 2,048 cells, field 'f' "
              f"(fingerprint {ia['fingerprint']}), but {p('b.vtu')} has 9,409 points and 2,048 "
              f"cells, field 'f' (fingerprint {ib['fingerprint']}) (the same sizes, but other "
              f"coordinates, connectivity or values): compute its tree with hoct tree "
              f"{p('b.vtu')} --json ...")
    R.check(expect in r.stderr, f"the message names both:\n{r.stderr}")
    open(p("old.png"), "wb").write(b"precious")
    r = run("render", p("b.vtu"), "--tree", p("a.json"), "-o", p("old.png"), check=False)
    R.check(r.returncode == 1 and open(p("old.png"), "rb").read() == b"precious",
            "an existing picture is left as it was")
    # Other sizes: the tree of another dataset.
    run("generate", "gauss", "-o", p("gauss.vtu"))
    r = run("render", p("gauss.vtu"), "--tree", p("a.json"), "-o", p("g.png"), check=False)
    R.check(r.returncode == 1 and "9,409 points and 2,048 cells" in r.stderr
            and "the same sizes" not in r.stderr and not os.path.exists(p("g.png")),
            f"render gauss.vtu --tree a.json: {r.stderr.strip()}")
    # --no-critical-points reads no tree.
    r = run("render", p("b.vtu"), "--tree", p("a.json"), "--no-critical-points",
            "-o", p("plain.png"), check=False)
    R.check(r.returncode == 0, f"--no-critical-points: {r.stderr.strip()}")

    # hoct check: the same refusal; its own tree (in any encoding) still passes.
    r = run("check", p("a.json"), p("b.vtu"), check=False)
    R.check(r.returncode == 1 and "is the tree of a mesh with" in r.stderr
            and "--scalar and --merge-duplicates" in r.stderr and r.stdout == "",
            f"check a.json b.vtu: exit {r.returncode}\n{r.stdout}{r.stderr}")
    r = run("check", p("a.json"), p("a-ascii.vtu"), check=False)
    R.check(r.returncode == 0 and "OK" in r.stdout, f"check a.json a-ascii.vtu: {r.stderr}")

    # A file of an earlier version (no "input"): accepted, with a warning.
    old = dict(a)
    del old["input"]
    json.dump(old, open(p("old.json"), "w"))
    r = run("render", p("a.vtu"), "--tree", p("old.json"), "-o", p("old-tree.png"), check=False)
    warning = (f"hoct: warning: {p('old.json')} records no input fingerprint (written by an "
               f"earlier hoct): cannot check that it is the tree of {p('a.vtu')}")
    R.check(r.returncode == 0 and warning in r.stderr and os.path.exists(p("old-tree.png")),
            f"render with an old tree: exit {r.returncode}, {r.stderr.strip()}")
    r = run("check", p("old.json"), p("a.vtu"), check=False)
    R.check(r.returncode == 0 and "OK" in r.stdout and "records no input fingerprint" in r.stderr,
            f"check with an old tree: exit {r.returncode}, {r.stderr.strip()}")

    # A malformed "input": a clear error.
    bad = dict(a, input=dict(ia, fingerprint="xyz"))
    json.dump(bad, open(p("bad.json"), "w"))
    r = run("render", p("a.vtu"), "--tree", p("bad.json"), "-o", p("bad.png"), check=False)
    R.check(r.returncode == 1 and "\"fingerprint\" must be 16 hexadecimal digits" in r.stderr
            and not os.path.exists(p("bad.png")), f"bad fingerprint: {r.stderr.strip()}")

R.finish()
