"""`hoct.contour_tree(mesh, comm=...)` under mpi4py: the distributed exact tree from Python
(issue 31's Python entry point), the same library call as `mpirun -np N hoct tree`.

The independent truth is the command line's single-process tree, computed without MPI: on
generated genus-0 datasets (plateaus, quadrilaterals, a field at +1e7 with --simplify,
--augmented, the linear and the refine method on a plateau) and a plate with 100 holes (its Reeb graph) the JSON rank 0 writes
(`write_json(timings=False)`) must be byte-identical to `hoct tree --json --no-timings` for 1,
2 and 3 ranks (the command line's test takes 1, 2, 3, 4 and 7 through the same library call),
and the other ranks get None; with arc_paths=True rank 0's tree has every arc drawn on the
surface by the ranks' pieces (no jump longer than the command line's). The communicator is the one given: four ranks
split into two groups of two compute two different trees at once, each group's rank 0 matching
its own file's. Refusals are raised on every rank as HoctError with one message
(a method that is none, a comm that is no mpi4py communicator), and no rank is left waiting.

Skipped (exit 77) without mpirun, mpi4py or an MPI build of hoct."""
import os
import re
import subprocess
import sys
import textwrap

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hoct_testing import Results, run, tempdir  # noqa: E402
from mpi_testing import MPIRUN, PYTHON, require_modules  # noqa: E402  (skips without mpirun)

require_modules(("mpi4py.MPI", "python3-mpi4py"))
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
r = Results()

# One script for every case: argv = mode, then file and output pairs.
SCRIPT = textwrap.dedent('''
    import json, sys
    from mpi4py import MPI
    import hoct
    mode, args = sys.argv[1], sys.argv[2:]
    world = MPI.COMM_WORLD
    kwargs = json.loads(args[0])
    if mode == "trees":          # every rank: the tree of args[1], rank 0 writes args[2]
        comm, path, out = world, args[1], args[2]
    elif mode == "split":        # two groups of ranks, each its own file and output
        group = world.rank % 2
        comm = world.Split(group, world.rank)
        path, out = args[1 + 2 * group], args[2 + 2 * group]
    else:                        # "raises": every rank must raise HoctError
        path = args[1]
    mesh = hoct.read(path)
    if mode == "raises":
        try:
            hoct.contour_tree(mesh, comm=(world if kwargs.pop("world", True) else "world"),
                              threads=1, **kwargs)
        except hoct.HoctError as e:
            print(f"\\nRAISED {world.rank}: {e}", flush=True)
        else:
            print(f"\\nNOT RAISED {world.rank}", flush=True)
        sys.exit(0)
    tree = hoct.contour_tree(mesh, comm=comm, threads=1, **kwargs)
    if comm.rank == 0:
        tree.write_json(out, timings=False)
        if kwargs.get("arc_paths"):
            tree.write_vtp(out + ".vtp")
            paths = tree.arc_paths()
            print(f"\\nPATHS {len(paths)} {sum(len(p) > 2 for p in paths)}", flush=True)
    elif tree is not None:
        print(f"rank {world.rank} got a tree", flush=True)
        sys.exit(3)
''')


def mpi(n, *args):
    return subprocess.run([MPIRUN, "--oversubscribe", "-np", str(n), PYTHON, script,
                           *map(str, args)], capture_output=True, text=True, env=ENV, timeout=600)


def read(path):
    with open(path, "rb") as f:
        return f.read()


def flags(kwargs):
    out = []
    if "simplify" in kwargs:
        out += ["--simplify", kwargs["simplify"]]
    if kwargs.get("augmented"):
        out.append("--augmented")
    if kwargs.get("method") == "linear":
        out.append("--linear")
    if kwargs.get("method") == "refine":
        out += ["--refine", str(kwargs.get("refine", 4))]
    return out


with tempdir() as d:
    script = os.path.join(d, "tree_mpi.py")
    with open(script, "w") as f:
        f.write(SCRIPT)
    import json
    heater = os.path.join(d, "heater.vtu")
    run("generate", "heater", "--cells", "3000", "-o", heater)
    probe = mpi(1, "trees", "{}", heater, os.path.join(d, "probe.json"))
    if "built without MPI" in probe.stderr:
        print("SKIPPED: this hoct was built without MPI")
        sys.exit(77)
    r.check(probe.returncode == 0, f"one rank: exit {probe.returncode}: {probe.stderr[-2000:]}")

    cases = [
        ("heater", ["--cells", "3000"], {}),
        ("conductor", ["--cells", "2000"], {}),
        ("random", ["--cells", "3000", "--plateau", "30"], {}),
        ("random", ["--cells", "3000", "--plateau", "30"], {"augmented": True}),
        ("random", ["--cells", "2000", "--degree", "5", "--offset", "1e7"], {"simplify": "1%"}),
        ("random", ["--cells", "1500", "--quads", "--degree", "3"], {}),
        ("plate", ["--cells", "2000", "--degree", "2"], {}),  # 100 holes: a Reeb graph
        ("random", ["--cells", "3000", "--plateau", "30"], {"method": "linear"}),
        ("random", ["--cells", "1000", "--plateau", "30"], {"method": "refine", "refine": 2}),
    ]
    wants = []
    for k, (name, gen, kwargs) in enumerate(cases):
        path = os.path.join(d, f"{name}{k}.vtu")
        run("generate", name, *gen, "-o", path)
        want = os.path.join(d, f"want{k}.json")
        run("tree", path, "--json", want, "--no-timings", "-q", *flags(kwargs))
        wants.append((path, want))
        label = f"{name} {' '.join(gen)} {kwargs}"
        for n in (1, 2, 3):
            got = os.path.join(d, f"got{k}_{n}.json")
            p = mpi(n, "trees", json.dumps(kwargs), path, got)
            r.check(p.returncode == 0, f"{label}, {n} ranks: exit {p.returncode}: "
                    f"{p.stdout[-500:]}{p.stderr[-1500:]}")
            if p.returncode == 0:
                r.check(read(got) == read(want), f"{label}, {n} ranks: JSON differs from the CLI's")
        print(f"{label}: 1-3 ranks checked", flush=True)

    # Two communicators at once: ranks 0, 2 (group 0) and 1, 3 (group 1), two files.
    (a, want_a), (b, want_b) = wants[0], wants[2]
    got_a, got_b = os.path.join(d, "split_a.json"), os.path.join(d, "split_b.json")
    p = mpi(4, "split", "{}", a, got_a, b, got_b)
    r.check(p.returncode == 0, f"split communicators: exit {p.returncode}: {p.stderr[-1500:]}")
    if p.returncode == 0:
        r.check(read(got_a) == read(want_a), "split communicators: group 0's tree differs")
        r.check(read(got_b) == read(want_b), "split communicators: group 1's tree differs")
    print("split communicators checked", flush=True)

    # arc_paths=True: the ranks' pieces draw the arcs (exact/piece_arcs): one polyline per arc,
    # most over the surface, none with a step longer than the command line's longest.
    from mpi_testing import longest_step, polylines
    heater_vtp = os.path.join(d, "heater_cli.vtp")
    run("tree", heater, "--vtp", heater_vtp, "-q")
    for n in (2, 3):
        got = os.path.join(d, f"arcs_{n}.json")
        p = mpi(n, "trees", json.dumps({"arc_paths": True}), heater, got)
        counts = re.search(r"PATHS (\d+) (\d+)", p.stdout)
        lines = polylines(got + ".vtp") if os.path.exists(got + ".vtp") else []
        arcs = len(json.load(open(got))["arcs"]) if os.path.exists(got) else -1
        r.check(p.returncode == 0 and counts and int(counts[1]) == arcs == len(lines)
                and int(counts[2]) > arcs // 2 and longest_step(lines) <= 1.5 * longest_step(
                    polylines(heater_vtp)),
                f"arc_paths=True, {n} ranks: the pieces' arcs ({p.returncode}, {arcs} arcs, "
                f"{len(lines)} lines):\n{p.stdout[-500:]}{p.stderr[-1500:]}")
    print("arc_paths checked", flush=True)

    # Refusals: raised on every rank, with one message, and the job ends normally.
    for label, path, kwargs, text in [
        ("no such method", heater, {"method": "cubic"}, "method must be"),
        ("not a communicator", heater, {"world": False}, "mpi4py communicator"),
    ]:
        p = mpi(3, "raises", json.dumps(kwargs), path)
        # The ranks' lines may interleave: each rank's report is found by its own marker.
        raised = sorted(int(x) for x in re.findall(r"RAISED (\d+): ", p.stdout))
        r.check(p.returncode == 0 and raised == [0, 1, 2] and "NOT RAISED" not in p.stdout
                and p.stdout.count(text) == 3,
                f"{label}: want HoctError ('{text}') on all 3 ranks, got exit {p.returncode}: "
                f"{p.stdout[-1500:]}{p.stderr[-1000:]}")
        print(f"{label}: refused on every rank", flush=True)

r.finish()
